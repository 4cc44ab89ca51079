"""numerics.buffered: generated code into reused buffers gives the numbers lambdify gives."""

from __future__ import annotations

import pickle

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym import numerics as nm
from contactsym.numerics.buffered import BufferedCode

X = sp.symbols("x0:4")


def _random_expression(rng, depth: int = 3) -> sp.Expr:
    """A random expression of X: sums, products, integer powers, quotients, tan, relations and connectives."""
    if depth == 0 or rng.random() < 0.2:
        return X[rng.integers(len(X))] if rng.random() < 0.8 else sp.Rational(int(rng.integers(-5, 6)), 3)
    a, b = _random_expression(rng, depth - 1), _random_expression(rng, depth - 1)
    kind = rng.integers(7)
    if kind == 0:
        return a + b
    if kind == 1:
        return a - 2 * b
    if kind == 2:
        return a * b
    if kind == 3:
        return a ** int(rng.integers(-3, 5))
    if kind == 4:
        return a / (1 + b**2)
    if kind == 5:
        return sp.tan(X[0]) ** 2 * a + sp.Abs(b)
    return sp.exp(-(a**2)) * b


@pytest.mark.parametrize("seed", range(6))
def test_buffered_code_gives_lambdify_numbers_on_random_expressions(seed):
    rng = np.random.default_rng(seed)
    expressions = [_random_expression(rng) for _ in range(4)] + [sp.Gt(X[0], X[1]) & sp.Le(X[2], 1), sp.Integer(7)]
    code = BufferedCode(X, expressions)
    n = 257
    columns = [rng.uniform(0.5, 2.0, n) for _ in X]
    columns[3] = np.broadcast_to(1.25, (n,))  # one value for every point: read once
    buffers = np.empty((code.buffers, n))
    with np.errstate(all="ignore"):
        got = [np.broadcast_to(np.asarray(v, dtype=float), (n,)).copy() for v in code(columns, buffers)]
        again = [
            np.broadcast_to(np.asarray(v, dtype=float), (n,))
            for v in pickle.loads(pickle.dumps(code))(
                [np.ascontiguousarray(c) for c in columns], np.empty((code.buffers, n))
            )
        ]
        expected = [
            np.broadcast_to(np.asarray(f(*columns), dtype=float), (n,))
            for f in (sp.lambdify(X, e, modules="numpy") for e in expressions)
        ]
    assert np.mean([np.isfinite(e).mean() for e in expected]) > 0.9  # numbers to compare, not NaN
    for g, a, e in zip(got, again, expected):
        np.testing.assert_allclose(g, e, rtol=1e-12, atol=1e-300, equal_nan=True)
        np.testing.assert_allclose(a, e, rtol=1e-12, atol=1e-300, equal_nan=True)


def test_buffered_code_refuses_what_it_cannot_write():
    with pytest.raises(cs.errors.NumericsError, match="buffered"):
        BufferedCode(X, [X[0] ** X[1]])


def test_the_classifier_agrees_with_numpy_eigenvalues_with_values_given_once():
    """The brake's (6.4) slice: random points, the law as one value for all points (stride 0) and as full
    arrays; outside the band the verdict is that of numpy's eigenvalues of (4.5), across chunk boundaries."""
    st = cs.scene("brake").stability()
    lin = st.linearization
    by_name = {str(s): s for s in lin.jacobian.free_symbols | set().union(*[c.free_symbols for c in st.hurwitz])}
    names = ["alpha", "m", "mu", "Phi_1", "Phi_2", "Psi_1", "Psi_2"]
    parameters = [by_name[n] for n in names]
    classifier = nm.PointClassifier(st.hurwitz, parameters)
    rng = np.random.default_rng(23)
    n = 3000
    law = [-2.0, -1.5, -1.0, -0.7]
    grid = [rng.uniform(0.1, 3.0, n), rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n)]
    once = classifier(*grid, *[np.broadcast_to(v, (n,)) for v in law], chunk=1000)
    full = classifier(*grid, *[np.full(n, v) for v in law], chunk=777)
    assert np.array_equal(once.stable, full.stable) and np.array_equal(once.signs, full.signs)
    M = sp.lambdify(parameters, lin.jacobian, modules="numpy")
    eigen = np.array(
        [np.linalg.eigvals(np.array(M(*[g[i] for g in grid], *law), dtype=float)).real.max() < 0 for i in range(n)]
    )
    outside = ~once.in_band
    assert outside.sum() > 0.99 * n and np.array_equal(once.stable[outside] == 1, eigen[outside])
    assert 0.1 < eigen.mean() < 0.9  # both verdicts occur
