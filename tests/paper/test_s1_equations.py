"""§1: the sliding point (1.10)-(1.12), derived from its Lagrangian."""

import numpy as np
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from tests.helpers import same

scene = cs.scene("sliding-point")
fast = scene.fast_subsystem()
x, xdot = sp.symbols("x xdot", real=True)
b, mu, m = sp.symbols("b mu m", positive=True)
X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)
u, v = fast.u[0], fast.v[0]


def test_fast_subsystem_is_1_12_for_unit_mass():
    # printed (1.12): u' = -v - 2 b u - 2 b Y,  v' = u + Y
    printed = sp.Matrix([-v - 2 * b * u - 2 * b * Y, u + Y])
    assert same(fast.rhs.subs(m, 1), printed)


def test_kelvin_voigt_1_11_as_a_user_law_gives_the_same_phi_psi():
    # second derivation: N = -2 b c y' - c^2 y with c = 1/eps, through Law's limits
    q, qd = sp.symbols("q qdot", real=True)
    eps = sp.Symbol("epsilon", positive=True)
    c = 1 / eps
    law = cs.Law(-2 * b * c * qd - c**2 * q, q, qd, eps)
    assert law.phi_psi(u, v, None) == (-1, -2 * b)
    assert fast.Phi == (-1,) and fast.Psi == (-2 * b,)


def test_regularized_system_reduces_to_fast_subsystem_at_eps_zero():
    reg = scene.regularized()
    assert same(reg.Y.subs(scene.eps, 0), fast.rhs)
    # the slow time is the package's own t: it prints as t, and is no user's Symbol("t", real=True)
    assert reg.X[0] == 1 and str(reg.x[0]) == "t" and reg.x[0] != sp.Symbol("t", real=True)


def test_classical_law_is_recovered():
    # the fast equilibrium u* = -Y gives x'' = X - mu |Y| (unit mass in the paper)
    (branch,) = scene.equilibria().branches
    assert branch.u_star == (-Y,)
    reduced = scene.reduced_system().accelerations[x]
    assert same(reduced.subs(m, 1), X - mu * sp.Abs(Y))


@settings(max_examples=60, deadline=None)
@given(st.floats(0.01, 50), st.floats(0.05, 20))
def test_fast_motions_converge_for_every_b(b_value, m_value):
    # the paper says "eigenvalues negative"; exactly: real parts negative (complex for b < 1)
    J = np.array(fast.rhs.jacobian(fast.state).subs({b: b_value, m: m_value}), dtype=float)
    eigenvalues = np.linalg.eigvals(J)
    assert np.all(eigenvalues.real < 0)
    assert scene.stability().robustly_stable == sp.true
