"""The principal minors of A in a polynomial ring, exact and without rational-function arithmetic.

Two ways: from A = P / D itself (:class:`MinorsInRing`: the minors of P over D^|S|), or, for a
scene in contact space, from its factors A = W^T M^-1 V (:class:`FactoredMinors`: by the Schur
complement each minor is one polynomial over det M). Used by :mod:`contactsym.stages.linear`.
The same bordered determinants give the entries' numerators W_i^T adj(M) V_j, hence the positive
multiple |det M| A (:func:`positive_multiple`) whose signs the propositions of
:mod:`contactsym.stages.classification` read without a division.
"""

from __future__ import annotations

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..algebra.canonical_form import TrigField
from ..algebra.fraction_free import adjugate_and_det_in_field
from ..arguments import require

__all__ = [
    "MinorsInRing",
    "FactoredMinors",
    "entry_numerators",
    "equality_matrix",
    "minors_of",
    "polynomial_factors",
    "positive_multiple",
    "product_of",
]


class MinorsInRing:
    """A = P / D in the polynomial ring of a :class:`TrigField` (P polynomial, D the common
    denominator), with the minors det(P_(R, C)) by Laplace expansion, memoized and reduced
    (s^2 = 1, sin^2 + cos^2 = 1) after every product: exact, no rational-function arithmetic.

    Examples
    --------
    >>> a, b = sp.symbols("a b")
    >>> minors = MinorsInRing(sp.Matrix([[a, 1 / b], [1, b]]))
    >>> minors.field.present(minors.minor((0, 1)))
    a*b - 1/b
    """

    def __init__(self, A: sp.Matrix, extra=()):
        self.field = TrigField([*A, *extra])
        ring = self.field.ring
        entries = [[self.field.element(x) for x in row] for row in A.tolist()]
        self.denominator = ring.one
        for row in entries:
            for x in row:
                self.denominator = self.denominator.lcm(x.denom) if not x.denom.is_ground else self.denominator
        scale = ring.domain.one
        for row in entries:
            for x in row:
                if x.denom.is_ground:
                    scale = ring.domain.lcm(scale, ring.domain.convert(x.denom.LC))
        self.denominator = self.denominator * scale
        self.P = [[x.numer * self.denominator.exquo(x.denom) for x in row] for row in entries]
        self._cache: dict = {}

    def det(self, rows: tuple, cols: tuple):
        """det P restricted to ``rows`` and ``cols`` (equal lengths), a reduced ring element."""
        if not rows:
            return self.field.ring.one
        key = (rows, cols)
        if key not in self._cache:
            total = self.field.ring.zero
            for i, c in enumerate(cols):
                entry = self.P[rows[0]][c]
                if entry:
                    term = entry * self.det(rows[1:], cols[:i] + cols[i + 1 :])
                    total = total + term if i % 2 == 0 else total - term
            self._cache[key] = self.field.reduce_poly(total)
        return self._cache[key]

    def minor(self, S: tuple):
        """det(A_S) as a reduced field element."""
        # raw: reduce cancels, proving the gcd 1 first where it can (field.new would compute it)
        return self.field.reduce(self.field.field.raw_new(self.numerator(S), self.denominator ** self.power(S)))

    def numerator(self, S: tuple):
        """det(A_S) = numerator(S) / denominator^power(S)."""
        return self.det(S, S)

    def power(self, S: tuple) -> int:
        return len(S)

    #: The largest power of the denominator a principal minor has.
    @property
    def top_power(self) -> int:
        return len(self.P)

    @property
    def size(self) -> int:
        """k, for the k x k matrix whose minors these are."""
        return len(self.P)

    def extended(self, extra) -> MinorsInRing | None:
        """These minors in a field that also has the generators of ``extra`` (the law's values and
        lambda, for (4.6)): the same polynomials moved to the larger ring, not expanded again; None
        where the larger field would write these generators otherwise (then :func:`minors_of` anew).

        Examples
        --------
        >>> a, b, lam = sp.symbols("a b lambda")
        >>> minors = minors_of(sp.Matrix([[a, 1], [1, b]]))
        >>> wider = minors.extended([lam])
        >>> wider.numerator((0, 1)).as_expr(), lam in wider.field.ring.symbols
        (a*b - 1, True)
        """
        old = self.field.ring.symbols
        field = TrigField([*old, *extra])
        index = {g: i for i, g in enumerate(field.ring.symbols)}
        if any(g not in index for g in old):
            return None
        pairs = {(index[old[c]], index[old[s]]) for c, s in self.field.pairs}
        if not pairs <= set(field.pairs) or not {index[old[i]] for i in self.field.signs} <= set(field.signs):
            return None
        return _Extended(self, field)


class _Extended(MinorsInRing):
    """:meth:`MinorsInRing.extended`: the numerators of ``minors`` read in the ring of ``field``."""

    def __init__(self, minors: MinorsInRing, field: TrigField):
        self.field, self._minors = field, minors
        self.denominator = minors.denominator.set_ring(field.ring)

    def numerator(self, S: tuple):
        return self._minors.numerator(S).set_ring(self.field.ring)

    def power(self, S: tuple) -> int:
        return self._minors.power(S)

    @property
    def top_power(self) -> int:
        return self._minors.top_power

    @property
    def size(self) -> int:
        return self._minors.size


class FactoredMinors(MinorsInRing):
    """A = W^T M^-1 V with polynomial M (n x n), W, V (n x k), as a Lagrangian scene's contact
    space gives it. By the Schur complement, det(A_S) = (-1)^|S| det([[M, V_S], [W_S^T, 0]]) / det M:
    every principal minor is one polynomial over det M (not over D^|S| for the lcm D of A's
    denominators, whose cancellation would need a large gcd). The bordered determinants are
    expanded along the rows of W_S^T and then of M, their sub-determinants memoized and shared
    between the subsets S (a column of V is the same for every S that holds it).

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> M, W, V = sp.Matrix([[2, 1], [1, 1]]), sp.eye(2), sp.Matrix([[a, 0], [0, 1]])
    >>> minors = FactoredMinors(M, W, V)
    >>> minors.denominator.as_expr(), minors.numerator((0, 1)).as_expr()  # det M, det M det(A)
    (1, a)
    >>> minors.field.present(minors.minor((0, 1))) == (W.T * M.inv() * V).det()
    True
    """

    def __init__(self, M: sp.Matrix, W: sp.Matrix, V: sp.Matrix, extra=()):
        self.field = TrigField([*M, *W, *V, *extra])
        self.n, self.k = M.rows, W.cols
        self.M, self.W, self.V = (self._polynomials(X) for X in (M, W, V))
        self._cache, self._m_cache = {}, {}
        self.denominator = self._m_det(0, tuple(range(self.n)))

    def _polynomials(self, X: sp.Matrix) -> list[list]:
        rows = _polynomial_rows(self.field, X)
        if rows is None:
            raise ValueError("a factor of A with a polynomial denominator")
        return rows

    def _entry(self, row: int, column: int):
        """Row ``row`` of [M | V] at ``column`` (< n: a column of M; n + j: the column of V of contact j)."""
        return self.M[row][column] if column < self.n else self.V[row][column - self.n]

    def _m_det(self, level: int, columns: tuple):
        """det of the rows level.. of [M | V] on ``columns`` (as many as rows are left)."""
        if level == self.n:
            return self.field.ring.one
        key = (level, columns)
        if key not in self._m_cache:
            total = self.field.ring.zero
            for i, c in enumerate(columns):
                entry = self._entry(level, c)
                if entry:
                    term = entry * self._m_det(level + 1, columns[:i] + columns[i + 1 :])
                    total = total + term if i % 2 == 0 else total - term
            self._m_cache[key] = self.field.reduce_poly(total)
        return self._m_cache[key]

    def _bordered(self, S: tuple, level: int, columns: tuple):
        """det of [[W_S^T, 0], [M, V_C]] from the W-row ``level`` on, on ``columns`` (those of M and of
        the V_j, j in C, as ``columns`` names them: C = S for a principal minor)."""
        if level == len(S):
            return self._m_det(0, columns)
        key = (S, level, columns)
        if key not in self._cache:
            total = self.field.ring.zero
            for i, c in enumerate(columns):
                entry = self.W[c][S[level]] if c < self.n else None
                if entry:
                    term = entry * self._bordered(S, level + 1, columns[:i] + columns[i + 1 :])
                    total = total + term if i % 2 == 0 else total - term
            self._cache[key] = self.field.reduce_poly(total)
        return self._cache[key]

    def numerator(self, S: tuple):
        if not S:
            return self.field.ring.one
        # [[M, V_S], [W_S^T, 0]] is [[W_S^T, 0], [M, V_S]] with its p rows moved past n: (-1)^(n p)
        value = self._bordered(S, 0, tuple(range(self.n)) + tuple(self.n + j for j in S))
        return value if (len(S) + self.n * len(S)) % 2 == 0 else -value

    def entry_numerator(self, i: int, j: int):
        """a_ij det M = W_i^T adj(M) V_j = -det([[M, V_j], [W_i^T, 0]]) (the Schur complement, as for
        :meth:`numerator` with S = (i,) when i = j): a polynomial, the bordered determinant's
        sub-determinants shared with the principal minors."""
        value = self._bordered((i,), 0, tuple(range(self.n)) + (self.n + j,))
        return value if self.n % 2 else -value

    def power(self, S: tuple) -> int:
        return 1 if S else 0

    @property
    def top_power(self) -> int:
        return 1

    @property
    def size(self) -> int:
        return self.k

    def det(self, rows: tuple, cols: tuple):  # pragma: no cover - the factored form has no P
        raise NotImplementedError("the factored minors give numerator(S) over det M")


def product_of(M: sp.Matrix, W: sp.Matrix, V: sp.Matrix) -> sp.Matrix | None:
    """W^T M^-1 V in the canonical form, as W^T adj(M) V / det M in one polynomial ring (each entry
    cancelled once), or None when a factor is not polynomial.

    Examples
    --------
    >>> q, m = sp.symbols("q m", positive=True)
    >>> M, W = sp.Matrix([[m, 0], [0, m]]), sp.Matrix([sp.cos(q), sp.sin(q)])
    >>> product_of(M, W, W)
    Matrix([[1/m]])
    """
    field = TrigField([*M, *W, *V])
    adj, det = adjugate_and_det_in_field(field, M)
    parts = [*[x for row in adj for x in row], det]
    left, right = (_polynomial_rows(field, X.T) for X in (W, V))
    if left is None or right is None or any(not x.denom.is_ground for x in parts):
        return None
    adj = [[x.numer.quo_ground(x.denom.LC) for x in row] for row in adj]
    det = det.numer.quo_ground(det.denom.LC)
    n = M.rows
    adj_v = [
        [field.reduce_poly(sum((adj[r][c] * v[c] for c in range(n)), field.ring.zero)) for r in range(n)] for v in right
    ]

    def entry(i, j):
        numerator = field.reduce_poly(sum((left[i][r] * adj_v[j][r] for r in range(n)), field.ring.zero))
        return normalize(field.present(field.field.raw_new(numerator, det)))  # present cancels (coprime first)

    return sp.Matrix(W.cols, V.cols, entry)


def polynomial_factors(factors) -> bool:
    """True when ``factors`` = (M, W, V) are polynomial, so that :func:`minors_of` takes every minor of
    A = W^T M^-1 V from them (:class:`FactoredMinors`) and reads of A its shape only.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> polynomial_factors((sp.eye(1), sp.eye(1), sp.Matrix([[a]]))), polynomial_factors((sp.eye(1), sp.eye(1), sp.Matrix([[1 / a]])))
    (True, False)
    """
    if factors is None:
        return False
    field = TrigField([x for X in factors for x in X])
    return all(_polynomial_rows(field, X) is not None for X in factors)


def entry_numerators(factors, minors: MinorsInRing | None = None) -> tuple[list[list], FactoredMinors] | None:
    """The numerators N_ij = W_i^T adj(M) V_j = a_ij det M of A = W^T M^-1 V, as reduced ring elements
    read off the bordered determinants of :class:`FactoredMinors` (no division, no gcd), with those
    minors; None where a factor is not polynomial. ``minors``: the factors' :class:`FactoredMinors`
    when the caller has them (a linearization's), so that det M and its minors are not expanded again.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> M, W, V = sp.Matrix([[2, 0], [0, 3]]), sp.eye(2), sp.Matrix([[a, 1], [0, 1]])
    >>> numerators, minors = entry_numerators((M, W, V))
    >>> [[minors.field.present(minors.field.field.new(x)) for x in row] for row in numerators]
    [[3*a, 3], [0, 2]]
    """
    if minors is not None:
        fits = isinstance(minors, FactoredMinors) and (minors.n, minors.k) == (factors[0].rows, factors[1].cols)
        require(fits, "entry_numerators", "minors", minors, "the FactoredMinors of these factors, or None")
    else:
        try:
            minors = FactoredMinors(*factors)
        except ValueError:
            return None
    return [[minors.entry_numerator(i, j) for j in range(minors.k)] for i in range(minors.k)], minors


def _is_number_matrix(numerators, det) -> bool:
    """a_ij = N_ij / det M is a number c exactly when N_ij = c det M (both reduced: the normal form is unique)."""
    return all(x * det.LC == det * x.LC for row in numerators for x in row)


def positive_multiple(factors, positive=(), minors: MinorsInRing | None = None) -> tuple[sp.Matrix, int, bool] | None:
    """(|det M| A, the most terms of an entry's numerator, whether A is a number matrix) for A = W^T M^-1 V with polynomial factors
    ``factors`` = (M, W, V): the entries sign(det M) W_i^T adj(M) V_j (:func:`entry_numerators`). None where a factor is not
    polynomial or the sign of det M is not proved (``positive``: expressions known to be positive,
    as :func:`contactsym.algebra.basic.known_sign` takes them; det M of a mass matrix is listed by its scene).

    Examples
    --------
    >>> a = sp.Symbol("a", real=True)
    >>> m = sp.Symbol("m", positive=True)
    >>> M, W, V = sp.Matrix([[m, 0], [0, 2]]), sp.eye(2), sp.Matrix([[a, 1], [0, 1]])
    >>> positive_multiple((M, W, V))  # |det M| W^T M^-1 V = 2 m A
    (Matrix([
    [2*a, 2],
    [  0, m]]), 1, False)
    """
    found = entry_numerators(factors, minors)
    if found is None:
        return None
    numerators, minors = found
    sign = known_sign(minors.field.present(minors.field.field.new(minors.denominator)), positive)
    if sign is None:
        return None
    k = minors.k
    terms = max(len(x) for row in numerators for x in row)
    scaled = sp.Matrix(k, k, lambda i, j: sign * minors.field.present(minors.field.field.new(numerators[i][j])))
    return scaled, terms, _is_number_matrix(numerators, minors.denominator)


def equality_matrix(factors, diagonal, minors: MinorsInRing | None = None) -> tuple[sp.Matrix, bool] | None:
    """For A = W^T M^-1 V with polynomial factors and a det M that is not a number: (B, whether A is a
    number matrix), B with A's diagonal ``diagonal`` (a_ii, as the principal minors of size 1 have
    it) and the numerators N_ij = a_ij det M off it, so that a_ij = a_ji exactly when B_ij = B_ji
    (det M != 0) with no gcd of an entry over det M. None otherwise (A's own entries are then cheap
    or needed).

    Examples
    --------
    >>> a, m = sp.symbols("a m", positive=True)
    >>> M, W, V = sp.Matrix([[m, 0], [0, m]]), sp.eye(2), sp.Matrix([[a, 2], [2, 1]])
    >>> equality_matrix((M, W, V), [a / m, 1 / m])  # a_12 = a_21 = 2/m: N_12 = N_21 = 2 m
    (Matrix([
    [a/m, 2*m],
    [2*m, 1/m]]), False)
    """
    found = entry_numerators(factors, minors)
    if found is None or found[1].denominator.is_ground:
        return None
    numerators, minors = found

    def entry(i, j):
        return diagonal[i] if i == j else minors.field.present(minors.field.field.new(numerators[i][j]))

    return sp.Matrix(minors.k, minors.k, entry), _is_number_matrix(numerators, minors.denominator)


def _polynomial_rows(field, X: sp.Matrix) -> list[list] | None:
    """The rows of X as ring elements, or None when an entry has a polynomial denominator."""
    rows = [[field.element(x) for x in row] for row in X.tolist()]
    if any(not x.denom.is_ground for row in rows for x in row):
        return None
    return [[x.numer.quo_ground(x.denom.LC) for x in row] for row in rows]


def minors_of(A: sp.Matrix, factors=None, extra=()) -> MinorsInRing:
    """The minors of A: from its factors (M, W, V) when they are polynomial, else from A itself.

    Examples
    --------
    >>> a = sp.Symbol("a")
    >>> type(minors_of(sp.Matrix([[a]]))).__name__, type(minors_of(sp.Matrix([[a]]), (sp.eye(1), sp.eye(1), sp.Matrix([[a]])))).__name__
    ('MinorsInRing', 'FactoredMinors')
    """
    if factors is not None:
        try:
            return FactoredMinors(*factors, extra=extra)
        except ValueError:
            pass
    return MinorsInRing(A, extra)
