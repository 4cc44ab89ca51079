"""Friction laws (1.3): Coulomb and viscous friction (contactsym.laws.friction)."""

from __future__ import annotations

import pytest
import sympy as sp

import contactsym as cs

c = sp.Symbol("c", positive=True)


def test_coulomb_magnitude_is_mu_abs_n():
    mu, N, w = sp.symbols("mu N w", real=True)
    law = cs.Coulomb(mu, {})
    assert law.magnitude(N, w) == mu * sp.Abs(N)
    assert law.magnitude(-N, None) == mu * sp.Abs(N)
    assert law.magnitude(sp.Integer(-3), w) == 3 * mu
    assert law.point is None


def test_viscous_magnitude_is_c_times_slip_speed():
    N, w = sp.symbols("N w", real=True)
    law = cs.Viscous(c, {})
    assert law.magnitude(N, w) == c * w
    assert not law.magnitude(N, w).has(N)


def test_friction_laws_are_frozen():
    law = cs.Coulomb(sp.Symbol("mu"), {})
    with pytest.raises(AttributeError):
        law.mu = 1
