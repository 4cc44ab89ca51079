r"""Plain text with Unicode mathematics (μ₊, Ψ1², ≤, q̇_j) as LaTeX for pdflatex.

The errata table (:mod:`contactsym.report.errata`) and the report's notes are written in plain
text, as ``docs/errata.md`` shows them; :func:`text_to_latex` typesets them: mathematics
in ``$...$``, words as text.

Examples
--------
>>> print(text_to_latex("μ ≤ |cot α|"))
$\mu \le | \cot \alpha |$
"""

from __future__ import annotations

import re
import unicodedata

from ..arguments import checked

__all__ = ["text_to_latex"]

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


@checked
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
