"""The block on two legs: f against a hand Newton–Euler derivation, (4.5) against eigenvalues,
and the equilibria with lift-off against the counts at numeric points."""

import itertools

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.plotting.counts import count_equilibria, decide_counts
from tests.helpers import variant

m, J, a, b, mu1, mu2 = sp.symbols("m J a b mu_1 mu_2", positive=True)
Y, M = sp.symbols("Y M", real=True)
ISSUE_POINT = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)


def newton_euler(N1, N2):
    """Leg heights' accelerations for a level block at rest in rotation: y'' -+ a theta''."""
    F1, F2 = -mu1 * sp.Abs(N1), -mu2 * sp.Abs(N2)  # friction along -x, legs at (-a, -b), (a, -b)
    ydd = (Y + N1 + N2) / m
    # torque r_x F_y - r_y F_x of each leg force about the centre
    thdd = (M + (-a) * N1 - (-b) * F1 + a * N2 - (-b) * F2) / J
    return [ydd - a * thdd, ydd + a * thdd]


@pytest.mark.parametrize("name", ["two-leg-block", "two-leg-block-unilateral"])
def test_f_is_the_hand_newton_euler_acceleration(name):
    fast = variant(name).fast_subsystem()
    hand = newton_euler(*fast.u)
    assert all(sp.expand(fj - h) == 0 for fj, h in zip(fast.f, hand))


def test_fast_subsystem_eigenvalues_agree_with_the_hurwitz_verdict_on_every_orthant():
    scene = cs.scene("two-leg-block")
    rng = np.random.default_rng(4)
    verdicts = set()
    for pattern in scene.sign_patterns():
        lin = scene.linearization(signs=pattern)
        hurwitz = scene.stability(pattern).hurwitz
        symbols = sorted(lin.jacobian.free_symbols | set().union(*(h.free_symbols for h in hurwitz)), key=str)
        matrix = sp.lambdify(symbols, lin.jacobian, "numpy")
        conditions = sp.lambdify(symbols, hurwitz, "numpy")
        for _ in range(80):
            values = [-rng.uniform(0.1, 5) if str(s)[:3] in ("Phi", "Psi") else rng.uniform(0.1, 3) for s in symbols]
            real_parts = np.linalg.eigvals(np.array(matrix(*values), dtype=float)).real
            if np.min(np.abs(real_parts)) < 1e-9:
                continue
            stable = all(c > 0 for c in conditions(*values))
            assert stable == bool(np.all(real_parts < 0)), (pattern, values)
            verdicts.add(stable)
    assert verdicts == {True, False}


def test_the_issue_point_and_loads():
    block = cs.scene("two-leg-block")
    decision = decide_counts(block, **ISSUE_POINT)
    assert decision.label == "two or none" and decision.degree == 0
    assert sorted(np.sign(list(decision.determinants.values()))) == [-1, 1, 1, 1]  # one negative orthant
    counts, undecided = count_equilibria(block, Y=np.array([-24.5, 0.0]), M=np.array([-3.1, 5.0]), **ISSUE_POINT)
    assert counts.tolist() == [0, 2] and not undecided.any()


def test_lift_off_equilibria_are_the_counts_at_numeric_points():
    """Sliding branches plus lift-offs whose existence conditions hold = the orthant-map count."""
    block = variant("two-leg-block-unilateral")
    eq = block.equilibria()
    rng = np.random.default_rng(9)
    n = 5000
    values = {k: rng.uniform(0.2, 2.5, n) for k in ("m", "J", "a", "b", "mu_1", "mu_2")}
    values.update(Y=rng.uniform(-20, 20, n), M=rng.uniform(-20, 20, n))
    total = np.zeros(n, dtype=int)
    for e in itertools.chain(eq.branches, eq.lift_offs):
        symbols = sorted(e.condition.free_symbols, key=str)
        holds = sp.lambdify(symbols, e.condition, "numpy")(*[values[str(x)] for x in symbols])
        total += np.broadcast_to(holds, (n,))
    counts, undecided = count_equilibria(block, **values)
    assert np.all(total[~undecided] == counts[~undecided])
    assert set(counts[~undecided].tolist()) >= {0, 1, 2}


def test_lift_off_stability_is_that_of_the_closed_leg():
    block = variant("two-leg-block-unilateral")
    lifts = block.equilibria().lift_offs
    assert {lift.open for lift in lifts} == {(0,), (1,), (0, 1)}
    (both,) = [lift for lift in lifts if lift.open == (0, 1)]
    assert both.stable == sp.true and both.u_star == (0, 0)
    (first,) = [lift for lift in lifts if lift.open == (0,)]
    A22 = block.linearization(signs=(1, 1)).A[1, 1]
    # one closed contact: stable iff its diagonal entry of A is positive (Proposition 3)
    for condition in sp.And.make_args(first.stable):
        assert sp.cancel((condition.lhs - condition.rhs) / A22).is_positive
