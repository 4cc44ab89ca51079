"""Trigonometric polynomials as Fourier sums in multiple angles, for presentation.

A polynomial in sin q_i, cos q_i (the normal form of :mod:`contactsym.algebra.canonical_form`) equals a
unique sum of a_k cos(k.q) + b_k sin(k.q) over integer vectors k with first nonzero entry
positive. :func:`best_form` prints whichever of the two has fewer terms: cos(2 q1 - 2 q2) reads
better than its expansion in products, a single sin q better than its Fourier sum.
"""

from __future__ import annotations

from fractions import Fraction as Fraction_
from functools import cache, reduce

import sympy as sp

from ..arguments import checked

__all__ = ["best_form", "fourier_sum", "shorter_fourier_terms"]


def _fourier_terms(poly, pairs) -> dict:
    """{(k, other exponents): (a, b)}: the term a cos(k.q) + b sin(k.q) (k first nonzero > 0).

    With z = exp(i q): 2 cos q = z + 1/z and 2 sin q = (z - 1/z)/i; each monomial's trigonometric
    part becomes a Laurent polynomial in the z's with Gaussian-integer coefficients over a power
    of two (kept as integer pairs, one common denominator: exact and fast), and the frequencies
    k and -k pair into a cosine and a sine of k.q.
    """
    domain = poly.ring.domain
    trig = {i for pair in pairs for i in pair}
    terms_in = poly.terms()
    top = max(sum(monom[i] for i in trig) for monom, _ in terms_in)
    scale = reduce(sp.ilcm, [int(domain.denom(c)) for _, c in terms_in], 1)
    by_term: dict[tuple, list] = {}  # (k, other exponents) -> [re, im] of 2^top * scale * coefficient of z^k
    for monom, coeff in terms_in:
        rest = tuple(0 if i in trig else e for i, e in enumerate(monom))
        degree = sum(monom[i] for i in trig)
        laurent = {(): (int(domain.numer(coeff)) * (scale // int(domain.denom(coeff))) << (top - degree), 0)}
        for c, s in pairs:
            factor = _laurent(monom[c], monom[s])
            product: dict = {}
            for k, (ar, ai) in laurent.items():
                for j, (br, bi) in factor.items():
                    product[k + (j,)] = (ar * br - ai * bi, ar * bi + ai * br)
            laurent = product
        for k, (re, im) in laurent.items():
            entry = by_term.setdefault((k, rest), [0, 0])
            entry[0] += re
            entry[1] += im
    denominator = Fraction_(1, scale << top)
    terms = {}
    for (k, rest), a in by_term.items():
        if any(k) and _negative_first(k):
            continue  # taken with its partner
        b = by_term.get((tuple(-e for e in k), rest), (0, 0)) if any(k) else (0, 0)
        # a z^k + b z^-k = (a + b) cos(k.q) + i (a - b) sin(k.q); a constant term is real
        cosine, sine = (a[0] + b[0], b[1] - a[1]) if any(k) else (a[0], 0)
        if cosine or sine:
            terms[(k, rest)] = (cosine * denominator, sine * denominator)
    return terms


def fourier_sum(terms: dict, ring, pairs) -> sp.Expr:
    """The sympy expression of Fourier terms (see :func:`shorter_fourier_terms`), already expanded."""
    angles = [ring.symbols[s].args[0] for _, s in pairs]
    total = []
    for (k, rest), (cosine, sine) in terms.items():
        monomial = sp.Mul(*[g**e for g, e in zip(ring.symbols, rest) if e])
        angle = sp.Add(*[e * q for e, q in zip(k, angles) if e])
        if not any(k):
            total.append(_rational(cosine) * monomial)
            continue
        total.append(_rational(cosine) * monomial * sp.cos(angle))
        total.append(_rational(sine) * monomial * sp.sin(angle))
    return sp.Add(*total)


def _rational(x: Fraction_) -> sp.Rational:
    return sp.Rational(x.numerator, x.denominator)


@cache
def _laurent(cos_power: int, sin_power: int) -> dict:
    """(2 cos)^a (2 sin)^b as {frequency j: (re, im) of the coefficient of z^j}, integers."""
    result = {0: (1, 0)}
    factors = [{1: (1, 0), -1: (1, 0)}] * cos_power + [{1: (0, -1), -1: (0, 1)}] * sin_power
    for factor in factors:
        product: dict = {}
        for j, (ar, ai) in result.items():
            for i, (br, bi) in factor.items():
                re, im = product.get(j + i, (0, 0))
                product[j + i] = (re + ar * br - ai * bi, im + ar * bi + ai * br)
        result = {j: a for j, a in product.items() if a != (0, 0)}
    return result


def _negative_first(k: tuple) -> bool:
    first = next(e for e in k if e != 0)
    return first < 0


#: Polynomials with more terms than this are shown as they are, not converted to Fourier sums.
_FOURIER_LIMIT = 3000


def shorter_fourier_terms(poly, pairs) -> dict | None:
    """{(k, other exponents): (a, b)} of the Fourier sum of ``poly`` (a cos(k.q) + b sin(k.q), exact
    fractions) when that sum has fewer terms than ``poly``; None when it has not, or ``poly`` has no
    sine or cosine, or more than ``_FOURIER_LIMIT`` terms (a form nobody reads whole)."""
    if not pairs or not any(poly.degree(c) > 0 or poly.degree(s) > 0 for c, s in pairs):
        return None
    if len(poly) > _FOURIER_LIMIT:
        return None
    terms = _fourier_terms(poly, pairs)
    count = sum(bool(a) + bool(b) for a, b in terms.values())
    return terms if count < len(poly.terms()) else None


@checked(poly="PolyElement", pairs="Sequence[tuple[int, int]]")
def best_form(poly, pairs) -> sp.Expr:
    """The polynomial in sin q_i, cos q_i, or its Fourier sum when that has fewer terms.

    Examples
    --------
    ``cos^2 x - sin^2 x`` reduces to ``1 - 2 sin^2 x``, shown as the one-term Fourier sum:

    >>> import sympy as sp
    >>> from contactsym.algebra import TrigField
    >>> x = sp.Symbol("x")
    >>> K = TrigField([sp.cos(x)])
    >>> poly = K.element(sp.cos(x)**2 - sp.sin(x)**2).numer
    >>> poly.as_expr(), best_form(poly, K.pairs)
    (1 - 2*sin(x)**2, cos(2*x))
    """
    terms = shorter_fourier_terms(poly, pairs)
    return poly.as_expr() if terms is None else fourier_sum(terms, poly.ring, pairs)
