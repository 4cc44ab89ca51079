"""§4: two contacts. (4.5)-(4.10), Proposition 6 and Remarks 1-2."""

import math

import numpy as np
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from tests.helpers import max_real_part, same

a11, a12, a21, a22, b1, b2 = sp.symbols("a11 a12 a21 a22 b1 b2", real=True)
q1, q2 = dynamicsymbols("q_1 q_2")
N1, N2 = sp.symbols("N_1 N_2", real=True)
scene = cs.Scene.from_accelerations(
    [q1, q2],
    [a11 * N1 + a12 * N2 + b1, a21 * N1 + a22 * N2 + b2],
    [cs.Contact(coordinate=q1, reaction=N1), cs.Contact(coordinate=q2, reaction=N2)],
)
lin = scene.linearization()
Phi1, Phi2 = lin.Phi
Psi1, Psi2 = lin.Psi
D = a11 * a22 - a12 * a21
chi = [Phi1 * Phi2, Psi1 * Phi2 + Psi2 * Phi1, Psi1 * Psi2, a11 * Phi1 + a22 * Phi2, a11 * Psi1 + a22 * Psi2]
swap = {Phi1: Psi1, Psi1: Phi1, Phi2: Psi2, Psi2: Phi2}


def test_jacobian_is_4_3_and_matrix_is_4_5():
    assert lin.A == sp.Matrix([[a11, a12], [a21, a22]])
    expected = sp.Matrix(
        [[Psi1 * a11, Psi1 * a12, Phi1, 0], [Psi2 * a21, Psi2 * a22, 0, Phi2], [a11, a12, 0, 0], [a21, a22, 0, 0]]
    )
    assert lin.jacobian == expected


def test_characteristic_polynomial_is_4_6():
    p = lin.charpoly.all_coeffs()
    printed = [1, -chi[4], chi[2] * D - chi[3], chi[1] * D, chi[0] * D]
    assert all(same(a, b) for a, b in zip(p, printed))
    direct = (cs.lam * sp.eye(4) - lin.jacobian).det(method="berkowitz")
    assert same(lin.charpoly.as_expr(), direct)


def test_last_hurwitz_condition_is_4_7():
    p4, p3, p2, p1, p0 = lin.charpoly.all_coeffs()
    delta3 = scene.stability().hurwitz[-1]
    assert same(delta3, -(p4 * p1**2 - p1 * p2 * p3 + p0 * p3**2))


def derived_4_8():
    """Delta_3 / det A > 0 written as lhs < rhs, as the paper arranges it."""
    lhs = chi[1] ** 2 * D
    rhs = -chi[1] * chi[2] * chi[4] * D + chi[4] * (a11 * Phi1**2 * Psi2 + a22 * Psi1 * Phi2**2)
    return lhs, rhs


def printed_4_8():
    lhs = chi[1] ** 2 * D
    rhs = -chi[0] * chi[1] * chi[3] * D + chi[3] * (a11 * Psi1**2 * Phi2 + a22 * Phi1 * Psi2**2)
    return lhs, rhs


def test_4_8_derived_is_delta3_over_det_a():
    lhs, rhs = derived_4_8()
    assert same(scene.stability().hurwitz[-1], D * (rhs - lhs))


def test_printed_4_8_is_the_derived_form_with_phi_and_psi_swapped():
    printed_lhs, printed_rhs = printed_4_8()
    derived = sp.cancel(scene.stability().hurwitz[-1] / D)  # the library's Delta_3 / det A
    assert same(printed_rhs - printed_lhs, derived.xreplace(swap))
    assert not same(printed_rhs - printed_lhs, derived)


def test_printed_4_8_misjudges_stability_where_eigenvalues_decide():
    symbols = (a11, a12, a21, a22, Phi1, Phi2, Psi1, Psi2)
    coefficients_at = sp.lambdify(symbols, lin.charpoly.all_coeffs())
    delta3_at = sp.lambdify(symbols, scene.stability().hurwitz[-1])
    derived_at, printed_at = sp.lambdify(symbols, derived_4_8()), sp.lambdify(symbols, printed_4_8())
    rng = np.random.default_rng(4)
    disagreements = 0
    for _ in range(400):
        A = rng.normal(size=(2, 2))
        Phi, Psi = -np.exp(rng.normal(size=2) * 2), -np.exp(rng.normal(size=2) * 2)
        values = (*A.flat, *Phi, *Psi)
        if min(coefficients_at(*values)) <= 0:
            continue
        stable = max_real_part(A, Phi, Psi) < 0
        lhs, rhs = derived_at(*values)
        printed_lhs, printed_rhs = printed_at(*values)
        if abs(rhs - lhs) < 1e-9 * (abs(rhs) + abs(lhs)):
            continue
        assert (lhs < rhs) == stable  # the derived (4.8) is exact, given p_s > 0
        assert (delta3_at(*values) > 0) == stable  # and so is the library's Delta_3
        disagreements += (printed_lhs < printed_rhs) != stable
    assert disagreements > 0


def test_4_9_to_4_10_reduces_to_a_square():
    # (4.9) derived: chi_1^2 a11 a22 < chi_4 (a11 Phi1^2 Psi2 + a22 Psi1 Phi2^2); its slack is
    # Psi1 Psi2 (a11 Phi1 - a22 Phi2)^2 >= 0, i.e. (4.10) holds with Phi (printed: Psi) and
    # equality where a11 Phi1 = a22 Phi2 (Remark 1 prints a11 Psi1 = a22 Phi2).
    # From the library: Delta_3 / det A is linear in det A (write a21 through it); (4.9) keeps its
    # constant part on the right and puts det A = a11 a22 in chi_1^2 det A, chi_1 = p_1 / det A (4.6).
    det = sp.Symbol("det_A")
    per_det = sp.cancel(scene.stability().hurwitz[-1].subs(a21, (a11 * a22 - det) / a12) / det)
    assert sp.degree(per_det, det) == 1
    chi1 = sp.cancel(lin.charpoly.all_coeffs()[3] / D)
    slack = per_det.subs(det, 0) - chi1**2 * a11 * a22
    square = Psi1 * Psi2 * (a11 * Phi1 - a22 * Phi2) ** 2
    assert same(slack, square)
    dropped = per_det.coeff(det, 1) + chi1**2  # times det A: the term that (4.9) drops, "always positive"
    positive = {a11: sp.Symbol("b11", positive=True), a22: sp.Symbol("b22", positive=True)}
    assert sp.factor(dropped.xreplace(positive)).is_positive
    assert same(slack, chi[4] * (a11 * Phi1**2 * Psi2 + a22 * Psi1 * Phi2**2) - chi[1] ** 2 * a11 * a22)
    rng = np.random.default_rng(49)
    evaluate = sp.lambdify((a11, a12, a22, Phi1, Phi2, Psi1, Psi2), [slack, square])
    for _ in range(200):  # the same at random points, and never negative for laws (1.5)
        values = (*rng.normal(size=3), *-np.exp(rng.normal(size=4)))
        ours, theirs = evaluate(*values)
        assert ours >= -1e-12 * (1 + abs(theirs)) and math.isclose(ours, theirs, rel_tol=1e-9, abs_tol=1e-12)


def test_proposition_6_conditions_are_4_4():
    st = scene.stability()
    assert st.robustly_stable == sp.And(sp.Gt(a11, 0), sp.Gt(a22, 0), sp.Gt(sp.expand(D), 0), sp.Ge(a12 * a21, 0))
    # Prop. 6 says a11 < 0 and a22 < 0; the boundary a11, a22 <= 0 (det A > 0) is unstable too (p_3 <= 0)
    assert st.robustly_unstable == sp.Or(sp.Lt(sp.expand(D), 0), sp.And(sp.Le(a11, 0), sp.Le(a22, 0)))


def test_remark_2_hopf_frequency_makes_p_of_i_omega_vanish():
    # omega^2 = p1/p3 kills Im p(i omega) = omega (p1 - p3 omega^2); then
    # Re p(i omega) = p0 - p2 omega^2 + p4 omega^4 = -Delta_3 / p3^2, zero on the Hopf set.
    st = scene.stability()
    w2 = st.hopf_frequency**2
    p4, p3, p2, p1, p0 = lin.charpoly.all_coeffs()
    assert same(sp.together(w2 - p1 / p3), 0)
    real_part = p0 - p2 * w2 + p4 * w2**2
    assert same(sp.cancel(real_part * p3**2), -st.hurwitz[-1])
