"""Signs of closed numeric expressions by interval arithmetic with growing precision.

SymPy's ``evalf(strict=True)`` gives up when an expression cancels to many digits
(e.g. the Hurwitz conditions of the guides at phi a few ulps from pi/2). An interval
enclosure does not: each operation of ``mpmath.iv`` rounds outwards, so the exact
value lies inside the interval computed, and once the interval excludes 0 the sign is
proven. The precision doubles until that happens; only an expression that is exactly
0 (or closer to 0 than ``2**-max_bits`` relative) gets no answer here.

Examples
--------
>>> import sympy as sp
>>> interval_sign(sp.sin(sp.Rational(7074237288154227, 2**52)) - 1)  # phi a hair below pi/2
-1
>>> interval_sign(sp.sqrt(2)**2 - 2) is None  # exactly 0: no interval can show a sign
True
"""

from __future__ import annotations

import sympy as sp
from mpmath import iv

from ..arguments import between, checked

__all__ = ["interval_sign"]

_FUNCTIONS = {sp.sin: iv.sin, sp.cos: iv.cos, sp.tan: iv.tan, sp.exp: iv.exp, sp.log: iv.log}


class _Unsupported(Exception):
    pass


def _abs(x):
    lo, hi = x.a, x.b
    if lo >= 0:
        return x
    if hi <= 0:
        return -x
    return iv.mpf([0, max(-lo, hi)])


def _power(base, exponent: sp.Expr):
    if exponent.is_Integer:
        return base ** int(exponent)
    if exponent == sp.S.Half and base.a >= 0:
        return iv.sqrt(base)
    if exponent.is_Rational and base.a > 0:
        return iv.exp(iv.log(base) * _enclose(exponent))
    raise _Unsupported


def _enclose(expr: sp.Expr):
    """An interval that contains the exact value of ``expr`` at the current ``iv.prec``."""
    if expr.is_Integer:
        return iv.mpf(int(expr))
    if expr.is_Rational:
        return iv.mpf(int(expr.p)) / iv.mpf(int(expr.q))
    if expr is sp.pi:
        return iv.pi
    if expr is sp.E:
        return iv.e
    if expr.is_Add:
        total = iv.mpf(0)
        for term in expr.args:
            total += _enclose(term)
        return total
    if expr.is_Mul:
        product = iv.mpf(1)
        for factor in expr.args:
            product *= _enclose(factor)
        return product
    if expr.is_Pow:
        return _power(_enclose(expr.base), expr.exp)
    if isinstance(expr, sp.Abs):
        return _abs(_enclose(expr.args[0]))
    if expr.func in _FUNCTIONS and len(expr.args) == 1:
        argument = _enclose(expr.args[0])
        if expr.func is sp.log and not argument.a > 0:
            raise _Unsupported
        return _FUNCTIONS[expr.func](argument)
    raise _Unsupported  # floats, symbols and other functions: leave them to the caller


@checked(max_bits=between(1, 2**20))
def interval_sign(expr: sp.Expr, *, max_bits: int = 4096) -> int | None:
    """+1 or -1 when an enclosure of ``expr`` excludes 0 at some precision up to ``max_bits``; else None.

    ``expr`` must be closed and exact (integers, rationals, pi, E, +, *, powers,
    Abs, sin, cos, tan, exp, log); anything else gives None.

    Examples
    --------
    >>> import sympy as sp
    >>> interval_sign(sp.E - sp.Rational(271, 100)), interval_sign(sp.pi - sp.Rational(355, 113))
    (1, -1)
    >>> interval_sign(sp.sin(sp.pi)) is None  # exactly 0: no enclosure excludes it
    True
    >>> interval_sign(sp.Symbol("y")) is None  # not closed
    True
    """
    saved, bits = iv.prec, 64
    try:
        while bits <= max_bits:
            iv.prec = bits
            try:
                value = _enclose(expr)
            except (_Unsupported, ZeroDivisionError, ValueError, OverflowError):
                return None
            if value.a > 0:
                return 1
            if value.b < 0:
                return -1
            bits *= 4
    finally:
        iv.prec = saved
    return None
