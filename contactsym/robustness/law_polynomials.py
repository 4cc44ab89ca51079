"""The Liénard–Chipart conditions of (4.5) as exact polynomials in the law, for a numeric A.

With c_j = -Phi_j > 0 and d_j = -Psi_j > 0 the characteristic polynomial (4.6) is

    p(lam) = sum_S lam^(2k - 2|S|) det(A_S) prod_{j in S} (lam d_j + c_j),

so its coefficient p_s is multilinear in (c, d): the monomial d^T c^(S \\ T) (T a subset
of S) has the coefficient det(A_S) in p_(2k - 2|S| + ``|T|``). The Hurwitz minors of
:mod:`contactsym.algebra.hurwitz` (generic, fraction-free) turn these into the minors as
polynomials in (c, d) with rational coefficients. Everything here is exact (``QQ``);
:mod:`contactsym.robustness.classify` reads certificates and witness laws off these polynomials.

Examples
--------
>>> import sympy as sp
>>> lp = LawPolynomials(sp.Matrix([[1, 1], [-1, 1]]))
>>> lp.labels
[('p', 3), ('p', 2), ('p', 1), ('p', 0), ('Delta', 3)]
>>> lp.conditions()[0]
d1 + d2
"""

from __future__ import annotations

import itertools
from fractions import Fraction
from functools import cache, cached_property

import numpy as np
import sympy as sp
from sympy.polys.domains import QQ
from sympy.polys.rings import PolyElement, ring

from ..algebra.hurwitz import Hurwitz
from ..arguments import between, checked

__all__ = ["LawPolynomials", "law_ring", "fast_spectral_abscissa"]

#: Above this many contacts the top Hurwitz minor is not expanded (k = 4 gives 42,388 terms).
EXPAND_UP_TO_K = 3


@checked(k=between(1, 8))
@cache
def law_ring(k: int):
    """QQ[c1..ck, d1..dk] and its generators.

    Examples
    --------
    >>> R, gens = law_ring(2)
    >>> gens
    [c1, c2, d1, d2]
    """
    names = [f"c{j}" for j in range(1, k + 1)] + [f"d{j}" for j in range(1, k + 1)]
    R, *gens = ring(",".join(names), QQ)
    return R, gens


@cache
def _generic_conditions(k: int) -> tuple[list, list]:
    """(labels, conditions as term lists in a_1..a_2k) for lam^2k + a_1 lam^(2k-1) + ... + a_2k."""
    n = 2 * k
    a = sp.symbols(f"a_1:{n + 1}")
    lam = sp.Symbol("lambda")
    hurwitz = Hurwitz(sp.Poly(lam**n + sum(a[i - 1] * lam ** (n - i) for i in range(1, n + 1)), lam))
    terms = [sp.Poly(condition, *a).terms() for condition in hurwitz.conditions]
    return hurwitz.labels, terms


def _evaluate_terms(terms, values, one):
    """sum of integer * prod values[i]**e over the terms (values: p_(2k-1), ..., p_0)."""
    total = one * 0
    for exponents, coefficient in terms:
        term = one * int(coefficient)
        for value, e in zip(values, exponents):
            if e:
                term = term * value**e
        total = total + term
    return total


def _exact(x) -> sp.Expr:
    """A rational entry: floats at their exact binary value, other real numbers at their float value."""
    if isinstance(x, (float, np.floating)):
        return sp.Rational(float(x))
    x = sp.sympify(x)
    if x.is_Rational or x.free_symbols:
        return x
    return sp.Rational(float(x))


def _evaluate_poly(q: PolyElement, point: list):
    """q at a rational point (faster than ring evaluation for small polynomials)."""
    total = QQ(0)
    for exponents, coefficient in q.items():
        term = coefficient
        for x, e in zip(point, exponents):
            if e:
                term *= x**e
        total += term
    return total


def _rational_matrix(A) -> sp.Matrix:
    A = np.asarray(A, dtype=object) if isinstance(A, np.ndarray) else A
    return sp.Matrix(A).applyfunc(_exact)


@checked
def fast_spectral_abscissa(A: np.ndarray, c: np.ndarray, d: np.ndarray) -> np.ndarray:
    """max Re eig of (4.5) ``[[Psi A, Phi], [A, 0]]`` with Phi = -c, Psi = -d, for many laws at once.

    Examples
    --------
    >>> float(fast_spectral_abscissa(np.eye(1), np.ones((1, 1)), np.ones((1, 1)))[0]) < 0
    True
    """
    A = np.asarray(A, dtype=float)
    c, d = np.atleast_2d(c), np.atleast_2d(d)
    k = A.shape[0]
    M = np.zeros((c.shape[0], 2 * k, 2 * k))
    M[:, :k, :k] = -d[:, :, None] * A[None, :, :]
    M[:, k:, :k] = A
    M[:, np.arange(k), k + np.arange(k)] = -c
    return np.linalg.eigvals(M).real.max(axis=1)


@checked(A="sp.Matrix")
class LawPolynomials:
    """Exact Liénard–Chipart conditions of (4.5) as polynomials in the law (c, d), for numeric A.

    Parameters
    ----------
    A : matrix of numbers
        Floats are taken at their exact binary value.

    Examples
    --------
    One contact, A = [[a]]: (4.5) is lambda^2 + a d lambda + a c = 0, stable for every law when a > 0:

    >>> import sympy as sp
    >>> lp = LawPolynomials(sp.Matrix([[3]]))
    >>> lp.labels
    [('p', 1), ('p', 0)]
    >>> [str(v) for v in lp.values_at([2], [5])]  # a d, a c at c = 2, d = 5
    ['15', '6']
    """

    def __init__(self, A):
        self.A = _rational_matrix(A)
        if not all(x.is_Rational for x in self.A):
            raise TypeError("LawPolynomials needs a numeric A")
        self.k = self.A.rows
        self.ring, gens = law_ring(self.k)
        self.c, self.d = gens[: self.k], gens[self.k :]
        self._minors: dict[int, PolyElement] = {}

    @cached_property
    def minors(self) -> dict[tuple[int, ...], Fraction]:
        """det(A_S) for every nonempty S (indices from 0)."""
        k = self.k
        subsets = [S for r in range(1, k + 1) for S in itertools.combinations(range(k), r)]
        return {S: QQ.convert(self.A.extract(list(S), list(S)).det(method="bareiss")) for S in subsets}

    @cached_property
    def p(self) -> list[PolyElement]:
        """p_0, ..., p_2k of (4.6) in (c, d); p_2k = 1."""
        k, R = self.k, self.ring
        p = [R(0)] * (2 * k + 1)
        p[2 * k] = R(1)
        for S, minor in self.minors.items():
            for size in range(len(S) + 1):
                for T in itertools.combinations(S, size):
                    monomial = R(minor)
                    for j in S:
                        monomial *= self.d[j] if j in T else self.c[j]
                    p[2 * k - 2 * len(S) + size] += monomial
        return p

    @cached_property
    def labels(self) -> list[tuple[str, int]]:
        return list(_generic_conditions(self.k)[0])

    def conditions(self, expand_minors: bool | None = None) -> list[PolyElement | None]:
        """The Liénard–Chipart conditions in the order of :attr:`labels`; a Hurwitz minor is None
        when not expanded (by default only for k <= EXPAND_UP_TO_K)."""
        if expand_minors is None:
            expand_minors = self.k <= EXPAND_UP_TO_K
        return [self._condition(i) if expand_minors or kind == "p" else None for i, (kind, _) in enumerate(self.labels)]

    def _condition(self, index: int) -> PolyElement:
        kind, order = self.labels[index]
        if kind == "p":
            return self.p[order]
        if index not in self._minors:  # expanded once per object (k = 3: ~0.1 s)
            terms = _generic_conditions(self.k)[1][index]
            self._minors[index] = _evaluate_terms(terms, self.p[::-1][1:], self.ring(1))
        return self._minors[index]

    def values_at(self, c, d) -> list[Fraction]:
        """Exact values of the conditions at the rational law (c, d)."""
        point = [QQ.convert(x) for x in list(c) + list(d)]
        p = [_evaluate_poly(q, point) for q in self.p]
        terms = _generic_conditions(self.k)[1]
        return [_evaluate_terms(t, p[::-1][1:], QQ(1)) for t in terms]
