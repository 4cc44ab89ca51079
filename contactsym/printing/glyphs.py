r"""Glyphs: what a symbol's name looks like in print, and the package's own letters kept apart from a scene's.

Two different symbols must never print alike. SymPy prints the names ``lambda``, ``lambda_`` and
``lamda`` all as ``\lambda``, ``Phi1`` and ``Phi_1`` both as ``\Phi_{1}``, and the paper's printer
``epsilon`` and ``varepsilon`` both as ``\varepsilon``: :func:`look_alike` maps a name to one
spelling per glyph, so that "is this name taken?" asks about the glyph, not the spelling.

The package prints letters of its own: the theory's symbols (u, v, Phi, Psi, epsilon, tau, lambda,
which the stages rename themselves) and the letters of the report's and the command line's fixed
text (the time t, the slow state x and its parts X, Y, the Jacobian J, the identity I, A, the
names H_j of long expressions, ...). :class:`OwnLetters` spells each of them apart from the names
a scene uses, with the accent the stages use (``\hat{t}``, text ``that``), so that a report never
shows one glyph for two things.

Examples
--------
>>> look_alike("lambda_"), look_alike("Phi1"), look_alike("varepsilon")
('lambda', 'Phi_1', 'epsilon')
>>> letters = OwnLetters({"t", "lambda_", "x"})
>>> letters.tex("t"), letters.text("t"), letters.tex("lambda"), letters.tex("tau")
('\\hat{t}', 'that', '\\hat{\\lambda}', '\\tau')
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.printing.conventions import split_super_sub

from ..arguments import checked
from .latex_output import tex

__all__ = ["ACCENTS", "OwnLetters", "look_alike", "spelled_apart"]

#: The accents a package letter takes, in order, where its plain glyph is a scene's (as the stages' uhat).
ACCENTS = ("hat", "check", "tilde", "breve")

#: Greek names SymPy prints alike (``lamda`` is SymPy's own alias) and the paper's printer's variants.
_SAME_LETTER = {"lamda": "lambda", "Lamda": "Lambda", "varepsilon": "epsilon", "varphi": "phi"}


@checked
@lru_cache(maxsize=4096)
def look_alike(name: str) -> str:
    r"""One spelling per printed glyph: the name with empty sub- and superscripts dropped, digits after
    a letter written as a subscript, and SymPy's alternative Greek spellings unified.

    Parameters
    ----------
    name : str
        A symbol's name.

    Returns
    -------
    str
        A name that prints as ``name`` does; two names print alike when their ``look_alike`` agree.

    Examples
    --------
    >>> [look_alike(n) for n in ("u", "u1", "u_1", "lambda_", "lamda", "x__2", "tauhat")]
    ['u', 'u_1', 'u_1', 'lambda', 'lambda', 'x__2', 'tauhat']
    """
    base, supers, subs = split_super_sub(name)
    if not base:  # a name SymPy does not split (e.g. "_1"): printed as written
        return name
    base = _SAME_LETTER.get(base, base)
    supers, subs = [s for s in supers if s], [s for s in subs if s]
    return base + "".join(f"__{s}" for s in supers) + ("_" + "_".join(subs) if subs else "")


@checked(taken="Collection[str]", bases="Collection[str]")
def spelled_apart(letter: str, taken, bases=()) -> str:
    r"""``letter`` as the package prints it beside the names ``taken``: itself where its glyph is free,
    else with the first accent (hat, check, tilde, breve) whose glyph is free.

    Parameters
    ----------
    letter : str
        The package's letter, e.g. ``"t"`` or ``"Phi_1"`` (an index after the underscore keeps its place).
    taken : collection of str
        Names in :func:`look_alike` spelling (a scene's ``symbol_names``).
    bases : collection of str
        Letters taken with an index (``q`` where the scene has ``q_1``): for a letter printed with a
        generic index (``q_j``), which must then not be one of them either.

    Returns
    -------
    str
        A name whose glyph no name of ``taken`` has.

    Examples
    --------
    >>> spelled_apart("t", {"x"}), spelled_apart("t", {"t"}), spelled_apart("Phi_1", {"Phi_1", "Phihat_1"})
    ('t', 'that', 'Phicheck_1')
    >>> spelled_apart("q", {"q_1"}), spelled_apart("q", {"q_1"}, bases={"q"})
    ('q', 'qhat')
    """

    def free(name: str) -> bool:
        return look_alike(name) not in taken and look_alike(name) not in bases

    if free(letter):
        return letter
    base, underscore, index = letter.partition("_")
    for accent in ACCENTS:
        candidate = base + accent + underscore + index
        if free(candidate):
            return candidate
    return spelled_apart(base + base[-1] + underscore + index, taken, bases)


class OwnLetters:
    r"""The package's own letters of its fixed text, each spelled apart from a scene's names.

    Parameters
    ----------
    names : collection of str
        The names the scene's symbols print with (``Scene.symbol_names``; any spelling: each is read
        by :func:`look_alike`).

    Examples
    --------
    >>> letters = OwnLetters({"J", "I", "Y"})
    >>> letters.tex("J"), letters.tex("I"), letters.text("Y"), letters.tex("A")
    ('\\hat{J}', '\\hat{I}', 'Yhat', 'A')
    """

    @checked(names="Collection")
    def __init__(self, names=()):
        self.taken = frozenset(look_alike(str(n)) for n in names)
        #: the letters the scene uses with an index (q for q_1): a generic q_j would read as one of them
        self.bases = frozenset(look_alike(n).partition("_")[0] for n in self.taken if "_" in look_alike(n).lstrip("_"))

    def text(self, letter: str) -> str:
        """The letter as plain text (``t``, or ``that`` where ``t`` is a scene's)."""
        return spelled_apart(letter, self.taken)

    def symbol(self, letter: str) -> sp.Symbol:
        """The letter as a plain SymPy symbol, to print in a formula."""
        return sp.Symbol(self.text(letter))

    def tex(self, letter: str) -> str:
        r"""The letter as LaTeX (``t``, or ``\hat{t}`` where ``t`` is a scene's)."""
        return tex(self.symbol(letter))

    def index(self, letter: str, index: str) -> str:
        r"""LaTeX of the letter with a generic index (``q_j``; ``\hat{q}_j`` where the scene has ``q`` or ``q_1``).

        Examples
        --------
        >>> OwnLetters({"q_1"}).index("q", "j"), OwnLetters({"q_1"}).tex("q")
        ('\\hat{q}_j', 'q')
        """
        return tex(sp.Symbol(self.indexed(letter))) + "_" + index

    def indexed(self, letter: str) -> str:
        """The letter's name for a family ``letter_1, letter_2, ...`` (``H`` -> ``Hhat`` where the scene has ``H_1``)."""
        return spelled_apart(letter, self.taken, self.bases)
