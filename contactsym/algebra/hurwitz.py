"""Routh–Hurwitz conditions in the Liénard–Chipart form, fraction-free, any degree.

For ``p(lam) = a_0 lam^n + a_1 lam^(n-1) + ... + a_n`` with ``a_0 > 0`` every root has a
negative real part exactly when all ``a_i > 0`` and the Hurwitz determinants
``Delta_(n-1), Delta_(n-3), ...`` are positive. The determinants are computed once per
degree for generic coefficients (polynomials with integer coefficients, no division)
and then evaluated at the given coefficients.

A Hopf point is where ``Delta_(n-1) = 0`` with the other conditions positive; there
``p(i omega) = 0`` and ``omega^2`` is the common root of the even and odd parts. Generically
(once per degree) that root is ``omega^2 = N / Delta_(n-3)``: for n = 6,
``(a_5 Delta_2 - a_1^2 a_6) / Delta_3``, whose denominator is a Liénard–Chipart minor, positive
on the Hopf set. At the given coefficients it is kept as that quotient in the coefficients p_s
(no expansion) once its expansion would exceed :data:`EXPAND_TERMS` terms: expanding and
cancelling a k = 3 frequency with rational numbers in it costs tens of seconds and prints
ten times longer.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cache, cached_property

import sympy as sp

from ..arguments import checked, require
from ..printing.latex_output import Formula
from .reductions import reduce_signs

__all__ = [
    "hurwitz_matrix",
    "hurwitz_minors",
    "lienard_chipart",
    "hopf_omega_squared",
    "expansion_bound",
    "EXPAND_TERMS",
    "Hurwitz",
]

_z = sp.Symbol("z")
#: Expressions whose expansion may exceed this many terms (:func:`expansion_bound`) are kept as derived.
EXPAND_TERMS = 400


def expansion_bound(expr: sp.Expr) -> int:
    """An upper bound on the number of terms of the numerator of ``expr`` brought over one
    denominator and expanded, read off the expression tree without expanding anything.

    Each node gives (numerator terms, denominator terms): sums cross-multiply the denominators,
    products multiply, a power ``b**e`` takes at most ``C(t + e - 1, e)`` terms for ``t`` terms
    of ``b`` (a negative power swaps the two); function applications and numbers count one.

    Examples
    --------
    >>> x, y, z = sp.symbols("x y z")
    >>> expansion_bound((x + y) * (x + z) + 1), expansion_bound((x + y + z) ** 2 / (x - y) + x)
    (5, 8)
    """
    return _bounds(expr)[0]


def _bounds(expr: sp.Expr) -> tuple[int, int]:
    if isinstance(expr, sp.Add):
        parts = [_bounds(arg) for arg in expr.args]
        denominator = math.prod(d for _, d in parts)
        return sum(n * denominator // d for n, d in parts), denominator
    if isinstance(expr, sp.Mul):
        parts = [_bounds(arg) for arg in expr.args]
        return math.prod(n for n, _ in parts), math.prod(d for _, d in parts)
    if isinstance(expr, sp.Pow) and expr.exp.is_Integer:
        power = abs(int(expr.exp))
        n, d = (_power_bound(t, power) for t in _bounds(expr.base))
        return (n, d) if expr.exp > 0 else (d, n)
    return 1, 1


def _power_bound(terms: int, power: int) -> int:
    return min(terms**power, math.comb(terms + power - 1, power))


def _generic(n: int) -> tuple[sp.Symbol, ...]:
    return sp.symbols(f"a_0:{n + 1}")


@checked(coefficients="Sequence[sp.Expr]")
def hurwitz_matrix(coefficients) -> sp.Matrix:
    """The n x n Hurwitz matrix H[i, j] = a_(2j - i) (1-based), for a_0 lam^n + ... + a_n.

    Examples
    --------
    >>> hurwitz_matrix(sp.symbols("a0:4"))
    Matrix([
    [a1, a3,  0],
    [a0, a2,  0],
    [ 0, a1, a3]])
    """
    require(len(coefficients) >= 2, "hurwitz_matrix", "coefficients", coefficients, "two or more coefficients")
    a = list(coefficients)
    n = len(a) - 1

    def entry(i, j):
        index = 2 * (j + 1) - (i + 1)
        return a[index] if 0 <= index <= n else sp.S.Zero

    return sp.Matrix(n, n, entry)


@cache
def _generic_minors(n: int) -> tuple[sp.Expr, ...]:
    H = hurwitz_matrix(_generic(n))
    return tuple(sp.expand(H[:m, :m].det(method="berkowitz")) for m in range(1, n + 1))


def _coefficients(poly: sp.Poly) -> list[sp.Expr]:
    return [poly.coeff_monomial(poly.gen**i) for i in range(poly.degree(), -1, -1)]


@checked
def hurwitz_minors(poly: sp.Poly) -> list[sp.Expr]:
    """Delta_1 .. Delta_n of ``poly`` (unexpanded substitution into generic minors).

    Examples
    --------
    >>> x, a, b = sp.symbols("x a b")
    >>> hurwitz_minors(sp.Poly(x**2 + a*x + b, x))
    [a, a*b]
    """
    values = dict(zip(_generic(poly.degree()), _coefficients(poly)))
    return [m.xreplace(values) for m in _generic_minors(poly.degree())]


def _lienard_chipart_choice(poly: sp.Poly) -> tuple[list[int], list[int]]:
    """(powers s of the coefficients p_s that are not positive numbers, orders m of the
    minors Delta_(n-1), Delta_(n-3), ... down to Delta_2): the Liénard–Chipart conditions."""
    n = poly.degree()
    powers = [n - i for i, c in enumerate(_coefficients(poly)) if not (c.is_number and c > 0)]
    return powers, list(range(n - 1, 1, -2))


def _lienard_chipart_parts(poly: sp.Poly, minors: list[sp.Expr]) -> tuple[list, list]:
    """(the chosen coefficients, the chosen minors)."""
    powers, orders = _lienard_chipart_choice(poly)
    coefficients = _coefficients(poly)
    return [coefficients[poly.degree() - s] for s in powers], [minors[m - 1] for m in orders]


@checked
def lienard_chipart(poly: sp.Poly, minors: list[sp.Expr] | None = None) -> list[sp.Expr]:
    """Expressions that are all > 0 exactly when ``poly`` is Hurwitz stable.

    The leading coefficient must be positive; coefficients that are positive numbers
    are dropped, and Delta_1 (= a_1) is not repeated.

    Examples
    --------
    >>> x, a, b, c = sp.symbols("x a b c")
    >>> lienard_chipart(sp.Poly(x**3 + a*x**2 + b*x + c, x))
    [a, b, c, a*b - c]
    """
    coefficients, chosen = _lienard_chipart_parts(poly, minors or hurwitz_minors(poly))
    return coefficients + chosen


def _first_subresultant(A: sp.Poly, B: sp.Poly) -> sp.Poly:
    """The subresultant of degree 1 of A and B (deg A >= deg B >= 1), as one determinant.

    Rows z^i A (i < deg B - 1) and z^i B (i < deg A - 1); the columns hold the
    coefficients of z^(m+n-2) .. z^2 and, last, the row polynomial itself.
    """
    if A.degree() == 1:
        return A
    if B.degree() == 1:
        return B
    m, n = A.degree(), B.degree()
    rows = [A * _z**i for i in reversed(range(n - 1))] + [B * _z**i for i in reversed(range(m - 1))]
    top = m + n - 2
    matrix = sp.Matrix(
        [[row.coeff_monomial(_z ** (top - c)) for c in range(top - 1)] + [row.as_expr()] for row in rows]
    )
    return sp.Poly(matrix.det(method="berkowitz"), _z)


@cache
def _generic_omega_squared(n: int) -> sp.Expr | None:
    if n < 2:
        return None
    a = _generic(n)[::-1]  # a[i] is the coefficient of lam**i
    even = sp.Poly(sum((-1) ** i * a[2 * i] * _z**i for i in range(n // 2 + 1)), _z)
    odd = sp.Poly(sum((-1) ** i * a[2 * i + 1] * _z**i for i in range((n - 1) // 2 + 1)), _z)
    if odd.degree() < 1:
        return -even.coeff_monomial(1) / even.coeff_monomial(_z)
    s = _first_subresultant(even, odd)
    numerator, denominator = -s.coeff_monomial(1), s.coeff_monomial(_z)
    if n < 4:
        return numerator / denominator
    # the subresultant's leading coefficient is +-Delta_(n-3): write omega^2 over that minor
    minor = _generic_minors(n)[n - 4]
    sign = sp.cancel(denominator / minor)
    if sign not in (1, -1):  # pragma: no cover - a property of subresultants, checked for n <= 8 by the tests
        raise ArithmeticError(f"degree {n}: the subresultant's leading coefficient is not +-Delta_{n - 3}")
    return sp.Mul(sp.expand(sign * numerator), sp.Pow(minor, -1))


@checked
def hopf_omega_squared(poly: sp.Poly) -> sp.Expr | None:
    """omega^2 at a Hopf point (Delta_(n-1) = 0): the common root of Re and Im of p(i omega).

    Examples
    --------
    >>> x, a = sp.symbols("x a", positive=True)
    >>> hopf_omega_squared(sp.Poly(x**4 + 2*x**3 + 3*x**2 + a*x + 1, x))
    a/2
    """
    generic = _generic_omega_squared(poly.degree())
    if generic is None:
        return None
    values = dict(zip(_generic(poly.degree()), _coefficients(poly)))
    omega_squared = generic.xreplace(values)
    if expansion_bound(omega_squared) > EXPAND_TERMS:
        return reduce_signs(omega_squared)  # N(p)/Delta_(n-3)(p): see the module docstring
    return _cancelled(omega_squared)


def _cancelled(expr: sp.Expr) -> sp.Expr:
    """``expr`` cancelled, and then s^2 = 1 used in its numerator and denominator (cancelled
    again when that changed them); small expressions only."""
    cancelled = sp.cancel(expr)
    numerator, denominator = sp.fraction(cancelled)
    reduced = reduce_signs(numerator), reduce_signs(denominator)
    if reduced == (numerator, denominator):
        return cancelled
    return sp.cancel(reduced[0] / reduced[1])


def _relation(op, expr: sp.Expr) -> sp.Basic:
    """``op(expr, 0)``; unevaluated when ``expr`` is long: asking its sign costs seconds
    (a k = 3 stool's Delta_5 = 0: 2.7 s) and decides nothing."""
    if expansion_bound(expr) > EXPAND_TERMS:
        return op(expr, 0, evaluate=False)
    return op(expr, 0)


@checked
@dataclass(frozen=True, eq=False)
class Hurwitz:
    """Hurwitz data of a characteristic polynomial (4.6)-(4.7).

    ``equations`` are the equation numbers its conditions are cited with in :meth:`formulas`;
    the stage that owns the conditions sets them (:class:`~contactsym.stages.stability.Stability`:
    (3.2) for one contact, (4.7) for more), so this algebra cites no paper number of its own.

    Examples
    --------
    >>> x, a, b = sp.symbols("x a b")
    >>> Hurwitz(sp.Poly(x**2 + a*x + b, x)).conditions
    [a, b]
    >>> [f.cite() for f in Hurwitz(sp.Poly(x**2 + a*x + b, x), ("3.2",)).formulas()]
    ['(3.2)', '(3.2)']
    """

    poly: sp.Poly
    equations: tuple = ()

    @cached_property
    def coefficients(self) -> list[sp.Expr]:
        """p_n, ..., p_0 (leading first)."""
        return _coefficients(self.poly)

    @cached_property
    def minors(self) -> list[sp.Expr]:
        return hurwitz_minors(self.poly)

    @cached_property
    def _parts(self) -> tuple[list, list]:
        return _lienard_chipart_parts(self.poly, self.minors)

    @cached_property
    def conditions(self) -> list[sp.Expr]:
        coefficients, chosen = self._parts
        return coefficients + chosen

    @cached_property
    def labels(self) -> list[tuple[str, int]]:
        """What each condition is: ``("p", s)`` for the coefficient p_s of (4.6),
        ``("Delta", m)`` for the Hurwitz minor Delta_m of (4.7)."""
        powers, orders = _lienard_chipart_choice(self.poly)
        return [("p", s) for s in powers] + [("Delta", m) for m in orders]

    @cached_property
    def hopf_set(self) -> sp.Basic:
        """Delta_(n-1) = 0 with the other Liénard–Chipart conditions positive (degree >= 3)."""
        coefficients, chosen = self._parts
        if not chosen:
            return sp.false
        others = coefficients + chosen[1:]
        return sp.And(_relation(sp.Eq, chosen[0]), *[_relation(sp.Gt, c) for c in others])

    @cached_property
    def omega_squared(self) -> sp.Expr | None:
        return hopf_omega_squared(self.poly)

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """The conditions h_i > 0, cited with ``equations``: see :func:`contactsym.printing.latex_output.formulas`."""
        return tuple(Formula("hurwitz", f"h_{{{i}}}", c, "", self.equations) for i, c in enumerate(self.conditions, 1))
