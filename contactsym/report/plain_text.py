r"""Plain text for the report's LaTeX: names, messages and notes escaped or typeset.

Examples
--------
>>> print(_plain_to_latex("Phi_j < 0 at 90 deg"))
$\Phi _{j} < 0$ at $90 ^{\circ}$
"""

from __future__ import annotations

import re

from .errata import text_to_latex

__all__: list[str] = []


def _note(note: str) -> str:
    return r"\noindent{\footnotesize " + _plain_to_latex(note) + r"}\par"


def _plain_to_latex(text: str) -> str:
    """Notes are ASCII plain text with names like Phi_j, Delta_3, mu: typeset them."""
    names = {"Phi": "Φ", "Psi": "Ψ", "Delta": "Δ", "alpha": "α", "phi": "φ", "mu": "μ", "eps": "ε", "deg": "°"}
    for word, symbol in names.items():
        text = re.sub(rf"\b{word}\b", symbol, text)
        text = re.sub(rf"\b{word}_", symbol + "_", text)
    text = text.replace(" °", "°")
    return text_to_latex(text)


_SPECIALS = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "^": r"\^{}",
    "_": r"\_",
    "%": r"\%",
    "~": r"\~{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
}


def _escape(text: str) -> str:
    """Plain text (a name, a message, a path) for LaTeX: specials escaped, other characters through text_to_latex.

    Examples
    --------
    >>> print(_escape("a_b & 50% of {x}, mu > 2, μ"))
    a\\_b \\& 50\\% of \\{x\\}, mu \\textgreater{} 2, $\\mu$
    """
    out = []
    for c in text:
        if c in _SPECIALS:
            out.append(_SPECIALS[c])
        elif ord(c) < 128:
            out.append(c)
        else:
            try:
                out.append(text_to_latex(c))
            except ValueError:
                out.append("?")
    return "".join(out)
