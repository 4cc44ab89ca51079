"""Formula text at the boundary: the names a formula may use (:data:`FUNCTIONS`, :data:`CONSTANTS`),
the tokens of :mod:`contactsym.parse`'s grammar with positions and numbers for its messages, and
:func:`sympy_only`, the check that keeps text out of the Python API.

Examples
--------
>>> [(t.kind, t.text) for t in tokens("2*x^2", print)]
[('number', '2'), ('op', '*'), ('name', 'x'), ('op', '^'), ('number', '2'), ('end', '')]
>>> where("my.toml", 7, 12)
'my.toml:7:13'
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy as sp

from ..errors import ParseError
from .plain_values import cut

__all__ = ["CONSTANTS", "FUNCTIONS", "Token", "shown", "sympy_only", "tokens", "where"]

#: The functions a formula may call, by name, with their number of arguments.
FUNCTIONS = {
    "sin": (sp.sin, 1),
    "cos": (sp.cos, 1),
    "tan": (sp.tan, 1),
    "cot": (sp.cot, 1),
    "asin": (sp.asin, 1),
    "acos": (sp.acos, 1),
    "atan": (sp.atan, 1),
    "atan2": (sp.atan2, 2),
    "sinh": (sp.sinh, 1),
    "cosh": (sp.cosh, 1),
    "tanh": (sp.tanh, 1),
    "sqrt": (sp.sqrt, 1),
    "exp": (sp.exp, 1),
    "log": (sp.log, 1),
    "Abs": (sp.Abs, 1),
    "sign": (sp.sign, 1),
}

#: Constants every formula may use.
CONSTANTS = {"pi": sp.pi}


_TOKEN = re.compile(
    r"(?P<space>\s+)|(?P<number>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)|(?P<name>[A-Za-z][A-Za-z0-9_]*'*)"
    r"|(?P<op>\*\*|[-+*/^(),])"
)


@dataclass(frozen=True)
class Token:
    """One token of a formula, at its 0-based column."""

    kind: str  # 'number', 'name', 'op' or 'end'
    text: str
    column: int  # 0-based


def where(source: str, line: int, column: int) -> str:
    """``source:line:column`` of a message, the column counted from 1 (``column`` is 0-based)."""
    return f"{source}:{line}:{column + 1}"


def _digits(n: int) -> int:
    """Decimal digits of n, without printing it (Python refuses to print ints of over 4300 digits)."""
    n = abs(n)
    estimate = max(1, int(n.bit_length() * 0.30102999566398120))
    return estimate + (n >= 10**estimate)


def shown(expr: sp.Basic) -> str:
    """An expression for a message, cut short; a huge number by its number of digits."""
    if expr.is_Rational and max(abs(expr.p), expr.q).bit_length() > 300:
        return f"a number of {_digits(max(abs(expr.p), expr.q))} digits"
    return cut(str(expr))


def tokens(text: str, fail) -> list[Token]:
    """The tokens of ``text``, ending with an ``end`` token; ``fail(column, message)`` is called at a
    character outside the grammar (it raises)."""
    found, position = [], 0
    while position < len(text):
        match = _TOKEN.match(text, position)
        if match is None:
            bad = text[position]
            hint = (
                " (attributes, strings, brackets and other Python are not formulas)" if bad in ".[]{}'\"_:=<>" else ""
            )
            fail(position, f"unexpected character {bad!r}{hint}; expected a number, a name, an operator or '('")
        if match.lastgroup != "space":
            found.append(Token(match.lastgroup, match.group(), position))
        position = match.end()
    found.append(Token("end", "", len(text)))
    return found


def sympy_only(value, what: str):
    """``value`` as a SymPy object, if it is one or a number; text and other objects are refused.

    The Python API calls this on every expression it receives, so no string reaches
    ``sympify``. Text formulas go through :func:`contactsym.parse.parse_expression`, with declared names.

    Examples
    --------
    >>> sympy_only(0.5, "eps"), sympy_only(sp.Symbol("x") + 1, "a")
    (0.500000000000000, x + 1)
    >>> sympy_only("__import__('os').system('true')", "eps")
    Traceback (most recent call last):
    ...
    contactsym.errors.ParseError: eps is text ("__import__('os').system('true')"); contactsym never evaluates text: pass a SymPy expression or a number, or parse a formula with contactsym.parse_expression(text, names).
    """
    if isinstance(value, (str, bytes)):
        raise ParseError(
            f"{what} is text ({cut(repr(value))}); contactsym never evaluates text: pass a SymPy expression "
            "or a number, or parse a formula with contactsym.parse_expression(text, names)."
        )
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return value
    try:
        return sp.sympify(value, strict=True)
    except (sp.SympifyError, TypeError, ValueError) as error:
        raise ParseError(
            f"{what} = {cut(repr(value))} of type {type(value).__name__} is neither a SymPy object nor a number."
        ) from error
