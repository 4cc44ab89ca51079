"""The library of contact laws: Phi, Psi from the definitions, implicit inverses, domains, scenes."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.optimize import brentq

import contactsym as cs
from contactsym import numerics
from contactsym.errors import ComplianceError
from contactsym.laws import ImplicitDeformation
from contactsym.laws.library import CubicStiffening, Hertz, HuntCrossley, with_laws

u, v = sp.symbols("u v", real=True)
Q, V = sp.symbols("Q V", real=True)


def scaled(law) -> sp.Expr:
    """N(Q, V) from the law's own expression and the definition (1.8), not from the law's code."""
    eps = law.eps
    return sp.limit(sp.expand(law.expr.subs({law.q: eps**2 * Q, law.qdot: eps * V})), eps, 0, "+")


def Q_at(N: sp.Expr, u_value: float, v_value: float) -> float:
    """The compressive root (Q < 0) of N(Q, v) = u, numerically."""
    f = sp.lambdify(Q, N.subs(V, v_value) - u_value)
    return brentq(lambda x: float(np.real(f(complex(x)))), -50, -1e-12)


@pytest.mark.parametrize("kind", ["hertz", "hunt-crossley", "cubic"])
@pytest.mark.parametrize("k, d, u_value, v_value", [(2, 0.5, 1.5, 0.1), (0.7, 1.3, 3.0, -0.2)])
def test_phi_psi_and_their_u_derivative_follow_the_definitions(kind, k, d, u_value, v_value):
    law = {"hertz": Hertz(k, d), "hunt-crossley": HuntCrossley(k, d), "cubic": CubicStiffening(k, 1, d)}[kind]
    N = scaled(law)
    Phi, Psi = law.phi_psi(u, v, None)
    Q_star = Q_at(N, u_value, v_value)

    def at(expr, uu=u_value):
        if expr.atoms(ImplicitDeformation):  # the implicit Q(u, v): its numeric root
            expr = expr.xreplace({f: Q_at(N, uu, v_value) for f in expr.atoms(ImplicitDeformation)})
        return complex(expr.subs({u: uu, v: v_value})).real

    here = {Q: Q_star, V: v_value}
    assert at(Phi) == pytest.approx(float(sp.diff(N, Q).subs(here)), rel=1e-9)
    assert at(Psi) == pytest.approx(float(sp.diff(N, V).subs(here)), rel=1e-9)
    # dPhi/du by implicit differentiation against a central difference through the root
    h = 1e-5
    assert at(sp.diff(Phi, u)) == pytest.approx((at(Phi, u_value + h) - at(Phi, u_value - h)) / (2 * h), rel=1e-5)


def test_hertz_and_hunt_crossley_have_closed_forms_the_cubic_spring_is_implicit():
    assert not Hertz().phi_psi(u, v, None)[0].atoms(ImplicitDeformation)
    assert not HuntCrossley().phi_psi(u, v, None)[0].atoms(ImplicitDeformation)
    assert CubicStiffening().phi_psi(u, v, 1)[0].atoms(ImplicitDeformation)


@pytest.mark.parametrize("make", [Hertz, HuntCrossley])
def test_bad_parameters_are_refused(make):
    with pytest.raises(ComplianceError, match="stiffness = -1 is not positive"):
        make(-1, 1)
    with pytest.raises(ComplianceError, match="exponent n = 1/2 must be a number >= 1"):
        make(1, 1, sp.Rational(1, 2))


def test_where_makes_a_compression_law_admissible_and_the_check_names_the_domain():
    q, qd = sp.symbols("q qdot", real=True)
    eps, c = sp.symbols("epsilon c", positive=True)
    law = cs.Law(c * (-q) ** sp.Rational(3, 2) / eps**3 - qd / eps, q, qd, eps, where=[-q])
    assert law.domain == (-law.Q,)
    with pytest.raises(ComplianceError, match=r"where q > 0 is not negative"):
        cs.Law(c * q ** sp.Rational(3, 2) / eps**3 - qd / eps, q, qd, eps, where=[q])


def test_a_softening_spring_names_where_it_stops_being_monotone():
    q, qd = sp.symbols("q qdot", real=True)
    eps, k, c = sp.symbols("epsilon k c", positive=True)
    with pytest.raises(ComplianceError, match=r"vanishes at Q = q/eps\*\*2 = -sqrt\(3\)\*sqrt\(k\)/\(3\*sqrt\(c\)\)"):
        cs.Law(-k * q / eps**2 + c * (q / eps**2) ** 3 - qd / eps, q, qd, eps)


def test_the_brake_with_hertz_pads_has_phi_psi_at_the_equilibrium():
    brake = with_laws(cs.scene("brake"), Hertz(2, 1))
    lin = brake.linearization()
    assert not set().union(*(p.free_symbols for p in lin.Phi)) & set(lin.fast.u)
    values = {"m": 1, "mu": 0.5, "alpha": 1.2, "F_x": 0.3, "F_y": -4}
    ((_, u_star),) = numerics.equilibrium_reactions(brake, values)
    numbers = numerics.numeric_values(brake, values)
    Phi_law = Hertz(2, 1).phi_psi(u, v, None)[0]
    for Phi_j, u_j in zip(lin.Phi, u_star):
        assert float(numerics.substitute(Phi_j, numbers)) == pytest.approx(float(Phi_law.subs({u: u_j, v: 0})))
    assert len(brake.stability().hurwitz) == 5


def test_simulation_accepts_the_library_laws_and_refuses_uv_for_an_implicit_one():
    values = {"m": 1, "mu": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
    for law in (Hertz(), HuntCrossley(), CubicStiffening()):
        run = numerics.simulate_fast(cs.scene("brake"), values, (0, 5), laws={0: law, 1: law}, method="DOP853")
        assert run.status == "ok" and np.all(np.isfinite(run.reactions))
    with pytest.raises(numerics.NumericsError, match="form='deformation'"):
        numerics.fast_system(cs.scene("brake"), values, laws={0: CubicStiffening(), 1: CubicStiffening()}, form="uv")


def test_smooth_branch_is_the_reaction_inside_the_domain_and_is_not_cut_outside():
    Q, V = sp.symbols("Q V", real=True)
    law = Hertz(2, 1)
    smooth, cut = law.smooth_scaled(Q, V, None), law.reaction_scaled(Q, V, None)
    assert not smooth.has(sp.Piecewise) and cut.has(sp.Piecewise)
    for q, v in [(-0.5, 0.1), (-2.0, -0.3), (-0.1, 0.0)]:  # in compression: the two agree
        assert float(smooth.subs({Q: q, V: v})) == pytest.approx(float(cut.subs({Q: q, V: v})))
    assert cut.subs({Q: 0.5, V: 0}) == 0  # a gap: no reaction, but the smooth branch goes on
    assert sp.diff(smooth, Q).subs({Q: -1, V: 0}) == sp.diff(law.scaled, law.Q).subs({law.Q: -1, law.V: 0})
