"""Linearization (4.3), (4.5) and the characteristic polynomial (4.6) from principal minors."""

import itertools
from fractions import Fraction

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.algebra.basic import SignSymbol, normalize, reduce_signs, reduce_trig, sign_symbols
from contactsym.errors import SignPatternError
from contactsym.stages.linear import Linearization, charpoly, lam, principal_minors


def symbolic_data(k):
    A = sp.Matrix(k, k, lambda i, j: sp.Symbol(f"a_{i + 1}{j + 1}", real=True))
    Phi = sp.symbols(f"Phi_1:{k + 1}", negative=True)
    Psi = sp.symbols(f"Psi_1:{k + 1}", negative=True)
    return A, Phi, Psi


def block_matrix(A, Phi, Psi):
    """(4.5) written out independently of the library."""
    k = A.rows
    M = sp.zeros(2 * k, 2 * k)
    for i in range(k):
        for j in range(k):
            M[i, j] = Psi[i] * A[i, j]
            M[k + i, j] = A[i, j]
        M[i, k + i] = Phi[i]
    return M


def block_charpoly(M):
    """det(lam I - M), expanded as a 2k x 2k determinant."""
    return (lam * sp.eye(M.rows) - M).det(method="berkowitz")


def fast_charpoly(M):
    """det(lam I - M) through SymPy's own charpoly (fast for k >= 4)."""
    return M.charpoly(lam).as_expr(lam)  # SymPy names its own lambda: put the pipeline's in


# --- charpoly ---------------------------------------------------------------------


@pytest.mark.parametrize("k", [1, 2, 3])
def test_charpoly_equals_block_determinant_symbolic(k):
    A, Phi, Psi = symbolic_data(k)
    p = charpoly(A, Phi, Psi)
    assert isinstance(p, sp.Poly)
    assert p.gens == (lam,)
    assert sp.expand(p.as_expr() - block_charpoly(block_matrix(A, Phi, Psi))) == 0


def test_charpoly_equals_block_determinant_k4_numeric_A():
    A = sp.Matrix([[2, -1, 3, 0], [1, 1, -2, 5], [0, 4, -1, 1], [-3, 2, 1, 2]]) / 3
    _, Phi, Psi = symbolic_data(4)
    p = charpoly(A, Phi, Psi)
    assert sp.expand(p.as_expr() - fast_charpoly(block_matrix(A, Phi, Psi))) == 0


rationals = st.fractions(min_value=-6, max_value=6, max_denominator=5).map(
    lambda f: sp.Rational(f.numerator, f.denominator)
)
negatives = st.fractions(min_value=Fraction(1, 20), max_value=20, max_denominator=20).map(
    lambda f: -sp.Rational(f.numerator, f.denominator)
)


@settings(max_examples=25, deadline=None)
@given(st.data())
def test_charpoly_matches_numpy_eigenvalues(data):
    k = data.draw(st.integers(1, 4), label="k")
    A = sp.Matrix(k, k, data.draw(st.lists(rationals, min_size=k * k, max_size=k * k), label="A"))
    Phi = data.draw(st.lists(negatives, min_size=k, max_size=k), label="Phi")
    Psi = data.draw(st.lists(negatives, min_size=k, max_size=k), label="Psi")
    p = charpoly(A, Phi, Psi)
    assert p.degree() == 2 * k
    assert p.LC() == 1
    exact = sp.Poly(fast_charpoly(block_matrix(A, Phi, Psi)), lam)
    assert p == exact
    M = np.array(block_matrix(A, Phi, Psi).tolist(), dtype=float)
    numeric = np.poly(M)  # coefficients of det(lam I - M), leading first
    coeffs = np.array([float(c) for c in p.all_coeffs()])
    assert np.allclose(coeffs, numeric, rtol=1e-8, atol=1e-8 * max(1.0, np.abs(numeric).max()))


@pytest.mark.parametrize("k", [1, 2, 3])
def test_charpoly_constant_and_subleading_terms(k):
    A, Phi, Psi = symbolic_data(k)
    p = charpoly(A, Phi, Psi)
    # lam = 0: det(-Phi A) = (-1)^k det(A) prod Phi
    assert sp.expand(p.eval(0) - (-1) ** k * A.det(method="berkowitz") * sp.Mul(*Phi)) == 0
    # the lam^(2k-1) coefficient is -trace(Psi A)
    assert sp.expand(p.coeff_monomial(lam ** (2 * k - 1)) + sum(Psi[j] * A[j, j] for j in range(k))) == 0


def test_charpoly_docstring_example():
    a, Phi, Psi = sp.symbols("a Phi Psi")
    assert charpoly(sp.Matrix([[a]]), [Phi], [Psi]).as_expr() == lam**2 - Psi * a * lam - Phi * a


@pytest.mark.parametrize("k", [1, 2, 3])
def test_principal_minors(k):
    A, _, _ = symbolic_data(k)
    minors = principal_minors(A)
    subsets = [S for size in range(k + 1) for S in itertools.combinations(range(k), size)]
    assert sorted(minors) == sorted(subsets)
    assert minors[()] == 1
    for S, minor in minors.items():
        if S:
            assert sp.expand(minor - A.extract(list(S), list(S)).det()) == 0
    assert sp.expand(minors[tuple(range(k))] - A.det()) == 0


def test_lam_is_exported():
    assert cs.lam is lam
    assert lam.name == "lambda"


# --- algebra used by the linearization --------------------------------------------


def test_sign_symbols():
    (s,) = sign_symbols(1)
    assert isinstance(s, SignSymbol) and s.name == "s"
    many = sign_symbols(3)
    assert [x.name for x in many] == ["s_1", "s_2", "s_3"]
    assert all(isinstance(x, SignSymbol) and x.is_integer and x.is_nonzero for x in many)


def test_reduce_signs_examples():
    s = SignSymbol("s")
    s1, s2 = sign_symbols(2)
    x = sp.Symbol("x")
    assert reduce_signs(s**2) == 1
    assert reduce_signs(s**3) == s
    assert reduce_signs(s**-1) == s
    assert reduce_signs(s**-2) == 1
    assert reduce_signs(s**2 + 3 * s**3 - s**4) == 3 * s
    assert reduce_signs(s1**2 * s2**3 * x) == s2 * x
    assert reduce_signs(x**2 * s**4) == x**2  # plain symbols keep their powers
    assert reduce_signs(sp.sin(s**2 * x)) == sp.sin(x)
    assert reduce_signs(3) == 3


def test_reduce_signs_leaves_plain_symbols_named_s_alone():
    s = sp.Symbol("s")
    assert reduce_signs(s**2) == s**2


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(-5, 5), min_size=1, max_size=6), st.lists(st.integers(-4, 6), min_size=1, max_size=6))
def test_reduce_signs_agrees_at_plus_and_minus_one(coefficients, exponents):
    s1, s2 = sign_symbols(2)
    x = sp.Symbol("x")
    expr = sum(c * s1**e * s2 ** (e + 1) * x ** abs(e) for c, e in zip(coefficients, exponents))
    reduced = reduce_signs(expr)
    for a, b in itertools.product((1, -1), repeat=2):
        assert sp.expand(reduced.subs({s1: a, s2: b}) - expr.subs({s1: a, s2: b})) == 0
    for power in sp.preorder_traversal(reduced):
        if power.is_Pow and isinstance(power.base, SignSymbol):
            pytest.fail(f"power of a sign symbol left: {power}")


def test_reduce_trig_and_normalize():
    a, m = sp.symbols("alpha m", positive=True)
    assert reduce_trig(sp.sin(a) ** 2 / m + sp.cos(a) ** 2 / m) == 1 / m
    assert reduce_trig(sp.cos(a) ** 3) == sp.expand(sp.cos(a) * (1 - sp.sin(a) ** 2))
    s = SignSymbol("s")
    assert normalize((s * sp.cos(a)) ** 2 + sp.sin(a) ** 2) == 1


# --- Linearization on built-in scenes ---------------------------------------------


PATTERNS = [
    ("sliding-point", None),
    ("painleve-klein-rod", None),
    ("painleve-klein-rod", (1, -1)),
    ("painleve-klein-guides", None),
    ("painleve-klein-guides", (1, 1)),
    ("painleve-klein-guides", (-1, 1)),
    ("brake", None),
]


@pytest.mark.parametrize(("name", "signs"), PATTERNS)
def test_matrix_is_4_5(name, signs):
    lin = cs.scene(name).linearization(signs)
    k = lin.A.rows
    assert lin.jacobian.shape == (2 * k, 2 * k)
    assert lin.jacobian[:k, :k] == sp.diag(*lin.Psi) * lin.A
    assert lin.jacobian[:k, k:] == sp.diag(*lin.Phi)
    assert lin.jacobian[k:, :k] == lin.A
    assert lin.jacobian[k:, k:] == sp.zeros(k)


@pytest.mark.parametrize(("name", "signs"), PATTERNS)
def test_charpoly_of_matrix_is_charpoly(name, signs):
    lin = cs.scene(name).linearization(signs)
    p = lin.charpoly
    assert p.gens == (lam,)
    assert p.degree() == 2 * lin.A.rows
    assert normalize(p.as_expr() - block_charpoly(lin.jacobian)) == 0


@pytest.mark.parametrize(("name", "signs"), PATTERNS)
def test_A_is_the_jacobian_of_f_on_the_piece(name, signs):
    scene = cs.scene(name)
    lin = scene.linearization(signs)
    fast = scene.fast_subsystem()
    jacobian = fast.piece(lin.sign_values).jacobian(fast.u)
    assert (lin.A - jacobian).applyfunc(normalize) == sp.zeros(*lin.A.shape)
    assert normalize(lin.det_A - lin.A.det(method="berkowitz")) == 0
    at_rest = dict.fromkeys(fast.v, 0)
    assert lin.Phi == tuple(sp.sympify(x).subs(at_rest) for x in fast.Phi)
    assert lin.Psi == tuple(sp.sympify(x).subs(at_rest) for x in fast.Psi)
    assert not any(x.has(*fast.v) for x in lin.Phi + lin.Psi)


def test_brake_linearization():
    lin = cs.scene("brake").linearization()
    m, mu, alpha = sp.symbols("m mu alpha", positive=True)
    s, c = sp.sin(alpha), sp.cos(alpha)
    expected = sp.Matrix([[1 / m, (mu * s - c) / m], [(-mu * s - c) / m, 1 / m]])
    assert (lin.A - expected).applyfunc(sp.expand) == sp.zeros(2)
    assert normalize(lin.det_A - (1 + mu**2) * s**2 / m**2) == 0
    assert lin.sign_values == (1, 1)  # unilateral pads: N_j > 0
    assert [x.name for x in lin.Phi] == ["Phi_1", "Phi_2"]
    assert all(x.is_negative for x in lin.Phi + lin.Psi)
    assert isinstance(lin, Linearization)


def test_brake_charpoly_numeric_eigenvalues():
    lin = cs.scene("brake").linearization()
    values = {sp.Symbol(n, positive=True): v for n, v in [("m", 2), ("mu", 0.3), ("alpha", 1.1)]}
    values.update(zip(lin.Phi, (-1.5, -0.7)))
    values.update(zip(lin.Psi, (-0.2, -0.9)))
    M = np.array(lin.jacobian.subs(values).evalf().tolist(), dtype=float)
    roots = np.roots([float(c.subs(values)) for c in lin.charpoly.all_coeffs()])
    assert np.allclose(np.sort_complex(roots), np.sort_complex(np.linalg.eigvals(M)), atol=1e-9)


def test_sliding_point_kelvin_voigt():
    lin = cs.scene("sliding-point").linearization()
    b, m = sp.symbols("b m", positive=True)
    assert lin.Phi == (-1,) and lin.Psi == (-2 * b,)
    assert lin.A == sp.Matrix([[1 / m]])
    assert sp.expand(lin.charpoly.as_expr() - (lam**2 + 2 * b / m * lam + 1 / m)) == 0


def test_open_sign_patterns_use_sign_symbols():
    scene = cs.scene("painleve-klein-guides")
    lin = scene.linearization()
    s1, s2 = lin.sign_values
    assert isinstance(s1, SignSymbol) and isinstance(s2, SignSymbol)
    assert lin.A.has(s1) and lin.A.has(s2)
    fixed = scene.linearization((1, -1))
    assert not any(isinstance(x, SignSymbol) for x in fixed.A.free_symbols)
    assert (lin.A.subs({s1: 1, s2: -1}) - fixed.A).applyfunc(sp.expand) == sp.zeros(2)
    assert normalize(lin.charpoly.as_expr().subs({s1: 1, s2: -1}) - fixed.charpoly.as_expr()) == 0


def test_linearization_is_cached_per_pattern():
    scene = cs.scene("painleve-klein-guides")
    assert scene.linearization() is scene.linearization()
    assert scene.linearization((1, -1)) is scene.linearization([1, -1])
    assert scene.linearization((1, -1)) is not scene.linearization((1, 1))


@pytest.mark.parametrize("signs", [(1,), (1, 1, 1), (1, 0), (1, -1)])
def test_bad_sign_patterns_for_the_brake(signs):
    with pytest.raises(SignPatternError):
        cs.scene("brake").linearization(signs)


def user_scene(A, compliances=None):
    k = A.rows
    q = dynamicsymbols(f"q_1:{k + 1}")
    N = sp.symbols(f"N_1:{k + 1}", real=True)
    b = sp.symbols(f"b_1:{k + 1}", real=True)
    G = [sum(A[j, i] * N[i] for i in range(k)) + b[j] for j in range(k)]
    compliances = compliances or [None] * k
    contacts = [cs.Contact(coordinate=q[j], reaction=N[j], compliance=compliances[j]) for j in range(k)]
    return cs.Scene.from_accelerations(q, G, contacts)


def test_user_scene_linear_f_gives_its_matrix():
    A = sp.Matrix([[2, -1, sp.Rational(1, 3)], [0, 1, 4], [-2, 5, 1]])
    lin = user_scene(A).linearization()
    assert lin.A == A
    assert lin.det_A == A.det()
    _, Phi, Psi = symbolic_data(3)
    assert [x.name for x in lin.Phi] == [x.name for x in Phi]
    assert sp.expand(lin.charpoly.as_expr() - block_charpoly(block_matrix(A, lin.Phi, lin.Psi))) == 0


def test_user_scene_with_kelvin_voigt_contacts():
    A = sp.Matrix([[1, 2], [-3, 4]])
    k1, d1 = sp.symbols("k_1 d_1", positive=True)
    lin = user_scene(A, [cs.KelvinVoigt(k1, d1), cs.KelvinVoigt(3, 2)]).linearization()
    assert lin.Phi == (-k1, -3) and lin.Psi == (-d1, -2)
    assert lin.jacobian == block_matrix(A, (-k1, -3), (-d1, -2))


# --- the polynomial-ring path: equal to the Berkowitz determinants in the canonical form ----------

_s1, _s2 = sign_symbols(2)
_m, _x, _th = sp.Symbol("m", positive=True), sp.Symbol("x", real=True), sp.Symbol("theta", positive=True)
_entries = st.sampled_from(
    [
        sp.Integer(0),
        sp.Rational(3, 7),
        -sp.Rational(4317, 10000),
        _s1 * _x / _m,
        _s2 + _x,
        (_s1 * _x - 1) / _m**2,
        sp.cos(_th) / _m,
        sp.sin(_th) * _s2 - sp.Rational(1, 3),
        _x**2 - _s1 * _s2,
    ]
)


@settings(max_examples=20, deadline=None)
@given(st.integers(1, 3).flatmap(lambda k: st.lists(_entries, min_size=k * k, max_size=k * k)))
def test_ring_minors_and_charpoly_equal_the_berkowitz_path(entries):
    """Principal minors, det A and (4.6) computed in the polynomial ring equal, exactly, the
    canonical form of SymPy's Berkowitz determinants and of the summed expression."""
    from contactsym.stages.linear import _charpoly_of_expression

    k = int(round(len(entries) ** 0.5))
    A = sp.Matrix(k, k, entries)
    minors = principal_minors(A)
    for S, minor in minors.items():
        berkowitz = A.extract(list(S), list(S)).det(method="berkowitz") if S else sp.S.One
        assert minor == normalize(berkowitz), S
    Phi, Psi = sp.symbols(f"Phi_1:{k + 1}"), sp.symbols(f"Psi_1:{k + 1}")
    p = charpoly(A, Phi, Psi)
    assert p == _charpoly_of_expression(A, Phi, Psi, ())
    rng = np.random.default_rng(len(entries))
    for _ in range(2):  # and the block determinant (4.5) at a random point, with s = +-1
        point = {
            _s1: int(rng.choice([-1, 1])),
            _s2: int(rng.choice([-1, 1])),
            _x: sp.Rational(int(rng.integers(-9, 9)), 4),
        }
        point |= {_m: sp.Rational(int(rng.integers(1, 9)), 3), _th: sp.Rational(int(rng.integers(1, 9)), 5)}
        point |= {v: -sp.Rational(int(rng.integers(1, 9)), 2) for v in (*Phi, *Psi)}
        point[lam] = sp.Rational(3, 2)
        # det(lam I - M) in 50-digit floating point (mpmath LU), not symbolically: the entries hold
        # cos/sin of rationals, which made the exact Berkowitz expansion and its evaluation the slow part
        M = block_matrix(A.xreplace(point), [v.xreplace(point) for v in Phi], [v.xreplace(point) for v in Psi])
        with mpmath.workdps(50):
            direct = mpmath.det(mpmath.matrix((point[lam] * sp.eye(2 * k) - M).evalf(50).tolist()))
            assert abs(sp.N(p.as_expr().xreplace(point), 50) - direct) < 1e-30  # monic, as p


def test_linearization_det_a_equals_the_berkowitz_canonical_form():
    for name in cs.scene_names():
        lin = cs.scene(name).linearization()
        assert lin.det_A == normalize(lin.A.det(method="berkowitz")), name


def test_a_charpoly_with_large_coefficients_keeps_them_as_derived_and_is_the_jacobians():
    """Past EXPAND_NODES a coefficient is kept as derived (domain EX, no second parse), and the
    polynomial is still that of the Jacobian [[Psi A, Phi], [A, 0]] (numpy's, at random points)."""
    from contactsym.algebra.basic import EXPAND_NODES, node_count

    x = sp.symbols("x1:7")
    Phi, Psi = sp.symbols("Phi_1:3"), sp.symbols("Psi_1:3")
    rng = np.random.default_rng(7)

    def polynomial():
        return sum(int(rng.integers(-3, 4)) * x[i] * x[j] * x[k] for i, j, k in itertools.combinations(range(6), 3))

    A = sp.Matrix(2, 2, lambda i, j: polynomial())
    p = charpoly(A, Phi, Psi)
    assert p.domain == sp.EX and max(node_count(c, 10**6) for c in p.all_coeffs()) > EXPAND_NODES
    symbols = [*x, *Phi, *Psi]
    coefficients = sp.lambdify(symbols, p.all_coeffs(), "numpy")
    entries = sp.lambdify(symbols, A, "numpy")
    for _ in range(3):
        point = rng.uniform(-1, 1, len(symbols))
        An = np.array(entries(*point), dtype=float)
        J = np.block([[np.diag(point[8:]) @ An, np.diag(point[6:8])], [An, np.zeros((2, 2))]])
        c = np.array(coefficients(*point), dtype=float)
        assert c / c[0] == pytest.approx(np.poly(J), rel=1e-8, abs=1e-8)


def test_a_linearization_pickles_without_its_minors_and_derives_them_again():
    """An atlas sends the scene to its workers: the minors' polynomial rings stay behind (SymPy's
    PolyRing does not pickle reliably) and the unpickled linearization gives the same det A and (4.6)."""
    cloudpickle = pytest.importorskip("cloudpickle")  # how dask sends a scene (lambdified functions too)

    lin = cs.scene("brake").linearization()
    det_A, p = lin.det_A, lin.charpoly
    assert "minors" in lin.__dict__ and "minors" not in lin.__getstate__()
    again = cloudpickle.loads(cloudpickle.dumps(lin))
    assert "minors" not in again.__dict__
    assert again.det_A == det_A and again.charpoly == p and again.minors.size == 2


@pytest.mark.parametrize("name", ["sliding-point", "painleve-rod", "double-pendulum-tip", "chain-3"])
def test_one_contact_a_is_its_minor_and_the_adjugate_path_gives_the_same(name):
    """k = 1: A = (det A), read off the bordered determinant over det M without adj(M); the same
    canonical entry as W^T adj(M) V / det M (minors.product_of), and the same value at a random point."""
    from contactsym.scenes.link_chain import build_chain
    from contactsym.stages.minors import product_of

    scene = build_chain(3) if name == "chain-3" else cs.scene(name)
    lin = scene.linearization()
    assert lin.fast.k == 1 and lin.factors is not None
    assert lin.A == product_of(*lin.factors)
    M, W, V = lin.factors
    symbols = sorted(set().union(*(X.free_symbols for X in (M, W, V))), key=str)
    point = {x: -1 if isinstance(x, SignSymbol) else sp.Rational(3 + i, 5 + 2 * i) for i, x in enumerate(symbols)}
    numeric = [np.array(X.xreplace(point).evalf(30).tolist(), dtype=float) for X in (M, W, V)]
    direct = numeric[1].T @ np.linalg.solve(numeric[0], numeric[2])
    assert float(lin.A[0, 0].xreplace(point)) == pytest.approx(direct[0, 0], rel=1e-9)
