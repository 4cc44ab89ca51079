"""The two reductions every stage relies on, and signs from assumptions (no ``simplify``).

- ``SignSymbol`` and ``reduce_signs``: s**2 = 1 for the sign symbols of open sign patterns;
- ``reduce_trig``: cos(x)**2 = 1 - sin(x)**2, a polynomial reduction;
- ``known_sign``: +1 or -1 when assumptions and declared positive expressions decide it.

A leaf module: :mod:`contactsym.algebra.canonical_form` builds its normal form on these rules, and
:mod:`contactsym.algebra.basic` gathers both for the stages.
"""

from __future__ import annotations

import sympy as sp

from ..errors import SignPatternError
from ..parse import sympy_only

__all__ = ["SignSymbol", "sign_symbols", "reduce_signs", "reduce_trig", "known_sign"]


class SignSymbol(sp.Symbol):
    """A symbol for sign(sigma) on an open sign pattern: its value is +1 or -1."""

    def __new__(cls, name, **assumptions):
        if not isinstance(name, str) or not name.strip():
            raise SignPatternError(f"a SignSymbol's name must be text such as 's', not {type(name).__name__}.")
        return super().__new__(cls, name, integer=True, nonzero=True)


def sign_symbols(count: int) -> tuple[SignSymbol, ...]:
    """s (one switching function) or s_1, ..., s_count."""
    if count == 1:
        return (SignSymbol("s"),)
    return tuple(SignSymbol(f"s_{i}") for i in range(1, count + 1))


def reduce_signs(expr: sp.Expr) -> sp.Expr:
    """Use s**2 = 1 for every SignSymbol s.

    Examples
    --------
    >>> s = SignSymbol("s")
    >>> reduce_signs(s**2 + 3*s**3 - s**4)
    3*s
    """
    return sympy_only(expr, "the expression").replace(  # never sympify text: it would be evaluated
        lambda e: e.is_Pow and isinstance(e.base, SignSymbol) and e.exp.is_Integer,
        lambda e: e.base ** (e.exp % 2),
    )


def reduce_trig(expr: sp.Expr) -> sp.Expr:
    """Replace cos(x)**n, n >= 2, by cos(x)**(n % 2) (1 - sin(x)**2)**(n // 2), expanded.

    Examples
    --------
    >>> a, m = sp.symbols("alpha m", positive=True)
    >>> reduce_trig(sp.sin(a)**2/m + sp.cos(a)**2/m)
    1/m
    """

    def is_cos_power(e):
        return e.is_Pow and isinstance(e.base, sp.cos) and e.exp.is_Integer and e.exp >= 2

    def rewrite(e):
        n = int(e.exp)
        return e.base ** (n % 2) * (1 - sp.sin(e.base.args[0]) ** 2) ** (n // 2)

    return sp.expand(sympy_only(expr, "the expression").replace(is_cos_power, rewrite))


def known_sign(expr: sp.Expr, positive=()) -> int | None:
    """+1 or -1 when the sign of ``expr`` follows from assumptions, else None.

    ``positive`` lists expressions known to be positive in the scene's domain
    (e.g. ``sin(phi)`` for 0 < phi < pi/2).

    Examples
    --------
    >>> m = sp.Symbol("m", positive=True)
    >>> Phi = sp.Symbol("Phi", negative=True)
    >>> known_sign(-3*m*Phi), known_sign(Phi - m), known_sign(sp.Symbol("x"))
    (1, -1, None)
    >>> a = sp.Symbol("alpha", positive=True)
    >>> known_sign(sp.sin(a)**2 + 1), known_sign(sp.sin(a)), known_sign(sp.sin(a), [sp.sin(a)])
    (1, None, 1)
    """
    stand_ins = {p: sp.Dummy(positive=True) for p in positive}
    expr = sympy_only(expr, "the expression").subs(stand_ins)
    if expr.is_positive:
        return 1
    if expr.is_negative:
        return -1
    return None
