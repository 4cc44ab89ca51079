"""Certificate and witness search for :mod:`contactsym.robustness` (proofs P3-P5 there).

Polynomials are ``QQ[c1..ck, d1..dk]`` ring elements from
:class:`contactsym.law_polynomials.LawPolynomials`; every certificate found in floating
point (a linear program) is re-checked in rationals before it is returned.

Examples
--------
>>> from contactsym.law_polynomials import law_ring
>>> R, (c1, c2, d1, d2) = law_ring(2)
>>> amgm_certificate(c1**2 - c1*c2 + c2**2)
'amgm'
>>> amgm_certificate(c1**2 - 3*c1*c2 + c2**2) is None
True
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from math import isqrt

import numpy as np
from scipy.optimize import linprog
from sympy.polys.domains import QQ

__all__ = ["amgm_certificate", "positivstellensatz_certificate", "rational_law", "vertex_laws"]


def rational_law(c, d, digits: int = 4) -> tuple[list, list]:
    """A float law rounded to ``digits`` significant decimal digits, as exact rationals."""
    return [QQ.convert(Fraction(f"{x:.{digits}g}")) for x in c], [QQ.convert(Fraction(f"{x:.{digits}g}")) for x in d]


# --- (P4) AM-GM -----------------------------------------------------------------------------


def _sqrt_lower_bound(x) -> Fraction:
    """A rational r <= sqrt(x), exact when x is the square of a rational."""
    x = Fraction(int(QQ.numer(x)), int(QQ.denom(x))) if not isinstance(x, Fraction) else x
    n, d = x.numerator, x.denominator
    rn, rd = isqrt(n), isqrt(d)
    if rn * rn == n and rd * rd == d:
        return Fraction(rn, rd)
    scale = 10**30
    return Fraction(isqrt(n * d * scale * scale), d * scale)


def amgm_certificate(g) -> str | None:
    """``"coefficients"`` if g has nonnegative coefficients (one positive), ``"amgm"`` if each
    negative term is absorbed by midpoint AM-GM pairs of positive terms (shares split evenly
    among the pairs a positive term is in), else None. Either way g > 0 on the open orthant."""
    positive = {e: v for e, v in g.items() if v > 0}
    negative = {e: -v for e, v in g.items() if v < 0}
    if not positive:
        return None
    if not negative:
        return "coefficients"
    pairs = {b: [] for b in negative}
    for b in negative:
        for a1 in positive:
            a2 = tuple(2 * x - y for x, y in zip(b, a1))
            if a2 in positive and a1 < a2:
                pairs[b].append((a1, a2))
    uses = {a: 0 for a in positive}
    for found in pairs.values():
        for a1, a2 in found:
            uses[a1] += 1
            uses[a2] += 1
    for b, need in negative.items():
        have = sum(2 * _sqrt_lower_bound(positive[a1] * positive[a2] / (uses[a1] * uses[a2])) for a1, a2 in pairs[b])
        if have < Fraction(int(QQ.numer(need)), int(QQ.denom(need))):
            return None
    return "amgm"


# --- (P3) vertex laws ----------------------------------------------------------------------


def _vertex_direction(b, others) -> np.ndarray | None:
    """An integer w with w.(b - a) >= 1 for every a in others, or None if b is not a vertex."""
    if not others:
        return None
    differences = np.array([np.subtract(b, a) for a in others], dtype=float)
    n = differences.shape[1]
    result = linprog(np.zeros(n), A_ub=-differences, b_ub=-np.ones(len(others)), bounds=[(-20, 20)] * n, method="highs")
    if result.status != 0:
        return None
    w = np.round(4 * result.x).astype(int)
    return w if (differences @ w >= 1).all() else None


def vertex_laws(lp, conditions, per_condition: int = 2, tries: int = 12) -> list[tuple[list, list]]:
    """Laws t^w on which a negative vertex coefficient of a condition dominates (P3); at most
    ``tries`` negative terms per condition, largest first."""
    laws = []
    for g in conditions:
        if g is None:
            continue
        negative = sorted((e for e, v in g.items() if v < 0), key=lambda e: g[e])[:tries]
        found = 0
        for b in negative:
            w = _vertex_direction(b, [a for a in g if a != b])
            if w is None:
                continue
            for t in (2, 4, 16, 256, 2**16):
                point = [QQ(t) ** int(x) if x >= 0 else QQ(1, t ** int(-x)) for x in w]
                if g(*point) < 0:
                    laws.append((point[: lp.k], point[lp.k :]))
                    found += 1
                    break
            if found >= per_condition:
                break
    return laws


# --- (P5) Positivstellensatz linear program -------------------------------------------------


def _multipliers(gens, degree: int) -> list:
    one = gens[0].ring(1)
    found = [one]
    for r in range(1, degree + 1):
        found += [np.prod(m) for m in itertools.combinations_with_replacement(gens, r)]
    return found


def positivstellensatz_certificate(lp, conditions, degree: int | None = None) -> str | None:
    """(P5): monomial multipliers s_i >= 0 with every coefficient of sum s_i g_i <= 0, checked exactly."""
    known = [g for g in conditions if g is not None]
    if degree is None:
        degree = 2 if lp.k <= 3 else 1
    gens = list(lp.c) + list(lp.d)
    columns = [(g, mu) for g in known for mu in _multipliers(gens, degree)]
    products = [g * mu for g, mu in columns]
    monomials = sorted({e for q in products for e in q})
    row = {e: i for i, e in enumerate(monomials)}
    matrix = np.zeros((len(monomials), len(products)))
    for j, q in enumerate(products):
        for e, v in q.items():
            matrix[row[e], j] = float(v)
    scale = np.maximum(np.abs(matrix).max(axis=0), 1e-300)
    matrix /= scale  # columns of comparable size
    for margin in (1e-7, 1e-10, 0.0):  # a margin keeps the rounded multipliers on the right side
        statement = _solve_and_check(lp, matrix, scale, products, margin, degree)
        if statement:
            return statement
    return None


def _solve_and_check(lp, matrix, scale, products, margin, degree) -> str | None:
    result = linprog(
        matrix.sum(axis=0),
        A_ub=matrix,
        b_ub=-margin * np.ones(matrix.shape[0]),
        A_eq=np.ones((1, len(products))),
        b_eq=[1.0],
        bounds=(0, None),
        method="highs",
    )
    if result.status != 0:
        return None
    weights = [Fraction(x / s).limit_denominator(10**12) if x > 1e-12 else 0 for x, s in zip(result.x, scale)]
    total = lp.ring(0)
    used = 0
    for w, q in zip(weights, products):
        if w:
            total += q * QQ(w.numerator, w.denominator)
            used += 1
    if used == 0 or any(v > 0 for v in total.values()):
        return None
    return f"a combination of {used} Liénard–Chipart conditions times monomials of degree <= {degree} has every coefficient <= 0"
