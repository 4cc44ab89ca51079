r"""The report's LaTeX document: :func:`report_tex` and its sections, from the equations of motion to the errata.

The sections follow the derivation chain of the paper: equations of motion (1.4), the
regularization (1.6)--(1.9), the fast subsystem (2.1), its equilibria (4.2), the
linearization (4.3)--(4.6), the Routh--Hurwitz conditions (4.7), the regions in closed
form, the reduced system (2.2), the figures and, for the paper's own scenes, its errata.

The document uses only packages of Debian's texlive-latex-base (amsmath, amssymb,
graphicx, geometry, longtable, array).

Examples
--------
>>> import contactsym as cs
>>> tex = report_tex(cs.scene("sliding-point"))
>>> tex.startswith(r"\documentclass")
True
>>> r"\tag*{(3.1), (1.12)}" in tex
True
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import sympy as sp

from ..counts.one_sided import one_sided_cases
from ..errors import ContactsymError
from ..mechanism.scene import Scene, paper_equations
from ..printing.latex_output import Formula, formulas, tex
from ..scenes import paper_name
from ..stages.stability import generic_minors, hurwitz_names, robustness_formulas
from ..validate import checked_fields, cut, instance_of
from .errata import AGREE, latex_table, text_to_latex
from .scene_parts import _count_tag, _special_cases
from .summary import ADVICE, _counts, conditions
from .typesetting import WIDTH, _describe, _display, _escape, _Named, _tidy, width

__all__ = ["Figure", "report_tex"]


@dataclass(frozen=True)
class Figure:
    r"""A PNG for the report: its path and caption (LaTeX).

    Examples
    --------
    >>> from pathlib import Path
    >>> import contactsym as cs
    >>> figure = Figure(Path("figures/map.png"), r"The $(\alpha, \mu)$ plane")
    >>> tex = report_tex(cs.scene("sliding-point"), figures=[figure])
    >>> "map.png" in tex, r"The $(\alpha, \mu)$ plane" in tex
    (True, True)
    """

    path: Path
    caption: str

    def __post_init__(self):
        checked_fields(self)


# --- sections -----------------------------------------------------------------------


def _section(title: str, intro: str = "") -> str:
    return f"\\section*{{{title}}}\n" + (intro + "\n" if intro else "")


def _parameters(scene) -> str:
    rows = []
    for symbol in scene.parameters:
        facts = [name for name in ("positive", "negative", "real") if getattr(symbol, f"is_{name}")]
        rows.append(f"${tex(symbol)}$" + (f" ({facts[0]})" if facts else ""))
    return "Parameters of the fast subsystem: " + ", ".join(rows) + "."


def _chain(scene, named: _Named) -> list[str]:
    parts = []
    parts.append(
        _section(
            "1. Equations of motion",
            r"The accelerations (1.4), friction written out, as the scene states them.",
        )
    )
    parts += [_display(f, named) for f in formulas(scene)]

    reg = scene.regularized()
    parts.append(
        _section(
            r"2. Regularization (1.6)--(1.9)",
            r"New fast variables $u_j = N_j$, $v_j = \dot q_j/\varepsilon$ and the stretched time "
            r"$\tau = t/\varepsilon$ give $x' = \varepsilon X(x, y, \varepsilon)$, $y' = Y(x, y, \varepsilon)$ "
            r"with the slow variables $x = (" + ", ".join(tex(x) for x in reg.x) + r")$; "
            r"the slow part is below, and $Y(x, y, 0)$ is the fast subsystem of Section 3.",
        )
    )
    parts += [_display(f, named) for f in formulas(reg) if f.lhs.rstrip("'") in {tex(x) for x in reg.x}]

    fast = scene.fast_subsystem()
    laws = []
    for j in range(fast.k):
        for letter, value in (("Phi", fast.Phi[j]), ("Psi", fast.Psi[j])):
            symbol = sp.Symbol(f"{letter}{_index(fast, j)}")
            if not (isinstance(value, sp.Symbol) and value.name == symbol.name):
                laws.append(f"${tex(symbol)} = {tex(value)}$")
    law = (
        "here " + ", ".join(laws) if laws else r"here negative symbols: the results hold for every admissible law (1.5)"
    )
    parts.append(
        _section(
            "3. Fast subsystem (2.1)",
            r"The associated system in the stretched time, the slow state frozen on the contact manifold; "
            r"$\Phi_j = \lim \varepsilon^2 \partial N_j/\partial q_j$, "
            r"$\Psi_j = \lim \varepsilon \partial N_j/\partial \dot q_j$ (" + law + ").",
        )
    )
    parts += [_display(f, named) for f in formulas(fast)]

    parts.append(_equilibria_section(scene, named))
    parts.append(_linearization_section(scene, named))
    parts.append(_hurwitz_section(scene, named))
    return parts


def _index(fast, j: int) -> str:
    return "" if fast.k == 1 else f"_{j + 1}"


def _equilibria_section(scene, named: _Named) -> str:
    fast = scene.fast_subsystem()
    text = [_section("4. Equilibria (4.2)")]
    if fast.switching:
        sigmas = ", ".join(f"$\\sigma_{{{i}}} = {tex(s)}$" for i, s in enumerate(fast.switching, 1))
        text.append(
            r"$f$ is smooth on each sign pattern $s$ of the switching functions " + sigmas + r"; the root "
            r"$u^*$ of a piece is an equilibrium where $s_i\,\sigma_i(u^*) > 0$ for every $i$ "
            r"(the conditions in full are in \texttt{conditions.json})."
        )
    try:
        branches = scene.equilibria().branches
    except ContactsymError as error:
        return "\n".join(text) + "\n" + _escape(f"No closed-form equilibria: {error}")
    for branch in branches:
        if branch.signs:
            signs = ", ".join("+" if s == 1 else "-" for s in branch.signs)
            text.append(f"\\paragraph{{Sign pattern $s = ({signs})$.}}")
        rows = [f for f in formulas(branch) if f.key == "equilibrium"]
        for row in rows:
            numbers, note = paper_equations(scene, "equilibrium")
            text.append(_display(Formula(row.key, row.lhs, row.rhs, "=", numbers, ""), named))
    return "\n".join(text)


def _linearization_section(scene, named: _Named) -> str:
    lin = scene.linearization()
    k = lin.A.rows
    text = [
        _section(
            "5. Linearization (4.3)--(4.6)",
            r"At an equilibrium $(u^*, 0)$ the Jacobian of the fast subsystem is "
            r"$J = \begin{pmatrix} \Psi A & \Phi \\ A & 0 \end{pmatrix}$ (4.5) with "
            r"$\Phi = \operatorname{diag}(\Phi_j)$, $\Psi = \operatorname{diag}(\Psi_j)$, for every compliance law. "
            + (
                r"The signs $s_i = \pm 1$ stand for the sign pattern. "
                if any(s.name.startswith("s") for s in lin.A.free_symbols if s.is_integer)
                else ""
            )
            + ("Presented in the paper's variables." if scene.presentation else ""),
        )
    ]
    show = scene.present if scene.presentation else (lambda e: e)
    A = show(lin.A)
    numbers, note = paper_equations(scene, "A")
    if width(tex(A)) <= WIDTH:
        text.append(_display(Formula("A", "A", A, "=", numbers, note), named))
    else:
        for i in range(k):
            for j in range(k):
                entry = Formula("A", f"a_{{{i + 1}{j + 1}}}", A[i, j], "=", numbers, note)
                text.append(_display(entry, named))
    numbers, note = paper_equations(scene, "det A")
    text.append(_display(Formula("det A", r"\det A", sp.factor(show(lin.det_A)), "=", numbers, note), named))
    n = lin.charpoly.degree()
    p = " + ".join(
        f"p_{{{s}}} \\lambda^{{{s}}}" if s > 1 else ("p_{1} \\lambda" if s == 1 else "p_{0}") for s in range(n, -1, -1)
    )
    numbers, _ = paper_equations(scene, "charpoly")
    text.append(_display(Formula("charpoly", r"\det(\lambda I - J)", p, "=", numbers, ""), named))
    coefficients = lin.charpoly.all_coeffs()
    for s, c in zip(range(n, -1, -1), coefficients):
        numbers, _ = paper_equations(scene, "coefficient")
        text.append(_display(Formula("coefficient", f"p_{{{s}}}", _tidy(show(c)), "=", numbers, ""), named))
    return "\n".join(text)


def _hurwitz_section(scene, named: _Named) -> str:
    st = scene.stability()
    names = hurwitz_names(st)
    n = st.linearization.charpoly.degree()
    generic = generic_minors(n)
    always = {entry["name"]: entry["always"] for entry in conditions(scene)["hurwitz"] if "always" in entry}
    needed = [name for name in names if name not in always]
    intro = r"Li\'enard--Chipart form: all roots of (4.6) have negative real parts " + (
        f"exactly when ${', '.join(needed)} > 0$" if needed else "always"
    )
    intro += r" (coefficients that are positive numbers are left out"
    intro += "".join(f"; ${name} > 0$ always: {_escape(reason)}" for name, reason in always.items()) + ")."
    text = [_section("6. Routh--Hurwitz conditions (4.7)", intro)]
    show = scene.present if scene.presentation else (lambda e: e)
    numbers, _ = paper_equations(scene, "hurwitz")
    for name, condition in zip(names, st.hurwitz):
        if not name.startswith(r"\Delta"):
            continue
        m = int(name[len(r"\Delta_{") : -1])
        text.append(_display(Formula("hurwitz", name, generic[m], "=", numbers, ""), named))
        expanded = _tidy(show(condition))
        text.append(_display(Formula("hurwitz", name, expanded, "=", (), ""), named))
    if st.hopf_frequency is not None:
        text.append(
            r"On the Hopf set $\Delta_{" + str(n - 1) + r"} = 0$ the roots $\pm i\omega$ have "
            r"$\omega^2$ the common root of the real and imaginary parts of $p(i\omega)$:"
        )
        numbers, note = paper_equations(scene, "hopf frequency")
        omega2 = _tidy(show(st.routh_hurwitz.omega_squared))
        text.append(_display(Formula("hopf frequency", r"\omega^{2}", omega2, "=", numbers, note), named))
    text += [_display(formula, named) for formula in robustness_formulas(st.robustness)]
    return "\n".join(text)


def _regions_section(scene, named: _Named) -> str:
    text = [
        _section(
            "7. Regions in closed form",
            "Each raw condition factored, factors of known sign dropped, written in the paper's variables.",
        )
    ]
    for name, region in scene.regions().items():
        numbers, note = paper_equations(scene, name)
        text.append(f"\\paragraph{{{_escape(name.capitalize())}.}}")
        text.append(_display(Formula(name, "", region.condition, "", numbers, note), named))
    text += _special_cases(scene, named)
    counts, note = _counts(scene)
    if counts:
        text.append(r"\subsection*{Number of equilibria}")
        for name, region in counts.items():
            reason = _escape(region.description.split(": ", 1)[-1])  # the description starts with the scene's name
            text.append(f"\\paragraph{{{_escape(name.capitalize())}.}} {reason}")
            text.append(_display(Formula(name, "", region.condition, "", _count_tag(scene, name), ""), named))
    elif note:
        text.append(r"\paragraph{Number of equilibria.} " + _escape(note))
    text += _one_sided_section(scene, named)
    return "\n".join(text)


def _one_sided_section(scene, named: _Named) -> list[str]:
    """The one-sided Painleve cases of a unilateral contact (k = 1), with lift-off."""
    if scene.k != 1 or not scene.contacts[0].unilateral:
        return []
    text = [r"\subsection*{One-sided contact: consistent, inconsistent, indeterminate}"]
    try:
        cases = one_sided_cases(scene)
    except Exception as error:  # a section that cannot be derived must not cost the rest of the report
        return text + [_not_derived(scene, "the one-sided cases", error)]
    words = {True: "stable", False: "unstable", None: "stability not decided"}
    if any(case.assumed for case in cases):
        text.append(
            "Where a sign does not follow from those of $a$ and $b$ (nor from the mechanics), the case is "
            "split in two, as in the paper: the undecided expression positive, then negative."
        )
    for case in cases:
        found = ", ".join(f"{kind} ({words[stable]})" for kind, stable in case.equilibria)
        text.append(f"\\paragraph{{{_escape(case.name.capitalize())}.}} " + _escape(found or "no equilibrium"))
        for expr, sign in case.assumed:
            text.append("The sign of this expression was not decided; this case takes it " + _sign_word(sign) + ":")
            text.append(_display(Formula(case.name, "0", expr, "<" if sign > 0 else ">", (), ""), named))
        text.append(_display(Formula(case.name, "", case.region.condition, "", (), ""), named))
    return text


def _not_derived(scene, stage: str, error: Exception) -> str:
    """A paragraph in place of a section that could not be derived: the stage, the scene, the reason cut short."""
    reason = cut(str(error) or type(error).__name__, 300)
    return _escape(f"Not derived: {stage} of scene '{scene.name}' ({type(error).__name__}: {reason}). {ADVICE}")


def _sign_word(sign: int) -> str:
    return "positive" if sign > 0 else "negative"


def _figures_section(figures: list[Figure], notes: list[str]) -> str:
    text = [_section("9. Figures")]
    for figure in figures:
        text.append(
            "\\begin{figure}[htbp]\n\\centering\n"
            f"\\includegraphics[width=0.85\\textwidth]{{figures/{figure.path.name}}}\n"
            f"\\caption{{{figure.caption}}}\n\\end{{figure}}"
        )
    if not figures:
        text.append("No figures for this scene.")
    for note in notes:
        text.append(r"\noindent " + _escape(note) + r"\par")
    return "\n".join(text)


def _named_section(named: _Named) -> str:
    if not named.items:
        return ""
    lines = [r"\paragraph{Long expressions.} Too long to print here; in full in \texttt{conditions.json}:"]
    lines.append(r"\begin{itemize}")
    for symbol, expr in named.items:
        lines.append(f"\\item ${tex(symbol)}$: " + _describe(expr) + ".")
    lines.append(r"\end{itemize}")
    return "\n".join(lines)


def _errata_section() -> str:
    agree = ", ".join(AGREE)
    return "\n".join(
        [
            _section("Errata of the paper"),
            r"Found by deriving each formula from the mechanics and comparing with the print; the evidence "
            r"for each entry is a test in \texttt{tests/paper/} (see \texttt{docs/errata.md}). "
            r"Derived and in agreement with the print: " + text_to_latex(agree) + ".",
            r"{\small",
            latex_table(),
            "}",
        ]
    )


_PREAMBLE = r"""\documentclass[10pt,a4paper]{article}
\usepackage[margin=2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage{longtable,array}
\allowdisplaybreaks
\setlength{\parindent}{0pt}
\setlength{\parskip}{4pt}
"""


def report_tex(scene, figures: list[Figure] | tuple = (), notes: list[str] | tuple = ()) -> str:
    r"""The standalone LaTeX document of one scene.

    ``figures`` are PNGs in ``figures/`` beside the document; ``notes`` are plain-text
    remarks printed under the figures (e.g. a figure that could not be drawn).

    Examples
    --------
    >>> import contactsym as cs
    >>> tex = report_tex(cs.scene("sliding-point"), notes=["The phase portrait needs values for b."])
    >>> tex.startswith(r"\documentclass"), tex.rstrip().endswith(r"\end{document}")
    (True, True)
    >>> "The phase portrait needs values for b." in tex
    True
    """
    instance_of(scene, Scene, "scene", "pass a Scene, e.g. contactsym.scene('brake')")
    listed = isinstance(figures, (list, tuple)) and isinstance(notes, (list, tuple))
    if not listed or not all(isinstance(f, Figure) for f in figures) or not all(isinstance(n, str) for n in notes):
        raise ContactsymError("report_tex: figures must be a list of report.Figure, and notes a list of text.")
    named = _Named()
    paper = paper_name(scene) is not None  # the paper's own scene object, not one that shares its name
    title = _escape(f"contactsym: {scene.name}")
    description = _escape(scene.description) if scene.description else ""
    body = [
        _PREAMBLE,
        r"\begin{document}",
        f"\\section*{{{title}}}",
        description + r"\par" if description else "",
        r"Derived by contactsym from the mechanics. Numbers on the right, as (4.3), are the equations "
        r"of A.\,P.~Ivanov, \emph{On the properties of solutions of the basic problem of dynamics in "
        r"systems with non-ideal constraints}, PMM, 2005"
        + (
            r"; where the print differs, the derived form is shown and the errata table at the end says why."
            if paper
            else r", whose general results this scene's formulas instantiate."
        ),
        _parameters(scene),
        r"{\small",
    ]
    body += _chain(scene, named)
    body.append(_regions_section(scene, named))
    body.append(_named_section(named))
    body.append(_reduced_section(scene, named))
    body.append("}")
    body.append(_figures_section(list(figures), list(notes)))
    if paper:
        body.append(_errata_section())
    body.append(r"\end{document}")
    return "\n\n".join(part for part in body if part) + "\n"


def _reduced_section(scene, named: _Named) -> str:
    text = [
        _section(
            "8. Reduced system (2.2)",
            "The slow motion with the reactions of an equilibrium branch: the classical rigid-contact model.",
        )
    ]
    try:
        branches = scene.equilibria().branches
    except Exception as error:  # the reduced system is an extra: its failure must not cost the report
        return "\n".join(text + [_not_derived(scene, "the reduced system", error)])
    if len(branches) != 1:
        text.append(
            _escape(
                f"The scene has {len(branches)} equilibrium branches; "
                "each has its own reduced system (Scene.reduced_system(signs=...))."
            )
        )
        return "\n".join(text)
    try:
        rows = [f for f in formulas(scene.reduced_system()) if f.key == "reduced"]
    except Exception as error:  # as above
        return "\n".join(text + [_not_derived(scene, "the reduced system", error)])
    text += [_display(f, named) for f in rows]
    return "\n".join(text)
