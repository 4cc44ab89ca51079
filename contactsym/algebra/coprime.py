"""Coprimality proved by specialization, before a multivariate gcd is paid for.

Most gcds the pipeline asks for are 1: a fraction derived by the stages is usually already
cancelled, and SymPy's heuristic gcd spends most of its time finding that out (trial divisions of
large polynomials). A cheap certificate decides most of them.

Why a specialization proves coprimality. Let G = gcd(f, g) in R[x_1, ..., x_n] (R = Z or Q) and
x one of the variables. Put integers a_j for every other variable. G divides f and g, so G(a)
divides both images f(a), g(a) in Q[x], hence their univariate gcd. If the coefficient of the
highest power of x in f (or in g) does not vanish at a, neither does G's (it divides it), so
G(a) has the x-degree of G. So when gcd(f(a), g(a)) is a constant, G has degree 0 in x. When that
holds for every variable that occurs in both f and g (a common factor cannot contain a variable
that one of them lacks), G is a constant. A point where the test fails proves nothing: the full
gcd is computed then, so the answer never depends on luck.

:func:`cofactors` and :func:`cancel` return exactly what ``f.cofactors(g)`` and ``f.cancel(g)``
of SymPy's sparse polynomials return (tested on random polynomials), only faster when the
certificate holds.

Examples
--------
>>> from sympy.polys.rings import ring
>>> from sympy import ZZ
>>> R, x, y = ring("x, y", ZZ)
>>> proved_coprime(x**2 + y, x*y + 1)
True
>>> proved_coprime((x + y) * (x - 1), (x + y) * (y + 2))
False
>>> cancel(6*x**2 + 6*y, 4*x*y + 4) == (6*x**2 + 6*y).cancel(4*x*y + 4)
True
"""

from __future__ import annotations

from math import gcd, lcm

from sympy import ZZ
from sympy.polys.euclidtools import dup_gcd

__all__ = ["cancel", "cofactors", "divided_by_term", "proved_coprime"]

#: The values given to the variables, one per variable (cycled): small primes keep the images small.
POINTS = (3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73)


def proved_coprime(f, g) -> bool:
    """True when ``f`` and ``g`` (of one ring over ZZ or QQ) are proved to have no common factor of
    positive degree (module docstring); False means *not proved*, not that a factor exists."""
    if not f or not g or not (f.ring.domain.is_ZZ or f.ring.domain.is_QQ):
        return False
    shared = [i for i in range(f.ring.ngens) if f.degree(i) > 0 and g.degree(i) > 0]
    if not shared:
        return True
    point = [POINTS[i % len(POINTS)] for i in range(f.ring.ngens)]
    f_terms, g_terms = _integer_terms(f, point), _integer_terms(g, point)
    for i in shared:
        image_f, image_g = _image(f_terms, i, f.degree(i), point), _image(g_terms, i, g.degree(i), point)
        if not (image_f[0] or image_g[0]):
            return False  # both leading coefficients vanish at the point: the degree of G may drop
        if len(dup_gcd(_stripped(image_f), _stripped(image_g), ZZ)) > 1:
            return False
    return True


def cofactors(f, g):
    """``f.cofactors(g)``: (h, f / h, g / h) with h the gcd, by the certificate where it holds
    (after the common monomial, x^min(a, b) for each variable, is divided out).

    >>> from sympy.polys.rings import ring
    >>> from sympy import QQ
    >>> R, x, y = ring("x, y", QQ)
    >>> cofactors(x / 2 + y, x * y + 3)
    (1, 1/2*x + y, x*y + 3)
    >>> cofactors(x**2 * y + x, x * y**2 - x)
    (x, x*y + 1, y**2 - 1)
    """
    if len(f) > 1 and len(g) > 1:
        monomial, f1, g1 = _without_common_monomial(f, g)
        if proved_coprime(f1, g1):
            ring = f.ring
            if ring.domain.is_QQ:  # the gcd over a field is monic
                return monomial, f1, g1
            common = gcd(_content(f1), _content(g1))  # over ZZ: the gcd of the contents
            return monomial.mul_ground(common), f1.quo_ground(common), g1.quo_ground(common)
    return f.cofactors(g)


def cancel(f, g):
    """``f.cancel(g)``: f / g in lowest terms, the denominator's leading coefficient positive.

    >>> from sympy.polys.rings import ring
    >>> from sympy import QQ
    >>> R, x, y = ring("x, y", QQ)
    >>> cancel(x / 2 + y, -x * y / 3 - 1)
    (-3*x - 6*y, 2*x*y + 6)
    """
    if not f or len(f) == 1 or len(g) == 1:
        return f.cancel(g)
    _, f, g = _without_common_monomial(f, g)
    if not proved_coprime(f, g):
        return f.cancel(g)
    ring = f.ring
    domain = ring.domain
    if domain.is_QQ:  # over Z: integer parts with the contents' gcd removed, each times the other's scale
        scale_f, scale_g = _denominator(f), _denominator(g)
        whole_f, whole_g = f.mul_ground(scale_f), g.mul_ground(scale_g)
        common = gcd(_content(whole_f), _content(whole_g))
        both = gcd(scale_f, scale_g)
        p = whole_f.mul_ground(domain(scale_g // both, common))
        q = whole_g.mul_ground(domain(scale_f // both, common))
    else:
        common = gcd(_content(f), _content(g))
        p, q = f.quo_ground(common), g.quo_ground(common)
    if domain.is_negative(q.LC):
        p, q = -p, -q
    return p, q


def _without_common_monomial(f, g):
    """(m, f / m, g / m) with m the monomial of the least exponents of each variable in f and g."""
    least = [min(e) for e in zip(*f.monoms(), *g.monoms())]
    ring = f.ring
    if not any(least):
        return ring.one, f, g
    monomial = ring({tuple(least): ring.domain.one})
    return monomial, divided_by_term(f, monomial), divided_by_term(g, monomial)


def divided_by_term(poly, term):
    """``poly.exquo(term)`` for a one-term ``term`` that divides ``poly``: exponents subtracted, one
    pass (SymPy's division looks for the leading term of every remainder: quadratic in the terms).

    >>> from sympy.polys.rings import ring
    >>> from sympy import ZZ
    >>> R, x, y = ring("x, y", ZZ)
    >>> divided_by_term(6*x**3*y + 4*x*y**2, 2*x*y)
    3*x**2 + 2*y
    """
    ((monom, coefficient),) = term.items()
    exquo = poly.ring.domain.exquo
    return poly.ring.from_dict({tuple(a - b for a, b in zip(m, monom)): exquo(c, coefficient) for m, c in poly.items()})


def _integer_terms(poly, point) -> list[tuple[tuple, int, int]]:
    """(monomial, integer coefficient, value of the monomial at the point) for each term; the
    coefficients scaled by one common denominator (which does not change a gcd's degree)."""
    scale = _denominator(poly)
    terms = []
    for monom, coeff in poly.items():
        value = 1
        for a, e in zip(point, monom):
            if e:
                value *= a**e
        terms.append((monom, int(coeff * scale), value))
    return terms


def _image(terms, i: int, degree: int, point) -> list[int]:
    """The univariate image in variable ``i`` (highest power first) of the other variables at the point."""
    image = [0] * (degree + 1)
    a = point[i]
    for monom, coeff, value in terms:
        e = monom[i]
        image[degree - e] += coeff * (value // a**e)
    return image


def _stripped(image: list[int]) -> list:
    """A dense list without leading zeros, in ZZ (what ``dup_gcd`` reads)."""
    start = 0
    while start < len(image) and not image[start]:
        start += 1
    return [ZZ(c) for c in image[start:]]


def _denominator(poly) -> int:
    """The least common denominator of the coefficients (1 over ZZ)."""
    if not poly.ring.domain.is_QQ:
        return 1
    return lcm(*(int(c.denominator) for c in poly.values()))


def _content(poly) -> int:
    """The gcd of the integer coefficients."""
    return gcd(*(int(c) for c in poly.values()))
