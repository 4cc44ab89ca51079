"""The factors of a relation's numerator: SymPy's ``factor_list``, skipped where a short proof says irreducible.

A scene's stability conditions are mostly multilinear (in the sign symbols s_j, the law's
Phi_j and Psi_j, the masses), and ``factor_list`` spends up to seconds on each (Wang's
algorithm on 40-60 terms) only to find one irreducible factor. A shorter proof suffices:

    a primitive polynomial f = a x + b of degree 1 in some variable x, with gcd(a, b) = 1
    in the other variables, is irreducible over the rationals

(Gauss's lemma: of two factors of f, one is free of x, so it divides a and b, hence is a
unit). Where gcd(a, b) = g is not 1, f = g (f/g) with f/g irreducible so, and g is split
the same way. :func:`factor_list` takes out the rational content and the monomial factor, as
``factor_list`` does, and factors the rest so; only where a part has no variable of degree 1
does it call ``factor_list``. Its answer is exactly SymPy's: the factorization into the content
and primitive factors with a positive leading coefficient is unique, so both give the same
coefficient and the same factors (listed perhaps in another order).
"""

from __future__ import annotations

from collections import Counter

import sympy as sp
from sympy.polys.polyerrors import PolynomialError

from ..arguments import checked

__all__ = ["factor_list", "split_by_degree_one"]


@checked
def factor_list(expr: sp.Expr) -> tuple[sp.Expr, list[tuple[sp.Expr, int]]]:
    """``sympy.factor_list(expr)``, without Wang's algorithm where degree-1 variables split the polynomial.

    Examples
    --------
    >>> x, y, m = sp.symbols("x y m")
    >>> factor_list(6 * m**2 * x * y + 4 * m**2 * y**2 - 2 * m**2)  # degree 1 in x, gcd(3 y, 2 y**2 - 1) = 1
    (2, [(m, 2), (3*x*y + 2*y**2 - 1, 1)])
    >>> factor_list(x * y**2 + x + y**3 + y)  # gcd(y**2 + 1, y**3 + y) = y**2 + 1: (x + y)(y**2 + 1)
    (1, [(x + y, 1), (y**2 + 1, 1)])
    >>> factor_list(x**2 - y**2)  # no variable of degree 1: sympy.factor_list
    (1, [(x - y, 1), (x + y, 1)])
    """
    if isinstance(expr, sp.Mul):
        numerator, denominator = sp.together(expr).as_numer_denom()  # as sympy.factor_list begins
        if denominator == 1 and isinstance(numerator, sp.Mul):
            product = _factored_product(numerator)
            if product is not None:
                return product
    cheap = _factored_by_degree_one(expr) if isinstance(expr, sp.Add) else None
    return cheap if cheap is not None else sp.factor_list(expr)


def _factored_product(expr: sp.Mul) -> tuple[sp.Expr, list[tuple[sp.Expr, int]]] | None:
    """A product factored as ``sympy.factor_list`` factors it, each factor here by :func:`factor_list`.

    SymPy makes each argument of the Mul its own polynomial and merges two factors only where they are
    equal as polynomials, generators and domain included (so ``(x + 1)(x y + x + y + 1)`` lists ``x + 1``
    twice); the same rule here gives the same list, while a large argument of degree 1 in some variable is
    split without Wang's algorithm. None where an argument is not a polynomial to a positive integer power
    (SymPy then takes the whole over one denominator first).
    """
    coefficient, merged = sp.S.One, {}
    for arg in expr.args:
        if arg.is_Number:
            coefficient *= arg
            continue
        base, power = arg.as_base_exp() if arg.is_Pow else (arg, sp.S.One)
        if not (power.is_Integer and power > 0) or base.is_Number or not base.is_polynomial():
            return None
        try:
            poly = sp.Poly(base)
        except PolynomialError:
            return None
        inner, factors = factor_list(base)
        coefficient *= inner**power
        for factor, multiplicity in factors:
            key = (factor, poly.gens, poly.domain)
            merged[key] = merged.get(key, 0) + multiplicity * power
    return coefficient, [(factor, multiplicity) for (factor, _, _), multiplicity in merged.items()]


@checked
def split_by_degree_one(poly: sp.Poly) -> list[sp.Poly] | None:
    """The irreducible factors of a primitive polynomial (content 1, no monomial factor, positive leading
    coefficient) found through variables of degree 1; None where that does not finish.

    For f = a x + b with g = gcd(a, b): f = g h, where h = (a/g) x + b/g is irreducible (its
    coefficients are coprime) and g, free of x, is split the same way (or factored, where it has
    no variable of degree 1). A factor is listed as often as it divides f.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> split_by_degree_one(sp.Poly(x * y + y**2 + 1)), split_by_degree_one(sp.Poly(x**2 + y**2)) is None
    ([Poly(x*y + y**2 + 1, x, y, domain='ZZ')], True)
    """
    degrees = poly.degree_list()
    terms = poly.terms()
    candidates = [i for i, d in enumerate(degrees) if d == 1]
    # the variable whose coefficient a has the fewest terms first: gcd(a, b) is cheapest there
    candidates.sort(key=lambda i: sum(1 for monomial, _ in terms if monomial[i] == 1))
    for i in candidates[:1]:
        a, b = {}, {}
        for monomial, coefficient in terms:
            (a if monomial[i] == 1 else b)[monomial[:i] + (0,) + monomial[i + 1 :]] = coefficient
        if not b:
            return None  # f = a x: has a monomial factor (excluded) or is x itself
        common = sp.Poly.from_dict(a, *poly.gens, domain=poly.domain).gcd(
            sp.Poly.from_dict(b, *poly.gens, domain=poly.domain)
        )
        if common.is_ground:
            return [poly]
        common = _positive(common)
        rest = split_by_degree_one(common)
        if rest is None:  # no variable of degree 1 in g: factored (smaller than f)
            rest = [factor for factor, power in common.factor_list()[1] for _ in range(power)]
        return [_positive(poly.exquo(common)), *rest]
    return None


def _positive(poly: sp.Poly) -> sp.Poly:
    return -poly if poly.LC() < 0 else poly


def _factored_by_degree_one(expr: sp.Add) -> tuple[sp.Expr, list[tuple[sp.Expr, int]]] | None:
    """SymPy's answer where :func:`split_by_degree_one` finds every factor; else None."""
    try:
        poly = sp.Poly(expr)
    except PolynomialError:
        return None
    if poly.domain not in (sp.ZZ, sp.QQ) or poly.is_ground:
        return None
    if not all(gen.is_Symbol or gen.is_Function for gen in poly.gens):
        return None  # 1/m, sqrt(m): sympy.factor_list brings the expression over one denominator first
    exponents, reduced = poly.terms_gcd()
    if reduced.domain == sp.QQ:
        _, reduced = reduced.clear_denoms(convert=True)
    _, primitive = reduced.primitive()
    if primitive.is_ground:
        return None
    factors = split_by_degree_one(_positive(primitive))
    if factors is None:
        return None
    # the content is what is left: expr = coefficient * monomial * factors, their leading coefficients known
    coefficient = sp.Rational(poly.LC()) / sp.Mul(*[sp.Rational(f.LC()) for f in factors])
    monomial = [(gen, power) for gen, power in zip(poly.gens, exponents) if power]
    return coefficient, [*monomial, *Counter(f.as_expr() for f in factors).items()]
