"""contactsym.numerics.systems: the full system's laws and its analytic Jacobian."""

import numpy as np
import pytest

import contactsym as cs
from contactsym import numerics as nm
from tests.numerics.brake import brake, brake_values


def test_generic_law_without_phi_psi_is_refused_with_a_fix():
    values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    with pytest.raises(nm.NumericsError, match="generic compliance law; give numeric values for Phi and Psi"):
        nm.full_system(cs.scene("painleve-klein-rod"), values, 1e-3)
    run = nm.simulate_full(
        cs.scene("painleve-klein-rod"), values, 1e-3, (0, 0.1), {"x_1": 0, "xdot_1": 1}, laws={0: cs.KelvinVoigt(1, 1)}
    )
    assert run.ok


def test_analytic_jacobian_matches_finite_differences():
    values = brake_values(-2.1, -1.0, 1.0, 1.0)
    system = nm.full_system(brake, values, 1e-2, unilateral=False)
    z = np.array([1e-4, -2e-4, 0.3, 0.1, -0.2, 1.0])
    J = system.jac(0.0, z)
    h = 1e-7
    numeric = np.column_stack([(system.fun(0.0, z + h * e) - system.fun(0.0, z - h * e)) / (2 * h) for e in np.eye(6)])
    assert np.allclose(J, numeric, rtol=1e-5, atol=1e-3)
