"""Compliance laws (1.5), (1.8); the small parameter eps (1.6). Friction laws: tests/test_friction.py."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.errors import ComplianceError, SceneError

q, qd = sp.symbols("q qdot", real=True)
eps, k, d, c = sp.symbols("epsilon k d c", positive=True)
u, v = sp.symbols("u v", real=True)
Q, V = sp.symbols("Q V", real=True)


def direct(N: sp.Expr) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """(N, Phi, Psi) from the definitions, in the scaled variables q = eps^2 Q, q' = eps V:
    N0 = lim N, Phi = lim eps^2 dN/dq, Psi = lim eps dN/dq'."""
    at = {q: eps**2 * Q, qd: eps * V}
    N0 = sp.limit(N.subs(at), eps, 0, "+")
    Phi = sp.limit((eps**2 * sp.diff(N, q)).subs(at), eps, 0, "+")
    Psi = sp.limit((eps * sp.diff(N, qd)).subs(at), eps, 0, "+")
    return N0, Phi, Psi


def same(a: sp.Expr, b: sp.Expr) -> bool:
    return sp.simplify(a - b) == 0


# --- Generic ------------------------------------------------------------------------


def test_generic_law_gives_negative_symbols():
    Phi, Psi = cs.Generic().phi_psi(u, v, None)
    assert (str(Phi), str(Psi)) == ("Phi", "Psi") and Phi.is_negative and Psi.is_negative
    assert (Phi, Psi) != (sp.Symbol("Phi", negative=True), sp.Symbol("Psi", negative=True))  # the law's own
    Phi2, Psi2 = cs.Generic().phi_psi(u, v, 2)
    assert str(Phi2) == "Phi_2" and str(Psi2) == "Psi_2"
    assert Phi2.is_negative and Psi2.is_negative
    assert cs.Generic().constant
    assert cs.Generic() == cs.Generic()


def test_generic_deformation_is_of_order_eps_squared():
    deformation = cs.Generic().deformation(u, v, eps, 1)
    assert sp.limit(deformation / eps**2, eps, 0) == sp.Function("Q_1")(u, v)


def test_generic_law_in_a_scene_uses_indexed_symbols_for_k_2():
    fast = cs.scene("brake").fast_subsystem()
    assert [str(p) for p in fast.Phi] == ["Phi_1", "Phi_2"]
    assert [str(p) for p in fast.Psi] == ["Psi_1", "Psi_2"]
    assert all(p.is_negative for p in fast.Phi + fast.Psi)


# --- Kelvin-Voigt ---------------------------------------------------------------------


@pytest.mark.parametrize("stiffness, damping", [(1, 1), (3, sp.Rational(1, 2)), (k, d), (k**2 + 1, 2 * c)])
def test_kelvin_voigt_phi_psi(stiffness, damping):
    law = cs.KelvinVoigt(stiffness, damping)
    assert law.phi_psi(u, v, None) == (-sp.sympify(stiffness), -sp.sympify(damping))
    assert law.constant


def test_kelvin_voigt_agrees_with_the_definition():
    N = -k * q / eps**2 - d * qd / eps
    N0, Phi, Psi = direct(N)
    assert cs.KelvinVoigt(k, d).phi_psi(u, v, None) == (Phi, Psi)
    # its deformation inverts u = N(q, q') with q' = eps v
    deformation = cs.KelvinVoigt(k, d).deformation(u, v, eps, None)
    assert sp.expand(N.subs({q: deformation, qd: eps * v}) - u) == 0


def test_kelvin_voigt_of_the_paper_example_1_11():
    b = sp.Symbol("b", positive=True)
    assert cs.KelvinVoigt(1, 2 * b).phi_psi(u, v, None) == (-1, -2 * b)
    fast = cs.scene("sliding-point").fast_subsystem()
    assert (fast.Phi, fast.Psi) == ((-1,), (-2 * b,))


@pytest.mark.parametrize("value", [0, -1, -k, sp.Rational(-1, 3)])
def test_kelvin_voigt_non_positive_stiffness(value):
    with pytest.raises(ComplianceError) as info:
        cs.KelvinVoigt(value, 1)
    message = str(info.value)
    assert f"stiffness = {value} is not positive" in message
    assert "(1.5)" in message
    assert "use a positive stiffness" in message


@pytest.mark.parametrize("value", [0, -2, -d])
def test_kelvin_voigt_non_positive_damping(value):
    with pytest.raises(ComplianceError) as info:
        cs.KelvinVoigt(1, value)
    message = str(info.value)
    assert f"damping = {value} is not positive" in message
    assert "use a positive damping" in message


@pytest.mark.parametrize(
    "stiffness, damping, what, shown",
    [
        (sp.Symbol("K"), 1, "stiffness", "K"),
        (1, sp.Symbol("D", real=True), "damping", "D"),
        (k - 1, 1, "stiffness", "k - 1"),
    ],
)
def test_kelvin_voigt_undecidable_sign_suggests_positive_true(stiffness, damping, what, shown):
    with pytest.raises(ComplianceError) as info:
        cs.KelvinVoigt(stiffness, damping)
    message = str(info.value)
    assert f"cannot show {what} = {shown} > 0" in message
    assert "positive=True" in message


# --- user laws ------------------------------------------------------------------------

LAWS = [
    # linear spring-damper
    -k * q / eps**2 - d * qd / eps,
    # cubic damping (docstring)
    -k * q / eps**2 - d * qd / eps - c * (qd / eps) ** 3,
    # saturating damping
    -k * q / eps**2 - d * sp.atan(qd / eps),
    # higher-order terms that vanish under the scaling (1.8)
    -k * q / eps**2 - d * qd / eps + q + qd**2 - k * q**2 / eps**2 + q / eps,
    # nonlinear stiffness depending on the deformation: Phi depends on u
    k * (1 - sp.exp(q / eps**2)) - d * qd / eps,
    # preload and a deformation-dependent damping that vanishes under scaling
    -k * q / eps**2 - d * qd / eps * (1 + sp.cos(q)) - 5,
]


@pytest.mark.parametrize("N", LAWS, ids=range(len(LAWS)))
def test_law_phi_psi_agree_with_direct_limits(N):
    law = cs.Law(N, q, qd, eps)
    Phi, Psi = law.phi_psi(u, v, None)
    assert not (Phi.free_symbols | Psi.free_symbols) & {q, qd, eps}
    N0, Phi_direct, Psi_direct = direct(N)
    # the law is written in (u, v): u = N0(Q, V), v = V
    back = {u: N0, v: V}
    assert same(Phi.subs(back), Phi_direct)
    assert same(Psi.subs(back), Psi_direct)
    # and the deformation inverts u = N(eps^2 Q, eps v) in the limit
    deformation = law.deformation(u, v, eps, None)
    assert same(N0.subs({Q: deformation / eps**2, V: v}), u)


def test_law_docstring_example_and_constancy():
    law = cs.Law(-k * q / eps**2 - d * qd / eps - c * (qd / eps) ** 3, q, qd, eps)
    assert law.phi_psi(u, v, None) == (-k, -3 * c * v**2 - d)
    assert not law.constant
    assert cs.Law(-k * q / eps**2 - d * qd / eps, q, qd, eps).constant


def test_law_with_deformation_dependent_stiffness_gives_phi_of_u():
    law = cs.Law(k * (1 - sp.exp(q / eps**2)) - d * qd / eps, q, qd, eps)
    Phi, Psi = law.phi_psi(u, v, None)
    assert sp.expand(Phi - (u + d * v - k)) == 0
    assert Psi == -d


@settings(max_examples=12, deadline=None)
@given(
    st.integers(1, 5),
    st.integers(1, 5),
    st.integers(0, 3),
    st.integers(-3, 3),
    st.integers(-3, 3),
    st.integers(0, 2),
)
def test_random_polynomial_laws_agree_with_direct_limits(kk, dd, cubic, junk_q, junk_qd, shift):
    """N = -kk Q - dd V - cubic V^3 (scaled), plus terms that vanish under (1.8) and a preload."""
    N = -kk * q / eps**2 - dd * qd / eps - cubic * (qd / eps) ** 3 + junk_q * q / eps + junk_qd * qd**2 - shift
    Phi, Psi = cs.Law(N, q, qd, eps).phi_psi(u, v, None)
    _, Phi_direct, Psi_direct = direct(N)
    assert Phi == Phi_direct == -kk
    assert sp.expand(Psi - Psi_direct.subs(V, v)) == 0
    assert sp.expand(Psi - (-dd - 3 * cubic * v**2)) == 0


def test_law_with_positive_stiffness_names_dN_dq():
    with pytest.raises(ComplianceError) as info:
        cs.Law(k * q / eps**2 - d * qd / eps, q, qd, eps)
    message = str(info.value)
    assert "(1.5) requires dN/dq < 0" in message
    assert "Phi = eps**2 dN/dq = k is not negative" in message
    assert "penetration" in message


def test_law_without_damping_names_dN_dqdot():
    with pytest.raises(ComplianceError) as info:
        cs.Law(-k * q / eps**2 + d * qd / eps, q, qd, eps)
    assert "(1.5) requires dN/dq' < 0" in str(info.value)
    assert "dissipate" in str(info.value)
    with pytest.raises(ComplianceError, match="dN/dq' < 0"):
        cs.Law(-k * q / eps**2, q, qd, eps)


def test_law_with_undecidable_sign_suggests_positive_true_or_check_false():
    K = sp.Symbol("K")
    with pytest.raises(ComplianceError) as info:
        cs.Law(-K * q / eps**2 - d * qd / eps, q, qd, eps)
    message = str(info.value)
    assert "cannot be shown negative" in message
    assert "positive=True" in message and "check=False" in message


def test_law_scaled_too_strongly_positive_divergence():
    with pytest.raises(ComplianceError) as info:
        cs.Law(k * q / eps**3 - d * qd / eps, q, qd, eps)
    message = str(info.value)
    assert "not scaled as (1.8)" in message
    assert "stiffness/eps**2 and damping/eps" in message


def test_law_scaled_as_eps_cubed_is_rejected():
    """The brief's example -k q / eps**3: some ComplianceError (see the xfail below for its message)."""
    with pytest.raises(ComplianceError):
        cs.Law(-k * q / eps**3 - d * qd / eps, q, qd, eps)


@pytest.mark.parametrize("check", [True, False])
@pytest.mark.parametrize("N", [-k * q / eps**3 - d * qd / eps, -k * q / eps**2 - d * qd / eps**2])
def test_law_scaled_too_strongly_negative_divergence(N, check):
    with pytest.raises(ComplianceError, match=r"not scaled as \(1\.8\)"):
        cs.Law(N, q, qd, eps, check=check).phi_psi(u, v, None)


HERTZ = c * (-q) ** sp.Rational(3, 2) / eps**3


def test_hertz_law_is_refused_by_the_sign_check():
    """Hertz stiffness vanishes at q = 0, so (1.5) cannot be shown: an error that offers check=False."""
    with pytest.raises(ComplianceError) as info:
        cs.Law(HERTZ - d * qd / eps, q, qd, eps)
    message = str(info.value)
    assert "dN/dq" in message
    assert "check=False" in message


def test_hertz_law_with_check_false_gives_phi_of_u():
    law = cs.Law(HERTZ, q, qd, eps, check=False)
    Phi, Psi = law.phi_psi(u, v, None)
    assert Psi == 0
    # direct: eps^2 dN/dq = -(3/2) c (-Q)^(1/2) and u = c (-Q)^(3/2)
    for c_value, u_value in [(1, 8), (2, 3), (sp.Rational(1, 2), 5)]:
        expected = -sp.Rational(3, 2) * c_value ** sp.Rational(2, 3) * u_value ** sp.Rational(1, 3)
        assert abs(complex(Phi.subs({c: c_value, u: u_value})) - complex(expected)) < 1e-12


# --- eps (1.6) ------------------------------------------------------------------------

x, y = dynamicsymbols("x y")
N_, Y_ = sp.symbols("N Y", real=True)


def scene_with_eps(value):
    return cs.Scene.from_accelerations([x, y], [0, N_ + Y_], [cs.Contact(coordinate=y, reaction=N_)], eps=value)


def test_default_eps_is_a_positive_symbol():
    s = scene_with_eps(None)
    assert str(s.eps) == "epsilon" and s.eps.is_positive and s.eps != sp.Symbol("epsilon", positive=True)
    assert s.regularized().eps is s.eps


@pytest.mark.parametrize("value", [sp.Rational(1, 10), 0.01, 3, sp.Symbol("e", positive=True)])
def test_positive_eps_is_accepted(value):
    assert scene_with_eps(value).eps == sp.sympify(value)


@pytest.mark.parametrize("value", [0, -1, -0.5, sp.Symbol("e", negative=True), -sp.Symbol("e", positive=True)])
def test_non_positive_eps_gets_a_clear_error(value):
    with pytest.raises(SceneError) as info:
        scene_with_eps(value)
    message = str(info.value)
    assert f"eps = {sp.sympify(value)} must be > 0" in message
    assert "(1.6)" in message


@pytest.mark.parametrize("value", [sp.Symbol("e"), sp.Symbol("e", real=True), sp.Symbol("e", nonnegative=True)])
def test_eps_of_unknown_sign_asks_for_positive_true(value):
    with pytest.raises(SceneError) as info:
        scene_with_eps(value)
    message = str(info.value)
    assert "cannot show eps = e > 0" in message
    assert "positive=True" in message


# --- the reaction each law writes for the numerics (Compliance.reaction, reaction_scaled) ----------


LAWS = [
    cs.Generic(),
    cs.KelvinVoigt(k, d),
    cs.Law(-k * q / eps**2 - d * qd / eps - c * (qd / eps) ** 3, q, qd, eps),
    cs.Law(-k * q / eps**2 - c * (q / eps**2) ** 3 - d * qd / eps, q, qd, eps),
]


@pytest.mark.parametrize("index", [None, 2])
@pytest.mark.parametrize("law", LAWS, ids=lambda law: type(law).__name__)
def test_scaled_reaction_is_the_limit_of_the_reaction_and_its_slopes_are_phi_psi(law, index):
    # (1.8): N(eps^2 Q, eps V, eps) -> reaction_scaled(Q, V) as eps -> 0, and (3.1): its slopes in Q and V
    # are Phi and Psi, the law's own phi_psi, at u = N (checked where Q(u, v) is not implicit)
    N = law.reaction(eps**2 * Q, eps * V, eps, index)
    scaled = law.reaction_scaled(Q, V, index)
    assert same(sp.limit(N, eps, 0, "+"), scaled)
    Phi, Psi = law.phi_psi(u, v, index)
    if isinstance(law, cs.Law) and not law.constant:
        Phi, Psi = (e.xreplace({s: Q for s in e.atoms(cs.laws.ImplicitDeformation)}) for e in (Phi, Psi))
    at = {u: scaled, v: V}
    assert same(sp.diff(scaled, Q), Phi.subs(at)) and same(sp.diff(scaled, V), Psi.subs(at))


def test_only_a_generic_law_needs_numbers_for_phi_psi_and_laws_name_their_parameters():
    assert cs.Generic().coefficients(1) == cs.Generic().phi_psi(u, v, 1)
    assert all(law.coefficients(1) == () for law in LAWS[1:])
    assert cs.KelvinVoigt(k, 2 * d).parameters() == {k, d}
    assert LAWS[2].parameters() == {k, d, c}


def test_a_law_defined_in_compression_gives_no_reaction_where_the_contact_opens():
    hertz = cs.Law((-q) ** sp.Rational(3, 2) / eps**3 - qd / eps, q, qd, eps, where=[-q])
    f = sp.lambdify([Q, V], hertz.reaction_scaled(Q, V, None))
    assert f(-4.0, 0.0) == pytest.approx(8.0) and f(1.0, -5.0) == 0.0  # open: N = 0, never a complex power
