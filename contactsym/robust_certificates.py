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
from functools import cache
from math import isqrt

import numpy as np
import sympy as sp
from scipy.optimize import linprog
from scipy.spatial import ConvexHull, QhullError
from sympy.polys.domains import QQ, ZZ
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError
from sympy.polys.rings import ring

from .law_polynomials import _evaluate_terms, _generic_conditions

__all__ = [
    "amgm_certificate",
    "generic_vertex_coefficients",
    "positivstellensatz_certificate",
    "rational_law",
    "vertex_laws",
]


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


@cache
def generic_vertex_coefficients(k: int) -> tuple[tuple[tuple[int, ...], sp.Expr], ...]:
    """(subset S, coefficient) pairs: the coefficients, as polynomials in symbols m_S for the
    principal minors det(A_S), at the vertices of the Newton polytopes of the Hurwitz minors
    among the Liénard–Chipart conditions of the generic A (P3). A negative value at some A gives an
    unstable law: the vertex of the generic support is a vertex of any support inside it."""
    subsets = [S for r in range(1, k + 1) for S in itertools.combinations(range(k), r)]
    m = {S: sp.Symbol("m_" + "_".join(str(j + 1) for j in S)) for S in subsets}
    names = [f"c{j}" for j in range(1, k + 1)] + [f"d{j}" for j in range(1, k + 1)]
    R, *gens = ring(",".join(names), ZZ[tuple(m.values())])
    c, d = gens[:k], gens[k:]
    p = [R(0)] * (2 * k + 1)
    p[2 * k] = R(1)
    for S in subsets:
        for size in range(len(S) + 1):
            for T in itertools.combinations(S, size):
                term = R(R.domain.convert(m[S]))
                for j in S:
                    term *= d[j] if j in T else c[j]
                p[2 * k - 2 * len(S) + size] += term
    labels, conditions = _generic_conditions(k)
    found = []
    for (kind, _), terms in zip(labels, conditions):
        if kind != "Delta":
            continue
        g = _evaluate_terms(terms, p[::-1][1:], R(1))
        for b in _vertices(list(g)):
            found.append((b, R.domain.to_sympy(g[b])))
    return tuple(found)


def _vertices(points: list) -> list:
    """The vertices of the convex hull of integer points: qhull in their affine hull, each
    vertex then confirmed by an exact integer direction (P3)."""
    X = np.array(points, dtype=float)
    centred = X - X.mean(axis=0)
    _, singular, basis = np.linalg.svd(centred, full_matrices=False)
    rank = int((singular > 1e-9 * max(1.0, singular.max())).sum())
    try:
        candidates = ConvexHull(centred @ basis[:rank].T).vertices if rank >= 2 else range(len(points))
    except QhullError:
        candidates = range(len(points))
    return [
        points[i] for i in candidates if _vertex_direction(points[i], [a for a in points if a != points[i]]) is not None
    ]


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


def positivstellensatz_certificate(lp, conditions, degrees: tuple | None = None) -> str | None:
    """(P5): monomial multipliers s_i >= 0 with every coefficient of sum s_i g_i <= 0, checked exactly;
    multipliers of degree ``degrees[0]``, then ``degrees[1]``, ..."""
    for degree in degrees or ((2, 3) if lp.k <= 3 else (1, 2)):
        statement = _positivstellensatz(lp, conditions, degree)
        if statement:
            return statement
    return None


def _positivstellensatz(lp, conditions, degree: int) -> str | None:
    known = [g for g in conditions if g is not None]
    gens = list(lp.c) + list(lp.d)
    products = [g * mu for g in known for mu in _multipliers(gens, degree)]
    monomials = sorted({e for q in products for e in q})
    row = {e: i for i, e in enumerate(monomials)}
    matrix = np.zeros((len(monomials), len(products)))
    for j, q in enumerate(products):
        for e, v in q.items():
            matrix[row[e], j] = float(v)
    scale = np.maximum(np.abs(matrix).max(axis=0), 1e-300)
    matrix /= scale  # columns of comparable size
    for margin in (1e-7, 0.0):  # a margin keeps the rounded multipliers on the right side
        statement = _solve_and_check(lp, matrix, scale, products, monomials, margin, degree)
        if statement:
            return statement
    return None


def _exact_weights(matrix, scale, products, monomials, x) -> list | None:
    """Rational multipliers near the float solution x that keep its tight rows exactly at 0.

    The rows x makes (nearly) 0, and sum s = 1, form a linear system K s = r; the rounded x is
    projected onto it in rationals, s = x + K^T (K K^T)^-1 (r - K x), K reduced to independent
    rows. The caller re-checks every coefficient exactly."""
    support = [j for j, value in enumerate(x) if value > 1e-12]
    if not support:
        return None
    values = matrix[:, support] @ x[support]
    touched = np.abs(matrix[:, support]).max(axis=1) > 0
    tight = [monomials[i] for i in np.nonzero(touched & (np.abs(values) <= 1e-9))[0]]
    rows = [[products[j].get(e, QQ(0)) for j in support] for e in tight] + [[QQ(1)] * len(support)]
    _, independent = DomainMatrix(rows, (len(rows), len(support)), QQ).transpose().rref()
    K = DomainMatrix([rows[i] for i in independent], (len(independent), len(support)), QQ)
    target = DomainMatrix([[QQ(int(i == len(rows) - 1))] for i in independent], (len(independent), 1), QQ)
    rounded = [QQ.convert(Fraction(x[j] / scale[j]).limit_denominator(10**15)) for j in support]
    start = DomainMatrix([[w] for w in rounded], (len(support), 1), QQ)
    try:
        y = (K * K.transpose()).lu_solve(target - K * start)
    except (ValueError, ZeroDivisionError, DMNonInvertibleMatrixError):
        return None
    exact = (start + K.transpose() * y).to_Matrix()
    if any(w < 0 for w in exact):
        return None
    weights = [QQ(0)] * len(products)
    for position, j in enumerate(support):
        weights[j] = QQ.convert(exact[position])
    return weights


def _solve_and_check(lp, matrix, scale, products, monomials, margin, degree) -> str | None:
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
    weights = _exact_weights(matrix, scale, products, monomials, result.x)
    if weights is None:
        return None
    total = lp.ring(0)
    used = 0
    for w, q in zip(weights, products):
        if w:
            total += q * w
            used += 1
    if used == 0 or any(v > 0 for v in total.values()):
        return None
    return f"a combination of {used} Liénard–Chipart conditions times monomials of degree <= {degree} has every coefficient <= 0"
