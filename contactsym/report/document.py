r"""The report's LaTeX document: :func:`report_tex` and its sections, from the equations of motion to the errata.

The sections follow the derivation chain of the paper: equations of motion (1.4), the
regularization (1.6)--(1.9), the fast subsystem (2.1), its equilibria (4.2), the
linearization (4.3)--(4.6), the Routh--Hurwitz conditions (4.7), the regions in closed
form, the reduced system (2.2), the figures and, for the paper's own scenes, its errata.
Sections 1-6 are in :mod:`~contactsym.report.derivation`.

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

from ..counts.one_sided import one_sided_cases
from ..errors import ContactsymError
from ..mechanism.equation_numbers import paper_equations
from ..mechanism.scene import Scene
from ..printing.latex_output import Formula, formulas, tex
from ..scenes import paper_name
from ..validate import checked_fields, cut, instance_of
from .derivation import _chain, _section
from .descriptions import describe
from .errata import AGREE, latex_table, text_to_latex
from .plain_text import _escape, own_letters
from .scene_parts import _count_tag, _special_cases
from .summary import ADVICE, _counts, no_equilibrium_note
from .typesetting import _display, _Named

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


def _parameters(scene) -> str:
    rows = []
    for symbol in scene.parameters:
        facts = [name for name in ("positive", "negative", "real") if getattr(symbol, f"is_{name}")]
        rows.append(f"${tex(symbol)}$" + (f" ({facts[0]})" if facts else ""))
    return "Parameters of the fast subsystem: " + ", ".join(rows) + "."


def _regions_section(scene, named: _Named) -> str:
    intro = "Each raw condition factored, factors of known sign dropped, written in the paper's variables."
    if scene.declared_positive:  # the factors dropped and the divisions made hold in the domain only
        domain = ", ".join(f"${tex(e)} > 0$" for e in scene.declared_positive)
        intro += f" The regions are stated in the scene's domain, where {domain}."
    if scene.k >= 3:  # the statements are proved on sufficient regions only: False is "proved nowhere"
        intro += (
            " With three or more contacts each statement is proved on a sufficient region: where it is not "
            "proved (the region undecided) it may still hold, and False means that it is proved at no point."
        )
    text = [_section("7. Regions in closed form", intro)]
    note = no_equilibrium_note(scene)
    if note:
        text.append(_escape(note))
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
    letters = own_letters(scene)  # a and b of f(N) = a + b N, apart from a scene's own a and b
    if any(case.assumed for case in cases):
        text.append(
            f"Where a sign does not follow from those of ${letters.tex('a')}$ and ${letters.tex('b')}$ (nor from the "
            "mechanics), the case is "
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
        lines.append(f"\\item ${tex(symbol)}$: " + describe(expr) + ".")
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
    named = _Named(letter=own_letters(scene).indexed("H"))
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
