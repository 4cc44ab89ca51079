"""Fraction-free linear algebra: sums of field elements cancelled once equal SymPy's step-by-step sums."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import QQ
from sympy.polys.fields import field

from contactsym.algebra.fraction_free import _field_sum, adjugate_and_det, solve_fraction_free

K, x, y, z = field("x, y, z", QQ)
coefficients = st.fractions(-4, 4, max_denominator=3).map(QQ.convert)
monomials = st.tuples(st.integers(0, 2), st.integers(0, 2), st.integers(0, 1))
polynomials = st.dictionaries(monomials, coefficients, min_size=1, max_size=4).map(
    lambda terms: K.ring.from_dict({m: c for m, c in terms.items() if c})
)
shared = st.sampled_from([K.ring.one, K.ring.gens[0] + 1, K.ring.gens[1] - K.ring.gens[2]])


@st.composite
def fractions(draw):
    """n / d with d often sharing a factor with other terms' denominators (what a common denominator meets)."""
    numer, denom = draw(polynomials), draw(polynomials)
    if not denom:
        denom = K.ring.one
    return numer, denom * draw(shared)


@settings(max_examples=80)
@given(st.lists(fractions(), min_size=1, max_size=5))
def test_a_sum_cancelled_once_is_sympys_sum_cancelled_at_every_step(terms):
    expected = sum((K.new(n, d) for n, d in terms), K.zero)
    found = _field_sum(K, terms)
    assert found == expected
    assert (found.numer, found.denom) == (expected.numer, expected.denom)  # the same representation


@settings(max_examples=40)
@given(st.lists(st.lists(st.integers(-3, 3), min_size=3, max_size=3), min_size=3, max_size=3), st.integers(1, 3))
def test_solutions_satisfy_the_system(rows, shift):
    q, m = sp.symbols("q m", positive=True)
    M = sp.Matrix(rows) + sp.diag(shift * 10 + m, 10 + sp.cos(q) ** 2, 10)  # diagonally dominant: invertible
    load = sp.Matrix([1, sp.sin(q), m])
    (solution,) = solve_fraction_free(M, [load])
    residual = (M * sp.Matrix(solution) - load).subs({q: sp.Rational(3, 7), m: sp.Rational(5, 2)})
    assert all(abs(sp.N(r, 50)) < 1e-30 for r in residual)


def test_adjugate_times_matrix_is_the_determinant():
    a, b, c, d = sp.symbols("a b c d")
    adj, det = adjugate_and_det([[a, b], [c, d]], sp.expand)
    assert sp.expand((sp.Matrix(adj) * sp.Matrix([[a, b], [c, d]]))[0, 0] - det) == 0


_q, _m = sp.symbols("q m")
_entries = st.sampled_from(
    [0, 1, -2, _m, _m / 12, sp.cos(_q), sp.sin(_q), _m * sp.cos(_q) ** 2, sp.sin(_q) * sp.cos(_q) - _m]
)


@settings(max_examples=25)
@given(st.integers(1, 5).flatmap(lambda n: st.lists(_entries, min_size=n * n, max_size=n * n)))
def test_det_by_minors_is_the_adjugates_det(entries):
    """polynomial_det (Laplace, minors memoized) and polynomial_adjugate's det (Faddeev-LeVerrier) are the
    same reduced polynomial (sin^2 + cos^2 = 1 applied) where the adjugate's path takes M (integer
    coefficients), and det M at a point is numpy's."""
    import numpy as np

    from contactsym.algebra.fraction_free import polynomial_adjugate, polynomial_det

    n = int(len(entries) ** 0.5)
    M = sp.ImmutableMatrix(n, n, entries)
    det, adjugate = polynomial_det(M), polynomial_adjugate(M)
    assert adjugate is None or det == adjugate[1]
    point = {_q: 0.43, _m: 1.7}
    value = float(det.as_expr().evalf(subs=point)) if det else 0.0
    assert value == pytest.approx(np.linalg.det(np.array(M.evalf(subs=point), dtype=float)), rel=1e-9, abs=1e-9)
