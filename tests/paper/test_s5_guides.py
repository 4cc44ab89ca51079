"""§5: Painlevé–Klein with a rigid rod and deformable guides, (5.1)-(5.10), Fig. 1."""

import functools
import math

import numpy as np
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym.algebra.basic import SignSymbol
from tests.helpers import fast_numeric, fast_truth, max_real_part, max_real_parts, same

scene = cs.scene("painleve-klein-guides")
fast = scene.fast_subsystem()
u1, u2 = fast.u
phi, x, y = sp.symbols("phi x y", real=True)
l = sp.Symbol("l", positive=True)
mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
X, Y, M = sp.symbols("X Y M", real=True)
kappa = sp.Symbol("kappa", positive=True)
v1, v2 = sp.symbols("v_1 v_2", real=True)
s1, s2 = SignSymbol("s_1"), SignSymbol("s_2")
lin = scene.linearization()
st_all = scene.stability()


def test_equations_5_1_include_the_moment_m():
    # (5.1) prints x-dot, y-dot for the accelerations and omits M in the moment equation
    from sympy.physics.mechanics import dynamicsymbols

    xs, ys, phis = dynamicsymbols("x y phi")
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    b, h = l * sp.cos(phis), l * sp.sin(phis)
    acc = scene.accelerations
    assert same(acc[xs], -mu1 * sp.Abs(N1) - mu2 * sp.Abs(N2) + X)
    assert same(acc[ys], -N1 + N2 + Y)
    assert same(l**2 * acc[phis], h * (mu1 * sp.Abs(N1) - mu2 * sp.Abs(N2)) - b * (N1 + N2) + M)


def test_contact_accelerations_are_5_2():
    b, h, k = l * sp.cos(phi), l * sp.sin(phi), l
    for j in (1, 2):
        printed = (
            (-1) ** j * (u2 - u1 + Y)
            + b / k**2 * (b * (u1 + u2) - M)
            - b * h / k**2 * (mu1 * sp.Abs(u1) - mu2 * sp.Abs(u2))
        )
        assert same(fast.f[j - 1], cs.algebra.normalize(printed))


def test_matrix_is_5_4_and_determinant_is_5_5():
    sin2 = 1 / (1 + kappa**2)
    printed = sin2 * sp.Matrix([[1 + 2 * kappa**2 - v1, -1 - v2], [-1 - v1, 1 + 2 * kappa**2 - v2]])
    assert same(scene.present(lin.A), printed)
    assert same(scene.present(lin.det_A), 2 * (2 * kappa**2 - v1 - v2) * sin2)


presented = {
    name: sp.lambdify((kappa, v1, v2, s1, s2), scene.present(getattr(st_all, name)))
    for name in ("robustly_stable", "robustly_unstable", "law_dependent")
}


def in_v(name, kappa_value, v1_value, v2_value, s=(1, 1)):
    """Evaluate a presented condition at (kappa, v1, v2) and sign pattern s."""
    return bool(presented[name](kappa_value, v1_value, v2_value, *s))


def corrected_5_6(k, a, b):
    return a + b < 2 * k**2 and a < 1 + 2 * k**2 and b < 1 + 2 * k**2 and (1 + a) * (1 + b) >= 0


samples = st.tuples(
    st.floats(0.05, 3), st.floats(-8, 8), st.floats(-8, 8), st.sampled_from([1, -1]), st.sampled_from([1, -1])
)


@settings(max_examples=200, deadline=None)
@given(samples)
def test_stability_region_is_corrected_5_6_and_instability_is_5_7(sample):
    k, a, b, *s = sample
    assume(abs(a + b - 2 * k**2) > 1e-6 and abs((1 + a) * (1 + b)) > 1e-6)
    stable = in_v("robustly_stable", k, a, b, s)
    assert stable == corrected_5_6(k, a, b)
    # the same set: a triangle plus a right-angle sector
    assert stable == ((a + b < 2 * k**2 and a >= -1 and b >= -1) or (a <= -1 and b <= -1))
    assert in_v("robustly_unstable", k, a, b, s) == (a + b > 2 * k**2)


def law_search(A):
    """Max real parts of (4.5) over a spread of laws (Phi, Psi < 0), one batched eigenvalue call."""
    grid = -(10.0 ** np.arange(-3, 4))
    Phi1, Phi2, Psi1, Psi2 = (x.ravel() for x in np.meshgrid(grid, grid, grid, grid, indexing="ij"))
    return max_real_parts(A, np.stack([Phi1, Phi2], axis=1), np.stack([Psi1, Psi2], axis=1)).tolist()


def test_the_batched_law_search_is_max_real_part_law_by_law():
    A = np.array([[1.0, -2.0], [0.5, 3.0]])
    parts, grid = law_search(A), 10.0 ** np.arange(-3, 4)
    laws = [(p1, p2, q1, q2) for p1 in grid for p2 in grid for q1 in grid for q2 in grid]
    assert np.allclose(parts, [max_real_part(A, [-p1, -p2], [-q1, -q2]) for p1, p2, q1, q2 in laws])


@functools.cache
def _presented_A():
    return scene.present(lin.A)


def A_at(k, a, b):
    presented = _presented_A()
    values = {kappa: k, v1: a, v2: b, s1: 1, s2: 1}
    return np.array([[fast_numeric(e, values) for e in row] for row in presented.tolist()])


def test_robust_claims_hold_for_every_sampled_law_and_the_rest_depends_on_the_law():
    rng = np.random.default_rng(5)
    seen = {"stable": 0, "unstable": 0, "law": 0}
    for _ in range(60):
        k, a, b = rng.uniform(0.2, 2), rng.uniform(-5, 5), rng.uniform(-5, 5)
        if abs(a + b - 2 * k**2) < 1e-3 or abs((1 + a) * (1 + b)) < 1e-3:
            continue
        parts = law_search(A_at(k, a, b))
        if in_v("robustly_stable", k, a, b):
            assert max(parts) < 0
            seen["stable"] += 1
        elif in_v("robustly_unstable", k, a, b):
            assert min(parts) > 0
            seen["unstable"] += 1
        else:
            assert in_v("law_dependent", k, a, b)
            assert min(parts) < 0 < max(parts)
            seen["law"] += 1
    assert min(seen.values()) > 0


def orthant_determinants():
    return [scene.linearization(signs=s).det_A for s in scene.sign_patterns()]


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 1.5), st.floats(0, 4), st.floats(0, 4))
def test_unique_square_5_8_is_coherent_orientation(phi_value, m1, m2):
    k = 1 / math.tan(phi_value)
    assume(abs(k * (m1 + m2) - 2 * k**2) > 1e-6)
    values = {phi: phi_value, mu1: m1, mu2: m2}
    dets = [fast_numeric(d, values) for d in orthant_determinants()]
    coherent = all(d > 0 for d in dets) or all(d < 0 for d in dets)
    assert coherent == (k * m1 + k * m2 < 2 * k**2)  # |v1| + |v2| < 2 kappa^2


def solutions_of_5_3(m1, m2, k, y_load, m_star):
    """Independent count: N2 from 2 k N2 - m1 |N2 + Y| + m2 |N2| = M*, by enumeration."""
    count = 0
    for a in (1, -1):  # sign(N2 + Y)
        for b in (1, -1):  # sign(N2)
            slope = 2 * k - m1 * a + m2 * b
            if abs(slope) < 1e-12:
                continue
            n2 = (m_star + m1 * a * y_load) / slope
            if a * (n2 + y_load) > 0 and b * n2 > 0:
                count += 1
    return count


@settings(max_examples=150, deadline=None)
@given(st.floats(0.1, 1.4), st.floats(0, 4), st.floats(0, 4), st.floats(-5, 5), st.floats(-5, 5))
def test_equilibria_count_matches_5_3_and_the_regions_of_fig_1(phi_value, m1, m2, y_load, m_load):
    k = 1 / math.tan(phi_value)
    values = {phi: phi_value, mu1: m1, mu2: m2, Y: y_load, M: m_load, l: 1.0}
    for signs in scene.sign_patterns():
        assume(abs(fast_numeric(scene.linearization(signs=signs).det_A, values)) > 1e-6)
    for branch in scene.equilibria():  # no root on a switching line N_j = 0
        assume(min(abs(fast_numeric(u, values)) for u in branch.u_star) > 1e-6)
    found = [b for b in scene.equilibria() if fast_truth(b.condition, values)]
    m_star = m_load / math.sin(phi_value) - k * y_load  # M* = M/h - kappa Y with h = l sin(phi)
    for branch in found:  # each branch solves (5.3)
        n1, n2 = (fast_numeric(u, values) for u in branch.u_star)
        assert math.isclose(n1, n2 + y_load, abs_tol=1e-7 * (1 + abs(n1)))
        lhs = 2 * k * n2 - m1 * abs(n2 + y_load) + m2 * abs(n2)
        assert math.isclose(lhs, m_star, rel_tol=1e-7, abs_tol=1e-7)
    assert len(found) == solutions_of_5_3(m1, m2, k, y_load, m_star)
    v_abs = (k * m1, k * m2)
    if sum(v_abs) < 2 * k**2:
        assert len(found) == 1  # the square (5.8)
    elif abs(v_abs[0] - v_abs[1]) > 2 * k**2:
        assert len(found) in (0, 2)  # the sectors (5.10)
    else:
        assert len(found) in (1, 3)  # the half-strips


def test_threshold_5_9_comes_out_of_the_stability_region():
    # The square |v1| + |v2| < 2 kappa^2 leaves the robust region first at its corner
    # (0, -2 kappa^2) (or (-2 kappa^2, 0)), where the factor (1 + v1)(1 + v2) of a12 a21 changes sign.
    coupling = scene.present(lin.A[0, 1] * lin.A[1, 0])
    at_corner = sp.factor(coupling.subs({v1: 0, v2: -2 * kappa**2, s1: 1, s2: 1}))
    (kappa_star,) = sp.solve(at_corner, kappa)
    phi_star = sp.acot(kappa_star)
    assert sp.simplify(sp.tan(phi_star) - sp.sqrt(2)) == 0
    assert math.isclose(math.degrees(float(phi_star)), 54.7356, abs_tol=1e-3)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.2, 1.5))
def test_square_inside_the_stability_region_iff_phi_at_least_arctan_sqrt2(phi_value):
    assume(abs(phi_value - math.atan(math.sqrt(2))) > 1e-3)
    k = 1 / math.tan(phi_value)
    rng = np.random.default_rng(int(phi_value * 1e6))
    points = rng.uniform(-1, 1, size=(400, 2))
    points = points[np.abs(points).sum(axis=1) < 1] * 2 * k**2
    points = np.vstack([points, [[0, -2 * k**2 * 0.999], [-2 * k**2 * 0.999, 0]]])
    inside = all(in_v("robustly_stable", k, a, b) for a, b in points)
    assert inside == (phi_value >= math.atan(math.sqrt(2)))
