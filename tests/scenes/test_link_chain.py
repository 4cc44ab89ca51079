"""Beyond the paper: n-link chains with a frictional tip contact (double-pendulum-tip is n = 2).

The pipeline's contact-space derivation (fraction-free Delassus matrix, canonical form) is
checked against an independent numerical derivation: Lagrange's equations solved by NumPy at
a point, the tip's vertical acceleration differenced in N; and its stability verdicts against
eigenvalues of (4.5) built from that numerical A.
"""

from __future__ import annotations

import random
from functools import cache

import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import LagrangesMethod, Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

import contactsym as cs
from contactsym.scenes.link_chain import build_chain
from tests.helpers import fast_numeric, fast_truth

t = dynamicsymbols._t


@cache
def _numeric_chain(n: int):
    """Tip acceleration f(q, q', N, s, parameters) from Lagrange's equations solved numerically."""
    q = dynamicsymbols(f"a1:{n + 1}")
    m = sp.symbols(f"M1:{n + 1}", positive=True)
    l = sp.symbols(f"L1:{n + 1}", positive=True)
    g, mu, N, s = sp.symbols("g mu N s", real=True)
    O = ReferenceFrame("O")
    pivot = Point("O")
    pivot.set_vel(O, 0)
    joint, particles = pivot, []
    for i in range(n):
        joint = joint.locatenew(f"J{i}", l[i] * (sp.sin(q[i]) * O.x - sp.cos(q[i]) * O.y))
        joint.set_vel(O, joint.pos_from(pivot).dt(O))
        p = Particle(f"p{i}", joint, m[i])
        p.potential_energy = m[i] * g * joint.pos_from(pivot).dot(O.y)
        particles.append(p)
    force = N * O.y - mu * s * N * O.x  # normal reaction and Coulomb friction |N| = s N, sliding in +x
    method = LagrangesMethod(Lagrangian(O, *particles), q, forcelist=[(joint, force)], frame=O)
    method.form_lagranges_equations()
    tip = joint.pos_from(pivot).dot(O.y)
    qd = [x.diff(t) for x in q]
    jac = [tip.diff(x) for x in q]
    curvature = sum(tip.diff(a).diff(b) * qd[i] * qd[j] for i, a in enumerate(q) for j, b in enumerate(q))
    args = [*q, *qd, *m, *l, g, mu, N, s]
    return (
        sp.lambdify(args, method.mass_matrix, "numpy"),
        sp.lambdify(args, method.forcing, "numpy"),
        sp.lambdify(args, sp.Matrix(jac), "numpy"),
        sp.lambdify(args, curvature, "numpy"),
    )


def _tip_acceleration(n, angles, rates, masses, lengths, gravity, mu, N, s):
    M, F, J, h = _numeric_chain(n)
    args = [*angles, *rates, *masses, *lengths, gravity, mu, N, s]
    qdd = np.linalg.solve(np.array(M(*args), float), np.array(F(*args), float).ravel())
    return float(np.array(J(*args), float).ravel() @ qdd + h(*args))


def _random_point(n, rng):
    angles = [rng.uniform(-1.3, 1.3) for _ in range(n)]
    masses = [rng.uniform(0.5, 2) for _ in range(n)]
    lengths = [rng.uniform(0.5, 2) for _ in range(n)]
    # rates on the manifold: the tip's vertical velocity sum l_i sin(q_i) q_i' vanishes
    rates = [rng.uniform(-1, 1) for _ in range(n - 1)]
    last = -sum(lengths[i] * np.sin(angles[i]) * rates[i] for i in range(n - 1)) / (lengths[-1] * np.sin(angles[-1]))
    return angles, rates + [last], masses, lengths, rng.uniform(5, 10), rng.uniform(0.1, 1.5)


def _symbols(scene, n):
    name = (lambda base, i: f"{base}") if n == 1 else (lambda base, i: f"{base}{i + 1}")
    by_name = {str(x): x for x in scene.parameters}
    by_name.update({str(x): x for x in scene.fast_subsystem().u})
    return by_name, name


@pytest.mark.parametrize("n", [1, 2, 3])
def test_contact_acceleration_and_A_match_the_numerical_derivation(n):
    scene = build_chain(n)
    fast, lin = scene.fast_subsystem(), scene.linearization()
    by_name, name = _symbols(scene, n)
    rng = random.Random(n)
    for _ in range(4):
        angles, rates, masses, lengths, gravity, mu = _random_point(n, rng)
        N = rng.choice([-1, 1]) * rng.uniform(0.5, 3)
        s = 1 if N > 0 else -1
        named = {"mu": mu, "g": gravity}
        for i in range(n):
            named.update({name("q", i): angles[i], name("m", i): masses[i], name("l", i): lengths[i]})
            named[name("q", i) + "dot"] = rates[i]
        values = {by_name[key]: value for key, value in named.items() if key in by_name}
        values[fast.u[0]] = N
        expected = _tip_acceleration(n, angles, rates, masses, lengths, gravity, mu, N, s)
        assert fast_numeric(fast.f[0], values) == pytest.approx(expected, rel=1e-9, abs=1e-9)
        slope = (
            _tip_acceleration(n, angles, rates, masses, lengths, gravity, mu, N + 1e-3, s)
            - _tip_acceleration(n, angles, rates, masses, lengths, gravity, mu, N - 1e-3, s)
        ) / 2e-3
        A = fast_numeric(lin.A[0], {**values, lin.sign_values[0]: s})
        assert A == pytest.approx(slope, rel=1e-6, abs=1e-8)


def test_double_pendulum_A_is_compact():
    A = cs.scene("double-pendulum-tip").linearization().A[0]
    assert sp.count_ops(A) <= 60


def test_double_pendulum_stability_against_eigenvalues():
    scene = cs.scene("double-pendulum-tip")
    st, lin = scene.stability(), scene.linearization()
    by_name, name = _symbols(scene, 2)
    Phi, Psi = lin.Phi[0], lin.Psi[0]
    s_symbol = lin.sign_values[0]
    rng = random.Random(11)
    agree = 0
    for _ in range(60):
        angles, rates, masses, lengths, gravity, mu = _random_point(2, rng)
        mu *= 3
        s = rng.choice([1, -1])
        phi, psi = -rng.uniform(0.1, 5), -rng.uniform(0.1, 5)
        named = {"mu": mu, "q1": angles[0], "q2": angles[1], "m1": masses[0], "m2": masses[1]}
        values = {by_name[key]: value for key, value in named.items() if key in by_name}
        values.update({s_symbol: s, Phi: phi, Psi: psi})
        a = (
            _tip_acceleration(2, angles, rates, masses, lengths, gravity, mu, s * 1.0 + 1e-3, s)
            - _tip_acceleration(2, angles, rates, masses, lengths, gravity, mu, s * 1.0 - 1e-3, s)
        ) / 2e-3
        eigenvalues = np.linalg.eigvals(np.array([[psi * a, phi], [a, 0.0]]))
        stable_numeric = bool(np.all(eigenvalues.real < 0))
        margins = [fast_numeric(c, values) for c in st.hurwitz]
        if min(abs(x) for x in margins) < 1e-6:
            continue
        assert all(x > 0 for x in margins) == stable_numeric
        assert fast_truth(st.robustly_stable, values) == (a > 0)
        agree += 1
    assert agree > 40
