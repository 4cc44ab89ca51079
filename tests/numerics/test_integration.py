"""contactsym.numerics.integration: the budget of a run."""

import sympy as sp

import contactsym as cs
from contactsym import numerics as nm

x, xdot = sp.symbols("x xdot", real=True)
X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)


def test_lsoda_budget_stops_with_a_message_instead_of_running_for_ever():
    scene = cs.scene("sliding-point")
    values = {"m": 1.0, "b": 1e-3, "mu": 0.5, X: 1, Y: -1}
    run = nm.simulate_full(scene, values, 1e-6, (0, 1), {x: 0, xdot: 1}, method="RK45", max_rhs=5000)
    assert run.status == "failed" and "Radau" in run.message
