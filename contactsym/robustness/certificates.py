"""Certificates for :mod:`contactsym.robustness.classify` (proofs P4, P5 and P8 there): AM-GM and
Positivstellensatz linear programs. The witness-law searches are in :mod:`contactsym.robustness.witnesses`
(their names are imported here too).

Polynomials are ``QQ[c1..ck, d1..dk]`` ring elements from
:class:`contactsym.robustness.law_polynomials.LawPolynomials`; every certificate found in floating
point (a linear program) is re-checked in rationals before it is returned.

Examples
--------
>>> from contactsym.robustness.law_polynomials import law_ring
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
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from ..arguments import between, checked
from .witnesses import (
    climbed_laws,
    fisher_fuller_laws,
    generic_vertex_coefficients,
    rational_law,
    sampled_laws,
    vertex_laws,
    weak_damping_laws,
)

__all__ = [
    "amgm_certificate",
    "climbed_laws",
    "fisher_fuller_laws",
    "sampled_laws",
    "weak_damping_laws",
    "generic_vertex_coefficients",
    "positivstellensatz_certificate",
    "damped_positivstellensatz_certificate",
    "rational_law",
    "vertex_laws",
]


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


@checked(g="PolyElement")
def amgm_certificate(g) -> str | None:
    """``"coefficients"`` if g has nonnegative coefficients (one positive), ``"amgm"`` if each
    negative term is absorbed by midpoint AM-GM pairs of positive terms (shares split evenly
    among the pairs a positive term is in), else None. Either way g > 0 on the open orthant.

    Examples
    --------
    >>> from contactsym.robustness import law_ring
    >>> R, (c1, c2, d1, d2) = law_ring(2)
    >>> amgm_certificate(c1*d2 + 2*c2), amgm_certificate(c1**2 - c1*c2 + c2**2)
    ('coefficients', 'amgm')
    >>> amgm_certificate(c1**2 - 3*c1*c2 + c2**2) is None  # negative at c1 = c2
    True
    """
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


# --- (P5) Positivstellensatz linear program -------------------------------------------------


def _multipliers(gens, degree: int) -> list:
    one = gens[0].ring(1)
    found = [one]
    for r in range(1, degree + 1):
        found += [np.prod(m) for m in itertools.combinations_with_replacement(gens, r)]
    return found


@checked(lp="LawPolynomials", conditions="Sequence")
def positivstellensatz_certificate(lp, conditions, degrees: tuple | None = None) -> str | None:
    """(P5): monomial multipliers s_i >= 0 with every coefficient of sum s_i g_i <= 0, checked exactly;
    multipliers of degree ``degrees[0]``, then ``degrees[1]``, ...

    Examples
    --------
    An A with det A > 0 but no nested sequence, unstable for every law:

    >>> import sympy as sp
    >>> from contactsym.robustness import LawPolynomials
    >>> lp = LawPolynomials(sp.Matrix([[13, -17, -13], [-11, -13, 12], [15, 3, -19]]) / 10)
    >>> p = [g for (kind, _), g in zip(lp.labels, lp.conditions()) if kind == "p"]
    >>> print(positivstellensatz_certificate(lp, p))
    a combination of 6 Liénard–Chipart conditions times monomials of degree <= 2 has every coefficient <= 0
    >>> stable = LawPolynomials(sp.eye(2))  # stable for every law: no certificate of the contrary
    >>> positivstellensatz_certificate(stable, stable.p) is None
    True
    """
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


@checked(lp="LawPolynomials", conditions="Sequence", degree=between(0, 12))
def damped_positivstellensatz_certificate(lp, conditions, degree: int = 4) -> str | None:
    """(P8): P5 on the other conditions after d_i = u + sum_(j != i) (-a_jj / a_ii) d_j, when a_ii > 0 is the
    only positive diagonal entry: u > 0 exactly when p_(2k-1) = sum a_jj d_j > 0 (u reuses the generator d_i).

    Examples
    --------
    It applies only when exactly one diagonal entry of A is positive (a search where it applies takes
    seconds: ``decide`` runs it last):

    >>> import sympy as sp
    >>> from contactsym.robustness import LawPolynomials
    >>> lp = LawPolynomials(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]))
    >>> damped_positivstellensatz_certificate(lp, lp.conditions()) is None
    True
    """
    diagonal = [lp.minors[(j,)] for j in range(lp.k)]
    positive = [j for j, a in enumerate(diagonal) if a > 0]
    if len(positive) != 1:
        return None
    i = positive[0]
    d_i = lp.d[i] + sum((-diagonal[j] / diagonal[i]) * lp.d[j] for j in range(lp.k) if j != i)
    substituted = [g.compose(lp.d[i], d_i) for g in conditions if g is not None]
    statement = positivstellensatz_certificate(lp, substituted, degrees=(degree,))
    if statement is None:
        return None
    return f"with d_{i + 1} = u + sum_j (-a_jj / a_{i + 1}{i + 1}) d_j (u > 0 exactly when p_{2 * lp.k - 1} > 0): {statement}"
