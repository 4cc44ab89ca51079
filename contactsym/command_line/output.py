"""What the commands of :mod:`contactsym.cli` print: a scene's derivation chain as plain text
(``contactsym show``), and its conditions as text or LaTeX (``contactsym conditions``).

Examples
--------
>>> print(derivation_chain("painleve-rod").splitlines()[0])
scene painleve-rod: classical Painleve rod, one end sliding on a rough floor (one-sided: the end may lift off)
"""

from __future__ import annotations

import re

import sympy as sp

from ..mechanism.files.reader import scene_or_file
from ..mechanism.scene import Scene
from ..report.plain_text import own_letters
from ..report.summary import no_equilibrium_note

__all__ = ["conditions_latex", "conditions_text", "derivation_chain"]


def derivation_chain(name) -> str:
    """The derivation chain of a scene (a built-in name, a scene file or a Scene), as plain text.

    Examples
    --------
    >>> print(derivation_chain("sliding-point").splitlines()[0])
    scene sliding-point: (1.10)-(1.12): a point sliding on a rough line, Kelvin-Voigt contact
    """
    s = name if isinstance(name, Scene) else scene_or_file(name)
    fast = s.fast_subsystem()
    lin = s.linearization()
    st = s.stability()
    letters = own_letters(s)  # the package's t, eps, A, omega apart from the scene's own names
    eps = "eps" if letters.text("eps") == "eps" else str(s.eps)
    u, A = fast.u[0].name.partition("_")[0], letters.text("A")
    lines = [f"scene {s.name}: {s.description}", "", "accelerations (1.4):"]
    lines += [f"  {s.plain(q)}'' = {s.plain(g)}" for q, g in s.accelerations.items()]
    lines += ["", f"fast subsystem (2.1), {s.regularized().tau} = {letters.text('t')}/{eps}:"]
    lines += [f"  {eq.lhs} = {eq.rhs}" for eq in fast.equations]
    lines += ["", f"equilibria {letters.text('f')}({u}*) = 0 (4.2):"]
    for branch in s.equilibria():
        lines.append(f"  signs {branch.signs}: {u}* = {branch.u_star}, exists where {branch.condition}")
    lines += [
        "",
        f"{A} (4.3) = {lin.A.tolist()}",
        f"det {A} = {lin.det_A}",
        f"characteristic polynomial (4.6): {lin.charpoly.as_expr()}",
        "",
        "Hurwitz conditions (4.7), all > 0:",
    ]
    lines += [f"  {c}" for c in st.hurwitz]
    note = no_equilibrium_note(s)
    if note:  # the statements below would concern an equilibrium that exists nowhere
        lines += ["", "for every admissible contact law: no claim. " + note]
        return "\n".join(lines)
    lines += [
        "",
        "for every admissible contact law:",
        f"  stable where   {_verdict_text(st.robustly_stable)}",
        f"  unstable where {_verdict_text(st.robustly_unstable)}",
        f"  law-dependent where {_verdict_text(st.law_dependent)}",
    ]
    if st.k >= 3 and st.A.free_symbols and st.undecided != sp.false:
        lines.append(f"  undecided where {st.undecided}")
    if st.hopf_frequency is not None:
        lines.append(f"Hopf frequency {letters.text('omega')} (stretched time) = {st.hopf_frequency}")
    return "\n".join(lines)


def _verdict_text(value) -> str:
    """A robustness statement as text: its region, or "undecided" where it is neither proved nor disproved."""
    return "undecided" if value is None else str(value)


def conditions_text(data: dict) -> str:
    """The conditions of :func:`contactsym.report.conditions` as plain text, in full."""
    lines = [f"{data['scene']}: {data['description']}"]
    if data.get("signs"):
        lines.append(f"sign pattern {tuple(data['signs'])}")
    if data.get("equilibria_note"):
        lines.append(data["equilibria_note"])
    if data.get("domain"):
        lines.append("in the scene's domain: " + ", ".join(entry["sympy"] for entry in data["domain"]))
    lines.append("closed-form regions:")
    for name, entry in data["regions"].items():
        cite = ", ".join(entry.get("paper", []))
        lines.append(f"  {name}: {entry['sympy']}" + (f"   {cite}" if cite else ""))
    if data.get("equilibrium_counts"):
        lines.append("number of equilibria:")
        for name, entry in data["equilibrium_counts"].items():
            cite = ", ".join(entry.get("paper", []))
            lines.append(f"  {name}: {entry['sympy']}" + (f"   {cite}" if cite else ""))
    lines.append("Routh-Hurwitz conditions (4.7), all > 0:")
    for entry in data["hurwitz"]:
        name = re.sub(r"\\hat\{\\?([A-Za-z]+)\}", r"\1hat", entry["name"])  # \hat{p}_{1} -> phat_1
        name = name.replace("\\", "").replace("{", "").replace("}", "")
        lines.append(
            f"  {name} > 0 always: {entry['always']}" if entry.get("always") else f"  {name} = {entry['sympy']}"
        )
    hopf = data.get("hopf_frequency")
    if hopf:
        name, time = hopf.get("name", "omega"), hopf.get("time", "tau")
        lines.append(f"Hopf frequency {name} (stretched time {time}) = {hopf['sympy']}")
    return "\n".join(lines)


def conditions_latex(data: dict) -> str:
    r"""The conditions as a LaTeX fragment (amsmath ``align*``), one numbered line each.

    Examples
    --------
    >>> from contactsym import scene
    >>> from contactsym.report import conditions
    >>> print(conditions_latex(conditions(scene("brake"))).splitlines()[2])
    \text{stable for every law:} &\quad \mu \leq \left|{\cot{\left(\alpha \right)}}\right| \tag*{(4.4), (6.3)} \\
    """
    lines = [f"% contactsym conditions: {data['scene']}", r"\begin{align*}"]
    rows = []
    for name, entry in data["regions"].items():
        rows.append((name, entry))
    for name, entry in (data.get("equilibrium_counts") or {}).items():
        rows.append((f"equilibria, {name}", entry))
    for entry in data["hurwitz"]:
        rows.append((None, {**entry, "latex": f"{entry['name']} = {entry['latex']}"}))
    if data.get("hopf_frequency"):
        hopf = data["hopf_frequency"]
        rows.append((None, {**hopf, "latex": hopf.get("name_latex", r"\omega") + " = " + hopf["latex"]}))
    body = []
    for name, entry in rows:
        label = r"\text{" + name.replace("_", r"\_") + r":} " if name else ""
        tag = r" \tag*{" + ", ".join(entry["paper"]) + "}" if entry.get("paper") else ""
        body.append(f"{label}&\\quad {entry['latex']}{tag}")
    lines.append(" \\\\\n".join(body) + " \\\\")
    lines.append(r"\end{align*}")
    return "\n".join(lines)
