"""Stability of the fast subsystem and its robustness to the contact law (Propositions 3-8).

The library's exact conditions are compared with numpy eigenvalues of (4.5)
``[[Psi A, Phi], [A, 0]]`` for many sampled laws (Phi_j, Psi_j < 0).
"""

from fractions import Fraction
from functools import cache

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, event, example, given, settings
from hypothesis import strategies as st
from sympy.core.cache import clear_cache
from sympy.logic.boolalg import Boolean
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.algebra.basic import SignSymbol
from contactsym.algebra.hurwitz import Hurwitz, hurwitz_minors
from contactsym.errors import SingularJacobianError
from contactsym.stages.stability import Stability
from tests.helpers import exact, small_fractions

# --- scenes ---------------------------------------------------------------------------


def user_scene(A, compliances=None, extra=None):
    """q_j'' = sum_i A[j, i] N_i + b_j (+ extra[j]): f(u) = A u + b, generic laws by default."""
    k = A.rows
    q = dynamicsymbols(f"q_1:{k + 1}")
    N = sp.symbols(f"N_1:{k + 1}", real=True)
    b = sp.symbols(f"b_1:{k + 1}", real=True)
    G = [sum(A[j, i] * N[i] for i in range(k)) + b[j] + (extra[j] if extra else 0) for j in range(k)]
    compliances = compliances or [None] * k
    contacts = [cs.Contact(coordinate=q[j], reaction=N[j], compliance=compliances[j]) for j in range(k)]
    return cs.Scene.from_accelerations(q, G, contacts)


def symbols_matrix(k):
    return sp.Matrix(k, k, lambda i, j: sp.Symbol(f"a_{i + 1}{j + 1}", real=True))


@cache
def symbolic(k):
    """A scene with a fully symbolic A, and its Stability, built once per k."""
    A = symbols_matrix(k)
    scene = user_scene(A)
    return A, scene.stability()


def truth(boolean, values):
    """A sympy Boolean at numbers: True or False (fails if it does not evaluate)."""
    value = exact(boolean, values)  # = xreplace, by exact arithmetic in a compiled function
    assert value in (sp.true, sp.false), f"{boolean} did not evaluate at {values}: {value}"
    return bool(value)


def values_for(k, A, Phi=None, Psi=None):
    symbols, stability = symbolic(k)
    values = {symbols[i, j]: A[i, j] for i in range(k) for j in range(k)}
    lin = stability.linearization
    if Phi is not None:
        values.update(zip(lin.Phi, Phi))
        values.update(zip(lin.Psi, Psi))
    return values


# --- numerics -------------------------------------------------------------------------


def block_matrices(A, P, S):
    """(4.5) for many laws at once: Phi = -P, Psi = -S (arrays of shape (laws, k))."""
    A = np.asarray(A, dtype=float)
    P, S = np.atleast_2d(P), np.atleast_2d(S)
    k = A.shape[0]
    M = np.zeros((P.shape[0], 2 * k, 2 * k))
    M[:, :k, :k] = -S[:, :, None] * A[None, :, :]
    M[:, k:, :k] = A
    for j in range(k):
        M[:, j, k + j] = -P[:, j]
    return M


def spectra(A, P, S):
    """(max Re eigenvalue, min |Re eigenvalue|, tolerance) for each law."""
    M = block_matrices(A, P, S)
    eig = np.linalg.eigvals(M)
    tol = 1e-9 * np.maximum(1.0, np.abs(M).sum(axis=(1, 2)))
    return eig.real.max(axis=1), np.abs(eig.real).min(axis=1), tol


def sampled_laws(k, seed, count=300):
    """Random laws with |Phi_j|, |Psi_j| log-uniform in 1e-3..1e3, plus a decade grid's corners."""
    rng = np.random.default_rng(seed)
    P = 10.0 ** rng.uniform(-3, 3, (count, k))
    S = 10.0 ** rng.uniform(-3, 3, (count, k))
    corners = np.array([1e-3, 1.0, 1e3])
    grid = np.array(np.meshgrid(*[corners] * (2 * k))).reshape(2 * k, -1).T
    return np.vstack([P, grid[:, :k]]), np.vstack([S, grid[:, k:]])


def law_search_k2(A):
    """A few thousand laws for k = 2: a decade grid, the paper's recipes, random ones.

    Recipes: Phi_1 = Phi_2 large vs small (with Psi small or large); and Psi -> 0 with
    |Phi_j| a_jj equal, where Phi A has complex eigenvalues when a_12 a_21 < 0.
    """
    decades = 10.0 ** np.arange(-3, 4)
    grid = np.array(np.meshgrid(decades, decades, decades, decades)).reshape(4, -1).T
    P, S = [grid[:, :2]], [grid[:, 2:]]
    for t in 10.0 ** np.arange(-3, 4):
        for s in (1e-3, 1e-2, 1e3):
            P.append(np.array([[t, t]]))
            S.append(np.array([[s, s]]))
            diagonal = np.abs([float(A[0, 0]), float(A[1, 1])])
            if diagonal.min() > 0:
                P.append(t / diagonal[None, :])
                S.append(np.array([[s, s]]) * 1e-2)
    rng = np.random.default_rng(0)
    P.append(10.0 ** rng.uniform(-3, 3, (500, 2)))
    S.append(10.0 ** rng.uniform(-3, 3, (500, 2)))
    return np.vstack(P), np.vstack(S)


# --- strategies -----------------------------------------------------------------------


def rational(f: Fraction) -> sp.Rational:
    return sp.Rational(f.numerator, f.denominator)


entries = small_fractions(min_value=-4, max_value=4, max_denominator=3).map(rational)
nonzero_entries = st.builds(
    lambda sign, f: sign * rational(f),
    st.sampled_from([1, -1]),
    small_fractions(min_value=Fraction(1, 3), max_value=4, max_denominator=3),
)
magnitudes = st.builds(lambda m, e: sp.Rational(m) * sp.Rational(10) ** e, st.integers(1, 9), st.integers(-2, 2))


# strategies are built once per argument (cache): tests that draw them from st.data() would otherwise
# build and validate a fresh strategy tree at every example (a fifth of test_hurwitz_iff_...'s time);
# the draws are the same


@cache
def general_matrices(k, entry=entries):
    return st.lists(entry, min_size=k * k, max_size=k * k).map(lambda xs: sp.Matrix(k, k, xs))


@cache
def spd_matrices(k):
    """B^T B + D with D > 0 diagonal: symmetric positive definite (Proposition 7)."""
    small = st.integers(-2, 2)
    return st.builds(
        lambda B, d: B.T * B + sp.diag(*d),
        st.lists(small, min_size=k * k, max_size=k * k).map(lambda xs: sp.Matrix(k, k, xs)),
        st.lists(st.integers(1, 3).map(lambda n: sp.Rational(n, 2)), min_size=k, max_size=k),
    )


@cache
def matrices(k):
    return st.one_of(general_matrices(k), spd_matrices(k))


@cache
def laws(k):
    vector = st.lists(magnitudes, min_size=k, max_size=k)
    return st.tuples(vector.map(lambda xs: [-x for x in xs]), vector.map(lambda xs: [-x for x in xs]))


def as_float(A):
    return np.array(A.tolist(), dtype=float)


# --- (a) Hurwitz conditions <=> eigenvalues of (4.5) ------------------------------------


@pytest.mark.parametrize("k", [1, 2, 3])
@settings(max_examples=200, deadline=None)
@given(data=st.data())
def test_hurwitz_iff_eigenvalues_in_left_half_plane(k, data):
    _, stability = symbolic(k)
    conditions = stability.hurwitz
    A = data.draw(matrices(k), label="A")
    Phi, Psi = data.draw(laws(k), label="law")
    P = np.array([-float(x) for x in Phi])
    S = np.array([-float(x) for x in Psi])
    top, closest, tol = spectra(as_float(A), P, S)
    assume(closest[0] > 1e-6 * max(1.0, abs(top[0])) and closest[0] > tol[0])
    values = values_for(k, A, Phi, Psi)
    evaluated = [exact(c, values) for c in conditions]  # = xreplace, by exact arithmetic in a compiled function
    assert all(v.is_Rational for v in evaluated)
    stable = all(v > 0 for v in evaluated)
    event("stable" if stable else "unstable")
    assert stable == bool(top[0] < 0)


# --- (b) robust classes are robust over sampled laws ------------------------------------


@pytest.mark.parametrize("k", [1, 2, 3])
@settings(max_examples=200, deadline=None)
@given(data=st.data())
def test_robust_classes_agree_with_sampled_laws(k, data):
    _, stability = symbolic(k)
    A = data.draw(matrices(k), label="A")
    seed = data.draw(st.integers(0, 2**32 - 1), label="seed")
    values = values_for(k, A)
    robustly_stable = truth(stability.robustly_stable, values)
    robustly_unstable = truth(stability.robustly_unstable, values)
    assert not (robustly_stable and robustly_unstable)
    if not (robustly_stable or robustly_unstable):
        event("neither")
        return
    P, S = sampled_laws(k, seed)
    top, _, tol = spectra(as_float(A), P, S)
    if robustly_stable:
        event("robustly stable")
        assert (top < tol).all(), f"a sampled law is unstable: Phi={-P[top >= tol][0]}, Psi={-S[top >= tol][0]}"
    else:
        event("robustly unstable")
        assert (top > -tol).all(), f"a sampled law is stable: Phi={-P[top <= -tol][0]}, Psi={-S[top <= -tol][0]}"


@settings(max_examples=40, deadline=None)
@given(spd_matrices(3))
def test_proposition_7_spd_is_robustly_stable(A):
    _, stability = symbolic(3)
    assert truth(stability.robustly_stable, values_for(3, A))
    assert not truth(stability.robustly_unstable, values_for(3, A))


# --- (c) law-dependent (k = 2): some law is stable, some unstable -----------------------


def law_dependent_k2_matrices():
    """General 2 x 2 matrices (half of them with a nonzero diagonal), and a_jj > 0 > a_12 a_21 ones."""
    general = st.one_of(general_matrices(2, nonzero_entries), general_matrices(2))
    positive = small_fractions(min_value=Fraction(1, 3), max_value=4, max_denominator=3).map(rational)
    coupled = st.builds(
        lambda a, d, b, c: sp.Matrix([[a, b], [-c, d]]),
        positive,
        positive,
        positive,
        positive,
    )
    return st.one_of(general, coupled)


@settings(max_examples=150, deadline=None)
@given(law_dependent_k2_matrices())
@example(sp.Matrix([[1, 1], [-1, 1]]))  # the brake at alpha = 90 deg, m = mu = 1
@example(sp.Matrix([[5, 1], [-sp.Rational(1, 9), sp.Rational(1, 3)]]))  # narrow window of |Phi_1|/|Phi_2|
@example(sp.Matrix([[2, 1], [-3, -1]]))  # a_11 > 0 > a_22
def test_law_dependent_finds_stable_and_unstable_laws(A):
    _, stability = symbolic(2)
    values = values_for(2, A)
    assume(truth(stability.law_dependent, values))
    assert not truth(stability.robustly_stable, values)
    assert not truth(stability.robustly_unstable, values)
    assert not truth(stability.undecided, values)
    P, S = law_search_k2(A)
    top, _, tol = spectra(as_float(A), P, S)
    assert (top < -tol).any(), "no stable law found"
    assert (top > tol).any(), "no unstable law found"
    # and the library's own Hurwitz conditions agree at one stable and one unstable law
    for index in (int(np.argmin(top)), int(np.argmax(top))):
        # the law as exact rationals (the floats' own values), evaluated exactly in a compiled function
        law_values = values_for(2, A, [-sp.Rational(p) for p in P[index]], [-sp.Rational(s) for s in S[index]])
        assert all(exact(c, law_values) > 0 for c in stability.hurwitz) == bool(top[index] < 0)


@settings(max_examples=200, deadline=None)
@given(general_matrices(2))
def test_k2_classification_is_exclusive_and_complete_off_det_zero(A):
    _, stability = symbolic(2)
    values = values_for(2, A)
    verdicts = [truth(b, values) for b in (stability.robustly_stable, stability.robustly_unstable)]
    verdicts.append(truth(stability.law_dependent, values))
    assert sum(verdicts) <= 1
    assert truth(stability.undecided, values) == (not any(verdicts))
    if A.det() != 0:
        assert sum(verdicts) == 1  # Proposition 6 with Remarks 1-2 decides every det A != 0
    event(
        ["robustly stable", "robustly unstable", "law dependent", "undecided"][
            verdicts.index(True) if any(verdicts) else 3
        ]
    )


@pytest.mark.parametrize("A", [[[0, 1], [-1, -1]], [[0, 1], [-1, 0]], [[-2, 1], [-1, 0]]])
def test_k2_zero_diagonal_boundary_is_robustly_unstable(A):
    """det A > 0, a_11 <= 0, a_22 <= 0 with a zero on the diagonal: p_3 <= 0, unstable for every law.

    (The first version of Stability, with strict a_jj < 0 as printed in Proposition 6, called these
    law-dependent.)
    """
    A = sp.Matrix(A)
    stability = user_scene(A).stability()
    assert A.det() > 0 and A[0, 0] <= 0 and A[1, 1] <= 0
    P, S = law_search_k2(A)
    top, _, tol = spectra(as_float(A), P, S)
    assert (top > -tol).all()  # numerically no law is stable
    assert stability.law_dependent == sp.false
    assert stability.robustly_unstable == sp.true
    assert stability.undecided == sp.false


def test_k2_p3_nonpositive_means_unstable_for_every_law():
    """The reason behind the test above, checked exactly on the characteristic polynomial."""
    A = sp.Matrix([[0, 1], [-1, -1]])
    stability = user_scene(A).stability()
    p3 = stability.routh_hurwitz.coefficients[1]
    Psi_1, Psi_2 = stability.linearization.Psi
    assert sp.expand(p3 - Psi_2) == 0  # -(Psi_1 * 0 + Psi_2 * (-1)) = Psi_2 < 0
    assert p3.is_negative


# --- numeric scenes agree with the symbolic one ----------------------------------------


@pytest.mark.parametrize("k", [1, 2, 3])
@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_numeric_scene_agrees_with_symbolic_scene(k, data):
    _, symbolic_stability = symbolic(k)
    A = data.draw(matrices(k), label="A")
    law = data.draw(laws(k), label="law")
    assume(A.det() != 0)
    values = values_for(k, A, *law)
    numeric = user_scene(A).stability()
    assert numeric.A == A
    for name in ("robustly_stable", "robustly_unstable", "law_dependent"):
        exact = getattr(numeric, name)
        at_point = symbolic_stability.verdicts[name].at(values)  # three-valued at the point
        if k <= 2:  # Propositions 3 and 6 decide every det A != 0
            assert exact in (sp.true, sp.false), f"{name} = {exact} is not decided for numeric A"
            assert exact == at_point == truth(getattr(symbolic_stability, name), values)
        elif at_point is not None:  # what the closed forms decide, the numeric A decides alike
            assert exact == at_point, f"{name}: {exact} for numeric A, {at_point} from the symbolic regions"
    lin = numeric.linearization
    law_values = dict(zip(lin.Phi + lin.Psi, law[0] + law[1]))
    ours = [c.xreplace(law_values) for c in numeric.hurwitz]
    theirs = [c.xreplace(values) for c in symbolic_stability.hurwitz]
    assert all(c > 0 for c in ours) == all(c > 0 for c in theirs)


def test_singular_A_raises():
    stability = user_scene(sp.Matrix([[1, 2], [2, 4]])).stability()
    with pytest.raises(SingularJacobianError):
        _ = stability.hurwitz
    assert stability.robustly_stable == sp.false
    assert stability.law_dependent == sp.false
    assert stability.undecided == sp.true


# --- Hopf set and frequency ------------------------------------------------------------


@st.composite
def hopf_k2(draw):
    """A with a_11, a_22 > 0 and (a_11 - a_22)^2 + 4 a_12 a_21 < 0, equal laws on the Hopf set.

    With Phi_j = -P, Psi_j = -S, T = a_11 + a_22, D = det A: Delta_3 = D S^2 P (P (T^2 - 4 D) + 2 T D S^2),
    so P = 2 T D S^2 / (4 D - T^2), and omega^2 = p_1 / p_3 = 2 D P / T.
    """
    positive = small_fractions(min_value=Fraction(1, 3), max_value=4, max_denominator=3).map(rational)
    a11, a22, a12, extra, S = draw(positive), draw(positive), draw(positive), draw(positive), draw(positive)
    a21 = -((a11 - a22) ** 2 / (4 * a12) + extra)
    A = sp.Matrix([[a11, a12], [a21, a22]])
    T, D = a11 + a22, A.det()
    P = 2 * T * D * S**2 / (4 * D - T**2)
    return A, P, S, 2 * D * P / T


def on_hopf_set(stability, values):
    """Delta_(n-1) = 0 with the other Liénard–Chipart conditions positive (the Hopf set, evaluated directly)."""
    poly = stability.linearization.charpoly
    minor = hurwitz_minors(poly)[poly.degree() - 2]  # Delta_(n-1), recomputed independently
    others = [c for c in stability.hurwitz if sp.expand(c - minor) != 0]
    assert len(others) == len(stability.hurwitz) - 1
    return minor.xreplace(values) == 0 and all(c.xreplace(values) > 0 for c in others)


@settings(max_examples=60, deadline=None)
@given(hopf_k2())
def test_hopf_set_and_frequency_k2(data):
    A, P, S, omega_squared = data
    _, stability = symbolic(2)
    values = values_for(2, A, [-P, -P], [-S, -S])
    assert truth(stability.law_dependent, values)
    assert on_hopf_set(stability, values)
    assert truth(stability.hopf, values)
    assert stability.hopf_frequency.xreplace(values) ** 2 == omega_squared
    eig = np.linalg.eigvals(block_matrices(as_float(A), [float(P)] * 2, [float(S)] * 2)[0])
    omega = float(sp.sqrt(omega_squared))
    assert np.abs(eig - 1j * omega).min() < 1e-6 * max(1.0, omega)
    assert np.abs(eig.real).min() < 1e-6 * max(1.0, np.abs(eig).max())
    # just off the Hopf set the pair crosses: smaller |Phi| stable, larger unstable
    below = spectra(as_float(A), [float(P) * 0.9] * 2, [float(S)] * 2)[0][0]
    above = spectra(as_float(A), [float(P) * 1.1] * 2, [float(S)] * 2)[0][0]
    assert below < 0 < above
    off = values_for(2, A, [-P * 11 / 10] * 2, [-S, -S])  # Delta_3 is linear in P on this line: one zero
    assert not on_hopf_set(stability, off)
    assert not truth(stability.hopf, off)


def hopf_point_k2():
    A = sp.Matrix([[1, 1], [-1, 1]])  # T = 2, D = 2: with S = 1, P = 2 T D / (4 D - T^2) = 2
    return A, values_for(2, A, [-2, -2], [-1, -1])


def test_hopf_boolean_on_a_fresh_stability_object():
    A, values = hopf_point_k2()
    stability = user_scene(symbols_matrix(2)).stability()
    assert truth(stability.hopf, values)
    assert stability.hopf_frequency.xreplace(values) == 2  # omega^2 = 2 D P / T = 4
    assert not truth(stability.hopf, {**values, stability.linearization.Phi[0]: -3})


def test_hopf_boolean_does_not_depend_on_the_sympy_cache():
    """Regression: hopf once excluded Delta_(n-1) from the other conditions by object identity
    (``c is not minor``) between two separate computations of the minors, so after a cache eviction
    it became And(Delta > 0, ..., Eq(Delta, 0)), False everywhere."""
    A, values = hopf_point_k2()
    stability = user_scene(symbols_matrix(2)).stability()
    _ = stability.hurwitz  # the Liénard–Chipart conditions are computed first (as any caller may do)
    clear_cache()  # what enough unrelated SymPy work does to the LRU cache
    assert on_hopf_set(stability, values)
    assert truth(stability.hopf, values)


def test_hopf_is_false_for_one_contact():
    _, stability = symbolic(1)
    assert stability.hopf == sp.false
    assert stability.hopf_frequency is None


# --- k = 1 and k >= 3 bookkeeping --------------------------------------------------------


def test_k1_propositions_3_4_5():
    (a,), stability = symbolic(1)[0], symbolic(1)[1]
    propositions = stability.propositions
    names = " ".join(propositions)
    for number in (3, 4, 5):
        assert f"Proposition {number}" in names
    assert propositions["Proposition 3 (stable)"] == sp.Gt(a, 0)
    assert propositions["Proposition 3 (unstable)"] == sp.Lt(a, 0)
    assert propositions["Proposition 5 (no cycles)"] == sp.true  # generic law: constant Phi, Psi
    assert stability.law_dependent == sp.false


def test_k1_with_abs_friction_and_sign_symbols():
    a, c = sp.symbols("a c", real=True)
    N = sp.Symbol("N_1", real=True)
    scene = user_scene(sp.Matrix([[a]]), extra=[c * sp.Abs(N)])
    stability = scene.stability()
    (s,) = stability.linearization.sign_values
    assert isinstance(s, SignSymbol)
    assert stability.robustly_stable == sp.Gt(a + c * s, 0)
    for sign in (1, -1):
        fixed = scene.stability(signs=(sign,))
        assert fixed.robustly_stable == sp.Gt(a + sign * c, 0)
        assert not any(isinstance(x, SignSymbol) for x in fixed.robustly_stable.free_symbols)
    unique = stability.propositions["Proposition 4 (unique stable reaction for every load)"]
    for av, cv, expected in [(3, 1, True), (3, -1, True), (1, 2, False), (1, -2, False)]:
        assert truth(unique, {a: av, c: cv}) == expected


def test_k1_nonlinear_law_has_no_proposition_5():
    q, qd = sp.symbols("q qdot", real=True)
    eps, kk, d, cc = sp.symbols("epsilon k d c", positive=True)
    law = cs.Law(-kk * q / eps**2 - d * qd / eps - cc * (qd / eps) ** 3, q, qd, eps)
    stability = user_scene(sp.Matrix([[2]]), compliances=[law]).stability()
    assert stability.propositions["Proposition 5 (no cycles)"] == sp.false
    assert stability.robustly_stable == sp.true
    assert stability.linearization.Psi == (-d,)


def test_k3_law_dependent_is_a_region_and_undecided_is_boolean():
    A, stability = symbolic(3)
    assert isinstance(stability.law_dependent, Boolean)
    assert isinstance(stability.undecided, Boolean)
    names = " ".join(stability.propositions)
    assert "Proposition 7" in names and "Proposition 8" in names
    # a non-symmetric A with all principal minors positive: no closed form decides
    B = sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]])
    values = {A[i, j]: B[i, j] for i in range(3) for j in range(3)}
    assert truth(stability.undecided, values)
    spd = {**values, A[0, 1]: -1, A[1, 2]: -1}  # [[2, -1, 0], [-1, 2, -1], [0, -1, 2]]: SPD
    assert truth(stability.robustly_stable, spd)
    assert not truth(stability.undecided, spd)
    # three-valued at the point: a nested sequence of positive minors disproves "unstable for every law",
    # nothing in closed form decides the other two
    verdicts = stability.verdicts
    assert verdicts["robustly_unstable"].at(values) == sp.false
    assert verdicts["robustly_stable"].at(values) is None
    assert verdicts["law_dependent"].at(values) is None
    numeric = user_scene(B).stability()
    assert numeric.robustness.verdict == "law-dependent"  # the point decision finds witness laws
    assert numeric.law_dependent == sp.true  # and the property says so (it once said False)
    assert numeric.robustly_stable == sp.false and numeric.robustly_unstable == sp.false
    assert numeric.undecided == sp.false


def test_k4_law_dependent_is_decided():
    A = sp.Matrix([[3, 1, 0, 0], [1, 3, 1, 0], [0, 1, 3, 1], [0, 0, 1, 3]])
    stability = user_scene(A).stability()
    assert stability.law_dependent == sp.false
    assert stability.robustly_stable == sp.true
    assert isinstance(stability.undecided, Boolean) and stability.undecided == sp.false
    assert isinstance(stability, Stability)


# --- the brake (§6) ---------------------------------------------------------------------

brake = cs.scene("brake")
m, mu, alpha = sp.symbols("m mu alpha", positive=True)

brake_parameters = st.fixed_dictionaries(
    {alpha: st.floats(0.1, 3.0), mu: st.floats(0.05, 2.0), m: st.floats(0.2, 5.0)}
).map(lambda d: {key: sp.Float(value) for key, value in d.items()})


def brake_A(values):
    return np.array(brake.linearization().A.xreplace(values).tolist(), dtype=float)


@settings(max_examples=100, deadline=None)
@given(brake_parameters, st.integers(0, 2**32 - 1))
def test_brake_robustness_over_sampled_laws(values, seed):
    stability = brake.stability()
    margin = float(mu.xreplace(values)) - abs(1 / np.tan(float(alpha.xreplace(values))))
    assume(abs(margin) > 1e-3)
    robustly_stable = truth(stability.robustly_stable, values)
    assert robustly_stable == (margin < 0)  # (6.3): mu < |cot alpha|
    assert not truth(stability.robustly_unstable, values)  # a_jj = 1/m > 0, det A > 0
    assert truth(stability.law_dependent, values) == (not robustly_stable)
    A = brake_A(values)
    if robustly_stable:
        event("robustly stable")
        P, S = sampled_laws(2, seed)
        top, _, tol = spectra(A, P, S)
        assert (top < tol).all()
    else:
        event("law dependent")
        P, S = law_search_k2(sp.Matrix(A))
        top, _, tol = spectra(A, P, S)
        assert (top < -tol).any() and (top > tol).any()


@settings(max_examples=100, deadline=None)
@given(brake_parameters, laws(2))
def test_brake_hurwitz_iff_eigenvalues(values, law):
    stability = brake.stability()
    lin = stability.linearization
    Phi, Psi = law
    P = np.array([-float(x) for x in Phi])
    S = np.array([-float(x) for x in Psi])
    top, closest, tol = spectra(brake_A(values), P, S)
    assume(closest[0] > 1e-6 * max(1.0, abs(top[0])) and closest[0] > tol[0])
    full = {**values, **dict(zip(lin.Phi + lin.Psi, [sp.Float(x) for x in Phi + Psi]))}
    assert all(c.xreplace(full) > 0 for c in stability.hurwitz) == bool(top[0] < 0)


@pytest.mark.parametrize(
    ("mu_value", "m_value", "Psi_value"), [(1, 1, -1), (sp.Rational(1, 2), 1, -2), (2, 3, -sp.Rational(1, 3))]
)
def test_brake_right_angle_hopf_6_4(mu_value, m_value, Psi_value):
    """alpha = 90 deg, Phi_j = Phi, Psi_j = Psi: stable iff -mu^2 m Phi < Psi^2 (1 + mu^2) ((6.4) for m = 1);
    at equality a Hopf point with omega = -(1 + mu^2) Psi / (m mu)."""
    stability = brake.stability()
    lin = stability.linearization
    Phi_value = -(1 + mu_value**2) * Psi_value**2 / (m_value * mu_value**2)
    base = {alpha: sp.pi / 2, mu: mu_value, m: m_value}
    at = {**base, **dict(zip(lin.Phi + lin.Psi, [Phi_value] * 2 + [Psi_value] * 2))}
    assert truth(stability.law_dependent, base)
    assert on_hopf_set(stability, at)
    omega = -(1 + mu_value**2) * Psi_value / (m_value * mu_value)
    assert sp.simplify(stability.hopf_frequency.xreplace(at) - omega) == 0
    for factor, stable in [(sp.Rational(9, 10), True), (sp.Rational(11, 10), False)]:
        near = {**at, **dict(zip(lin.Phi, [Phi_value * factor] * 2))}
        assert all(c.xreplace(near) > 0 for c in stability.hurwitz) == stable


def test_brake_open_signs_are_fixed_by_unilateral_contacts():
    stability = brake.stability()
    assert stability.linearization.sign_values == (1, 1)
    assert brake.stability(signs=(1, 1)).robustly_stable == stability.robustly_stable
    assert not any(isinstance(x, SignSymbol) for x in stability.robustly_stable.free_symbols)


# --- a scene with open sign patterns (§5) ---------------------------------------------


guides = cs.scene("painleve-klein-guides")
phi, mu1, mu2 = (next(p for p in guides.parameters if p.name == name) for name in ("phi", "mu_1", "mu_2"))


@settings(max_examples=80, deadline=None)
@given(
    st.sampled_from([(1, 1), (1, -1), (-1, 1), (-1, -1)]),
    st.fixed_dictionaries({phi: st.floats(0.1, 1.5), mu1: st.floats(0.0, 3.0), mu2: st.floats(0.0, 3.0)}),
    st.integers(0, 2**32 - 1),
)
def test_guides_classification_per_sign_pattern(signs, parameters, seed):
    values = {key: sp.Float(v) for key, v in parameters.items()}
    stability = guides.stability(signs=signs)
    A = np.array(stability.A.xreplace(values).tolist(), dtype=float)
    assume(abs(np.linalg.det(A)) > 1e-3 and np.abs(np.diag(A)).min() > 1e-3)
    assume(abs(A[0, 1] * A[1, 0]) > 1e-3)
    stable = truth(stability.robustly_stable, values)
    unstable = truth(stability.robustly_unstable, values)
    dependent = truth(stability.law_dependent, values)
    assert stable + unstable + dependent == 1
    # the open-pattern object, with the sign symbols substituted, says the same
    open_pattern = guides.stability()
    s1, s2 = open_pattern.linearization.sign_values
    with_signs = {**values, s1: signs[0], s2: signs[1]}
    assert truth(open_pattern.robustly_stable, with_signs) == stable
    assert truth(open_pattern.law_dependent, with_signs) == dependent
    if dependent:
        event("law dependent")
        P, S = law_search_k2(sp.Matrix(A))
        top, _, tol = spectra(A, P, S)
        assert (top < -tol).any() and (top > tol).any()
    else:
        event("robustly stable" if stable else "robustly unstable")
        P, S = sampled_laws(2, seed)
        top, _, tol = spectra(A, P, S)
        assert (top < tol).all() if stable else (top > -tol).all()


def test_the_hurwitz_conditions_cite_the_equation_of_their_stage():
    """Hurwitz is algebra: the stage owns the number ((3.2) for one contact, (4.7) for more)."""
    one = cs.scene("sliding-point").stability().routh_hurwitz.formulas()
    two = cs.scene("painleve-klein-guides").stability().routh_hurwitz.formulas()
    assert one and {f.cite() for f in one} == {"(3.2)"}
    assert two and all(f.paper[0] == "4.7" for f in two)
    a, b = sp.symbols("a b")
    plain = Hurwitz(sp.Poly(cs.lam**2 + a * cs.lam + b, cs.lam)).formulas()
    assert [f.rhs for f in plain] == [a, b] and not any(f.paper for f in plain)  # no stage, no number


# --- the k = 3 stool: Hopf frequency against the subresultant root and the eigenvalues ----------

from tests.stool import h as stool_h  # noqa: E402
from tests.stool import mu as stool_mu  # noqa: E402
from tests.stool import stool_scene  # noqa: E402


@cache
def _stool():
    stability = stool_scene().stability()
    return stability, stability.hurwitz, stability.hopf_frequency


def _old_omega_squared(poly):
    """omega^2 as it was derived before: the root of SymPy's degree-1 subresultant of the even
    and odd parts of p(i omega), cancelled (independent of the library's Hurwitz code)."""
    z = sp.Symbol("z")
    a = poly.all_coeffs()[::-1]  # a[i]: the coefficient of lambda**i
    n = poly.degree()
    even = sp.Poly(sum((-1) ** i * a[2 * i] * z**i for i in range(n // 2 + 1)), z)
    odd = sp.Poly(sum((-1) ** i * a[2 * i + 1] * z**i for i in range((n - 1) // 2 + 1)), z)
    linear = sp.Poly([s for s in sp.subresultants(even, odd) if sp.Poly(s, z).degree() == 1][0], z)
    return -linear.coeff_monomial(1) / linear.coeff_monomial(z)


def _stool_point(rng, tau=None):
    stability, conditions, _ = _stool()
    values = {}
    for s in sorted(set().union(*[c.free_symbols for c in conditions]), key=str):
        if isinstance(s, SignSymbol):
            values[s] = int(rng.choice([-1, 1]))
        elif s == stool_mu:
            values[s] = sp.Rational(int(rng.integers(1, 150)), 100)
        elif s == stool_h:
            values[s] = sp.Rational(int(rng.integers(20, 300)), 100)
        elif s.name.startswith("Phi"):
            values[s] = -sp.Rational(int(rng.integers(1, 100)), 10)
        else:  # Psi_j = -tau d_j: a line of laws through the origin
            values[s] = -(tau if tau is not None else 1) * sp.Rational(int(rng.integers(1, 100)), 10)
    return values


def test_stool_frequency_equals_the_subresultant_root_at_random_points():
    """The k = 3 frequency is kept as N/Delta_3 in the coefficients (no expansion); at exact random
    points it equals the old derivation's value."""
    stability, _, omega = _stool()
    assert omega.is_Pow and omega.exp == sp.S.Half
    charpoly = stability.linearization.charpoly
    rng = np.random.default_rng(25)
    for _ in range(4):
        values = _stool_point(rng)
        # the old derivation at the point: the subresultant root of the numeric polynomial
        old = _old_omega_squared(sp.Poly(charpoly.as_expr().xreplace(values), charpoly.gens[0]))
        assert omega.base.xreplace(values) == old


@settings(max_examples=6, deadline=None)
@given(st.integers(0, 10**6))
def test_stool_frequency_is_the_imaginary_pair_on_the_hopf_set(seed):
    """At points of the Hopf set (Delta_5 = 0 solved on a line Psi = -tau d, the other conditions
    positive there), (4.5) has eigenvalues +-i omega and the others in the left half-plane."""
    stability, conditions, omega = _stool()
    labels = stability.routh_hurwitz.labels
    tau = sp.Symbol("tau", positive=True)
    values = _stool_point(np.random.default_rng(seed), tau)
    minor = sp.Poly(sp.expand(conditions[labels.index(("Delta", 5))].xreplace(values)), tau)
    roots = [r for r in minor.real_roots() if r > 0] if minor.degree() > 0 else []
    others = [c for c, label in zip(conditions, labels) if label != ("Delta", 5)]
    on_hopf = [r for r in roots if all(sp.N(c.xreplace(values).xreplace({tau: r}), 40) > 0 for c in others)]
    event(f"points on the Hopf set: {len(on_hopf)}")
    assume(on_hopf)
    point = {s: (v.xreplace({tau: on_hopf[0]}) if isinstance(v, sp.Basic) else v) for s, v in values.items()}
    assert truth_of(stability.hopf, point, digits=40)
    w = complex(sp.N(omega.xreplace(point), 30))
    J = stability.linearization.jacobian.xreplace(point).evalf(30)
    eigenvalues = np.linalg.eigvals(np.array(J.tolist(), dtype=complex))
    assert abs(w.imag) < 1e-20 and w.real > 0
    assert np.abs(eigenvalues - 1j * w.real).min() < 1e-7 * max(1.0, w.real)
    assert np.abs(eigenvalues + 1j * w.real).min() < 1e-7 * max(1.0, w.real)
    rest = sorted(eigenvalues, key=lambda e: min(abs(e - 1j * w.real), abs(e + 1j * w.real)))[2:]
    assert max(e.real for e in rest) < 0


def truth_of(condition, values, digits=30) -> bool:
    """A Boolean of relations at an exact point: Eq by exact zero, the others by 40-digit signs."""
    results = []
    for c in sp.And.make_args(condition):
        value = c.lhs - c.rhs
        if isinstance(c, sp.Eq):
            results.append(abs(sp.N(value.xreplace(values), digits)) < sp.Float(10) ** (-digits // 2))
        else:
            results.append(bool(c.func(sp.N(value.xreplace(values), digits), 0)))
    return all(results)
