"""The common factors of P and Q that only the circle sees, cancelled through t = tan(q/2).

The reduced P and Q of a :class:`~contactsym.algebra.trig_field.TrigFraction` are polynomials
modulo the ideal (cos^2 q + sin^2 q - 1, ...). That quotient ring is no unique factorisation
domain (sin^2 q = (1 - cos q)(1 + cos q)), so a polynomial gcd misses factors that cancel only
modulo the ideal: ``m h / ((2 + cos a) h)`` with h = 1 + sin a + cos a, expanded and with cos^2 a
written as 1 - sin^2 a, has coprime numerator and denominator as polynomials.

The circle is rational. cos q = (1 - t^2)/(1 + t^2), sin q = 2t/(1 + t^2) maps the ring
Q[cos q, sin q]/(cos^2 q + sin^2 q - 1) injectively into Q(t) (the ideal is prime and the map is
the circle's parametrisation), so it maps the fraction field isomorphically onto Q(t), and one
such t per angle maps a fraction P/Q onto an element of Q(params, t_1, ..., t_n), a field of
rational functions in independent variables. There a fraction has one cancelled form, N/D with
gcd(N, D) = 1, unique up to a constant: :func:`cancelled_on_the_circle` computes it and maps it
back, writing t^j / (1 + t^2)^K as ((1 - cos q)/2)^(j//2) (sin q/2)^(j%2) ((1 + cos q)/2)^(K - ceil(j/2))
with the least K per angle that makes N and D trigonometric polynomials. Both steps are
functions of the field element alone, so equal fractions give equal (P', Q') up to a constant
(the caller fixes it). Sign symbols s (s^2 = 1) stay variables: Q is free of them (they were
moved up), so a common factor of Q is one of both parts of P = P0 + s P1, which the polynomial
gcd finds.

Examples
--------
>>> import sympy as sp
>>> from contactsym.algebra.trig_field import to_fraction
>>> a, m = sp.symbols("a m", positive=True)
>>> h = 1 + sp.sin(a) + sp.cos(a)
>>> fraction = to_fraction((m*sp.sin(a) + m*sp.cos(a) + m) / (-sp.sin(a)**2 + sp.sin(a)*sp.cos(a) + 2*sp.sin(a) + 3*sp.cos(a) + 3))
>>> fraction.as_expr()  # the polynomial gcd sees no common factor
(m*sin(a) + m*cos(a) + m)/(-sin(a)**2 + sin(a)*cos(a) + 2*sin(a) + 3*cos(a) + 3)
>>> cancelled_on_the_circle(fraction).as_expr()
m/(cos(a) + 2)
"""

from __future__ import annotations

import sympy as sp
from sympy.polys.rings import PolyRing

from .coprime import cofactors
from .trig_field import TrigFraction, _integral, _reduce

__all__ = ["cancelled_on_the_circle", "circle_form"]

#: Above this many terms in P or Q the step is skipped (the form is still correct; the module
#: docstring of :mod:`contactsym.algebra.canonical_form` says what is then not guaranteed).
MAX_TERMS = 5000


def cancelled_on_the_circle(fraction: TrigFraction) -> TrigFraction:
    """``fraction`` with every common factor of P and Q modulo the circle cancelled (module docstring).

    Only the angles of Q are mapped: a common factor divides Q, so it is free of the others, and
    a polynomial free of an angle divides P modulo that angle's circle exactly when it divides the
    reduced P as a polynomial (reduction acts on P's coefficients of the factor alone). Returns
    ``fraction`` itself when Q has no sine or cosine (then no angle is left) or when P or Q has
    more than :data:`MAX_TERMS` terms.
    """
    return circle_form(fraction)[0]


def circle_form(fraction: TrigFraction) -> tuple[TrigFraction, bool]:
    """:func:`cancelled_on_the_circle` and whether its result is the unique cancelled form.

    True when the result's (P', Q') is, up to a constant, a function of the fraction's value:
    Q had no sign symbol and P, Q at most :data:`MAX_TERMS` terms (step 5 ran), or P = 0, or Q
    is free of the angles (P/Q is then cancelled by the polynomial gcd of the reduced parts,
    which is unique in a polynomial ring over the other generators and the reduced angles).
    False where step 5 was skipped and only the polynomial gcd of step 4 cancelled.

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.algebra.trig_field import to_fraction
    >>> a = sp.Symbol("a", positive=True)
    >>> circle_form(to_fraction((1 + sp.cos(a)) / sp.sin(a)**2))[1]
    True
    """
    numer, denom, pairs, signs = fraction.numer, fraction.denom, fraction.pairs, fraction.signs
    ring = numer.ring
    trig = [(c, s) for c, s in pairs if denom.degree(c) > 0 or denom.degree(s) > 0]
    if any(i for i in signs if denom.degree(i) > 0):
        return fraction, False
    if not numer or not trig:
        return fraction, True
    if len(numer) > MAX_TERMS or len(denom) > MAX_TERMS:
        return fraction, False
    kept = [i for i in range(ring.ngens) if all(i not in pair for pair in trig)]
    half = PolyRing([ring.symbols[i] for i in kept] + [sp.Dummy(f"t{n}") for n in range(len(trig))], ring.domain)
    ts = half.gens[len(kept) :]
    degrees_p = [_degree(numer, c, s) for c, s in trig]
    degrees_q = [_degree(denom, c, s) for c, s in trig]
    N, D = _to_half(numer, trig, kept, half, degrees_p), _to_half(denom, trig, kept, half, degrees_q)
    for t, dp, dq in zip(ts, degrees_p, degrees_q):  # P/Q = N (1 + t^2)^-dp / (D (1 + t^2)^-dq)
        if dq > dp:
            N *= (half.one + t**2) ** (dq - dp)
        elif dp > dq:
            D *= (half.one + t**2) ** (dp - dq)
    common, N, D = cofactors(N, D)
    powers = [(max(N.degree(t), D.degree(t)) + 1) // 2 for t in ts]
    if common.is_ground and powers == [max(p, q) for p, q in zip(degrees_p, degrees_q)]:
        # mapped back with these powers, N and D are P and Q again (each is the normal form of its own value)
        return fraction, True
    numer = _reduce(_from_half(N, trig, kept, ring, powers), pairs, signs)
    denom = _reduce(_from_half(D, trig, kept, ring, powers), pairs, signs)
    numer, denom = _integral(numer, denom)
    return TrigFraction(numer, denom, pairs, signs), True


def _degree(poly, c: int, s: int) -> int:
    """The total degree of ``poly`` in cos q, sin q."""
    return max((m[c] + m[s] for m in poly.monoms()), default=0)


def _to_half(poly, trig, kept, half, degrees):
    """(1 + t_i^2)^(n_i) poly(cos = (1 - t^2)/(1 + t^2), sin = 2t/(1 + t^2)), n_i its degree in angle i."""
    ts = half.gens[len(kept) :]
    cos_, sin_, one_ = [half.one - t**2 for t in ts], [2 * t for t in ts], [half.one + t**2 for t in ts]
    powers: dict = {}

    def power(table, i, e):
        key = (id(table), i, e)
        if key not in powers:
            powers[key] = table[i] ** e
        return powers[key]

    result = half.zero
    for monom, coeff in poly.items():
        term = half({tuple(monom[i] for i in kept) + (0,) * len(ts): coeff})
        for i, (c, s) in enumerate(trig):
            ec, es = monom[c], monom[s]
            term *= power(cos_, i, ec) * power(sin_, i, es) * power(one_, i, degrees[i] - ec - es)
        result += term
    return result


def _from_half(poly, trig, kept, ring, powers):
    """poly / prod (1 + t_i^2)^(K_i) as a polynomial in cos q_i, sin q_i (module docstring)."""
    by_power: dict = {}  # the exponents of the t_i -> the polynomial in the other generators
    for monom, coeff in poly.items():
        others = [0] * ring.ngens
        for position, i in enumerate(kept):
            others[i] = monom[position]
        part = by_power.setdefault(monom[len(kept) :], {})
        part[tuple(others)] = coeff
    half = ring.domain.convert(sp.Rational(1, 2))
    basis: dict = {}  # (i, j) -> t_i^j / (1 + t_i^2)^K_i in the trigonometric ring
    result = ring.zero
    for exponents, part in by_power.items():
        term = ring.from_dict(part)
        for i, ((c, s), j) in enumerate(zip(trig, exponents)):
            if (i, j) not in basis:
                C, S = ring.gens[c], ring.gens[s]
                rest = powers[i] - (j + 1) // 2
                basis[(i, j)] = (
                    ((ring.one - C) * half) ** (j // 2) * (S * half) ** (j % 2) * ((ring.one + C) * half) ** rest
                )
            term *= basis[(i, j)]
        result += term
    return result
