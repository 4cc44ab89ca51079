"""§3: one contact. Propositions 3-5 and the Painlevé–Klein rod (3.5)-(3.9)."""

import math

import numpy as np
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import contactsym as cs
from tests.helpers import fast_numeric, fast_truth, numeric, same, truth

rod = cs.scene("painleve-klein-rod")
fast = rod.fast_subsystem()
(u,) = fast.u
phi, l = sp.symbols("phi l", positive=True)
mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
X1, X2, Y1, Y2 = sp.symbols("X_1 X_2 Y_1 Y_2", real=True)
mu_p, mu_m = sp.symbols("mu_+ mu_-", real=True)


def printed_3_6(star_divisor):
    """(3.6) with Y*_j = Y_j / star_divisor: the print has cos(phi), the derivation sin(phi)."""
    Xs = (X2 - X1) / sp.cos(phi)
    Y1s, Y2s = Y1 / star_divisor, Y2 / star_divisor
    m1, m2 = mu1 * sp.tan(phi), mu2 * sp.tan(phi)
    return Xs + m1 * sp.Abs(u - Y1s) - m2 * sp.Abs(u + Y2s) + 2 * u


parameters = st.fixed_dictionaries(
    {
        phi: st.floats(0.05, 1.5),
        mu1: st.floats(0, 3),
        mu2: st.floats(0, 3),
        X1: st.floats(-5, 5),
        X2: st.floats(-5, 5),
        Y1: st.floats(-5, 5),
        Y2: st.floats(-5, 5),
        u: st.floats(-20, 20),
    }
)


@settings(max_examples=150, deadline=None)
@given(parameters)
def test_f_is_3_6_with_y_star_over_sin_phi(values):
    f = fast.f[0]
    assert math.isclose(
        fast_numeric(f, values), fast_numeric(printed_3_6(sp.sin(phi)), values), rel_tol=1e-9, abs_tol=1e-9
    )


def test_printed_y_star_over_cos_phi_is_a_misprint():
    values = {phi: 0.4, mu1: 0.7, mu2: 0.2, X1: 1, X2: 2, Y1: 1.5, Y2: -0.5, u: 0.3}
    assert abs(numeric(fast.f[0], values) - numeric(printed_3_6(sp.cos(phi)), values)) > 0.1


def test_the_two_forms_agree_when_phi_is_45_degrees():
    values = {phi: sp.pi / 4, mu1: 0.7, mu2: 0.2, X1: 1, X2: 2, Y1: 1.5, Y2: -0.5, u: 0.3}
    assert math.isclose(numeric(fast.f[0], values), numeric(printed_3_6(sp.cos(phi)), values), rel_tol=1e-12)


def slope(signs):
    return rod.present(rod.linearization(signs=signs).A[0])


def test_slopes_of_the_four_pieces_in_mu_pm():
    # switching functions: sigma_1 = u sin(phi) - Y_1 = N_1, sigma_2 = u sin(phi) + Y_2 = -N_2
    assert same(slope((1, 1)), 2 + mu_m)
    assert same(slope((1, -1)), 2 + mu_p)
    assert same(slope((-1, 1)), 2 - mu_p)
    assert same(slope((-1, -1)), 2 - mu_m)


def test_case_y1_plus_y2_zero_has_slopes_2_pm_mu_minus_3_7():
    # With Y*_2 = -Y*_1 both switching functions change sign at u = Y*_1: only s_1 = s_2 occurs.
    # The print says "2 - mu_+ and 2 + mu_-"; the pieces are 2 - mu_- and 2 + mu_-.
    values = {phi: 0.6, mu1: 1.3, mu2: 0.4, X1: 0.0, X2: 1.0, Y1: 0.8, Y2: -0.8}
    corner = 0.8 / math.sin(0.6)
    tan = math.tan(0.6)
    left = numeric(fast.f[0], {**values, u: corner - 1}) - numeric(fast.f[0], {**values, u: corner - 2})
    right = numeric(fast.f[0], {**values, u: corner + 2}) - numeric(fast.f[0], {**values, u: corner + 1})
    minus = (1.3 - 0.4) * tan
    assert math.isclose(left, 2 - minus) and math.isclose(right, 2 + minus)
    assert not math.isclose(left, 2 - (1.3 + 0.4) * tan)


def test_3_8_is_proposition_4_on_the_pieces_of_the_symmetric_case():
    unique = sp.And(sp.Gt(slope((1, 1)), 0), sp.Gt(slope((-1, -1)), 0))
    for mu_value in np.linspace(-4, 4, 81):
        assert truth(unique, {mu_m: mu_value}) == (abs(mu_value) < 2)


@settings(max_examples=200, deadline=None)
@given(st.floats(0.05, 1.5), st.floats(0, 3), st.floats(0, 3))
def test_3_9_is_proposition_4_on_all_pieces(phi_value, m1, m2):
    mu_plus = (m1 + m2) * math.tan(phi_value)
    assume(abs(mu_plus - 2) > 1e-9)
    unique = rod.stability().unique_for_every_load
    assert fast_truth(unique, {phi: phi_value, mu1: m1, mu2: m2}) == (mu_plus < 2)


def corners(values):
    return sorted([values[Y1] / math.sin(values[phi]), -values[Y2] / math.sin(values[phi])])


def roots_numerically(values):
    """Roots of the piecewise-linear f, found from its values at the corners."""

    def f(x):
        return fast_numeric(fast.f[0], {**values, u: x})

    low, high = corners(values)
    grid = [low - 1e6, low, high, high + 1e6]
    roots = []
    for a, b in zip(grid, grid[1:]):
        fa, fb = f(a), f(b)
        if fa * fb < 0:
            roots.append(a - fa * (b - a) / (fb - fa))
    return roots


@settings(max_examples=150, deadline=None)
@given(parameters)
def test_equilibrium_branches_are_the_roots_of_f(values):
    values = {k: v for k, v in values.items() if k is not u}
    assume(all(abs(fast_numeric(fast.f[0], {**values, u: c})) > 1e-6 for c in corners(values)))  # no root on a corner
    for signs in rod.sign_patterns():  # no flat piece
        assume(abs(fast_numeric(rod.linearization(signs=signs).A[0], values)) > 1e-6)
    expected = roots_numerically(values)
    found = [b for b in rod.equilibria() if fast_truth(b.condition, values)]
    assert len(found) == len(expected)
    for branch in found:
        u_star = fast_numeric(branch.u_star[0], values)
        assert min(abs(u_star - r) for r in expected) < 1e-6 * (1 + abs(u_star))
        # Proposition 3: stable iff the slope is positive, for every law
        a = fast_numeric(rod.linearization(signs=branch.signs).A[0], values)
        stable = rod.stability(signs=branch.signs)
        assert fast_truth(stable.robustly_stable, values) == (a > 0)


def test_proposition_5_no_cycles_for_constant_laws():
    # V = Phi v^2/2 - Pi(u), Pi' = f: along the derived (3.1) V' = -Psi f^2 >= 0 (the print says V' < 0;
    # either way V is monotone and no cycle exists)
    assert rod.stability().no_cycles and fast.constant_laws
    (v,), (f,), (Phi,), (Psi,) = fast.v, fast.f, fast.Phi, fast.Psi
    V = Phi * v**2 / 2 - sp.Integral(f, u)
    dV = sum(V.diff(x) * x_dot for x, x_dot in zip(fast.state, fast.rhs))
    assert same(dV, -Psi * f**2)
    symbols = (phi, mu1, mu2, X1, X2, Y1, Y2, u, v, Phi, Psi)
    rate, expected = sp.lambdify(symbols, dV.doit()), sp.lambdify(symbols, -Psi * f**2)
    rng = np.random.default_rng(5)
    for _ in range(200):  # the same at random points of the state and the parameters, and never negative
        values = (rng.uniform(0.05, 1.5), *rng.uniform(0, 3, 2), *rng.normal(0, 3, 6), *-rng.exponential(2, 2))
        assert rate(*values) >= 0
        assert math.isclose(rate(*values), expected(*values), rel_tol=1e-9, abs_tol=1e-12)


def test_cusp_three_roots_and_fold_none_occur():
    # zigzag: |mu_-| < 2 < mu_+, Y*_1 + Y*_2 > 0 -> three roots for X* in a window (cusp)
    base = {phi: math.atan(1.0), mu1: 1.5, mu2: 1.2, X1: 0.0, Y1: 2.0, Y2: 2.0}
    counts = {len(roots_numerically({**base, X2: x})) for x in np.linspace(-8, 8, 161) * math.cos(math.atan(1.0))}
    assert counts == {1, 3}
    # fold: mu_- > 2 -> two roots or none (impact-type catastrophe)
    base = {phi: math.atan(1.0), mu1: 3.0, mu2: 0.2, X1: 0.0, Y1: 1.0, Y2: -1.0}
    counts = {len(roots_numerically({**base, X2: x})) for x in np.linspace(-8, 8, 161)}
    assert counts == {0, 2}
