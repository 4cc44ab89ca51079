"""The classical Painlevé rod: f against a hand Newton–Euler derivation, (4.5) against
eigenvalues, mu = 4/3 at tan(theta) = 2 from the derived regions, and the one-sided
classification (consistent / inconsistent / indeterminate) with lift-off."""

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.counts.one_sided import one_sided_cases
from tests.helpers import variant

m, l, g, mu = sp.symbols("m l g mu", positive=True)
theta, omega, N = sp.symbols("theta thetadot N", real=True)


def newton_euler_normal_acceleration():
    """Height of the end, y - l sin(theta), differentiated twice, with Newton-Euler for the rod.

    Forces at the end: N up, friction +mu N along x (the end slides to the -x side). Torque
    about the centre of a force F at r = -l (cos, sin): r_x F_y - r_y F_x.
    """
    J = m * l**2 / 3
    Fx, Fy = mu * N, N
    ydd = Fy / m - g
    thdd = (-l * sp.cos(theta) * Fy + l * sp.sin(theta) * Fx) / J
    return ydd - l * sp.cos(theta) * thdd + l * sp.sin(theta) * omega**2


@pytest.mark.parametrize("name", ["painleve-rod", "painleve-rod-bilateral"])
def test_f_is_the_hand_newton_euler_acceleration(name):
    fast = variant(name).fast_subsystem()
    (u,) = fast.u
    f = fast.f[0].subs(sp.Abs(u), u)  # on N > 0
    assert sp.simplify(f - newton_euler_normal_acceleration().subs(N, u)) == 0


def test_critical_friction_four_thirds_at_tan_two_comes_out_of_the_count_regions():
    region = cs.scene("painleve-rod").equilibrium_counts()["two or none"].condition
    (rel,) = [region] if isinstance(region, sp.core.relational.Relational) else region.args
    boundary = rel.lhs - rel.rhs
    th = sp.Symbol("theta", real=True)
    assert sp.diff(boundary, mu, 2) == 0 and sp.diff(boundary, mu).subs(th, 1) != 0
    mu_c = -boundary.subs(mu, 0) / sp.diff(boundary, mu)  # the region is mu > mu_c(theta)
    t = sp.Symbol("t", positive=True)  # t = tan(theta), 0 < theta < pi/2
    by_tan = sp.simplify(mu_c.subs({sp.sin(th): t / sp.sqrt(1 + t**2), sp.cos(th): 1 / sp.sqrt(1 + t**2)}))
    (critical,) = sp.solve(sp.diff(by_tan, t), t)
    assert critical == 2
    assert sp.simplify(by_tan.subs(t, critical)) == sp.Rational(4, 3)
    assert sp.diff(by_tan, t, 2).subs(t, 2) > 0  # a minimum: the paradox needs mu > 4/3
    # the same from the hand derivation: b = dN-coefficient < 0 iff mu > (1 + 3 cos^2)/(3 sin cos)
    b = sp.diff(newton_euler_normal_acceleration(), N)
    grid = np.linspace(0.05, 1.5, 400)
    hand = [float((-b.subs(mu, 0) / sp.diff(b, mu)).subs(theta, t)) for t in grid[::40]]
    derived = [float(mu_c.subs(th, t)) for t in grid[::40]]
    assert np.allclose(hand, derived)


def test_fast_subsystem_eigenvalues_agree_with_the_hurwitz_verdict():
    scene = cs.scene("painleve-rod")
    lin = scene.linearization(signs=(1,))
    hurwitz = scene.stability((1,)).hurwitz
    symbols = sorted(lin.jacobian.free_symbols | set().union(*(h.free_symbols for h in hurwitz)), key=str)
    matrix = sp.lambdify(symbols, lin.jacobian, "numpy")
    conditions = sp.lambdify(symbols, hurwitz, "numpy")
    rng = np.random.default_rng(7)
    verdicts = set()
    for _ in range(300):
        values = [
            -rng.uniform(0.1, 5)
            if str(s) in ("Phi", "Psi")
            else rng.uniform(0.05, 1.5)
            if str(s) == "theta"
            else rng.uniform(0.1, 3)
            for s in symbols
        ]
        stable = all(c > 0 for c in conditions(*values))
        real_parts = np.linalg.eigvals(np.array(matrix(*values), dtype=float)).real
        if np.min(np.abs(real_parts)) < 1e-9:
            continue
        assert stable == bool(np.all(real_parts < 0))
        verdicts.add(stable)
    assert verdicts == {True, False}


def test_one_sided_classification_matches_the_classical_table_from_a_hand_derivation():
    cases = one_sided_cases(cs.scene("painleve-rod"))
    assert {c.name for c in cases} == {"consistent", "inconsistent", "indeterminate"}
    (indeterminate,) = [c for c in cases if c.name == "indeterminate"]
    assert indeterminate.equilibria == (("sliding", False), ("lift-off", True))
    f = newton_euler_normal_acceleration()
    ab = sp.lambdify((m, l, g, mu, theta, omega), [f.subs(N, 0), sp.diff(f, N)], "numpy")
    rng = np.random.default_rng(11)
    n = 20_000
    values = dict(m=rng.uniform(0.1, 3, n), l=rng.uniform(0.1, 3, n), g=rng.uniform(0.1, 10, n))
    values.update(mu=rng.uniform(0, 3, n), theta=rng.uniform(0.05, 1.5, n), thetadot=rng.uniform(-4, 4, n))
    a, b = (np.asarray(x) for x in ab(*values.values()))
    # the literature's table for f = a + b N, N >= 0
    expected = np.where(b > 0, "consistent", np.where(a > 0, "indeterminate", "inconsistent"))
    found = np.full(n, "", dtype=object)
    for case in cases:
        inside = case.region.evaluate(**{s: values[s] for s in case.region.symbol_names})
        assert not np.any(inside & (found != ""))
        found[inside] = case.name
    clear = np.minimum(np.abs(a), np.abs(b)) > 1e-9
    assert np.all(found[clear] == expected[clear])
    assert set(expected[clear]) == {"consistent", "inconsistent", "indeterminate"}


def test_counts_with_lift_off_at_numeric_points():
    from contactsym.plotting.counts import count_equilibria, decide_counts

    rod = cs.scene("painleve-rod")
    point = dict(m=1.0, l=1.0, g=9.81, mu=2.0, theta=float(np.arctan(2)))
    assert decide_counts(rod, **point).label == "two or none"
    counts, undecided = count_equilibria(rod, thetadot=np.array([0.0, 5.0]), **point)
    assert counts.tolist() == [0, 2] and not undecided.any()  # inconsistent, then indeterminate
    assert decide_counts(rod, **{**point, "mu": 1.0}).label == "unique"


def test_one_sided_cases_refuse_a_bilateral_contact():
    with pytest.raises(cs.ContactsymError, match="unilateral"):
        one_sided_cases(variant("painleve-rod-bilateral"))


def test_report_lists_the_one_sided_cases_and_the_corrected_count_labels():
    from contactsym.report import report_tex

    tex = report_tex(cs.scene("painleve-rod"))
    assert r"\paragraph{Indeterminate.} sliding (unstable), lift-off (stable)" in tex
    assert r"\paragraph{Inconsistent.} no equilibrium" in tex
    assert r"\paragraph{Two or none.}" in tex and "one or three" not in tex.lower()
