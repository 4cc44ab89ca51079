"""§6: a disc braked by two pads (Fig. 2), (6.1)-(6.4) and the squeal frequency omega."""

import math

import numpy as np
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import contactsym as cs
from tests.helpers import fast_matrix, fast_truth, max_real_part, max_real_parts, same, truth

scene = cs.scene("brake")
fast = scene.fast_subsystem()
u1, u2 = fast.u
m, mu, alpha = sp.symbols("m mu alpha", positive=True)
F1, F2 = sp.symbols("F_1 F_2", real=True)
lin = scene.linearization()
stab = scene.stability()
Phi1, Phi2 = lin.Phi
Psi1, Psi2 = lin.Psi
Phi, Psi = sp.symbols("Phi Psi", negative=True)


def newton_6_1() -> sp.Matrix:
    """m q_j'' by Newton's law for the disc's centre: a second derivation, apart from the library's Lagrangian.

    n_1 = (0, 1), n_2 = (-sin a, -cos a); the disc's surface slides along t_j = z x n_j at pad j,
    friction -mu N_j t_j opposes it, and F_j = n_j . F.
    """
    normals = [sp.Matrix([0, 1]), sp.Matrix([-sp.sin(alpha), -sp.cos(alpha)])]
    tangents = [sp.Matrix([-n[1], n[0]]) for n in normals]
    force = sum((N * (n - mu * t) for N, n, t in zip((u1, u2), normals, tangents)), sp.zeros(2, 1))
    along = [sp.expand(n.dot(force)).subs(sp.cos(alpha) ** 2, 1 - sp.sin(alpha) ** 2) for n in normals]
    return sp.Matrix([sp.expand(a) + F for a, F in zip(along, (F1, F2))])


def test_equations_along_the_normals_are_6_1():
    # at rest on the pads (N_j > 0): m q1'' = N1 + N2 (mu sin a - cos a) + F1, m q2'' = N2 - N1 (mu sin a + cos a) + F2
    f = scene.present(fast.piece((1, 1)))
    printed = [u1 + u2 * (mu * sp.sin(alpha) - sp.cos(alpha)) + F1, u2 - u1 * (mu * sp.sin(alpha) + sp.cos(alpha)) + F2]
    for ours, newton, paper in zip(m * f, newton_6_1(), printed):
        assert same(ours, paper) and same(newton, paper)


def test_pads_only_push_so_one_sign_pattern_is_enumerated():
    assert scene.sign_patterns() == [(1, 1)]
    assert len(scene.equilibria()) == 1


def test_matrix_is_6_2():
    printed = sp.Matrix([[1, mu * sp.sin(alpha) - sp.cos(alpha)], [-mu * sp.sin(alpha) - sp.cos(alpha), 1]]) / m
    assert same(lin.A, printed)
    assert same(newton_6_1().jacobian([u1, u2]) / m, printed)
    assert same(lin.det_A, (1 + mu**2) * sp.sin(alpha) ** 2 / m**2)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 3.09), st.floats(0, 3), st.floats(0.1, 10))
def test_robust_stability_is_6_3_with_equality_allowed(a, mu_value, m_value):
    bound = abs(1 / math.tan(a))
    assume(abs(mu_value - bound) > 1e-9)
    values = {alpha: a, mu: mu_value, m: m_value}
    assert fast_truth(stab.robustly_stable, values) == (mu_value < bound)
    assert fast_truth(stab.law_dependent, values) == (mu_value > bound)
    assert stab.robustly_unstable == sp.false


def test_6_3_against_eigenvalues_over_a_spread_of_laws():
    # the bound |cot alpha| checked independently of Proposition 6, on the pipeline's A: below it
    # every sampled law is stable, above it some sampled law is stable and some is not
    A_of = sp.lambdify((alpha, mu, m), lin.A)
    grid = [10.0**e for e in range(-2, 3)]
    laws = [([-p1, -p2], [-s1, -s2]) for p1 in grid for p2 in grid for s1 in grid for s2 in grid]
    Phis, Psis = np.array([Phi for Phi, _ in laws]), np.array([Psi for _, Psi in laws])
    rng = np.random.default_rng(36)
    seen = {True: 0, False: 0}
    for _ in range(40):
        a, mu_value, m_value = rng.uniform(0.05, 3.09), rng.uniform(0, 3), math.exp(rng.normal())
        bound = abs(1 / math.tan(a))
        if abs(mu_value - bound) < 0.05:
            continue
        A = A_of(a, mu_value, m_value)
        parts = max_real_parts(A, Phis, Psis)  # batched: tests/paper/test_s5_guides.py checks it law by law
        if mu_value < bound:
            assert max(parts) < 0
        else:
            assert min(parts) < 0 < max(parts)
        seen[mu_value < bound] += 1
    assert min(seen.values()) >= 5


def test_6_3_boundary_mu_equal_cot_alpha_is_stable_for_every_sampled_law():
    rng = np.random.default_rng(63)
    on_boundary = sp.lambdify(alpha, lin.A.subs({mu: sp.cot(alpha), m: 1}))
    for _ in range(300):
        A = on_boundary(rng.uniform(0.1, 1.5))
        Phi_values, Psi_values = -np.exp(rng.normal(0, 2, 2)), -np.exp(rng.normal(0, 2, 2))
        assert max_real_part(A, Phi_values, Psi_values) < 0
    values = {alpha: sp.pi / 3, mu: sp.cot(sp.pi / 3), m: 1}
    assert truth(stab.robustly_stable, values)  # mu = |cot alpha| is inside (4.4)


# the paper's special case: identical pads (Phi_j = Phi, Psi_j = Psi) at a right angle
right_angle = {alpha: sp.pi / 2, Phi1: Phi, Phi2: Phi, Psi1: Psi, Psi2: Psi}
# printed (6.4), corrected as in erratum 13 (the print has m = 1): stable iff -m mu^2 Phi < Psi^2 (1 + mu^2)
printed_6_4 = sp.Lt(-m * mu**2 * Phi, Psi**2 * (1 + mu**2))
margin_6_4 = printed_6_4.rhs - printed_6_4.lhs
hurwitz_at_right_angle = [sp.factor(c.subs(right_angle)) for c in stab.hurwitz]
(hopf_equation,) = stab.hopf.atoms(sp.Eq)  # Delta_(n-1) = 0 of the Hopf set
delta_at_right_angle = sp.factor((hopf_equation.lhs - hopf_equation.rhs).subs(right_angle))
A_at_right_angle = sp.lambdify((mu, m), lin.A.subs(alpha, sp.pi / 2))
derived_hurwitz = sp.lambdify((mu, m, Phi, Psi), hurwitz_at_right_angle)
printed_margin = sp.lambdify((mu, m, Phi, Psi), margin_6_4)


def test_hopf_condition_is_6_4_with_the_mass():
    # Delta_3 = -4 Phi Psi^2 (1 + mu^2) (m mu^2 Phi + (1 + mu^2) Psi^2) / m^5: a positive factor
    # times the margin of the corrected (6.4), so the two conditions have the same sign everywhere
    assert same(delta_at_right_angle, -4 * Phi * Psi**2 * (1 + mu**2) * (m * mu**2 * Phi + (1 + mu**2) * Psi**2) / m**5)
    factor = sp.factor(delta_at_right_angle / margin_6_4)
    assert factor.is_positive  # None if the margin did not divide Delta_3 exactly
    assert same(sp.together(factor * margin_6_4 - delta_at_right_angle), 0)
    assert delta_at_right_angle in hurwitz_at_right_angle
    for c in hurwitz_at_right_angle:  # the others, the first group of (4.7), hold for every law
        assert c == delta_at_right_angle or c.is_positive
    # the Hopf set is the line where the margin of (6.4) vanishes
    on_line = {Phi: sp.solve(margin_6_4, Phi)[0]}
    assert same(sp.cancel(delta_at_right_angle.subs(on_line)), 0)
    assert stab.hopf.subs(right_angle).subs(on_line).simplify() == sp.true
    assert stab.hopf.subs(right_angle).subs(Phi, 2 * on_line[Phi]).simplify() == sp.false


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 3), st.floats(0.1, 10), st.floats(-10, -0.01), st.floats(-10, -0.01))
def test_6_4_agrees_with_eigenvalues(mu_value, m_value, phi_value, psi_value):
    # eigenvalues of (4.5) built from the pipeline's own A, against the pipeline's Hurwitz
    # conditions and the corrected print, both at the same random point
    growth = max_real_part(A_at_right_angle(mu_value, m_value), [phi_value] * 2, [psi_value] * 2)
    assume(abs(growth) > 1e-9)
    derived = all(c > 0 for c in derived_hurwitz(mu_value, m_value, phi_value, psi_value))
    printed = printed_margin(mu_value, m_value, phi_value, psi_value) > 0
    assert derived == (growth < 0)
    assert printed == derived


def test_hopf_frequency_on_the_line_is_omega_over_m():
    omega = sp.factor(stab.hopf_frequency.subs(right_angle))
    on_line = {Phi: -(1 + mu**2) * Psi**2 / (m * mu**2)}
    printed_over_m = -(mu**2 + 1) * Psi / (mu * m)
    assert same(sp.sqrt(sp.factor(omega.subs(on_line) ** 2)), sp.Abs(printed_over_m))
    rng = np.random.default_rng(6)
    for _ in range(20):
        mu_v, m_v, psi_v = rng.uniform(0.2, 3), rng.uniform(0.2, 5), -rng.uniform(0.1, 5)
        phi_v = -(1 + mu_v**2) * psi_v**2 / (m_v * mu_v**2)
        eigenvalues = np.linalg.eigvals(fast_matrix(A_at_right_angle(mu_v, m_v), [phi_v] * 2, [psi_v] * 2))
        critical = eigenvalues[np.argmax(eigenvalues.real)]
        expected = -(1 + mu_v**2) * psi_v / (mu_v * m_v)
        assert abs(critical.real) < 1e-8 * expected
        assert math.isclose(abs(critical.imag), expected, rel_tol=1e-9)
        symbolic = float(omega.subs({mu: mu_v, m: m_v, Psi: psi_v, Phi: phi_v}))
        assert math.isclose(symbolic, expected, rel_tol=1e-9)
