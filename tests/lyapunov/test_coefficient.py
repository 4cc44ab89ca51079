"""The first Lyapunov coefficient on systems whose cycles are known independently."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from contactsym.errors import HopfError
from contactsym.lyapunov.coefficient import (
    derivative_tensors,
    first_lyapunov_from_derivatives,
    lyapunov_symbolic,
    multilinear,
)
from tests.helpers import fast_complex

x, y = sp.symbols("x y", real=True)


def simulated_amplitude(F: sp.Matrix, start, periods_time: float, settle: float) -> float:
    """Half the peak-to-peak range of the first component after ``settle`` (a cycle reached)."""
    f = sp.lambdify([x, y], list(F))
    run = solve_ivp(lambda t, z: f(*z), (0, settle + periods_time), start, rtol=1e-8, atol=1e-10, dense_output=True)
    z = run.sol(np.linspace(settle, settle + periods_time, 20000))[0]
    return (z.max() - z.min()) / 2


def predicted_amplitude(F_critical: sp.Matrix, alpha: float, at: dict, transform=None) -> float:
    """2 r |q_0| with r^2 = -alpha / Re c1, from l1 at the critical point."""
    h = first_lyapunov_from_derivatives(*derivative_tensors(F_critical, [x, y], at))
    q = h.q if transform is None else transform @ h.q
    return 2 * h.radius(alpha) * abs(q[0])


# --- the Hopf normal form: the cycle is the circle x^2 + y^2 = -beta/s exactly ----------


@settings(max_examples=15, deadline=None)
@given(st.floats(-3, 3).filter(lambda s: abs(s) > 0.05), st.floats(0.2, 5), st.floats(1e-4, 0.1))
def test_normal_form_l1_and_amplitude(s, w, beta):
    r2 = x**2 + y**2
    critical = sp.Matrix([-w * y + s * x * r2, w * x + s * y * r2])
    h = first_lyapunov_from_derivatives(*derivative_tensors(critical, [x, y], {x: 0, y: 0}))
    # polar coordinates: R' = beta R + s R^3, and |z| = R / sqrt(2) for <q, q> = 1, so Re c1 = 2 s
    assert h.l1 == pytest.approx(2 * s / w, rel=1e-12)
    alpha = beta if s < 0 else -beta  # the small cycle lives where alpha s < 0
    assert predicted_amplitude(critical, alpha, {x: 0, y: 0}) == pytest.approx(np.sqrt(-alpha / s), rel=1e-12)
    assert h.radius(-alpha) is None  # no small cycle on the other side


@settings(max_examples=4, deadline=None)
@given(st.lists(st.integers(-2, 2), min_size=4, max_size=4), st.sampled_from([-1, 1]))
def test_amplitude_is_invariant_under_a_random_linear_change_of_coordinates(entries, s):
    """x = M y: the prediction made in y and mapped back by M is the exact circle of x."""
    M = sp.Matrix(2, 2, entries) + 6 * sp.eye(2)  # invertible: diagonally dominant
    r2 = x**2 + y**2
    field_x = sp.Matrix([-y + s * x * r2, x + s * y * r2])
    X = M * sp.Matrix([x, y])  # the new coordinates are called (x, y) too
    field_y = (M.inv() * field_x.subs({x: X[0], y: X[1]}, simultaneous=True)).applyfunc(sp.expand)
    M = np.array(M.tolist(), dtype=float)
    alpha = -0.01 * s
    predicted = predicted_amplitude(field_y, alpha, {x: 0, y: 0}, transform=M)
    assert predicted == pytest.approx(np.sqrt(0.01), rel=1e-9)
    h = first_lyapunov_from_derivatives(*derivative_tensors(field_y, [x, y], {x: 0, y: 0}))
    assert np.sign(h.l1) == s  # the sign is invariant


# --- van der Pol x'' - (mu - x^2) x' + x = 0: the cycle has amplitude 2 sqrt(mu) -------


def test_van_der_pol_prediction_matches_averaging_and_simulation():
    critical = sp.Matrix([y, -x - x**2 * y])
    h = first_lyapunov_from_derivatives(*derivative_tensors(critical, [x, y], {x: 0, y: 0}))
    assert h.l1 < 0 and h.omega == pytest.approx(1)
    mu = 0.04
    predicted = predicted_amplitude(critical, mu / 2, {x: 0, y: 0})  # Re lambda = mu/2
    assert predicted == pytest.approx(2 * np.sqrt(mu), rel=1e-9)  # averaging
    simulated = simulated_amplitude(sp.Matrix([y, -x + mu * y - x**2 * y]), [0.3, 0], 13, 300)
    assert simulated == pytest.approx(predicted, rel=0.02)


# --- the Brusselator x' = a - (b + 1) x + x^2 y, y' = b x - x^2 y, Hopf at b = 1 + a^2 ---


def brusselator(a, b):
    return sp.Matrix([a - (b + 1) * x + x**2 * y, b * x - x**2 * y])


@pytest.mark.parametrize("a", [0.7, 1.5])
def test_brusselator_is_supercritical_with_the_simulated_amplitude(a):
    b_star = 1 + a**2
    at = {x: a, y: b_star / a}
    h = first_lyapunov_from_derivatives(*derivative_tensors(brusselator(a, b_star), [x, y], at))
    assert h.l1 < 0 and h.omega == pytest.approx(a)
    b = b_star * 1.01
    alpha = (b - b_star) / 2  # trace / 2 = (b - 1 - a^2) / 2
    predicted = predicted_amplitude(brusselator(a, b_star), alpha, at)
    settle = 12 / alpha
    simulated = simulated_amplitude(brusselator(a, b), [a * 1.01, b / a], 8 * np.pi / a, settle)
    assert simulated == pytest.approx(predicted, rel=0.1)


def test_brusselator_symbolic_l1_agrees_with_the_numeric_one():
    a = sp.Symbol("a", positive=True)
    F = brusselator(a, 1 + a**2)
    state, at = [x, y], {x: a, y: (1 + a**2) / a}
    J = F.jacobian(state).subs(at)
    H = [[[sp.diff(F[i], state[j], state[k]).subs(at) for k in range(2)] for j in range(2)] for i in range(2)]
    T = [
        [[[sp.diff(F[i], state[j], state[k], state[m]).subs(at) for m in range(2)] for k in range(2)] for j in range(2)]
        for i in range(2)
    ]
    q = (J - sp.I * a * sp.eye(2)).nullspace()[0]
    p = (J.T + sp.I * a * sp.eye(2)).nullspace()[0]
    l1 = lyapunov_symbolic(J, multilinear(H, 2), multilinear(T, 3), a, q, p)
    for value in (0.3, 1.0, 2.5):
        numeric = first_lyapunov_from_derivatives(
            *derivative_tensors(brusselator(value, 1 + value**2), state, {x: value, y: (1 + value**2) / value})
        )
        exact = fast_complex(l1.subs(a, value))  # complex(), by one mpmath pass over the tree
        assert exact.real == pytest.approx(numeric.l1, rel=1e-9) and abs(exact.imag) < 1e-12
    # supercritical for every a > 0: l1 is a negative rational function of a
    assert sp.factor(l1).is_negative  # factor alone: -(a^2 + 2)/(2a(2a^2 + 1)) (simplify first: 3 s more)


def test_off_the_hopf_set_is_a_clear_error_saying_how_far():
    F = sp.Matrix([0.1 * x - y - x * (x**2 + y**2), x + 0.1 * y - y * (x**2 + y**2)])
    with pytest.raises(HopfError, match=r"off the Hopf set.*0\.1 \+- 1 i.*Re\(lambda\)/omega = 0\.1"):
        first_lyapunov_from_derivatives(*derivative_tensors(F, [x, y], {x: 0, y: 0}))
    with pytest.raises(HopfError, match="no complex pair"):
        first_lyapunov_from_derivatives(*derivative_tensors(sp.Matrix([x, -y]), [x, y], {x: 0, y: 0}))
