"""Cycles by shooting (numerics.continuation): Floquet multipliers against systems whose answer is
known, and cycles of the brake against short simulations started on them."""

from __future__ import annotations

import numpy as np
import pytest

import contactsym as cs
from contactsym import numerics
from contactsym.laws.library import Hertz
from contactsym.numerics.continuation import fast_field, hopf_guess, sample_orbits, shoot

LAWS = {0: Hertz(), 1: Hertz()}
DISC = {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}


class _NormalFormField:
    """(x, u, y, w): a Hopf normal form in (x, y) with c1 = -s (cycle of radius sqrt(a/s), period
    2 pi/omega, multiplier exp(-2 a T)) and a decoupled linear focus in (u, w) (exp((-b +- i nu) T))."""

    k = 2

    def __init__(self, a, s, omega, b, nu):
        self.a, self.s, self.omega, self.b, self.nu = a, s, omega, b, nu

    def rhs_and_jac(self, z, p):
        x, u, y, w = z
        r2 = x**2 + y**2
        a, s, om, b, nu = self.a, self.s, self.omega, self.b, self.nu
        rhs = np.array([a * x - om * y - s * r2 * x, -b * u - nu * w, om * x + a * y - s * r2 * y, nu * u - b * w])
        M = z.shape[1]
        J = np.zeros((M, 4, 4))
        J[:, 0, 0], J[:, 0, 2] = a - s * (3 * x**2 + y**2), -om - 2 * s * x * y
        J[:, 2, 0], J[:, 2, 2] = om - 2 * s * x * y, a - s * (x**2 + 3 * y**2)
        J[:, 1, 1], J[:, 1, 3], J[:, 3, 1], J[:, 3, 3] = -b, -nu, nu, -b
        return rhs, J

    def rhs(self, z, p):
        return self.rhs_and_jac(z, p)[0]

    def opened(self, z, p):
        return np.zeros(z.shape[1], dtype=bool)


def test_floquet_multipliers_of_a_normal_form_cycle_are_the_exact_ones():
    """Seeded random systems, one batch: the cycle, its period and all four multipliers
    (1, exp(-2 a T), exp((-b +- i nu) T)) as the closed form gives them."""
    rng = np.random.default_rng(2026)
    for _ in range(6):
        a, s, omega, b, nu = (
            rng.uniform(0.05, 0.5),
            rng.uniform(0.5, 2),
            rng.uniform(0.5, 3),
            rng.uniform(0.1, 1),
            rng.uniform(0, 2),
        )
        field = _NormalFormField(a, s, omega, b, nu)
        radius, T = np.sqrt(a / s), 2 * np.pi / omega
        # guesses off by 10% in radius and period, and off the cycle in the linear part
        start = np.array([[1.1 * radius, 0.05, 0.0, -0.05]])
        orbits = shoot(field, [], start, np.array([0.9 * T]), tol=1e-11, rtol=1e-11)
        assert orbits.converged[0]
        assert abs(orbits.period[0] - T) < 1e-8 * T
        assert abs(abs(orbits.start[0, 0]) - radius) < 1e-8 and np.max(np.abs(orbits.start[0, [1, 3]])) < 1e-8
        exact = np.array([np.exp(-2 * a * T), np.exp((-b + 1j * nu) * T), np.exp((-b - 1j * nu) * T)])
        found = orbits.multipliers[0]
        assert abs(found[-1] - 1) < 1e-7  # the trivial one, last
        for value in exact:
            assert np.min(np.abs(found[:-1] - value)) < 1e-7, (found, exact)
        assert orbits.leading_multiplier[0] == pytest.approx(max(np.abs(exact)), abs=1e-7)


def test_a_rest_state_is_not_a_cycle():
    field = _NormalFormField(0.2, 1.0, 1.0, 0.5, 1.0)
    orbits = shoot(field, [], np.zeros((1, 4)), np.array([2 * np.pi]))
    assert not orbits.converged[0]


@pytest.fixture(scope="module")
def brake_cycles():
    h = numerics.hopf_point(cs.scene("brake"), {**DISC, "mu": 1.0}, "mu", laws=LAWS)
    field = fast_field(cs.scene("brake"), laws=LAWS)
    mu = h.value * np.array([1.004, 1.015])
    p = [0, -4, np.pi / 2, 1, mu]  # in the order of field.params
    assert [str(s) for s in field.params] == ["F_x", "F_y", "alpha", "m", "mu"]
    start, period = hopf_guess(h, field, p, mu)
    orbits = shoot(field, p, start, period)
    return h, field, mu, p, orbits


def test_shooting_finds_the_cycle_a_simulation_started_on_it_keeps(brake_cycles):
    """Started on the shot cycle, a simulation of the fast subsystem (its own generated code,
    DOP853) returns to the start after one period and has the same reaction amplitude."""
    h, field, mu, p, orbits = brake_cycles
    assert orbits.converged.all() and np.all(orbits.leading_multiplier < 1)
    _, reactions = sample_orbits(field, p, orbits)
    for n, value in enumerate(mu):
        T = orbits.period[n]
        run = numerics.simulate_fast(
            cs.scene("brake"), {**DISC, "mu": value}, (0, T), initial=orbits.start[n], laws=LAWS,
            method="DOP853", rtol=1e-10, t_eval=np.linspace(0, T, 801),
        )  # fmt: skip
        assert np.max(np.abs(run.y[:, -1] - orbits.start[n])) < 1e-6
        simulated = np.max(np.ptp(run.reactions, axis=1)) / 2
        shot = np.max(np.ptp(reactions[n], axis=1)) / 2
        assert abs(simulated - shot) / shot < 1e-4
        # the normal form agrees to leading order: its error grows like the distance to the line
        predicted = np.max(h.amplitude(value))
        assert abs(predicted - shot) / shot < 4 * (value / h.value - 1)
