"""Signs of an expression at exact sample points of its domain: a cheap disproof before a proof.

A proof that ``expr > 0`` throughout the domain (:func:`contactsym.algebra.reductions.known_sign`)
expands ``expr`` in a polynomial ring, seconds for a Hurwitz determinant of a few thousand terms.
One point of the domain where ``expr <= 0`` shows that no such proof exists, and one where it is
positive and another where it is negative show that neither sign can be proved. The points are
exact: every symbol gets a rational value its assumptions allow (positive, negative, real; a sign
symbol +1 or -1), each angle a rational point (cos q, sin q) = ((1 - t^2), 2 t) / (1 + t^2) of the
unit circle, and a point counts only where every declared positive expression is positive. The
value is then an exact rational, so a sign read off it is a fact about the domain, not a rounding.
Where a symbol's domain is not one of these (an integer, a complex or unassumed symbol, an unknown
function, an angle outside sin and cos, a non-integer power), no point is taken and nothing is
concluded.

Examples
--------
>>> import sympy as sp
>>> x = sp.Symbol("x", real=True)
>>> m = sp.Symbol("m", positive=True)
>>> q = sp.Symbol("q", real=True)
>>> sorted(sampled_signs(m - x**2)), sorted(sampled_signs(sp.cos(q)))
([-1, 1], [-1, 1])
>>> sampled_signs(m + x**2), sampled_signs(2 + sp.sin(q))
({1}, {1})
>>> sampled_signs(x - m, positive=[m - x])  # only points where m - x > 0 count
{-1}
>>> n = sp.Symbol("n", integer=True)
>>> sampled_signs(n - 1), sorted(sampled_signs(n * m, units=[n]))  # n any integer, or +1 and -1
(set(), [-1, 1])
"""

from __future__ import annotations

import random
from fractions import Fraction

import sympy as sp
from sympy.core.function import AppliedUndef

__all__ = ["sampled_signs"]

#: Sample points tried; each is skipped where a declared positive expression is not positive.
SAMPLES = 4


def sampled_signs(expr: sp.Expr, positive=(), units=(), samples: int = SAMPLES) -> set[int]:
    """The signs (-1, 0, 1) ``expr`` takes at exact sample points of its domain (module docstring);
    an empty set where no point can be taken. ``units``: the symbols whose values are +1 and -1 (the
    sign symbols of a sign pattern). Sines and cosines are of real symbols (angles expanded
    first); of anything else no point is taken. Deterministic: the same points for the same input."""
    exprs = [expr, *positive]
    if any(e.atoms(AppliedUndef) or _fractional_powers(e) for e in exprs):
        return set()
    trig = set().union(*(e.atoms(sp.sin, sp.cos) for e in exprs))
    angles = {f.args[0] for f in trig}
    if any(not (a.is_Symbol and a.is_real) for a in angles):
        return set()
    plain = set().union(*(_outside_trig(e) for e in exprs))
    if plain & angles:
        return set()  # an angle also outside sin and cos: a rational circle point gives no rational angle
    draw = random.Random(len(plain) + 7 * len(angles))
    found = set()
    for _ in range(samples):
        point = _point(sorted(plain, key=str), sorted(angles, key=str), set(units), draw)
        if point is None:
            return set()
        values = [e.xreplace(point) for e in exprs]
        if not all(v.is_Rational for v in values) or any(v <= 0 for v in values[1:]):
            continue  # outside the declared domain, or not evaluated exactly
        found.add(int(sp.sign(values[0])))
    return found


def _outside_trig(expr: sp.Expr) -> set:
    """The symbols of ``expr`` that occur outside sin and cos."""
    found, nodes = set(), sp.preorder_traversal(expr)
    for node in nodes:
        if isinstance(node, (sp.sin, sp.cos)):
            nodes.skip()
        elif node.is_Symbol:
            found.add(node)
    return found


def _fractional_powers(expr: sp.Expr) -> bool:
    return any(not p.exp.is_Integer for p in expr.atoms(sp.Pow))


def _point(symbols, angles, units, draw) -> dict | None:
    """Rational values for the symbols (by their assumptions) and rational circle points for the angles."""
    point = {}
    for s in symbols:
        size = Fraction(draw.randint(1, 12), draw.randint(1, 6))
        if s in units:
            point[s] = sp.Integer(draw.choice((-1, 1)))
        elif s.is_integer is not None or not s.is_real:
            return None  # an integer, complex or unassumed symbol: its domain is not sampled here
        elif s.is_positive or s.is_nonnegative:
            point[s] = sp.Rational(size.numerator, size.denominator)
        elif s.is_negative or s.is_nonpositive:
            point[s] = -sp.Rational(size.numerator, size.denominator)
        else:
            point[s] = sp.Rational(size.numerator, size.denominator) * draw.choice((-1, 1))
    for q in angles:
        t = sp.Rational(draw.randint(-9, 9), draw.randint(1, 7))
        point[sp.cos(q)], point[sp.sin(q)] = (1 - t**2) / (1 + t**2), 2 * t / (1 + t**2)
    return point
