"""Witness-law searches for :mod:`contactsym.robustness.classify`: laws (c, d) that make a statement
false, from nested sequences (P6), sampling, small damping (P7), hill climbing and the vertices of
Newton polytopes (P3).

A law is returned in exact rationals (:func:`rational_law`); :mod:`contactsym.robustness.classify`
confirms each one exactly before it is used.

Examples
--------
>>> c, d = rational_law([0.5, 2.0], [1/3, 5.0], digits=2)
>>> [str(x) for x in c], [str(x) for x in d]
(['1/2', '2'], ['33/100', '5'])
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from functools import cache

import numpy as np
import sympy as sp
from scipy.optimize import linprog, minimize
from scipy.spatial import ConvexHull, QhullError
from sympy.polys.domains import QQ, ZZ
from sympy.polys.rings import ring

from ..arguments import LARGEST, between, checked, require
from .law_polynomials import _evaluate_terms, _generic_conditions, fast_spectral_abscissa

__all__ = [
    "climbed_laws",
    "fisher_fuller_laws",
    "generic_vertex_coefficients",
    "rational_law",
    "sampled_laws",
    "vertex_laws",
    "weak_damping_laws",
]


@checked(c="RealArray", d="RealArray", digits=between(1, 17))
def rational_law(c, d, digits: int = 4) -> tuple[list, list]:
    """A float law rounded to ``digits`` significant decimal digits, as exact rationals.

    Examples
    --------
    >>> c, d = rational_law([0.123456, 2.0], [1/3, 5.0])
    >>> [str(x) for x in c], [str(x) for x in d]
    (['247/2000', '2'], ['3333/10000', '5'])
    """
    return [QQ.convert(Fraction(f"{x:.{digits}g}")) for x in c], [QQ.convert(Fraction(f"{x:.{digits}g}")) for x in d]


# --- witness searches (P6, P7, sampling) ---------------------------------------------


@checked(order="Sequence[int]", k=between(1, 16))
def fisher_fuller_laws(order, k) -> list[tuple[list, list]]:
    """(P6) laws (c, d) = (diag C, diag C), C = diag(delta^r) along the nested sequence ``order``.

    Examples
    --------
    For A = [[2, 1], [-1, 2]] both orders are nested sequences; the laws along (0, 1) are stable:

    >>> import sympy as sp
    >>> from contactsym.robustness import LawPolynomials, nested_sequences
    >>> lp = LawPolynomials(sp.Matrix([[2, 1], [-1, 2]]))
    >>> nested_sequences(lp.minors)
    [(0, 1), (1, 0)]
    >>> laws = fisher_fuller_laws((0, 1), 2)
    >>> [str(x) for x in laws[0][0]]
    ['1', '1/2']
    >>> all(v > 0 for c, d in laws for v in lp.values_at(c, d))
    True
    """
    require(sorted(order) == list(range(k)), "fisher_fuller_laws", "order", order, f"an ordering of 0..{k - 1}")
    laws = []
    for delta in (sp.Rational(1, 2), sp.Rational(1, 10), sp.Rational(1, 100), sp.Rational(1, 10**4)):
        c = [None] * k
        for r, j in enumerate(order):
            c[j] = delta**r
        laws.append((c, list(c)))
    return laws


@checked(count=between(0, 10**6), seed=between(0, LARGEST))
def sampled_laws(Af: np.ndarray, count: int, seed: int) -> tuple[list, list]:
    """(stable-looking, unstable-looking) rational laws from log-uniform samples, best first.

    Examples
    --------
    A law-dependent A: the best sampled laws of each kind, checked by the eigenvalues of (4.5):

    >>> A = np.array([[2.0, 1, 0], [-1, 2, 1], [0, -1, 2]])
    >>> stable, unstable = sampled_laws(A, 50, seed=0)
    >>> def abscissa(law):
    ...     c, d = (np.array([[float(x) for x in part]]) for part in law)
    ...     return float(fast_spectral_abscissa(A, c, d)[0])
    >>> abscissa(stable[0]) < 0 < abscissa(unstable[0])
    True
    """
    require(Af.ndim == 2 and Af.shape[0] == Af.shape[1], "sampled_laws", "Af", Af, "a square k x k array")
    k = Af.shape[0]
    rng = np.random.default_rng(seed)
    c = 10.0 ** rng.uniform(-3, 3, (count, k))
    d = 10.0 ** rng.uniform(-3, 3, (count, k))
    top = fast_spectral_abscissa(Af, c, d)
    order = np.argsort(top)
    stable = [rational_law(c[i], d[i]) for i in order[:8] if top[i] < 0]
    unstable = [rational_law(c[i], d[i]) for i in order[::-1][:8] if top[i] > 0]
    return stable, unstable


def _normalized(c: np.ndarray, d: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(c / t^2, d / t) with t = max(sqrt(c), d) per law: (c, d) -> (t^2 c, t d) scales every
    eigenvalue of (4.5) by t, so this keeps stability and makes abscissae comparable."""
    t = np.maximum(np.sqrt(c).max(axis=1), d.max(axis=1))[:, None]
    return c / t**2, d / t


@checked(seed=between(0, LARGEST), count=between(0, 10**6))
def weak_damping_laws(Af: np.ndarray, seed: int, count: int = 400) -> list:
    """Unstable laws with small damping. Left-multiplying lam^2 x + (lam D + C) A x = 0 by the left
    eigenvector y of CA (CA x = mu x) gives lam^2 + mu s lam + mu = 0 to first order in D, with
    s = sum_j (d_j / c_j) y_j x_j / (y.x): a non-real mu, or a real mu > 0 with some
    y_j x_j / (y.x) < 0 (then d concentrated on j makes s < 0), has Re lam > 0 for small D.

    Examples
    --------
    >>> A = np.array([[2.0, 1, 0], [-1, 2, 1], [0, -1, 2]])
    >>> c, d = weak_damping_laws(A, seed=0, count=50)[0]
    >>> [str(x) for x in d]  # small damping
    ['1/10000', '1/10000', '1/10000']
    >>> float(fast_spectral_abscissa(A, np.array([[float(x) for x in c]]), np.array([[float(x) for x in d]]))[0]) > 0
    True
    """
    require(Af.ndim == 2 and Af.shape[0] == Af.shape[1], "weak_damping_laws", "Af", Af, "a square k x k array")
    k = Af.shape[0]
    rng = np.random.default_rng(seed + 2)
    stiffness = np.vstack([np.ones(k), 10.0 ** rng.uniform(-3, 3, (count, k))])
    mu, X = np.linalg.eig(stiffness[:, :, None] * Af[None])
    laws = []
    for c, values, vectors in zip(stiffness, mu, X):
        if np.abs(values.imag).max() > 1e-6 * np.abs(values).max():
            laws.append(rational_law(c, 1e-4 * c))
        elif abs(np.linalg.det(vectors)) > 1e-12:
            weights = (np.linalg.inv(vectors).T * vectors).real  # column i: y_i x_i with y_i . x_i = 1
            i, j = np.unravel_index(np.argmin(weights.T), weights.T.shape)
            if weights[j, i] < -1e-9:
                d = 1e-6 * abs(weights[j, i]) * c
                d[j] = 1e-3 * c[j]
                laws.append(rational_law(c, d))
        if len(laws) >= 8:
            break
    return laws


@checked(seed=between(0, LARGEST), starts=between(1, 1000))
def climbed_laws(Af: np.ndarray, sign: float, seed: int, starts: int = 3) -> list:
    """Rational laws found by Nelder-Mead on log(c, d) maximising sign * (normalized abscissa), from
    the best of wide log-uniform samples (1e-6..1e6): the rare unstable (stable) laws sampling misses.

    Examples
    --------
    ``sign = 1`` climbs towards instability:

    >>> A = np.array([[2.0, 1, 0], [-1, 2, 1], [0, -1, 2]])
    >>> c, d = climbed_laws(A, 1.0, seed=0, starts=1)[0]
    >>> float(fast_spectral_abscissa(A, np.array([[float(x) for x in c]]), np.array([[float(x) for x in d]]))[0]) > 0
    True
    """
    require(Af.ndim == 2 and Af.shape[0] == Af.shape[1], "climbed_laws", "Af", Af, "a square k x k array")
    k = Af.shape[0]
    rng = np.random.default_rng(seed + 1)
    x = rng.uniform(-6, 6, (4000, 2 * k))

    def abscissa(y):
        return fast_spectral_abscissa(Af, *_normalized(10.0 ** y[:, :k], 10.0 ** y[:, k:]))

    top = sign * abscissa(x)
    found = []
    for start in x[np.argsort(-top)[:starts]]:
        best = minimize(
            lambda y: -sign * abscissa(np.clip(y, -8, 8)[None])[0],
            start,
            method="Nelder-Mead",
            options={"maxfev": 300, "xatol": 1e-3},
        )
        if -best.fun > 0:
            c, d = _normalized(10.0 ** np.clip(best.x[None, :k], -8, 8), 10.0 ** np.clip(best.x[None, k:], -8, 8))
            found.append(rational_law(c[0], d[0]))
    return found


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


@checked(k=between(1, 8))
@cache
def generic_vertex_coefficients(k: int) -> tuple[tuple[tuple[int, ...], sp.Expr], ...]:
    """(subset S, coefficient) pairs: the coefficients, as polynomials in symbols m_S for the
    principal minors det(A_S), at the vertices of the Newton polytopes of the Hurwitz minors
    among the Liénard–Chipart conditions of the generic A (P3). A negative value at some A gives an
    unstable law: the vertex of the generic support is a vertex of any support inside it.

    Examples
    --------
    >>> pairs = generic_vertex_coefficients(2)
    >>> len(pairs), pairs[0][1]
    (8, m_1**2*m_1_2)
    """
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


@checked(lp="LawPolynomials", conditions="Sequence", per_condition=between(1, 1000), tries=between(1, 10**4))
def vertex_laws(lp, conditions, per_condition: int = 2, tries: int = 12) -> list[tuple[list, list]]:
    """Laws t^w on which a negative vertex coefficient of a condition dominates (P3); at most
    ``tries`` negative terms per condition, largest first.

    Examples
    --------
    Each law makes some Liénard–Chipart condition negative, exactly:

    >>> import sympy as sp
    >>> from contactsym.robustness import LawPolynomials
    >>> lp = LawPolynomials(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]))
    >>> laws = vertex_laws(lp, lp.conditions())
    >>> len(laws) > 0, all(min(lp.values_at(c, d)) < 0 for c, d in laws)
    (True, True)
    """
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
