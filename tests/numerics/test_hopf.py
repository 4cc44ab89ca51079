"""The direction of the brake's Hopf bifurcation (6.4) with nonlinear pad laws, against simulation."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym import numerics
from contactsym.errors import ComplianceError, HopfError
from contactsym.laws.library import Hertz
from contactsym.lyapunov.coefficient import first_lyapunov_symbolic
from contactsym.numerics.hopf import full_cycle_start
from tests.helpers import fast_complex

q, qd = sp.symbols("q qdot", real=True)
eps = sp.Symbol("epsilon", positive=True)
V = qd / eps
BRAKE = {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
HERTZ = {0: Hertz(), 1: Hertz()}
# damping that weakens, then strengthens with the rate: Psi = -3/10 + V^2/10 - V^4/100 < 0 for all V
SPIN = {"thetadot": -1}  # the disc turns clockwise, as the scene's friction assumes
WEAKENING = cs.Law(-q / eps**2 - sp.Rational(3, 10) * V + V**3 / 30 - V**5 / 500, q, qd, eps, check=False)


def reaction_amplitudes(values, laws, start, duration, period):
    run = numerics.simulate_fast(
        cs.scene("brake"),
        values,
        (0, duration),
        initial=start,
        laws=laws,
        method="DOP853",
        rtol=1e-7,
        t_eval=np.linspace(duration - 2 * period, duration, 1500),
    )
    assert run.status == "ok"
    return (run.reactions.max(axis=1) - run.reactions.min(axis=1)) / 2


def full_run(values, laws, start, duration, period, eps):
    """The full system (1.9) at eps over ``duration`` in tau (t = eps tau); the last two periods sampled."""
    run = numerics.simulate_full(
        cs.scene("brake"),
        {**values, "r": 1, "J": 1},
        eps,
        (0, eps * duration),
        start,
        laws=laws,
        method="DOP853",
        rtol=1e-7,
        t_eval=eps * np.linspace(duration - 2 * period, duration, 1500),
        dense_output=False,
    )
    assert run.status == "ok"
    return run


def half_range(run) -> np.ndarray:
    return (run.reactions.max(axis=1) - run.reactions.min(axis=1)) / 2


@pytest.fixture(scope="module")
def hertz_line():
    return numerics.hopf_point(cs.scene("brake"), {**BRAKE, "mu": 1}, "mu", laws=HERTZ)


def test_hertz_pads_squeal_softly_with_the_predicted_amplitude(hertz_line):
    h = hertz_line
    assert h.direction == "supercritical" and h.l1 < 0 and h.dalpha > 0
    mu = 1.01 * h.value  # 1% past the line
    predicted = h.amplitude(mu)
    assert h.amplitude(0.99 * h.value) is None  # no small cycle on the stable side
    # the cycle attracts from inside and outside: after ~1/alpha the two runs bracket it
    duration = 0.8 / (h.dalpha * (mu - h.value))
    period = 2 * np.pi / h.omega
    inside, outside = (
        reaction_amplitudes({**BRAKE, "mu": mu}, HERTZ, h.cycle_start(mu, f), duration, period) for f in (0.8, 1.2)
    )
    assert np.all(inside < outside)
    for simulated in (inside, outside):
        assert simulated == pytest.approx(predicted, rel=0.1)


def test_the_full_system_at_small_eps_squeals_with_the_predicted_amplitude_and_period(hertz_line):
    """(1.9) with the gaps as x, y and the disc turning: the fast cycle, in t = eps tau."""
    h, eps = hertz_line, 1e-3
    mu = 1.01 * h.value
    values = {**BRAKE, "mu": mu}
    duration = 0.8 / (h.dalpha * (mu - h.value))
    period = 2 * np.pi / h.omega
    inside, outside = (
        full_run(
            values,
            HERTZ,
            full_cycle_start(cs.scene("brake"), h, values, eps, mu, factor=f, base=SPIN),
            duration,
            period,
            eps,
        )
        for f in (0.8, 1.2)
    )
    assert np.all(half_range(inside) < half_range(outside))
    for run in (inside, outside):
        assert half_range(run) == pytest.approx(h.amplitude(mu), rel=0.1)
    N = inside.reactions[0] - inside.reactions[0].mean()
    ups = inside.t[1:][(N[:-1] < 0) & (N[1:] >= 0)]  # upward zero crossings: one per period
    assert np.mean(np.diff(ups)) == pytest.approx(eps * period, rel=0.01)  # omega/eps in t, to O(distance)


def test_the_full_system_keeps_a_large_cycle_before_the_line_where_l1_is_positive():
    """Hysteresis in (1.9): at one mu before the line, the rest state and a large cycle both attract."""
    laws, eps = {0: WEAKENING, 1: WEAKENING}, 1e-3
    h = numerics.hopf_point(cs.scene("brake"), {**BRAKE, "mu": 0.3}, "mu", laws=laws)
    mu = 0.97 * h.value
    values = {**BRAKE, "mu": mu}
    duration = 1 / abs(h.dalpha * (mu - h.value))
    period = 2 * np.pi / h.omega
    below, above = (
        half_range(
            full_run(
                values,
                laws,
                full_cycle_start(cs.scene("brake"), h, values, eps, mu, factor=f, base=SPIN),
                duration,
                period,
                eps,
            )
        )
        for f in (0.7, 1.3)
    )
    assert np.all(below < 0.7 * h.amplitude(mu)) and np.all(above > 2 * h.amplitude(mu))


def test_weakening_damping_jumps_and_shows_hysteresis():
    h = numerics.hopf_point(cs.scene("brake"), {**BRAKE, "mu": 0.3}, "mu", laws={0: WEAKENING, 1: WEAKENING})
    assert h.direction == "subcritical" and h.l1 > 0 and h.dalpha > 0
    mu = 0.97 * h.value  # stable side: an unstable small cycle of the predicted size
    predicted = h.amplitude(mu)
    assert predicted is not None and h.amplitude(1.03 * h.value) is None
    laws = {0: WEAKENING, 1: WEAKENING}
    duration = 1 / abs(h.dalpha * (mu - h.value))
    period = 2 * np.pi / h.omega
    below = reaction_amplitudes({**BRAKE, "mu": mu}, laws, h.cycle_start(mu, 0.7), duration, period)
    above = reaction_amplitudes({**BRAKE, "mu": mu}, laws, h.cycle_start(mu, 1.3), duration, period)
    assert np.all(below < 0.7 * predicted)  # decays to the equilibrium
    assert np.all(above > 2 * predicted)  # jumps to a large cycle: two attractors at one mu (hysteresis)


def test_symbolic_l1_agrees_with_the_numeric_one_in_other_coordinates(hertz_line):
    """Stability.first_lyapunov (generic law, (u, v)) at the Hertz law's derivatives vs hopf (Q, V):
    the same cycle, so l1_uv = l1_QV / |q_uv|^2 with q_uv = (dN q, q_V) (normalization <q, q> = 1)."""
    h = hertz_line
    brake = cs.scene("brake")
    st = brake.stability()
    u, v = sp.symbols("u v", real=True)
    Phi_law, Psi_law = Hertz().phi_psi(u, v, None)
    P = {str(s): s for s in brake.parameters}
    at = {P["m"]: 1, P["mu"]: sp.Float(h.value, 20), P["alpha"]: sp.pi / 2}
    for j, (Phi, Psi) in enumerate(zip(st.linearization.Phi, st.linearization.Psi)):
        here = {u: h.u_star[j], v: 0}
        at[Phi], at[Psi] = Phi_law.subs(here), Psi_law.subs(here)
        for name in ("u", "v", "uu", "uv", "vv"):
            order = [u] * name.count("u") + [v] * name.count("v")
            at[sp.Symbol(f"Phi_{j + 1}_{name}", real=True)] = sp.diff(Phi_law, *order).subs(here)
            at[sp.Symbol(f"Psi_{j + 1}_{name}", real=True)] = sp.diff(Psi_law, *order).subs(here)
    l1_uv = fast_complex(first_lyapunov_symbolic(st, at))  # complex(), without evalf's seconds on its tree
    q_uv = np.concatenate([h.reaction_vector, h.vectors.q[2:]])
    assert l1_uv.real == pytest.approx(h.l1 / np.vdot(q_uv, q_uv).real, rel=1e-6)


def test_l1_off_the_line_says_how_far():
    with pytest.raises(
        HopfError, match=r"off the Hopf set: the critical eigenvalues are 0\.033.*Re\(lambda\)/omega = 0\.0158"
    ):
        numerics.first_lyapunov_at(cs.scene("brake"), {**BRAKE, "mu": 1.2}, laws=HERTZ)


def test_a_law_not_monotone_at_the_equilibrium_names_the_interval():
    # N = -Q + Q^3/30 - V: monotone for |Q| < sqrt(10), where N < 2 sqrt(10)/3 = 2.108; the brake needs 3.2
    softening = cs.Law(-q / eps**2 + (q / eps**2) ** 3 / 30 - V, q, qd, eps, check=False)
    with pytest.raises(
        ComplianceError,
        match=r"not monotone where it is used.*stops decreasing at Q = -3\.162.*covers only N in \[0, 2\.108\]",
    ):
        numerics.first_lyapunov_at(cs.scene("brake"), {**BRAKE, "mu": 0.5}, laws={0: softening, 1: softening})
