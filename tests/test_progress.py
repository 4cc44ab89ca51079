"""Progress reports and time limits: long runs report how far they got, and a spent budget says so honestly."""

from __future__ import annotations

import math

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym import numerics as nm
from contactsym.progress import Budget

ROD = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}
BRAKE = {
    "m": 1.0,
    "mu": 1.0,
    "alpha": math.pi / 2,
    "F_x": 2,
    "F_y": -4,
    "J": 1,
    "r": 1,
    "Phi_1": -2.1,
    "Phi_2": -2.1,
    "Psi_1": -1.0,
    "Psi_2": -1.0,
}


def test_budget_throttles_reports_and_keeps_time():
    seen = []
    budget = Budget(lambda fraction, message: seen.append(fraction), max_seconds=60, every=3600)
    assert budget.report(0.1) is False and budget.report(0.2) is False  # the second is within `every`
    assert budget.report(1.0) is False  # the end is always reported
    assert seen == [0.1, 1.0]
    with pytest.raises(cs.ContactsymError, match="max_seconds"):
        Budget(max_seconds=float("nan"))


def test_integrate_reports_progress_up_to_the_end():
    system = nm.fast_system(cs.scene("painleve-klein-rod"), ROD)
    seen = []
    run = nm.integrate(system, (0, 40), [0.0, 0.0], progress=lambda f, m: seen.append((f, m)), rtol=1e-10)
    assert run.ok
    assert seen[-1][0] == 1.0 and all(0 <= f <= 1 for f, _ in seen)
    assert [f for f, _ in seen] == sorted(f for f, _ in seen)


@pytest.mark.parametrize(
    "options, advice, not_advice",
    [
        ({"method": "Radau"}, "already had the analytic Jacobian", "use method='Radau'"),
        ({"method": "BDF", "jacobian": False}, "jacobian=True", "already had"),
        ({"method": "RK45"}, "use method='Radau' or 'BDF'", "already had"),
    ],
)
def test_a_spent_budget_says_how_far_the_run_got_and_advises_something_new(options, advice, not_advice):
    system = nm.fast_system(cs.scene("painleve-klein-rod"), ROD)
    run = nm.integrate(system, (0, 40), [0.0, 0.0], max_rhs=50, **options)
    assert run.status == "failed"
    assert "50 right-hand-side evaluations (max_rhs)" in run.message and "of the span" in run.message
    assert advice in run.message and not_advice not in run.message


def test_the_stiff_brake_at_eps_1e_6_stops_at_its_time_limit_without_advising_what_it_already_does():
    """Issue #14: at eps = 1e-6 Radau with the analytic Jacobian is the right solver; the span is the cost."""
    initial = {"x": 0, "y": 0, "theta": 0, "xdot": 0, "ydot": 0, "thetadot": -5}
    run = nm.simulate_full(cs.scene("brake"), BRAKE, 1e-6, (0, 1), initial, max_seconds=1.0)
    assert run.status == "failed" and run.analytic_jacobian and run.method == "Radau"
    assert "max_seconds = 1" in run.message
    assert "already had the analytic Jacobian" in run.message and "simulate_reduced" in run.message
    reached = float(run.message.split("it reached t = ")[1].split(",")[0])
    assert 0 <= reached < 1


def test_point_classifier_reports_the_exact_path_and_stops_at_its_limit():
    m, mu = sp.symbols("m mu", positive=True)
    pc = nm.PointClassifier([m - mu], [m, mu])
    values = np.linspace(0.5, 2.0, 40)  # m = mu exactly: every point goes the exact way
    seen = []
    out = pc(values, values, progress=lambda f, message: seen.append((f, message)))
    assert out.exact_points == 40 and out.stable.tolist() == [0] * 40
    assert seen[-1] == (1.0, "40 points, 40 decided exactly")
    with pytest.raises(nm.NumericsError, match=r"decided 0 of 40 points .* max_seconds = 0"):
        pc(values, values, max_seconds=0)
