"""Fraction-free linear algebra over the trigonometric field: adj(M), det(M) and M^-1 loads.

The Faddeev–LeVerrier recurrence divides only by integers, so every product is reduced at
once modulo sin^2 + cos^2 = 1 (:mod:`contactsym.algebra.canonical_form`) and nothing swells; one
common denominator det M is kept. Used by the contact-space derivation
(:mod:`contactsym.mechanism.contact_space`) and by the fast subsystem.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.physics.mechanics import dynamicsymbols

from ..arguments import checked, require
from .canonical_form import TrigField
from .coprime import cancel, cofactors

__all__ = [
    "adjugate_and_det",
    "adjugate_and_det_in_field",
    "polynomial_adjugate",
    "polynomial_det",
    "rational_point",
    "solve_fraction_free",
    "t",
    "value_at",
]

#: The time t of ``sympy.physics.mechanics`` (coordinates are functions q(t)).
#:
#: >>> from contactsym.algebra import t
#: >>> from sympy.physics.mechanics import dynamicsymbols
#: >>> dynamicsymbols('q').diff(t)
#: Derivative(q(t), t)
t = dynamicsymbols._t


@checked(reduce="Callable")
def adjugate_and_det(M: list[list], reduce) -> tuple[list[list], object]:
    """adj(M) and det(M) of a square matrix over a commutative ring containing Q.

    Faddeev–LeVerrier: with M_0 = 0 and c_n = 1, M_k = M M_(k-1) + c_(n-k+1) I and
    c_(n-k) = -tr(M M_k)/k give the characteristic polynomial sum c_i x^i; then
    det M = (-1)^n c_0 and adj M = (-1)^(n-1) M_n (Cayley–Hamilton). Only integer divisions
    occur, so ``reduce`` (a ring homomorphism's normal form) may be applied after every step.

    Examples
    --------
    >>> a, b, c, d = sp.symbols("a b c d")
    >>> adj, det = adjugate_and_det([[a, b], [c, d]], lambda x: sp.expand(x))
    >>> adj, det
    ([[d, -b], [-c, a]], a*d - b*c)
    """
    square = bool(M) and all(isinstance(row, (list, tuple)) and len(row) == len(M) for row in M)
    require(square, "adjugate_and_det", "M", M, "a square matrix as a list of rows")
    n = len(M)
    zero = M[0][0] * 0
    Mk = [[zero] * n for _ in range(n)]
    coefficient = zero + 1
    for k in range(1, n + 1):
        product = _matmul(M, Mk, reduce)
        Mk = [[product[i][j] + (coefficient if i == j else zero) for j in range(n)] for i in range(n)]
        trace = reduce(sum((M[i][j] * Mk[j][i] for i in range(n) for j in range(n)), zero))
        coefficient = reduce(-trace * sp.Rational(1, k))
    sign = -1 if n % 2 else 1
    return [[-sign * x for x in row] for row in Mk], reduce(sign * coefficient)


def _matmul(A, B, reduce):
    n, m, p = len(A), len(B), len(B[0])
    dot = _field_dot if _is_field_element(A[0][0]) and _is_field_element(B[0][0]) else _plain_dot
    return [[reduce(dot([A[i][r] for r in range(m)], [B[r][j] for r in range(m)])) for j in range(p)] for i in range(n)]


def _plain_dot(row, column):
    return sum((a * b for a, b in zip(row, column)), row[0] * 0)


def _is_field_element(x) -> bool:
    return hasattr(x, "numer") and hasattr(x, "field")


def _field_dot(row, column):
    """sum a_r b_r of elements of one fraction field, cancelled once (:func:`_field_sum`)."""
    return _field_sum(row[0].field, [(a.numer * b.numer, a.denom * b.denom) for a, b in zip(row, column) if a and b])


def _field_sum(field, terms):
    """The element sum n_r / d_r of ``field``, with one cancellation at the end.

    SymPy's field cancels after every operation; in lowest terms (integer coefficients, coprime
    contents, a positive leading coefficient below) a fraction has one representation, so one
    cancellation of the whole sum gives the same element, and :func:`contactsym.algebra.coprime.cancel`
    decides it cheaply where the gcd is 1. Terms over one denominator are added first, the others
    brought to their least common denominator.
    """
    by_denominator: dict = {}
    for numer, denom in terms:
        by_denominator[denom] = by_denominator.get(denom, field.ring.zero) + numer
    parts = [(numer, denom) for denom, numer in by_denominator.items() if numer]
    if not parts:
        return field.zero
    numer, denom = parts[0]
    for n, d in parts[1:]:  # over the least common denominator: the final gcd then has the least to find
        _, own, other = cofactors(denom, d)
        numer, denom = numer * other + n * own, denom * other
    return field.raw_new(*cancel(numer, denom))


@checked(substitution="Mapping | None", offsets="Sequence | None")
def solve_fraction_free(
    M: sp.Matrix, loads: list[sp.Matrix], rows: sp.Matrix | None = None, *, substitution=None, offsets=None
) -> list[list[sp.Expr]]:
    """Canonical entries of ``rows^T M^-1 load (+ offset)`` for each load (rows = identity by default).

    One trigonometric field for all entries; adj(M) and det(M) by :func:`adjugate_and_det`
    with every product reduced; one common denominator det M. ``substitution`` ({symbol:
    expression}) is applied to the loads and offsets inside the field, where a rational value
    (a rate on the contact manifold) costs one composition instead of a ``together``.

    Examples
    --------
    >>> q, m = sp.symbols("q m", positive=True)
    >>> M = sp.Matrix([[m, 0], [0, m*sp.sin(q)**2 + m*sp.cos(q)**2]])
    >>> solve_fraction_free(M, [sp.Matrix([1, sp.cos(q)])])
    [[1/m, cos(q)/m]]
    """
    rows = sp.eye(M.rows) if rows is None else rows
    substitution = dict(substitution or {})
    offsets = offsets or [None] * len(loads)
    extra = [x for offset in offsets if offset is not None for x in offset]
    field = TrigField([*M, *rows, *substitution, *substitution.values(), *extra] + [x for load in loads for x in load])
    values = {symbol: field.element(value) for symbol, value in substitution.items()}
    adj, det = adjugate_and_det_in_field(field, M)
    projected = _matmul([[field.element(x) for x in rows[:, i]] for i in range(rows.cols)], adj, field.reduce)
    results = []
    if not det:
        raise ZeroDivisionError("det M = 0: the mass matrix is singular")
    for load, offset in zip(loads, offsets):
        vector = [[field.substituted(x, values)] for x in load]
        column = [
            _field_sum(det.field, [(row[0].numer * det.denom, row[0].denom * det.numer)])
            for row in _matmul(projected, vector, field.reduce)
        ]
        if offset is not None:
            shifted = [field.substituted(y, values) for y in offset]
            column = [_field_sum(x.field, [(x.numer, x.denom), (y.numer, y.denom)]) for x, y in zip(column, shifted)]
        results.append([field.present(x) for x in column])
    return results


@checked(field="TrigField")
def adjugate_and_det_in_field(field, M: sp.Matrix):
    """adj M and det M as elements of ``field``; in the polynomial ring of M's own entries (no
    gcds, computed once per matrix) when they are polynomials, as a mass matrix usually is.

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.algebra import TrigField
    >>> a, b, c, d = sp.symbols("a b c d")
    >>> K = TrigField([a, b, c, d])
    >>> adj, det = adjugate_and_det_in_field(K, sp.Matrix([[a, b], [c, d]]))
    >>> [[K.present(x) for x in row] for row in adj], K.present(det)
    ([[d, -b], [-c, a]], a*d - b*c)
    """
    polynomial = polynomial_adjugate(sp.ImmutableMatrix(M))
    if polynomial is not None:
        adj, det = polynomial
        return [[field.field.new(x.set_ring(field.ring)) for x in row] for row in adj], field.field.new(
            det.set_ring(field.ring)
        )
    entries = [[field.element(x) for x in row] for row in M.tolist()]
    adj, det = adjugate_and_det(entries, field.reduce)
    # a constant may come back as a Python number (M = [[sin^2/12 + cos^2/12]] reduces to 1/12):
    # every caller reads .numer and .denom, so each entry is made an element of the field
    return [[field.field(x) for x in row] for row in adj], field.field(det)


@checked
@lru_cache(maxsize=16)
def polynomial_adjugate(M: sp.ImmutableMatrix):
    """(adj M, det M) as reduced polynomials of M's own field's ring, or None when an entry is
    not a polynomial; cached: the fast subsystem and the sign of det M both need it.

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> polynomial_adjugate(sp.ImmutableMatrix([[x, 1], [1, 2]]))
    ([[2, -1], [-1, x]], 2*x - 1)
    """
    field = TrigField(list(M))
    entries = [[field.element(x) for x in row] for row in M.tolist()]
    if any(x.denom != 1 for row in entries for x in row):
        return None
    return adjugate_and_det([[x.numer for x in row] for row in entries], field.reduce_poly)


@lru_cache(maxsize=16)
def polynomial_det(M: sp.ImmutableMatrix):
    """det M as a reduced polynomial of M's own field's ring, or None when an entry is not a
    polynomial: by Laplace expansion along the rows, the minor on each set of columns computed once
    (n 2^(n-1) products of an entry by a minor, where the adjugate of :func:`polynomial_adjugate`
    takes n matrix products, n^4; up to n = :data:`LAPLACE_MAX`, past it det M is the adjugate's).

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> polynomial_det(sp.ImmutableMatrix([[x, 1, 0], [1, 2, 1], [0, 1, x / 2]])).as_expr()
    x**2 - 3*x/2
    """
    if M.rows > LAPLACE_MAX:
        found = polynomial_adjugate(M)
        return None if found is None else found[1]
    field = TrigField(list(M))
    entries = [[field.element(x) for x in row] for row in M.tolist()]
    if any(not x.denom.is_ground for row in entries for x in row):
        return None
    rows = [[x.numer.quo_ground(x.denom.LC) for x in row] for row in entries]  # m l^2 / 12: a number below
    memo: dict = {}

    def minor(level: int, columns: tuple):  # det of the rows level.. on ``columns``
        if level == len(rows):
            return field.ring.one
        if columns not in memo:
            total = field.ring.zero
            for i, c in enumerate(columns):
                if rows[level][c]:
                    term = rows[level][c] * minor(level + 1, columns[:i] + columns[i + 1 :])
                    total = total + term if i % 2 == 0 else total - term
            memo[columns] = field.reduce_poly(total)
        return memo[columns]

    return minor(0, tuple(range(M.rows)))


#: The largest n whose det :func:`polynomial_det` expands by minors (2^n of them kept).
LAPLACE_MAX = 10


def rational_point(field: TrigField) -> list | None:
    """One exact point of the generators of ``field`` that respects its relations, or None.

    Each angle's cosine and sine get ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)) for a rational t, each
    sign symbol 1 and every other generator (a symbol, or a coordinate q(t): no relation holds
    between them) a rational, so that evaluating there is a ring homomorphism: a nonzero value
    proves a nonzero element. None when a generator has a relation the point would not respect
    (sqrt(l), a root with root^2 = l) or is of another kind.

    Examples
    --------
    >>> q, m = sp.symbols("q m")
    >>> field = TrigField([m * sp.cos(q)])
    >>> field.ring.symbols, [str(x) for x in rational_point(field)]
    ((cos(q), sin(q), m, q), ['12/13', '5/13', '4/11', '5/13'])
    >>> rational_point(TrigField([sp.sqrt(m)])) is None
    True
    """
    paired = {i for pair in field.pairs for i in pair}
    # a Dummy stands for a root (sqrt(m) -> root0, root0^2 = m): a relation the point would not respect
    roots = [g for g in field.ring.symbols if isinstance(g, sp.Dummy) and g.name.startswith("root")]
    free = [i in paired or g.is_Symbol or isinstance(g, AppliedUndef) for i, g in enumerate(field.ring.symbols)]
    if roots or not all(free):
        return None
    point = [sp.QQ(k + 2, 2 * k + 7) for k in range(field.ring.ngens)]
    for i in field.signs:
        point[i] = sp.QQ(1)
    for c, s in field.pairs:
        x = sp.QQ(c + 1, c + 5)
        point[c], point[s] = (1 - x**2) / (1 + x**2), 2 * x / (1 + x**2)
    return point


def value_at(value, point):
    """A field element (a ``FracElement``) at a point of rationals, one per generator, term by term
    (no ring per generator); raises ZeroDivisionError at a pole.

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.algebra import TrigField
    >>> a, b = sp.symbols("a b")
    >>> K = TrigField([a, b])
    >>> value_at(K.element((a**2 + 1) / b), [sp.QQ(1, 2), sp.QQ(5)]) == sp.Rational(1, 4)
    True
    """
    return _polynomial_at(value.numer, point) / _polynomial_at(value.denom, point)


def _polynomial_at(poly, point):
    total = sp.QQ(0)
    for monomial, coefficient in poly.terms():
        term = sp.QQ(coefficient)
        for x, e in zip(point, monomial):
            if e:
                term *= x**e
        total += term
    return total
