r"""Plain text for the report's LaTeX: names, messages and notes escaped or typeset.

Examples
--------
>>> print(_plain_to_latex("Phi_j < 0 at 90 deg"))
$\Phi _{j} < 0$ at $90 ^{\circ}$
"""

from __future__ import annotations

import re

import sympy as sp
from sympy.core.function import AppliedUndef

from ..algebra.reductions import PaperSymbol, SignSymbol
from ..printing.glyphs import OwnLetters, look_alike
from .errata import text_to_latex

__all__: list[str] = []


def own_letters(scene, reactions: bool = True) -> OwnLetters:
    r"""The report's own letters (t, x, J, I, ...) spelled apart from every name the scene prints:
    its symbols (``symbol_names``), its functions (the sliding point's force ``Y(x, xdot)``) and the
    parameters of its fast subsystem. ``reactions=False`` leaves the reactions out: for the letter N_j that
    names them (the sliding point's reaction N is no clash with it).

    Examples
    --------
    >>> import contactsym as cs
    >>> letters = own_letters(cs.scene("brake"))  # the brake's J is its inertia, x its coordinate
    >>> letters.tex("J"), letters.tex("x"), letters.tex("t"), letters.tex("I")
    ('\\hat{J}', '\\hat{x}', 't', 'I')
    """
    own = (PaperSymbol, SignSymbol)  # the theory's symbols (Phi_j, s_i) among the parameters are the package's
    names = set(scene.symbol_names) | {str(p) for p in scene.fast_subsystem().parameters if not isinstance(p, own)}
    exprs = list(scene.accelerations.values()) + list(scene.gaps)
    functions = {type(f).__name__ for e in exprs for f in sp.sympify(e).atoms(AppliedUndef)}
    names |= functions - {type(q).__name__ for q in scene.coordinates}  # q(t): in symbol_names as q, qdot
    names -= set() if reactions else {str(r) for r in scene.reactions}
    return OwnLetters(names | {look_alike(n) for n in names})


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
