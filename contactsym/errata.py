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

import re
import unicodedata
from dataclasses import dataclass

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


# --- plain text with Unicode mathematics -> LaTeX ------------------------------------

_GREEK = {
    "α": r"\alpha",
    "β": r"\beta",
    "γ": r"\gamma",
    "δ": r"\delta",
    "ε": r"\varepsilon",
    "κ": r"\kappa",
    "λ": r"\lambda",
    "μ": r"\mu",
    "τ": r"\tau",
    "φ": r"\varphi",
    "χ": r"\chi",
    "ψ": r"\psi",
    "ω": r"\omega",
    "Δ": r"\Delta",
    "Φ": r"\Phi",
    "Ψ": r"\Psi",
}
_SYMBOLS = {
    "−": "-",
    "≤": r"\le",
    "≥": r"\ge",
    "≠": r"\ne",
    "→": r"\to",
    "∞": r"\infty",
    "°": r"^{\circ}",
    "²": "^{2}",
    "³": "^{3}",
    "₀": "_{0}",
    "₁": "_{1}",
    "₂": "_{2}",
    "₊": "_{+}",
    "₋": "_{-}",
    "±": r"\pm",
    "√": r"\surd",
    "<": "<",
    ">": ">",
    "=": "=",
    "+": "+",
    "|": "|",
    "/": "/",
}
_ACCENTS = {"\u0307": r"\dot", "\u0308": r"\ddot"}
_FUNCTIONS = ("sin", "cos", "cot", "tan", "det")
_TEXT_ESCAPES = {"#": r"\#", "&": r"\&", "%": r"\%", "$": r"\$", "{": r"\{", "}": r"\}", "~": r"\~{}", "^": r"\^{}"}
_TOKEN = re.compile(
    r"(?P<sub>_(?:\{[^}]*\}|[A-Za-z0-9+-]))"
    r"|(?P<function>\b(?:" + "|".join(_FUNCTIONS) + r")\b)"
    r"|(?P<word>[A-Za-z]{2,})"
    r"|(?P<var>(?:[A-Za-z]|[" + "".join(_GREEK) + r"])[\u0307\u0308]?[0-9]*)"
    r"|(?P<symbol>[" + re.escape("".join(_SYMBOLS)) + r"])"
    r"|(?P<neutral>\s+|[0-9]+(?:\.[0-9]+)?|[()\[\],;.])"
    r"|(?P<other>.)",
    re.DOTALL,
)
_OPEN, _CLOSE = "([", ")]"


def _var(text: str) -> str:
    base, rest = text[0], text[1:]
    accent = ""
    if rest[:1] in _ACCENTS:
        accent, rest = _ACCENTS[rest[0]], rest[1:]
    out = _GREEK.get(base, base)
    if accent:
        out = f"{accent}{{{out}}}"
    return out + (f"_{{{rest}}}" if rest else "")


def _decompose(text: str) -> str:
    """Letters with a dot or diaeresis (ẋ, ÿ) as letter + combining accent; other characters kept."""
    return "".join(unicodedata.normalize("NFD", c) if c.isalpha() else c for c in text)


def _tokens(text: str) -> list[tuple[str, str]]:
    """(kind, LaTeX) with kind 'm' (mathematics), 'n' (neutral: spaces, digits, brackets) or 't' (text)."""
    tokens: list[tuple[str, str]] = []
    quote_open = False
    for match in _TOKEN.finditer(_decompose(text)):
        kind, value = match.lastgroup, match.group()
        previous_math = bool(tokens) and tokens[-1][0] == "m"
        if kind == "sub":
            tokens.append(("m", "_{" + value[1:].strip("{}") + "}"))
        elif kind == "function":
            tokens.append(("m", "\\" + value))
        elif kind == "word":
            tokens.append(("t", value))
        elif kind == "var":
            tokens.append(("m", _var(value)))
        elif kind == "symbol":
            tokens.append(("m", _SYMBOLS[value]))
        elif kind == "neutral":
            tokens.append(("n", value))
        elif value == "*" and previous_math:
            tokens.append(("m", "^{*}"))
        elif value == "'" and previous_math:
            tokens.append(("m", "'"))
        elif value == '"':
            tokens.append(("t", "''" if quote_open else "``"))
            quote_open = not quote_open
        elif value == "—":
            tokens.append(("t", "---"))
        elif value in _TEXT_ESCAPES:
            tokens.append(("t", _TEXT_ESCAPES[value]))
        elif ord(value) < 128:
            tokens.append(("t", value))
        else:
            raise ValueError(f"no LaTeX for the character {value!r} ({unicodedata.name(value, 'unnamed')}) in {text!r}")
    return tokens


def _unmatched(run: list[tuple[str, str]]) -> int | None:
    """Index of the first bracket in ``run`` that has no partner, or None."""
    stack = []
    for i, (kind, value) in enumerate(run):
        if kind != "n":
            continue
        if value in _OPEN:
            stack.append(i)
        elif value in _CLOSE:
            if not stack:
                return i
            stack.pop()
    return stack[0] if stack else None


def _depth(run: list[tuple[str, str]]) -> int:
    """Brackets opened and not closed in ``run``."""
    values = [value for kind, value in run if kind == "n"]
    return sum(value in _OPEN for value in values) - sum(value in _CLOSE for value in values)


def _math(run: list[tuple[str, str]]) -> str:
    parts = []
    for i, (kind, value) in enumerate(run):
        if kind == "n" and value.isspace():
            if i and run[i - 1][1] in ",;":
                parts.append(r"\ ")
            continue
        parts.append(value)
    return "$" + " ".join(parts) + "$"


def _render(run: list[tuple[str, str]]) -> str:
    """A run of mathematics and neutral tokens: its brackets balanced, its ends trimmed."""
    if not any(kind == "m" for kind, _ in run):
        return "".join(value for _, value in run)
    cut = _unmatched(run)
    if cut is not None:
        return _render(run[:cut]) + run[cut][1] + _render(run[cut + 1 :])
    start = 0
    while run[start][0] == "n" and (run[start][1].isspace() or run[start][1] in ",;."):
        start += 1
    # after the last mathematics: keep numbers and brackets that close, up to a comma or semicolon
    end = max(i for i, (kind, _) in enumerate(run) if kind == "m") + 1
    depth = _depth(run[start:end])
    for i in range(end, len(run)):
        value = run[i][1]
        if value in _CLOSE and depth > 0:
            depth -= 1
        elif not (value.isspace() or value[0].isdigit()):
            break
        if not value.isspace():
            end = i + 1
    lead = "".join(value for _, value in run[:start])
    tail = "".join(value for _, value in run[end:])
    return lead + _math(run[start:end]) + tail


def text_to_latex(text: str) -> str:
    r"""Plain text with Unicode mathematics (μ₊, Ψ1², ≤, q̇_j) as LaTeX for pdflatex.

    Mathematics goes into ``$...$`` (Greek letters, indices, relations; a letter
    followed by digits gets them as a subscript), words stay text. A character with
    no LaTeX form raises ValueError.

    Examples
    --------
    >>> print(text_to_latex("v1 + v2 < 2κ², (1 + v1)(1 + v2) ≥ 0"))
    $v_{1} + v_{2} < 2 \kappa ^{2} , \  ( 1 + v_{1} ) ( 1 + v_{2} ) \ge 0$
    >>> print(text_to_latex("φ = 45°, or Y1 = Y2 = 0 (the classical case)"))
    $\varphi = 45 ^{\circ}$, or $Y_{1} = Y_{2} = 0$ (the classical case)
    """
    tokens = _tokens(text)
    out: list[str] = []
    run: list[tuple[str, str]] = []
    for kind, value in [*tokens, ("t", "")]:
        if kind == "t":
            out.append(_render(run) if run else "")
            out.append(value)
            run = []
        else:
            run.append((kind, value))
    return "".join(out)


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
