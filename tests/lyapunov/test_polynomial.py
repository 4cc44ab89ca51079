"""The brake's closed-form l1 (alpha = 90 deg, identical pads) against independent computations."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym import numerics
from contactsym.laws.library import Hertz
from contactsym.lyapunov.coefficient import fast_hopf_forms, first_lyapunov_from_derivatives
from contactsym.scenes.brake import squeal_direction

# Hertz's nonzero derivatives (Psi = -d is constant) and the weakening damper's Psi_vv: both routes of g21,
# the field's second derivatives (Phi_u, Phi_v) and its third; all ten take ~15 s (notebook 06 shows them)
KEPT = ("Phi_u", "Phi_v", "Phi_uu", "Phi_uv", "Phi_vv", "Psi_vv")
SYMBOLS = [sp.Symbol(name, real=True) for name in KEPT]
BRAKE = cs.scene("brake")
P = {str(s): s for s in BRAKE.parameters}
m, mu = P["m"], P["mu"]
Psi = sp.Symbol("Psi", negative=True)


@pytest.fixture(scope="module")
def closed_form():
    return squeal_direction(cs.scene("brake"), KEPT)


@pytest.fixture(scope="module")
def tensors(closed_form):
    """J, H, T of the pipeline on the same slice, for a numeric l1 that shares nothing with the reduction."""
    Phi_line = closed_form[0]
    at = {P["alpha"]: sp.pi / 2, P["Phi_1"]: Phi_line, P["Phi_2"]: Phi_line, P["Psi_1"]: Psi, P["Psi_2"]: Psi}
    for j in (1, 2):
        for w in ("Phi", "Psi"):
            for order in ("u", "v", "uu", "uv", "vv"):
                name = f"{w}_{order}"
                at[sp.Symbol(f"{w}_{j}_{order}", real=True)] = sp.Symbol(name, real=True) if name in KEPT else 0
    J, H, T, *_ = fast_hopf_forms(BRAKE.stability(), at)
    return sp.lambdify([m, mu, Psi, *SYMBOLS], [J.tolist(), H, T])


def test_the_phi_uu_term_and_the_hopf_line(closed_form):
    Phi_line, l1 = closed_form
    assert sp.expand(Phi_line * m * mu**2 + Psi**2 * (1 + mu**2)) == 0
    expected = -m * mu**3 * (3 * mu**2 + 5) / (4 * (mu**2 + 1) * (mu**2 + 4) * (Psi**2 * (mu**2 + 1) + mu**2))
    assert sp.cancel(l1.coeff(SYMBOLS[2]) - expected) == 0
    assert sp.Poly(l1, *SYMBOLS).total_degree() == 2


@settings(max_examples=10, deadline=None)
@given(
    st.floats(0.3, 3),
    st.floats(0.2, 3),
    st.floats(-2, -0.1),
    st.lists(st.floats(-2, 2), min_size=len(KEPT), max_size=len(KEPT)),
)
def test_closed_form_equals_the_numeric_l1_on_the_hopf_line(closed_form, tensors, m_, mu_, Psi_, d):
    """Eigenvectors by numpy, solves by LAPACK, the same normalization <q, q> = <p, q> = 1."""
    J, H, T = (np.asarray(x, dtype=float) for x in tensors(m_, mu_, Psi_, *d))
    numeric = first_lyapunov_from_derivatives(J, H, T).l1
    symbolic = float(closed_form[1].subs({m: m_, mu: mu_, Psi: Psi_, **dict(zip(SYMBOLS, d))}))
    assert symbolic == pytest.approx(numeric, rel=1e-7, abs=1e-10)


def test_hertz_pads_at_equal_loads_agree_with_hopf_point_in_other_coordinates(closed_form):
    """Equal loads u*_1 = u*_2 = 2 (F_y = -u(1 + mu), F_x = u(1 - mu)); the Hopf point found along m
    by root finding on eigenvalues in (Q, V); l1_uv = l1_QV / |q_uv|^2 (the same cycle)."""
    Phi_line, l1 = closed_form
    mu_, u_star = 0.8, 2.0
    values = {"mu": mu_, "alpha": np.pi / 2, "F_x": u_star * (1 - mu_), "F_y": -u_star * (1 + mu_), "m": 1}
    h = numerics.hopf_point(BRAKE, values, "m", laws={0: Hertz(), 1: Hertz()})
    assert h.u_star == pytest.approx([u_star, u_star], rel=1e-12)
    u, v = sp.symbols("u v", real=True)
    Phi_law, Psi_law = Hertz().phi_psi(u, v, None)
    here = {u: u_star, v: 0}
    m_star = float(sp.solve(Phi_line - Phi_law.subs(here), m)[0].subs({mu: mu_, Psi: Psi_law}))
    assert h.value == pytest.approx(m_star, rel=1e-9)
    law = {
        s: sp.diff(Phi_law if s.name.startswith("Phi") else Psi_law, *[u if c == "u" else v for c in s.name[4:]])
        for s in SYMBOLS
    }
    at = {m: m_star, mu: mu_, Psi: Psi_law, **{s: float(e.subs(here)) for s, e in law.items()}}
    q_uv = np.concatenate([h.reaction_vector, h.vectors.q[2:]])
    assert float(l1.subs(at)) == pytest.approx(h.l1 / np.vdot(q_uv, q_uv).real, rel=1e-6)


def test_the_closed_form_sign_is_the_simulated_direction(closed_form):
    """A damper that weakens with the rate: Phi = -1, Psi = -3/10 + V^2/10 - ..., so only Psi_vv = 1/5 and
    the closed form says l1 > 0. Along m before the line the fast subsystem has two attractors."""
    q, qd, eps = sp.Symbol("q", real=True), sp.Symbol("qdot", real=True), sp.Symbol("epsilon", positive=True)
    V = qd / eps
    weakening = cs.Law(-q / eps**2 - sp.Rational(3, 10) * V + V**3 / 30 - V**5 / 500, q, qd, eps, check=False)
    l1 = closed_form[1].subs({m: 1, mu: sp.Rational(4, 5), Psi: sp.Rational(-3, 10)})
    sign = sp.sign(l1.subs({s: (sp.Rational(1, 5) if s.name == "Psi_vv" else 0) for s in SYMBOLS}))
    assert sign == 1
    mu_, u_star, laws = 0.8, 2.0, {0: weakening, 1: weakening}
    values = {"mu": mu_, "alpha": np.pi / 2, "F_x": u_star * (1 - mu_), "F_y": -u_star * (1 + mu_), "m": 1}
    h = numerics.hopf_point(BRAKE, values, "m", laws=laws)
    assert h.direction == "subcritical"
    m_before = h.value * (1 - 0.03 * np.sign(h.dalpha))
    duration, period = 1 / abs(h.dalpha * (m_before - h.value)), 2 * np.pi / h.omega
    amplitudes = []
    for factor in (0.7, 1.3):
        run = numerics.simulate_fast(
            BRAKE,
            {**values, "m": m_before},
            (0, duration),
            initial=h.cycle_start(m_before, factor),
            laws=laws,
            method="DOP853",
            rtol=1e-7,
            t_eval=np.linspace(duration - 2 * period, duration, 800),
        )
        amplitudes.append((run.reactions[0].max() - run.reactions[0].min()) / 2)
    assert amplitudes[0] < 0.7 * h.amplitude(m_before)[0] and amplitudes[1] > 2 * h.amplitude(m_before)[0]
