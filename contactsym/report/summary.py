"""The conditions of a scene as data: :func:`conditions` (written as ``conditions.json``) and :func:`summary_text`.

Each expression is given as SymPy text and LaTeX, with the paper's equation numbers where
it has them; the report's long expressions appear here in full.

Examples
--------
>>> import contactsym as cs
>>> data = conditions(cs.scene("painleve-klein-guides"))
>>> data["equilibrium_counts"]["unique"]["sympy"], data["equilibrium_counts"]["unique"]["paper"]
('Abs(v_1) + Abs(v_2) < 2*kappa**2', ['(5.8)'])
"""

from __future__ import annotations

import copy
import weakref

import sympy as sp

from ..algebra.basic import node_count
from ..algebra.reductions import known_sign, quotient_sign
from ..errors import ContactsymError
from ..mechanism.equation_numbers import paper_equations
from ..mechanism.scene import Scene
from ..printing.shared import sstr_shared
from ..stages.regions import REGION_NAMES, Region, proved_no_equilibrium
from ..stages.stability import UNDECIDED_TEX, hurwitz_names
from ..validate import cut, instance_of, sign_pattern
from .plain_text import own_letters
from .scene_parts import _count_tag
from .typesetting import UNORDERED_NODES, _tex

__all__ = ["always_positive", "conditions", "no_equilibrium_note", "summary_text"]


def _counts(scene) -> tuple[dict[str, Region], str]:
    """The scene's equilibrium-count regions and "", or no regions and why they could not be derived."""
    try:
        return scene.equilibrium_counts(), ""
    except (ContactsymError, NotImplementedError) as error:
        return {}, f"No equilibrium counts for this scene: {error}"


def _entry(expr, paper=(), note="") -> dict:
    large = node_count(expr, UNORDERED_NODES) > UNORDERED_NODES  # its terms printed unsorted, as by _tex
    entry = {"sympy": sstr_shared(expr, order="none" if large else None), "latex": _tex(expr)}  # _tex: printed once
    if paper:
        entry["paper"] = [f"({number})" for number in paper]
    if note:
        entry["note"] = note
    return entry


def always_positive(scene, condition) -> str | None:
    """Why ``condition > 0`` holds throughout the scene's domain, or None when that is not proved.

    The proof is exact (:func:`contactsym.algebra.reductions.known_sign`); the answer names it.

    Examples
    --------
    >>> import contactsym as cs
    >>> s = cs.scene("double-pendulum-tip")
    >>> [always_positive(s, h) for h in s.stability().hurwitz]
    ['a positive multiple of det M', None, None]
    """
    positive = tuple(scene.positive_expressions)
    factor = getattr(scene, "mass_matrix_factor", None)
    if factor is not None and quotient_sign(condition, factor, positive) == 1:
        return "a positive multiple of det M"
    if known_sign(condition, positive) != 1:
        return None
    if known_sign(condition) != 1:
        return "positive on the scene's declared intervals"
    return "positive for all values of its symbols"


def _hopf_names(scene) -> dict:
    """The names of omega and of the stretched time tau where a scene's own symbol prints as either
    (``{"name": "omegahat", "name_latex": "\\hat{\\omega}", "time": "tauhat"}``); empty otherwise.

    Examples
    --------
    >>> import contactsym as cs
    >>> _hopf_names(cs.scene("brake"))
    {}
    """
    letters = own_letters(scene)
    omega, tau = letters.text("omega"), str(scene.regularized().tau)
    if (omega, tau) == ("omega", "tau"):
        return {}
    return {"name": omega, "name_latex": letters.tex("omega"), "time": tau}


def no_equilibrium_note(scene, signs=None) -> str | None:
    """Why a scene's regions are empty when no equilibrium with every contact closed exists, and the
    lift-offs that do exist; None when some branch may exist (or its roots are not derived).

    Examples
    --------
    >>> import contactsym as cs
    >>> no_equilibrium_note(cs.scene("brake")) is None
    True
    """
    if not proved_no_equilibrium(scene, signs):
        return None
    equilibria = scene.equilibria(signs)
    note = (
        "No equilibrium with every contact closed exists where the scene is declared: the existence condition "
        "of each branch (4.2) is False (the loads pull a one-sided contact open), so no stability is claimed."
    )
    try:
        lifts = [lift for lift in equilibria.lift_offs if lift.condition != sp.false]
    except (ContactsymError, NotImplementedError):
        lifts = []
    for lift in lifts:
        opened = ", ".join(str(j + 1) for j in lift.open)
        note += f" Lift-off of contact {opened}: exists where {cut(sp.sstr(lift.condition), 100, count=False)}"
        note += f", stable where {cut(sp.sstr(lift.stable), 100, count=False)}."
    return note


#: conditions() of each scene, computed once: the report, the summary and the JSON share them.
_COMPUTED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def conditions(scene, signs=None) -> dict:
    """The scene's conditions as JSON-ready data: regions, Hurwitz conditions, A, branches.

    Each expression is given as SymPy text (``sympy``) and LaTeX (``latex``), with the
    paper's equation numbers where it has them. ``signs`` selects one sign pattern. A Hurwitz
    condition that always holds has a note ``always`` that says why (see :func:`always_positive`).
    Computed once per scene and sign pattern; each call returns its own copy.

    Examples
    --------
    >>> import contactsym as cs
    >>> data = conditions(cs.scene("brake"))
    >>> data["regions"]["stable for every law"]["sympy"], data["regions"]["stable for every law"]["paper"]
    ('mu <= Abs(cot(alpha))', ['(4.4)', '(6.3)'])
    """
    instance_of(scene, Scene, "scene", "pass a Scene, e.g. contactsym.scene('brake')")
    key = None if signs is None else sign_pattern(signs)  # a clear error for anything else
    try:
        computed = _COMPUTED.setdefault(scene, {})
    except TypeError:  # an object that cannot be weakly referenced: nothing to share
        computed = {}
    if key not in computed:
        try:
            computed[key] = _conditions(scene, signs)
        except ContactsymError as error:
            raise _located(error, scene) from error
    return copy.deepcopy(computed[key])


#: What a user can do when a sign or a closed form does not follow.
ADVICE = (
    "Declaring the intervals of the angles ([intervals] in a scene file) or the signs of the parameters "
    '([parameters], e.g. m = "positive") lets more signs be decided.'
)


def _located(error: ContactsymError, scene) -> ContactsymError:
    """The error again, its message cut to a readable length and naming the scene and what to do."""
    message = cut(str(error), 400)
    if f"'{scene.name}'" not in message:
        message = f"scene '{scene.name}', deriving its conditions: {message}"
    if ADVICE not in message:
        message += " " + ADVICE
    try:
        return type(error)(message)
    except TypeError:  # an error class with other arguments: the package's base class says the same
        return ContactsymError(message)


def _conditions(scene, signs) -> dict:
    st = scene.stability(signs)
    lin = scene.linearization(signs)
    data = {
        "scene": scene.name,
        "signs": None if signs is None else list(signs),
        "description": scene.description,
        "k": scene.k,
        "parameters": [
            {"name": str(s), "assumptions": [a for a in ("positive", "negative", "real") if getattr(s, f"is_{a}")]}
            for s in scene.parameters
        ],
        "regions": {},
        "hurwitz": [],
        "A": _entry(lin.A, *paper_equations(scene, "A")),
        "det_A": _entry(lin.det_A, *paper_equations(scene, "det A")),
        "charpoly": _entry(lin.charpoly.as_expr(), *paper_equations(scene, "charpoly")),
        "hopf_frequency": None,
        "equilibria": [],
        "equilibrium_counts": None,
    }
    if scene.presentation:
        data["presentation"] = {sp.sstr(k): sp.sstr(v) for k, v in scene.presentation.items()}
    if scene.declared_positive:  # the regions hold there (and may be divided by these expressions)
        data["domain"] = [_entry(sp.Gt(e, 0, evaluate=False)) for e in scene.declared_positive]
    regions = scene.regions(signs)
    for name in [*REGION_NAMES, *regions]:
        if name in regions:
            data["regions"][name] = _entry(regions[name].condition, *paper_equations(scene, name))
        elif getattr(st, REGION_NAMES[name]) is None:  # neither proved nor disproved at this numeric A
            data["regions"][name] = {"sympy": "undecided", "latex": UNDECIDED_TEX}
    for name, condition in zip(hurwitz_names(st), st.hurwitz):
        key = "coefficient" if name.startswith("p") else "hurwitz"
        entry = {"name": name, **_entry(condition, *paper_equations(scene, key))}
        reason = always_positive(scene, condition)
        if reason:
            entry["always"] = reason
        data["hurwitz"].append(entry)
    if st.hopf_frequency is not None:
        data["hopf_frequency"] = _entry(st.hopf_frequency) | _hopf_names(scene)
    if st.robustness is not None:
        data["robustness"] = _robustness_entry(st.robustness)
    try:
        for branch in scene.equilibria(signs).branches:
            data["equilibria"].append(
                {
                    "signs": list(branch.signs),
                    "u_star": [_entry(x) for x in branch.u_star],
                    "condition": _entry(branch.condition),
                }
            )
    except ContactsymError as error:
        data["equilibria"] = {"error": str(error)}
    note = no_equilibrium_note(scene, signs)
    if note:
        data["equilibria_note"] = note
    counts, note = _counts(scene)
    if counts:
        data["equilibrium_counts"] = {
            name: _entry(region.condition, _count_tag(scene, name)) for name, region in counts.items()
        }
    elif note:
        data["equilibrium_counts_note"] = note
    return data


def _robustness_entry(robustness) -> dict:
    """The point decision for a numeric A (k >= 3): verdict, certificate and witness laws."""
    laws = {}
    for name, law in (("stable", robustness.stable_law), ("unstable", robustness.unstable_law)):
        if law is not None:
            laws[name] = {"Phi": [sp.sstr(x) for x in law.Phi], "Psi": [sp.sstr(x) for x in law.Psi]}
    certificate = robustness.certificate
    return {
        "verdict": robustness.verdict,
        "certificate": None if certificate is None else {"kind": certificate.kind, "statement": certificate.statement},
        "witness_laws": laws,
    }


def summary_text(data: dict) -> str:
    """A short plain-text summary of :func:`conditions`: the closed-form regions.

    Examples
    --------
    >>> import contactsym as cs
    >>> for line in summary_text(conditions(cs.scene("brake"))).splitlines()[1:3]:
    ...     print(line)
      in the domain sin(alpha) > 0
      stable for every law: mu <= Abs(cot(alpha))   (4.4), (6.3)
    """
    if not isinstance(data, dict) or not {"scene", "regions"} <= set(data):
        raise ContactsymError("summary_text takes the dict that contactsym.conditions(scene) returns.")
    lines = [f"{data['scene']}: {data['description']}"]
    if data.get("domain"):
        lines.append("  in the domain " + ", ".join(entry["sympy"] for entry in data["domain"]))
    for name, entry in data["regions"].items():
        cite = ", ".join(entry.get("paper", []))
        text = cut(entry["sympy"], 100, count=False)
        lines.append(f"  {name}: {text}" + (f"   {cite}" if cite else ""))
    for name, entry in (data.get("equilibrium_counts") or {}).items():
        text = cut(entry["sympy"], 100, count=False)
        cite = ", ".join(entry.get("paper", []))
        lines.append(f"  equilibria, {name}: {text}" + (f"   {cite}" if cite else ""))
    if data.get("equilibria_note"):
        lines.append("  " + data["equilibria_note"])
    if data.get("hopf_frequency"):
        text = data["hopf_frequency"]["sympy"]
        lines.append(f"  Hopf frequency {data['hopf_frequency'].get('name', 'omega')}: " + cut(text, 100, count=False))
    return "\n".join(lines)
