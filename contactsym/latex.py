r"""LaTeX for every stage object and every region, through SymPy's printer.

Each stage object is a list of :class:`Formula` (see :func:`formulas`): one
formula-level result each, with the paper equations it corresponds to, e.g. the
fast subsystem (2.1)/(3.1)/(4.1), the matrix A (4.3), the linearization (4.5), the
characteristic polynomial (4.6) and the Routh–Hurwitz conditions (4.7). Scenes that
reproduce an example of the paper add its numbers ((5.4) for the guides' A, (6.3) for
the brake's robust stability, ...). :func:`latex` joins the formulas in an
``aligned`` block; ``_repr_latex_`` of each stage shows them with their citations.

Examples
--------
>>> import contactsym as cs
>>> lin = cs.scene("brake").linearization()
>>> [(f.key, f.cite()) for f in formulas(lin)]
[('A', '(4.3), (6.2)'), ('det A', ''), ('matrix', '(4.5)'), ('charpoly', '(4.6)')]
>>> print(formulas(lin)[0].tag())
\tag*{(4.3), (6.2)}
>>> print(latex(cs.scene("sliding-point").linearization().det_A))
\frac{1}{m}
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp
from sympy.printing.latex import LatexPrinter

from .scenes import paper_name

__all__ = ["Formula", "PAPER_EQUATIONS", "formulas", "hurwitz_names", "latex", "paper_equations", "tex"]


class _PaperPrinter(LatexPrinter):
    """SymPy's LaTeX printer with the paper's letters: \\varepsilon and \\varphi for the
    symbols (and functions) named epsilon and phi."""

    def _deal_with_super_sub(self, string: str, style: str = "plain") -> str:
        return re.sub(r"\\(epsilon|phi)(?![A-Za-z])", r"\\var\1", super()._deal_with_super_sub(string, style))


def tex(expr, **settings) -> str:
    r"""LaTeX of a SymPy object, as ``sympy.latex`` prints it but in the paper's letters.

    Examples
    --------
    >>> eps, phi_1 = sp.symbols("epsilon phi_1")
    >>> tex(eps**2 * sp.sin(phi_1))
    '\\varepsilon^{2} \\sin{\\left(\\varphi_{1} \\right)}'
    """
    return _PaperPrinter(settings).doprint(expr)


@dataclass(frozen=True)
class Formula:
    r"""One formula-level result: ``lhs relation rhs``, and where the paper has it.

    Attributes
    ----------
    key : str
        What the formula is: ``"A"``, ``"fast"``, ``"equilibrium"``, ...
    lhs : str
        LaTeX of the left side ("" for a condition standing alone).
    rhs : sympy object or str
        The right side (a str is taken as LaTeX).
    relation : str
        LaTeX of the relation, ``"="`` by default ("" for a condition).
    paper : tuple of str
        Equation numbers of the paper, most general first, e.g. ``("4.3", "6.2")``.
    note : str
        A remark for the reader (a correction of the print, a proposition's name).

    Examples
    --------
    >>> f = Formula("A", "A", sp.Symbol("a"), paper=("4.3",))
    >>> f.body, f.cite(), f.tag()
    ('A = a', '(4.3)', '\\tag*{(4.3)}')
    """

    key: str
    lhs: str
    rhs: object
    relation: str = "="
    paper: tuple = ()
    note: str = ""

    @property
    def rhs_latex(self) -> str:
        return self.rhs if isinstance(self.rhs, str) else tex(self.rhs)

    @property
    def body(self) -> str:
        """The formula as one line of LaTeX mathematics."""
        return " ".join(part for part in (self.lhs, self.relation, self.rhs_latex) if part)

    def cite(self) -> str:
        """The paper's equation numbers, ``"(4.3), (6.2)"`` ("" when the paper has no number)."""
        return ", ".join(f"({number})" for number in self.paper)

    def tag(self) -> str:
        """An amsmath ``\\tag*`` with the citation, or ``\\notag``."""
        return f"\\tag*{{{self.cite()}}}" if self.paper else r"\notag"


# --- the paper's equation numbers ---------------------------------------------------

#: Equation numbers, notes and errata of the paper's own examples, by scene and formula key.
#: A value is ``(numbers, note)``; keys are formula keys, or ``"key:detail"`` for one row.
PAPER_EQUATIONS: dict[str, dict[str, tuple[tuple, str]]] = {
    "sliding-point": {
        "accelerations": (("1.10",), ""),
        "regularized": (("1.12",), ""),
        "fast": (("1.12",), "eps = 0 in (1.12)"),
        "law": (("1.11",), "Kelvin-Voigt law (1.11)"),
    },
    "painleve-klein-rod": {
        "accelerations:x_1": (("3.5",), ""),
        "accelerations:delta": (("3.6",), "corrected: Y*_j = Y_j / sin(phi), erratum 1"),
        "f": (("3.6", "3.7"), "erratum 1"),
    },
    "painleve-klein-guides": {
        "accelerations": (("5.1",), "with the moment M, erratum 10"),
        "contact accelerations": (("5.2",), ""),
        "equilibrium": (("5.3",), ""),
        "A": (("5.4",), ""),
        "det A": (("5.5",), ""),
        "stable for every law": (("5.6",), "corrected: erratum 11"),
        "unstable for every law": (("5.7",), ""),
    },
    "brake": {
        "contact accelerations": (("6.1",), ""),
        "A": (("6.2",), ""),
        "stable for every law": (("6.3",), "with equality allowed: erratum 12"),
        "Hopf line": ((), "for Phi_j = Phi, Psi_j = Psi, alpha = 90 deg it is (6.4), with the mass: erratum 13"),
        "hopf frequency": ((), "the frequency after (6.4), with the mass: erratum 14"),
    },
}


def _generic(key: str, k: int) -> tuple[tuple, str]:
    """The numbers of the general theory (§§1-4) for a formula key, for k contacts."""
    by_k = {
        "fast": {1: ("3.1",), 2: ("4.1",)},
        "f": {1: ("3.1",), 2: ("4.1",)},
        "law": {1: ("3.1",), 2: ("4.1",)},
        "equilibrium": {1: ("3.2",), 2: ("4.2",)},
        "A": {1: ("3.2",), 2: ("4.3",)},
        "matrix": {1: (), 2: ("4.5",)},
        "charpoly": {1: (), 2: ("4.6",)},
        "coefficient": {1: (), 2: ("4.6",)},
        "hurwitz": {1: ("3.2",), 2: ("4.7",)},
        "stable for every law": {1: ("3.2",), 2: ("4.4",)},
        "unstable for every law": {1: ("3.2",), 2: ()},
        "Hopf line": {1: (), 2: ("4.7",)},
    }
    notes = {
        "stable for every law": {1: "Proposition 3", 2: "Proposition 6", 3: "Proposition 7"},
        "unstable for every law": {1: "Proposition 3", 2: "Proposition 6", 3: "Proposition 8"},
        "law-dependent": {2: "Remarks 1-2: Hopf bifurcation possible"},
        "Hopf line": {2: "Delta_3 = 0: Remarks 1-2"},
        "unique for every load": {1: "Proposition 4"},
    }
    fixed = {
        "accelerations": ("1.4",),
        "contact accelerations": ("1.4",),
        "regularized": ("1.9",),
        "reduced": ("2.2",),
        "unique for every load": ("3.3",),
    }
    numbers = fixed.get(key, by_k.get(key, {}).get(min(k, 2), ()))
    if key in ("fast", "f", "law") and k >= 3:
        numbers = ("2.1",)
    note = notes.get(key, {}).get(min(k, 3), "")
    return numbers, note


def paper_equations(scene, key: str, detail: str | None = None) -> tuple[tuple, str]:
    """The paper's equation numbers and a note for a formula of ``scene``.

    Examples
    --------
    >>> import contactsym as cs
    >>> paper_equations(cs.scene("painleve-klein-guides"), "A")
    (('4.3', '5.4'), '')
    >>> paper_equations(cs.scene("brake"), "stable for every law")
    (('4.4', '6.3'), 'Proposition 6; with equality allowed: erratum 12')
    """
    k = getattr(scene, "k", 2)
    numbers, note = _generic(key, k)
    own = PAPER_EQUATIONS.get(paper_name(scene) or "", {})  # by identity: a user scene named "brake" has none
    extra_numbers, extra_note = own.get(f"{key}:{detail}", own.get(key, ((), "")))
    numbers = tuple(dict.fromkeys(numbers + tuple(extra_numbers)))
    note = "; ".join(n for n in (note, extra_note) if n)
    return numbers, note


# --- formulas of each stage ------------------------------------------------------------


def _prime(symbol) -> str:
    return tex(symbol) + "'"


def _formula(scene, key, lhs, rhs, relation="=", detail=None) -> Formula:
    numbers, note = paper_equations(scene, key, detail)
    return Formula(key, lhs, rhs, relation, numbers, note)


def _scene_formulas(scene) -> list[Formula]:
    rows = []
    for q in scene.coordinates:
        plain = scene._plain(q)
        lhs = r"\ddot{" + tex(plain) + "}"
        rows.append(_formula(scene, "accelerations", lhs, scene._plain(scene.accelerations[q]), detail=str(plain)))
    if all(gap in scene.coordinates for gap in scene.gaps):
        return rows  # the contact accelerations are among the accelerations above
    for j, g in enumerate(scene.gap_accelerations, 1):
        lhs = r"\ddot{q}" + (f"_{{{j}}}" if scene.k > 1 else "")
        rows.append(_formula(scene, "contact accelerations", lhs, sp.expand(scene.freeze(g)), detail=str(j)))
    return rows


def _regularized_formulas(reg) -> list[Formula]:
    scene = reg.scene
    rows = [_formula(scene, "regularized", _prime(x), reg.eps * X) for x, X in zip(reg.x, reg.X)]
    rows += [_formula(scene, "regularized", _prime(y), Y) for y, Y in zip(reg.y, reg.Y)]
    return rows


def _fast_formulas(fast) -> list[Formula]:
    scene = fast.scene
    u = fast.u
    names = ["f"] if fast.k == 1 else [f"f_{j}" for j in range(1, fast.k + 1)]
    f_of_u = [sp.Function(name)(*u) for name in names]
    rows = []
    for j in range(fast.k):
        rows.append(_formula(scene, "fast", _prime(u[j]), fast.Phi[j] * fast.v[j] + fast.Psi[j] * f_of_u[j]))
        rows.append(_formula(scene, "fast", _prime(fast.v[j]), f_of_u[j]))
    for j in range(fast.k):
        rows.append(_formula(scene, "f", tex(f_of_u[j]), fast.f[j]))
    return rows


def _signs_latex(signs) -> str:
    return r"\left(" + ", ".join("+" if s == 1 else "-" for s in signs) + r"\right)"


def _branch_formulas(branch, scene=None) -> list[Formula]:
    k = len(branch.u_star)
    scene = scene if scene is not None else _KOnly(k)
    rows = []
    for j, value in enumerate(branch.u_star, 1):
        lhs = "u^{*}" if k == 1 else f"u_{{{j}}}^{{*}}"
        rows.append(_formula(scene, "equilibrium", lhs, value))
    if branch.signs:
        where = r"\text{where } s = " + _signs_latex(branch.signs) + r":\ "
        rows.append(Formula("existence", "", where + tex(branch.condition), ""))
    return rows


@dataclass(frozen=True)
class _KOnly:
    """A stand-in scene that only knows k (for a Branch printed on its own)."""

    k: int
    name: str = ""


def _equilibria_formulas(eq) -> list[Formula]:
    return [row for branch in eq.branches for row in _branch_formulas(branch, eq.scene)]


def _presenter(scene, present: bool):
    if present and scene is not None and getattr(scene, "presentation", None):
        return scene.present
    return lambda expr: expr


def _linearization_formulas(lin, present=False) -> list[Formula]:
    scene = lin.scene
    show = _presenter(scene, present)
    return [
        _formula(scene, "A", "A", show(lin.A)),
        _formula(scene, "det A", r"\det A", show(lin.det_A)),
        _formula(scene, "matrix", r"J", show(lin.matrix)),
        _formula(scene, "charpoly", r"p(\lambda)", show(lin.charpoly.as_expr())),
    ]


def hurwitz_names(stability) -> list[str]:
    r"""LaTeX names of ``stability.hurwitz``: coefficients ``p_s`` of (4.6), minors ``Delta_m`` of (4.7).

    Examples
    --------
    >>> import contactsym as cs
    >>> hurwitz_names(cs.scene("brake").stability())
    ['p_{3}', 'p_{2}', 'p_{1}', 'p_{0}', '\\Delta_{3}']
    """
    letters = {"p": "p", "Delta": r"\Delta"}
    return [f"{letters[kind]}_{{{index}}}" for kind, index in stability.poly.labels]


def _generic_minors(n: int) -> dict[int, sp.Expr]:
    """Delta_m in the coefficients p_n, ..., p_0 (symbols), for m = 1..n."""
    from .hurwitz import hurwitz_minors
    from .linear import lam

    p = [sp.Symbol(f"p_{s}") for s in range(n + 1)]
    minors = hurwitz_minors(sp.Poly(sum(p[s] * lam**s for s in range(n + 1)), lam))
    return {m: sp.expand(minor) for m, minor in enumerate(minors, 1)}


def _stability_formulas(st, present=False) -> list[Formula]:
    scene = st.linearization.scene
    show = _presenter(scene, present)
    names = hurwitz_names(st)
    n = st.linearization.charpoly.degree()
    generic = _generic_minors(n)
    rows = []
    for name, condition in zip(names, st.hurwitz):
        if name.startswith(r"\Delta"):
            m = int(name[len(r"\Delta_{") : -1])
            rows.append(_formula(scene, "hurwitz", name, generic[m]))
            rows.append(_formula(scene, "hurwitz", "", show(condition)))
        else:
            rows.append(_formula(scene, "coefficient", name, show(condition)))
    rows.append(_formula(scene, "hurwitz", ", ".join(names), sp.S.Zero, ">"))
    for key, attribute in (
        ("stable for every law", "robustly_stable"),
        ("unstable for every law", "robustly_unstable"),
        ("law-dependent", "law_dependent"),
        ("Hopf line", "hopf"),
    ):
        value = getattr(st, attribute)
        if value is None:
            continue
        numbers, note = paper_equations(scene, key)
        lhs = r"\text{" + key + "}"
        rows.append(Formula(key, lhs, show(value), ":", numbers, note))
    if st.hopf_frequency is not None:
        rows.append(_formula(scene, "hopf frequency", r"\omega", show(st.hopf_frequency)))
    return rows


def _reduced_formulas(red) -> list[Formula]:
    scene = red.scene
    rows = [_formula(scene, "reduced", tex(n), value) for n, value in red.reactions.items()]
    rows += [_formula(scene, "reduced", r"\ddot{" + tex(q) + "}", value) for q, value in red.accelerations.items()]
    if red.branch.signs:
        rows.append(Formula("existence", "", r"\text{where } " + tex(red.condition), ""))
    return rows


def _region_formulas(region) -> list[Formula]:
    return [Formula(region.name or "region", "", region.condition, "")]


def _hurwitz_formulas(hurwitz) -> list[Formula]:
    return [Formula("hurwitz", f"h_{{{i}}}", c, "", ("4.7",)) for i, c in enumerate(hurwitz.conditions, 1)]


def formulas(obj, *, present: bool = False) -> tuple[Formula, ...]:
    r"""The formula-level results of a stage object, a branch or a region, in order.

    ``present=True`` rewrites the linearization and stability formulas in the
    scene's presentation variables (kappa, v_j, mu_pm, ...).

    Examples
    --------
    >>> import contactsym as cs
    >>> fast = cs.scene("sliding-point").fast_subsystem()
    >>> [(f.key, f.body, f.cite()) for f in formulas(fast)][:2]
    [('fast', "u' = - 2 b f{\\left(u \\right)} - v", '(3.1), (1.12)'), ('fast', "v' = f{\\left(u \\right)}", '(3.1), (1.12)')]
    """
    from .equilibria import Branch, Equilibria
    from .fast import FastSubsystem
    from .hurwitz import Hurwitz
    from .linear import Linearization
    from .regions import Region
    from .regularize import ReducedSystem, Regularized
    from .scene import Scene
    from .stability import Stability

    printers = (
        (Scene, _scene_formulas),
        (Regularized, _regularized_formulas),
        (FastSubsystem, _fast_formulas),
        (Equilibria, _equilibria_formulas),
        (Branch, _branch_formulas),
        (ReducedSystem, _reduced_formulas),
        (Region, _region_formulas),
        (Hurwitz, _hurwitz_formulas),
    )
    for kind, printer in printers:
        if isinstance(obj, kind):
            return tuple(printer(obj))
    if isinstance(obj, Linearization):
        return tuple(_linearization_formulas(obj, present))
    if isinstance(obj, Stability):
        return tuple(_stability_formulas(obj, present))
    raise TypeError(f"no formulas for {type(obj).__name__}; give a stage object, a Branch or a Region.")


def _aligned(rows: tuple[Formula, ...], tags: bool) -> str:
    lines = []
    for row in rows:
        relation = row.relation if row.relation in ("", ":") else row.relation + " "
        line = f"{row.lhs} &{relation}{row.rhs_latex}" if row.lhs else f"& {row.rhs_latex}"
        line = line.replace("&:", r"&: \ ")
        if tags and row.paper:
            line += r" && \text{" + row.cite() + "}"
        lines.append(line)
    return r"\begin{aligned} " + r" \\ ".join(lines) + r" \end{aligned}"


def latex(obj, *, present: bool = False, tags: bool = False) -> str:
    r"""LaTeX for a scene, a stage object, a branch, a region, or any SymPy object.

    Stage objects print as an ``aligned`` block of their :func:`formulas`;
    ``tags=True`` adds each formula's paper equation numbers in a column on the right,
    ``present=True`` uses the scene's presentation variables. A region prints as its
    condition; anything else goes to ``sympy.latex``.

    Examples
    --------
    >>> import contactsym as cs
    >>> print(cs.latex(cs.scene("sliding-point").fast_subsystem()))
    \begin{aligned} u' &= - 2 b f{\left(u \right)} - v \\ v' &= f{\left(u \right)} \\ f{\left(u \right)} &= \frac{u}{m} + \frac{Y{\left(x,\dot{x} \right)}}{m} \end{aligned}
    >>> print(cs.latex(cs.scene("brake").regions()["stable for every law"]))
    \mu \leq \left|{\cot{\left(\alpha \right)}}\right|
    >>> print(cs.latex(cs.scene("sliding-point").equilibria(), tags=True))
    \begin{aligned} u^{*} &= - Y{\left(x,\dot{x} \right)} && \text{(3.2)} \end{aligned}
    """
    from .regions import Region

    if isinstance(obj, Region):
        return obj.latex()
    try:
        rows = formulas(obj, present=present)
    except TypeError:
        return tex(obj)
    return _aligned(rows, tags)


def _repr_latex(obj) -> str:
    """What ``_repr_latex_`` of a stage object returns: its formulas with their citations."""
    return f"$\\displaystyle {latex(obj, tags=True)}$"
