"""contactsym.numerics.certified: certified classification, exact near the boundary."""

import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym import numerics as nm
from tests.helpers import max_real_part
from tests.numerics.brake import (
    P1,
    P2,
    S1,
    S2,
    Phi,
    Psi,
    alpha,
    brake,
    m,
    mu,
    right_angle,
    stab,
)

# --- certified classification ------------------------------------------------------------


def exact_6_4_stable(mass: Fraction, friction: Fraction, phi: Fraction, psi: Fraction) -> int:
    """The corrected (6.4), in exact fractions: sign of Psi^2 (1 + mu^2) + m mu^2 Phi."""
    margin = psi**2 * (1 + friction**2) + mass * friction**2 * phi
    return (margin > 0) - (margin < 0)


@settings(max_examples=60, deadline=None)
@given(
    st.fractions(Fraction(1, 10), Fraction(10), max_denominator=97),
    st.fractions(Fraction(1, 20), Fraction(3), max_denominator=97),
    st.fractions(Fraction(-5), Fraction(-1, 10), max_denominator=97),
    st.sampled_from([0.0, 1e-15, -1e-15, 1e-13, -1e-13, 1e-12, -1e-12, 3e-16]),
)
def test_points_near_the_hopf_line_are_decided_exactly(mass, friction, psi, relative):
    on_line = -(1 + friction**2) * psi**2 / (mass * friction**2)
    phi = float(on_line) * (1 + relative)  # a float within 1e-12 (relative) of the boundary
    point = {
        "alpha": sp.pi / 2,
        "m": float(mass),
        "mu": float(friction),
        "Psi_1": float(psi),
        "Psi_2": float(psi),
        "Phi_1": phi,
        "Phi_2": phi,
    }
    truth = exact_6_4_stable(Fraction(float(mass)), Fraction(float(friction)), Fraction(phi), Fraction(float(psi)))
    result = nm.classify(brake, point)
    assert result.stable == truth
    assert result.exact[-1]  # inside the band: recomputed in rationals
    classifier = nm.PointClassifier([c.subs(right_angle) for c in stab.hurwitz], [m, mu, Phi, Psi])
    vectorised = classifier(
        np.array([float(mass)]), np.array([float(friction)]), np.array([phi]), np.array([float(psi)])
    )
    assert vectorised.stable[0] == truth and vectorised.exact_points == 1


def test_vectorised_classification_agrees_with_eigenvalues_outside_the_band():
    rng = np.random.default_rng(4)
    n = 3000
    a = rng.uniform(0.05, math.pi - 0.05, n)
    mass, friction = rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n)
    phis, psis = -np.exp(rng.normal(0, 1.5, (2, n))), -np.exp(rng.normal(0, 1.5, (2, n)))
    parameters = [alpha, m, mu, P1, P2, S1, S2]
    classifier = nm.PointClassifier(stab.hurwitz, parameters)
    result = classifier(a, mass, friction, phis[0], phis[1], psis[0], psis[1])
    assert 0.05 < np.mean(result.stable == 1) < 0.95  # both regions are sampled
    for i in range(n):
        if result.in_band[i]:
            continue
        A = (
            np.array(
                [
                    [1, friction[i] * math.sin(a[i]) - math.cos(a[i])],
                    [-friction[i] * math.sin(a[i]) - math.cos(a[i]), 1],
                ]
            )
            / mass[i]
        )
        eigen = max_real_part(A, phis[:, i], psis[:, i])
        if abs(eigen) > 1e-9:
            assert (eigen < 0) == (result.stable[i] == 1), i


def test_classify_reports_the_region_of_every_law():
    values = {"alpha": 0.5, "m": 1, "mu": 0.5, "Phi_1": -1, "Phi_2": -2, "Psi_1": -1, "Psi_2": -1}
    assert nm.classify(brake, values).region == "robustly stable"  # mu < cot(alpha), (6.3)
    assert nm.classify(brake, {**values, "mu": 3}).region == "law-dependent"


@settings(max_examples=30, deadline=None)
@given(theta=st.floats(-3.1, 3.1), beta=st.floats(-3.1, 3.1), friction=st.floats(0.05, 3.0))
def test_a_point_outside_the_declared_domain_gets_no_verdict(theta, beta, friction):
    """The spatial rod declares 0 < theta, beta < pi/2 (sin, cos > 0), and its printed regions divide
    by sin(theta) cos(beta) cos(theta): outside the domain classify refuses the point (it once gave
    'robustly stable' where the printed region said False); inside, its verdict is the printed region's."""
    import contactsym as cs

    rod = cs.scene("painleve-rod-3d")
    values = {"m": 1.0, "mu": friction, "beta": beta, "theta": theta, "Phi": -1.0, "Psi": -1.0}
    inside = min(math.sin(theta), math.cos(theta), math.sin(beta), math.cos(beta)) > 0  # checked with math
    if not inside:
        with pytest.raises(nm.NumericsError, match="outside the domain of 'painleve-rod-3d'|declared positive"):
            nm.classify(rod, values)
        return
    region = rod.regions()["stable for every law"]
    point = {s: values[str(s)] for s in region.condition.free_symbols}
    printed = bool(region.condition.subs(point))
    assert (nm.classify(rod, values).region == "robustly stable") == printed


def test_three_contacts_are_decided_at_the_point_where_the_regions_prove_nothing():
    """The stool (k = 3): where its symbolic regions are undecided, classify decides the point as the
    scene with the values fixed does (a second derivation); a symbolic sign pattern is named, not asked
    for as a value."""
    import contactsym as cs

    stool = cs.scene("stool-3d")
    law = {f"{name}_{j}": -1.0 for name in ("Phi", "Psi") for j in (1, 2, 3)}
    for friction in (0.3, 1.0):
        found = nm.classify(stool, {"h": 1, "mu": friction, **law}, signs=(1, 1, 1))
        fixed = stool.with_values({"h": 1, "mu": friction}).stability((1, 1, 1))
        names = {"robustly stable": "robustly_stable", "robustly unstable": "robustly_unstable"}
        assert found.region != "undecided"
        assert getattr(fixed, names.get(found.region, "law_dependent")) is sp.true
    with pytest.raises(nm.NumericsError, match=r"symbolic in the sign pattern \['s_1', 's_2', 's_3'\]"):
        nm.classify(stool.stability(), {"h": 1, "mu": 0.5, **law})
    with pytest.raises(nm.NumericsError, match="a Stability has its own"):
        nm.classify(stool.stability((1, 1, 1)), {"h": 1, "mu": 0.5, **law}, signs=(1, 1, 1))
