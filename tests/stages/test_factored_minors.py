"""Principal minors and A from the factors A = W^T M^-1 V (a scene in contact space).

Each minor is one polynomial over det M (Schur complement); checked against numpy
determinants of W^T M^-1 V at random rational points, and against the minors of A itself.
"""

import itertools
import random

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.algebra.basic import SignSymbol, normalize
from contactsym.stages.linear import charpoly, lam, principal_minors
from contactsym.stages.minors import equality_matrix, polynomial_factors, positive_multiple

q1, q2, m, a = sp.symbols("q1 q2 m a", positive=True)
s = SignSymbol("s")


def random_factors(seed: int, n: int, k: int):
    """A positive definite M (a Gram matrix plus m I) and W, V with trig and parameter entries."""
    rng = random.Random(seed)
    pool = [sp.cos(q1), sp.sin(q1), sp.cos(q2), a, 1, 1, s]

    def entry():
        return rng.choice([-2, -1, 1, 2]) * rng.choice(pool)

    B = sp.Matrix(n, n, lambda i, j: entry())
    M = B.T * B + m * sp.eye(n)
    W = sp.Matrix(n, k, lambda i, j: entry())
    V = sp.Matrix(n, k, lambda i, j: entry())
    return M, W, V


def product(M, W, V) -> sp.Matrix:
    """W^T M^-1 V as W^T adj(M) V / det M, unexpanded."""
    return W.T * M.adjugate(method="berkowitz") * V / M.det(method="berkowitz")


def random_point(rng):
    point = {x: rng.uniform(0.2, 1.4) for x in (q1, q2, m, a)}
    point[s] = rng.choice([-1, 1])
    return point


@pytest.mark.parametrize("seed, n, k", [(1, 2, 2), (4, 3, 1)])
def test_factored_minors_are_the_determinants_of_w_m_inverse_v(seed, n, k):
    M, W, V = random_factors(seed, n, k)
    minors = principal_minors(product(M, W, V), (M, W, V))
    rng = random.Random(seed)
    factors = sp.lambdify([q1, q2, m, a, s], [M, W, V], "numpy")
    subsets = [S for size in range(1, k + 1) for S in itertools.combinations(range(k), size)]
    values_of_minors = sp.lambdify([q1, q2, m, a, s], [minors[S] for S in subsets], "numpy")  # once, not per point
    for _ in range(3):
        point = random_point(rng)
        Mn, Wn, Vn = (np.array(x, dtype=float) for x in factors(*point.values()))
        An = Wn.T @ np.linalg.solve(Mn, Vn)
        for S, value in zip(subsets, values_of_minors(*point.values()), strict=True):
            expected = np.linalg.det(An[np.ix_(S, S)])
            assert float(value) == pytest.approx(expected, rel=1e-9, abs=1e-9)


def test_factored_and_plain_minors_agree_exactly():
    M, W, V = random_factors(5, 2, 2)
    A = product(M, W, V).applyfunc(normalize)
    factored, plain = principal_minors(A, (M, W, V)), principal_minors(A)
    for S in factored:
        assert normalize(factored[S] - plain[S]) == 0


def test_the_factored_characteristic_polynomial_is_that_of_the_jacobian():
    """p(lambda) from the factored minors, against numpy's characteristic polynomial of (4.5)."""
    M, W, V = random_factors(5, 3, 2)
    A = product(M, W, V)
    Phi, Psi = sp.symbols("Phi_1:3"), sp.symbols("Psi_1:3")
    p = charpoly(A, Phi, Psi, factors=(M, W, V))
    assert p.gen == lam and p.degree() == 4
    rng = random.Random(7)
    for _ in range(3):
        point = random_point(rng) | {x: rng.uniform(-2, 2) for x in (*Phi, *Psi)}
        An = np.array(sp.lambdify([q1, q2, m, a, s], A)(*[point[x] for x in (q1, q2, m, a, s)]), dtype=float)
        J = np.block(
            [[np.diag([point[x] for x in Psi]) @ An, np.diag([point[x] for x in Phi])], [An, np.zeros((2, 2))]]
        )
        coefficients = np.array([float(sp.lambdify(list(point), c)(*point.values())) for c in p.all_coeffs()])
        assert coefficients / coefficients[0] == pytest.approx(np.poly(J), rel=1e-8, abs=1e-8)


def test_a_lagrangian_scene_linearizes_from_its_factors():
    """A = W^T M^-1 V from the fast subsystem's factors is the Jacobian of f, entry for entry."""
    scene = cs.scene("two-leg-block")
    lin = scene.linearization()
    M, W, V = lin.factors
    assert (W.T * M.inv() * V - lin.A).applyfunc(sp.simplify) == sp.zeros(2, 2)
    jacobian = scene.fast_subsystem().jacobian(lin.sign_values).applyfunc(normalize)
    assert lin.A == jacobian


@pytest.mark.parametrize("seed, n, k", [(2, 2, 2), (3, 3, 2)])
def test_the_positive_multiple_is_det_m_times_a(seed, n, k):
    """|det M| A from the bordered determinants, against W^T M^-1 V and det M in numpy (det M > 0 here)."""
    M, W, V = random_factors(seed, n, k)
    assert polynomial_factors((M, W, V))
    scaled, terms, numeric = positive_multiple((M, W, V), [M.det(method="berkowitz")])
    assert terms >= 1 and not numeric
    from contactsym.stages.minors import minors_of

    shared = minors_of(sp.zeros(k), (M, W, V))  # a linearization's minors: the same numerators, not expanded again
    assert positive_multiple((M, W, V), [M.det(method="berkowitz")], shared) == (scaled, terms, numeric)
    rng = random.Random(seed)
    functions = sp.lambdify([q1, q2, m, a, s], [M, W, V, scaled], "numpy")
    for _ in range(3):
        point = random_point(rng)
        Mn, Wn, Vn, Sn = (np.array(x, dtype=float) for x in functions(*point.values()))
        expected = np.linalg.det(Mn) * (Wn.T @ np.linalg.solve(Mn, Vn))
        assert Sn == pytest.approx(expected, rel=1e-9, abs=1e-9)


def test_the_positive_multiple_needs_the_sign_of_det_m_and_polynomial_factors():
    W = V = sp.eye(2)
    scaled, _, _ = positive_multiple((sp.Matrix([[-a, 0], [0, 1]]), W, V))  # det M = -a < 0: proved
    assert scaled == sp.diag(-1, a)  # |det M| M^-1 = a diag(-1/a, 1)
    x = sp.Symbol("x", real=True)
    assert positive_multiple((sp.Matrix([[x, 0], [0, 1]]), W, V)) is None  # sign of det M = x unknown
    assert not polynomial_factors((sp.Matrix([[1 / x, 0], [0, 1]]), W, V))
    assert positive_multiple((sp.Matrix([[1 / x, 0], [0, 1]]), W, V)) is None
    scaled, _, numeric = positive_multiple((2 * sp.eye(2), sp.eye(2), 4 * sp.eye(2)))
    assert numeric and scaled == 8 * sp.eye(2)


@pytest.mark.parametrize("seed, n, k", [(6, 3, 3)])
def test_the_equality_matrix_has_a_on_its_diagonal_and_det_m_times_a_off_it(seed, n, k):
    """B_ii = a_ii and B_ij = det M a_ij (against W^T M^-1 V and det M in numpy), so B_ij = B_ji
    exactly when a_ij = a_ji (det M > 0 here)."""
    M, W, V = random_factors(seed, n, k)
    minors = principal_minors(sp.zeros(k), (M, W, V))
    B, numeric = equality_matrix((M, W, V), [minors[(i,)] for i in range(k)])
    assert not numeric
    rng = random.Random(seed)
    functions = sp.lambdify([q1, q2, m, a, s], [M, W, V, B], "numpy")
    for _ in range(3):
        point = random_point(rng)
        Mn, Wn, Vn, Bn = (np.array(x, dtype=float) for x in functions(*point.values()))
        An = Wn.T @ np.linalg.solve(Mn, Vn)
        expected = np.linalg.det(Mn) * An
        np.fill_diagonal(expected, np.diag(An))
        assert Bn == pytest.approx(expected, rel=1e-9, abs=1e-9)


def test_the_equality_matrix_is_for_a_det_m_that_is_not_a_number():
    M, W, V = 2 * sp.eye(3), sp.eye(3), sp.Matrix(3, 3, lambda i, j: a ** (i + j))
    assert equality_matrix((M, W, V), [1, 1, 1]) is None  # A's entries are cheap: a_ij = N_ij / 8
    assert equality_matrix((sp.diag(1 / a, 1, 1), W, V), [1, 1, 1]) is None  # not polynomial
    B, numeric = equality_matrix((sp.diag(a, 1, 1), W, sp.eye(3)), [1 / a, 1, 1])
    assert not numeric and B == sp.diag(1 / a, 1, 1)  # off the diagonal the numerators are 0


def test_a_mass_matrix_constant_on_the_circle_gives_field_elements():
    """M = [[sin^2/12 + cos^2/12]] is 1/12 in the field; its adjugate came back a Python int and
    product_of failed (a numeric one-link chain, found with --hypothesis-seed=22)."""
    from contactsym.stages.minors import product_of

    mu = sp.Symbol("mu")
    M = sp.Matrix([[sp.sin(q1) ** 2 / 12 + sp.cos(q1) ** 2 / 12]])
    W, V = sp.Matrix([[sp.sin(q1) / 3]]), sp.Matrix([[mu * sp.cos(q1) / 3 + sp.sin(q1) / 3]])
    A = product_of(M, W, V)
    rng = random.Random(5)
    for _ in range(5):
        point = {q1: rng.uniform(0, 3), mu: rng.uniform(0, 2)}
        direct = float((W.T * M.inv() * V)[0, 0].subs(point))
        assert abs(float(A[0, 0].subs(point)) - direct) < 1e-12 * (1 + abs(direct))


@pytest.mark.parametrize("seed, n, k", [(7, 2, 2), (8, 3, 2)])
def test_the_characteristic_polynomial_from_minors_built_once_is_the_same(seed, n, k):
    """(4.6) from the minors a linearization already has (moved to the ring with the law and lambda)
    equals (4.6) from minors built anew with them, for laws that bring new generators (an angle,
    a root): the two paths are compared exactly, and the moved minors are those of the factors."""
    from contactsym.stages.minors import minors_of

    M, W, V = random_factors(seed, n, k)
    zero = sp.zeros(k)
    built_once = minors_of(zero, (M, W, V))
    q3, c = sp.symbols("q3 c", positive=True)
    laws = [
        ([-c * sp.cos(q3) - 2] * k, [-sp.sqrt(c)] * k),
        ([-a - 1] * k, [-m] * k),
    ]
    for Phi, Psi in laws:
        wider = built_once.extended([*Phi, *Psi, lam])
        assert wider is not None
        expected = charpoly(zero, Phi, Psi, factors=(M, W, V))
        assert charpoly(zero, Phi, Psi, factors=(M, W, V), minors=built_once) == expected
    assert principal_minors(zero, (M, W, V), built_once) == principal_minors(zero, (M, W, V))


def test_minors_of_another_matrix_are_refused():
    from contactsym.errors import ArgumentError
    from contactsym.stages.minors import minors_of

    with pytest.raises(ArgumentError, match="the minors of A, a 1 x 1 matrix"):
        charpoly(sp.Matrix([[a]]), [a], [a], minors=minors_of(sp.eye(2)))
    with pytest.raises(ArgumentError, match="minors"):
        principal_minors(sp.Matrix([[a]]), minors="det")
