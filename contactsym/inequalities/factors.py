"""The factors of a relation's numerator: SymPy's ``factor_list``, skipped where a short proof says irreducible.

A scene's stability conditions are mostly multilinear (in the sign symbols s_j, the law's
Phi_j and Psi_j, the masses), and ``factor_list`` spends up to seconds on each (Wang's
algorithm on 40-60 terms) only to find one irreducible factor. A shorter proof suffices:

    a primitive polynomial f = a x + b of degree 1 in some variable x, with gcd(a, b) = 1
    in the other variables, is irreducible over the rationals

(Gauss's lemma: of two factors of f, one is free of x, so it divides a and b, hence is a
unit). :func:`factor_list` takes out the rational content and the monomial factor, as
``factor_list`` does, and tries this proof for each variable of degree 1; only when none
succeeds does it factor. Its answer is exactly SymPy's: the factorization into the content and
primitive factors with a positive leading coefficient is unique, so both give the same
coefficient and the same factors (listed perhaps in another order).
"""

from __future__ import annotations

import sympy as sp
from sympy.polys.polyerrors import PolynomialError

__all__ = ["factor_list", "irreducible_by_degree_one"]


def factor_list(expr: sp.Expr) -> tuple[sp.Expr, list[tuple[sp.Expr, int]]]:
    """``sympy.factor_list(expr)``, without factoring when a polynomial is proved irreducible.

    Examples
    --------
    >>> x, y, m = sp.symbols("x y m")
    >>> factor_list(6 * m**2 * x * y + 4 * m**2 * y**2 - 2 * m**2)  # degree 1 in x, gcd(3 y, 2 y**2 - 1) = 1
    (2, [(m, 2), (3*x*y + 2*y**2 - 1, 1)])
    >>> factor_list(x * y + x + y + 1)  # gcd(y + 1, y + 1) != 1: factored
    (1, [(y + 1, 1), (x + 1, 1)])
    """
    cheap = _proved_irreducible(expr) if isinstance(expr, sp.Add) else None
    return cheap if cheap is not None else sp.factor_list(expr)


def irreducible_by_degree_one(poly: sp.Poly) -> bool:
    """Whether a primitive polynomial (content 1, no monomial factor) is proved irreducible as a x + b, gcd(a, b) = 1.

    False proves nothing: the polynomial may still be irreducible.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> irreducible_by_degree_one(sp.Poly(x * y + y**2 + 1)), irreducible_by_degree_one(sp.Poly(x * y + y**2))
    (True, False)
    """
    degrees = poly.degree_list()
    candidates = [i for i, d in enumerate(degrees) if d == 1]
    # the variable whose coefficient a has the fewest terms first: gcd(a, b) is cheapest there
    terms = poly.terms()
    candidates.sort(key=lambda i: sum(1 for monomial, _ in terms if monomial[i] == 1))
    for i in candidates:
        a, b = {}, {}
        for monomial, coefficient in terms:
            rest = monomial[:i] + monomial[i + 1 :]
            (a if monomial[i] == 1 else b)[rest] = coefficient
        if not b:
            continue  # f = a x: reducible unless a is a unit, which the monomial factor excludes
        others = poly.gens[:i] + poly.gens[i + 1 :]
        if not others:  # univariate a x + b, a and b numbers: primitive, so irreducible
            return True
        gcd = sp.Poly.from_dict(a, *others, domain=poly.domain).gcd(sp.Poly.from_dict(b, *others, domain=poly.domain))
        if gcd.is_ground:
            return True
    return False


def _proved_irreducible(expr: sp.Add) -> tuple[sp.Expr, list[tuple[sp.Expr, int]]] | None:
    """SymPy's answer when expr, without content and monomial factor, is proved irreducible; else None."""
    try:
        poly = sp.Poly(expr)
    except PolynomialError:
        return None
    if poly.domain not in (sp.ZZ, sp.QQ) or poly.is_ground:
        return None
    exponents, reduced = poly.terms_gcd()
    if reduced.domain == sp.QQ:
        _, reduced = reduced.clear_denoms(convert=True)
    _, primitive = reduced.primitive()
    if primitive.LC() < 0:
        primitive = -primitive
    if primitive.is_ground or not irreducible_by_degree_one(primitive):
        return None
    # the content is what is left: expr = coefficient * monomial * primitive, all leading coefficients known
    coefficient = sp.Rational(poly.LC()) / sp.Rational(primitive.LC())
    monomial = [(gen, power) for gen, power in zip(poly.gens, exponents) if power]
    return coefficient, [*monomial, (primitive.as_expr(), 1)]
