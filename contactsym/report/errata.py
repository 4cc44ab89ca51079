"""The paper's errata as data: the table of ``docs/errata.md``, for the report and the docs.

``docs/errata.md`` is the human document (with the evidence for each entry); this
module holds its table as structured data, so that an installed contactsym can print
it (``markdown_table``) and typeset it (``latex_table``). A test checks that the two
agree.

Examples
--------
>>> ERRATA[12].formula, ERRATA[12].derived
('(6.4)', '−m μ² Φ < Ψ²(1 + μ²)')
>>> print(text_to_latex("μ ≤ |cot α|"))
$\\mu \\le | \\cot \\alpha |$
"""

from __future__ import annotations

from dataclasses import dataclass

from ..printing.unicode_math import text_to_latex

__all__ = ["AGREE", "ERRATA", "Erratum", "latex_table", "markdown_table", "text_to_latex"]


@dataclass(frozen=True)
class Erratum:
    """One row of the errata table: a printed formula against the derived one.

    Cells are plain text with Unicode mathematics, exactly as in ``docs/errata.md``.
    """

    number: int
    formula: str
    printed: str
    derived: str
    kind: str
    holds_when: str


#: Columns of the table, as ``docs/errata.md`` heads them.
HEADER = ("#", "Formula", "Printed", "Derived", "Kind", "Print holds when")

ERRATA: tuple[Erratum, ...] = (
    Erratum(
        1,
        "(3.6)",
        "Y*_{1,2} = Y_{1,2} / cos φ",
        "Y*_{1,2} = Y_{1,2} / sin φ",
        "misprint",
        "φ = 45°, or Y1 = Y2 = 0 (the classical case)",
    ),
    Erratum(
        2,
        "slopes after (3.7), case Y1* + Y2* = 0",
        "2 − μ₊ and 2 + μ₋",
        "2 − μ₋ and 2 + μ₋",
        "misprint",
        "μ₂ = 0",
    ),
    Erratum(
        3,
        "(3.4), Prop. 5",
        "V' = −Ψ f², \"V' < 0\"",
        "V' = −Ψ f² ≥ 0 (V increases)",
        "sign slip; the proposition stands",
        "never; the argument only needs V monotone",
    ),
    Erratum(
        4,
        "(4.8)",
        "χ1² det A < −χ0χ1χ3 det A + χ3(a11Ψ1²Φ2 + a22Φ1Ψ2²)",
        "χ1² det A < −χ1χ2χ4 det A + χ4(a11Φ1²Ψ2 + a22Ψ1Φ2²)",
        "substantive slip: Φ and Ψ interchanged",
        "Φ_j = Ψ_j",
    ),
    Erratum(
        5,
        "(4.9)",
        "χ1² a11a22 < χ3(a11Ψ1²Φ2 + a22Φ1Ψ2²)",
        "χ1² a11a22 < χ4(a11Φ1²Ψ2 + a22Ψ1Φ2²)",
        "follows from 4",
        "Φ_j = Ψ_j",
    ),
    Erratum(
        6,
        "(4.10)",
        "2a11a22Ψ1Ψ2 < a11²Ψ1² + a22²Ψ2²",
        "2a11a22Φ1Φ2 ≤ a11²Φ1² + a22²Φ2² (the slack of (4.9) is Ψ1Ψ2(a11Φ1 − a22Φ2)²)",
        "follows from 4; Prop. 6 stands",
        "Φ_j = Ψ_j",
    ),
    Erratum(
        7,
        "Remark 1, equality case",
        "a11Ψ1 = a22Φ2",
        "a11Φ1 = a22Φ2, with Ψ small (or Φ large)",
        "follows from 4",
        "—",
    ),
    Erratum(
        8,
        "Prop. 6 proof",
        '"since a12a21 > 0, det A < a11a22"',
        "a12a21 ≥ 0 gives det A ≤ a11a22",
        "misprint",
        "a12a21 ≠ 0",
    ),
    Erratum(
        9,
        "Prop. 6, instability",
        "a11 < 0 and a22 < 0",
        "also a11, a22 ≤ 0 (not both 0) with det A > 0: p3 ≤ 0",
        "the boundary is unstable too",
        "—",
    ),
    Erratum(
        10,
        "(5.1)",
        "ẋ, ẏ for the accelerations; k²φ̈ = h(μ1|N1| − μ2|N2|) − b(N1 + N2)",
        "ẍ, ÿ; k²φ̈ = h(μ1|N1| − μ2|N2|) − b(N1 + N2) + M",
        "misprint (M is used in (5.2))",
        "M = 0",
    ),
    Erratum(
        11,
        "(5.6)",
        "v1 + v2 < 2κ², v_{1,2} < 1 + 2κ² (1 + v1)(1 + v2) > 0",
        "v1 + v2 < 2κ², v_{1,2} < 1 + 2κ², (1 + v1)(1 + v2) ≥ 0",
        "misprint (comma) and strictness",
        "away from the rays v1 = −1, v2 = −1",
    ),
    Erratum(
        12,
        "(6.3)",
        "μ < |cot α|",
        "μ ≤ |cot α| (a12a21 ≥ 0 in (4.4))",
        "strictness; the print is sufficient",
        "μ ≠ |cot α|",
    ),
    Erratum(
        13,
        "(6.4)",
        "−μ²Φ < Ψ²(1 + μ²)",
        "−m μ² Φ < Ψ²(1 + μ²)",
        "the mass was set to 1",
        "m = 1",
    ),
    Erratum(
        14,
        "ω after (6.4)",
        "ω = −(μ² + 1)Ψ/μ",
        "ω = −(μ² + 1)Ψ/(μ m), in the stretched time τ (ω/ε in t)",
        "the mass was set to 1",
        "m = 1",
    ),
    Erratum(
        15,
        "text after (1.8)",
        "right-hand sides bounded as ε → ∞",
        "as ε → 0",
        "misprint",
        "—",
    ),
    Erratum(
        16,
        "text after (1.12)",
        '"eigenvalues negative"; "substitute u = −|Y|"',
        "real parts negative (complex for b < 1); u* = −Y",
        "wording, sign",
        "b ≥ 1; Y ≤ 0",
    ),
    Erratum(
        17,
        "(1.9), (4.1), (4.2), (4.5)",
        "x = (t, q_j, q̇_j); f_j(u_j, u_2); f_j = 0, f_2 = 0; right side without (u, v)",
        "x = (t, q_i, q̇_i); f_j(u_1, u_2); f_1 = 0, f_2 = 0; [[ΨA, Φ],[A, 0]](u, v)",
        "index misprints",
        "—",
    ),
)

#: Formulas that were derived and agree with the print.
AGREE: tuple[str, ...] = (
    "(1.12)",
    "(3.5)",
    "the slopes of (3.6) in the cases Y1* + Y2* < 0 and > 0",
    "(3.8)",
    "(3.9)",
    "(4.6)",
    "(4.7)",
    "(5.2)",
    "(5.3)",
    "(5.4)",
    "(5.5)",
    "(5.7)",
    "(5.8)",
    "(5.9)",
    "(5.10)",
    "(6.1)",
    "(6.2)",
)


def markdown_table() -> str:
    """The errata table as ``docs/errata.md`` writes it.

    Examples
    --------
    >>> print(markdown_table().splitlines()[2])
    | 1 | (3.6) | Y*_{1,2} = Y_{1,2} / cos φ | Y*_{1,2} = Y_{1,2} / sin φ | misprint | φ = 45°, or Y1 = Y2 = 0 (the classical case) |
    """
    lines = ["| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    for e in ERRATA:
        cells = [str(e.number), e.formula, e.printed, e.derived, e.kind, e.holds_when]
        lines.append("| " + " | ".join(c.replace("|", r"\|") for c in cells) + " |")
    return "\n".join(lines)


def latex_table() -> str:
    r"""The errata table as a ``longtable`` (packages: longtable, array; both in texlive-latex-base).

    Examples
    --------
    >>> table = latex_table()
    >>> table.startswith(r"\begin{longtable}"), table.count(r"\\[2pt]") == len(ERRATA)
    (True, True)
    """
    widths = (0.12, 0.245, 0.255, 0.12, 0.10)
    columns = "".join(
        r">{\raggedright" + (r"\arraybackslash" if i == len(widths) - 1 else "") + f"}}p{{{w}\\textwidth}}"
        for i, w in enumerate(widths)
    )
    head = " & ".join(r"\textbf{" + text_to_latex(h) + "}" for h in HEADER) + r" \\ \hline"
    lines = [
        r"\begin{longtable}{@{}r" + columns + "@{}}",
        r"\hline",
        head,
        r"\endhead",
        r"\hline",
        r"\endfoot",
    ]
    for e in ERRATA:
        cells = [str(e.number), e.formula, e.printed, e.derived, e.kind, e.holds_when]
        lines.append(" & ".join(text_to_latex(c) for c in cells) + r" \\[2pt]")
    lines.append(r"\end{longtable}")
    return "\n".join(lines)
