"""contactsym.numerics.cycles and the brake beyond its Hopf line: squeal frequency, growth, cycle."""

import math
from fractions import Fraction

import numpy as np
import sympy as sp

import contactsym as cs
from contactsym import numerics as nm
from tests.helpers import max_real_part
from tests.numerics.brake import (
    Phi,
    Psi,
    brake,
    brake_values,
    crossing_frequency,
    hopf_line,
    m,
    mu,
    right_angle,
    stab,
)

# --- the brake beyond its Hopf line: squeal frequency, growth, cycle ---------------------


def test_squeal_frequency_of_the_full_system_is_omega_over_eps():
    mass, friction, psi = Fraction(13, 10), Fraction(4, 5), Fraction(-3, 5)
    exact = {m: sp.Rational(mass), mu: sp.Rational(friction), Psi: sp.Rational(psi)}
    phi_c = hopf_line(exact)
    omega = stab.hopf_frequency.subs(right_angle).subs(exact).subs(Phi, phi_c)  # derived
    closed_form = -(1 + friction**2) * psi / (friction * mass)  # errata 14: omega = -(1 + mu^2) Psi/(mu m)
    assert math.isclose(float(omega), float(closed_form), rel_tol=1e-12)
    phi = float(phi_c) * (1 + 1e-4)  # just beyond the line: a slowly growing oscillation
    values = brake_values(phi, float(psi), float(mass), float(friction))
    assert nm.classify(brake, values).stable == -1
    ((_, u_star),) = nm.equilibrium_reactions(brake, values)
    eps = 1e-3
    T = 100 * 2 * math.pi / float(omega) * eps
    times = np.linspace(0, T, 4000)
    initial = {"x": 0, "y": 0, "theta": 0, "xdot": 0, "ydot": 0, "thetadot": -5}  # the disc slides throughout
    run = nm.simulate_full(
        brake, values, eps, (0, T), initial, unilateral=False, method="DOP853", rtol=1e-9, t_eval=times
    )
    assert run.ok, run.message
    measured = crossing_frequency(times, run["N_1"] - u_star[0]) * eps  # in tau
    print(f"squeal: measured omega {measured:.8f}, closed form {float(closed_form):.8f}")
    assert abs(measured / float(closed_form) - 1) < 1e-3


def test_linear_law_beyond_the_line_grows_at_the_rate_of_the_eigenvalues():
    psi, mass, friction = -0.6, 1.3, 0.8
    phi = 1.2 * float(hopf_line({m: mass, mu: friction, Psi: psi}))
    values = brake_values(phi, psi, mass, friction)
    fast = nm.fast_system(brake, values, unilateral=False)
    ((_, u_star),) = nm.equilibrium_reactions(brake, values)
    start = np.array([*u_star, 0, 0]) + np.array([1e-6, 0, 0, 0])
    times = np.linspace(0, 200, 4001)
    run = nm.simulate_fast(brake, values, (0, 200), start, unilateral=False, rtol=1e-11, t_eval=times, method="DOP853")
    deviation = np.abs(run.reactions[0] - u_star[0])
    late, early = deviation[-400:].max(), deviation[1600:2000].max()
    rate = math.log(late / early) / (times[-200] - times[1800])
    A = np.array([[1, friction], [-friction, 1]]) / mass
    expected = max_real_part(A, [phi] * 2, [psi] * 2)
    assert fast.time == "tau" and expected > 0
    assert math.isclose(rate, expected, rel_tol=0.05)


def test_unilateral_contact_bounds_the_oscillation_into_a_cycle_and_averages_match():
    values = brake_values(-2.1, -1.0, 1.0, 1.0)  # Hopf line at Phi = -2: beyond it
    assert nm.classify(brake, values).stable == -1
    ((_, u_star),) = nm.equilibrium_reactions(brake, values)
    cycle = nm.fast_cycle(brake, values, tol=1e-6, samples=2048)
    assert cycle.converged, cycle.message
    assert cycle.contact_loss  # pad 1 opens on part of the cycle
    # f is affine where the pads push, so a bounded motion has mean reactions u* exactly
    assert np.allclose(cycle.mean_reactions, u_star, rtol=2e-3)
    eps = 1e-2
    T = 80 * cycle.period * eps
    times = np.linspace(0, T, 20001)
    initial = {"x": 0, "y": 0, "theta": 0, "xdot": 0, "ydot": 0, "thetadot": -20}  # the disc slides throughout
    full = nm.simulate_full(brake, values, eps, (0, T), initial, method="DOP853", rtol=1e-9, t_eval=times)
    assert full.ok, full.message
    late = times > T / 2
    assert full.reactions[:, late].max() < 5 * max(u_star)  # bounded, not growing
    assert full.reactions[:, late].min() == 0.0  # loss of contact
    assert np.allclose(full.reactions[:, late].mean(axis=1), cycle.mean_reactions, rtol=2e-2)
    # averaged system (2.7): theta'' = mu r <|N_1| + |N_2|>/J, against the full slow motion
    averaged = nm.simulate_averaged(
        brake, values, (0, T), {"theta": 0, "thetadot": -20}, cycle_options={"tol": 1e-6, "samples": 2048}
    )
    assert averaged.ok
    slope_full = np.polyfit(times[late], full["thetadot"][late], 1)[0]
    slope_averaged = (averaged.at(T, "thetadot") - averaged.at(0, "thetadot")) / T
    assert math.isclose(slope_full, slope_averaged, rel_tol=2e-2)


def test_hunt_crossley_law_on_the_brake_gives_a_bounded_oscillation():
    q, qd = sp.symbols("q qdot", real=True)
    e, k, c = sp.symbols("epsilon k c", positive=True)
    # Hunt–Crossley with linear stiffness: N = k delta (1 + c delta'), delta = -q the penetration
    law = cs.Law(-k * q / e**2 * (1 - c * qd / e), q, qd, e, check=False)
    values = brake_values(-2.1, -1.0, 1.0, 1.0)
    values.update({k: 2.1, c: 0.3})
    cycle = nm.fast_cycle(brake, values, laws={0: law, 1: law}, tol=1e-6, samples=1024)
    assert cycle.converged, cycle.message
    assert np.all(np.isfinite(cycle.reactions)) and cycle.reactions.max() < 20


def test_a_slow_spiral_into_a_stable_equilibrium_is_not_a_cycle():
    """Just inside the Hopf line the equilibrium is a weakly damped focus: successive returns to
    the section agree to ``tol`` long before they reach the equilibrium. That is no cycle (it was
    once reported as one, of amplitude ~1e-5): the returns must also be near their limit."""
    values = {"m": 1, "mu": 1, "alpha": math.pi / 2, "F_x": 2, "F_y": -4}
    values |= {"Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    critical = nm.hopf_point(brake, values, "mu").value  # derived: the crossing of the critical pair
    for inside in (0.975, 0.985):
        point = values | {"mu": inside * critical}
        assert nm.classify(brake, point).stable == 1  # Routh-Hurwitz: a stable equilibrium
        cycle = nm.fast_cycle(brake, point, samples=64)
        assert not cycle.converged and "settles on the equilibrium" in cycle.message, cycle.message
    beyond = nm.fast_cycle(brake, values | {"mu": 1.01 * critical}, samples=64)
    assert beyond.converged and np.ptp(beyond.states, axis=1).max() > 1  # the squeal cycle, of finite size
