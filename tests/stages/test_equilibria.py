"""Equilibria (u*, 0) of the fast subsystem: one branch per sign pattern, with its existence condition."""

from __future__ import annotations

import math
from functools import cache

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.errors import ContactsymError, SingularJacobianError
from contactsym.stages.equilibria import Branch, Equilibria

x, y, z = dynamicsymbols("x y z")
N, N1, N2 = sp.symbols("N N_1 N_2", real=True)
X, Y, a = sp.symbols("X Y a", real=True)


@pytest.mark.parametrize(
    "name, count", [("sliding-point", 1), ("painleve-klein-rod", 4), ("painleve-klein-guides", 4), ("brake", 1)]
)
def test_one_branch_per_sign_pattern(name, count):
    s = cs.scene(name)
    eq = s.equilibria()
    assert isinstance(eq, Equilibria)
    assert len(eq) == count == len(eq.branches)
    assert list(eq) == list(eq.branches)
    assert [branch.signs for branch in eq] == s.sign_patterns() == eq.patterns
    assert all(isinstance(branch, Branch) and len(branch.u_star) == s.k for branch in eq)


@pytest.mark.parametrize("name", cs.scene_names())
def test_each_branch_solves_its_piece_exactly(name):
    s = cs.scene(name)
    fast = s.fast_subsystem()
    for branch in s.equilibria():
        at = dict(zip(fast.u, branch.u_star))
        residual = fast.piece(branch.signs).subs(at)
        # decide only what cancel leaves (the stool's eight branches: 3 s of simplify on zeros)
        assert residual.applyfunc(lambda e: _zeroed(sp.cancel(e))) == sp.zeros(s.k, 1), branch.signs
        assert not any(value.has(*fast.u) for value in branch.u_star)


def _zeroed(expr):
    """0 where ``expr`` is identically zero, by an exact test: its numerator, multiple angles expanded, with
    sin q = 2t/(1 + t^2), cos q = (1 - t^2)/(1 + t^2) (every real q but pi) cancels to 0 as a rational
    function of the t's (so it vanishes for every q, by continuity). simplify otherwise (the double
    pendulum's two zeros: 3.4 s of simplify, 0.4 s so)."""
    if expr == 0:
        return expr
    numerator = sp.expand_trig(sp.numer(sp.together(expr)))
    trig = numerator.atoms(sp.sin, sp.cos)
    if all(f.args[0].is_Symbol for f in trig):
        halfangle = {}
        for q in {f.args[0] for f in trig}:
            t = sp.Dummy("t", real=True)
            halfangle |= {sp.sin(q): 2 * t / (1 + t**2), sp.cos(q): (1 - t**2) / (1 + t**2)}
        if sp.cancel(numerator.xreplace(halfangle)) == 0:
            return sp.S.Zero
    return sp.simplify(expr)


def test_sliding_point_reaction_balances_the_load():
    branch = cs.scene("sliding-point").equilibria().branches[0]
    Yf = sp.Function("Y")(sp.Symbol("x", real=True), sp.Symbol("xdot", real=True))
    assert branch == Branch((), (-Yf,), sp.true)


def test_equilibria_of_one_sign_pattern():
    s = cs.scene("painleve-klein-guides")
    one = s.equilibria(signs=(1, -1))
    assert one is s.equilibria(signs=[1, -1])
    assert [b.signs for b in one] == [(1, -1)]
    assert one.branches[0] == next(b for b in s.equilibria() if b.signs == (1, -1))


# --- conditions against numerics ---------------------------------------------------------


def sample_strategy(names):
    """Random parameter values: loads anywhere, friction and masses positive, angles in (0, pi/2)."""
    positive = {"mu_1", "mu_2", "mu", "m", "l", "alpha"}

    def value(name):
        if name in ("phi", "alpha"):
            return st.floats(0.05, math.pi / 2 - 0.05)
        if name in positive:
            return st.floats(0.05, 3)
        return st.floats(-5, 5)

    return st.fixed_dictionaries({name: value(name) for name in names})


@cache
def compiled(condition, params):
    return sp.lambdify([params], condition, "math")


@cache
def numeric(name):
    """f with Abs, each branch's u*, condition and switching functions, lambdified."""
    s = cs.scene(name)
    fast = s.fast_subsystem()
    params = sorted(set().union(*(e.free_symbols for e in fast.f)) - set(fast.u), key=str)
    f = sp.lambdify([params, fast.u], list(fast.f), "math")
    switching = sp.lambdify([params, fast.u], list(fast.switching), "math")
    branches = []
    for branch in s.equilibria():
        u_star = sp.lambdify([params], list(branch.u_star), "math")
        branches.append((branch, u_star, switching))
    return s, params, f, branches


@cache
def rod_kinks_and_slopes():
    """Where each switching function of the rod vanishes, and the slope of f on each piece."""
    s, params, _, _ = numeric("painleve-klein-rod")
    fast = s.fast_subsystem()
    (u,) = fast.u
    kinks = sp.lambdify([params], [sp.solve(sw, u)[0] for sw in fast.switching], "math")
    slopes = sp.lambdify([params], [sp.diff(fast.piece(p)[0], u) for p in s.sign_patterns()], "math")
    return kinks, slopes


def off_the_switching_surfaces(branches, values, tolerance=1e-6) -> bool:
    for _, u_star, switching in branches:
        try:
            sigma = switching(values, u_star(values))
        except ZeroDivisionError:
            return False
        if any(abs(value) < tolerance for value in sigma):
            return False
    return True


def condition_value(condition, params, values):
    """The branch condition (a SymPy Boolean) at numeric parameter values."""
    return bool(compiled(condition, tuple(params))(values))


@pytest.mark.parametrize("name", ["painleve-klein-rod", "painleve-klein-guides", "brake"])
@settings(max_examples=40, deadline=None)
@given(data=st.data())
def test_condition_agrees_with_the_numeric_signs_of_the_switching_functions(name, data):
    s, params, f, branches = numeric(name)
    sample = data.draw(sample_strategy([str(p) for p in params]))
    values = [sample[str(p)] for p in params]
    for branch, u_star, switching in branches:
        try:
            u = u_star(values)
        except ZeroDivisionError:
            assume(False)
        sigma = switching(values, u)
        assume(all(abs(v) > 1e-7 for v in sigma) and all(abs(v) < 1e7 for v in u))
        inside = all(sign * value > 0 for sign, value in zip(branch.signs, sigma))
        assert condition_value(branch.condition, params, values) == inside
        if inside:
            # then u* is an equilibrium of the true, piecewise smooth f
            assert all(abs(fj) < 1e-6 * (1 + max(map(abs, u))) for fj in f(values, u))


def piecewise_linear_roots(f, breakpoints, margin=1e-6):
    """Roots of a continuous piecewise-linear scalar f with the given kinks, interval by interval."""
    cuts = sorted(breakpoints)
    edges = [-math.inf, *cuts, math.inf]
    roots = []
    for lo, hi in zip(edges, edges[1:]):
        if math.isinf(lo) and math.isinf(hi):
            p1, p2 = -1.0, 1.0
        elif math.isinf(lo):
            p1, p2 = hi - 2.0, hi - 1.0
        elif math.isinf(hi):
            p1, p2 = lo + 1.0, lo + 2.0
        else:
            p1, p2 = lo + (hi - lo) / 3, lo + 2 * (hi - lo) / 3
        f1, f2 = f(p1), f(p2)
        slope = (f2 - f1) / (p2 - p1)
        if slope == 0:
            continue
        root = p1 - f1 / slope
        if lo + margin < root < hi - margin:
            roots.append(root)
    return roots


@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_painleve_klein_rod_equilibria_are_all_the_roots_of_f(data):
    """0, 1, 2 or 3 reactions (fold, cusp): the true branches are exactly the roots of the piecewise f."""
    s, params, f, branches = numeric("painleve-klein-rod")
    sample = data.draw(sample_strategy([str(p) for p in params]))
    values = [sample[str(p)] for p in params]
    assume(off_the_switching_surfaces(branches, values))
    kinks = rod_kinks_and_slopes()[0](values)
    assume(abs(kinks[0] - kinks[1]) > 1e-4)
    roots = piecewise_linear_roots(lambda value: f(values, [value])[0], kinks)
    assume(all(min(abs(r - kink) for kink in kinks) > 1e-4 for r in roots))
    true_branches = [
        u_star(values)[0] for branch, u_star, _ in branches if condition_value(branch.condition, params, values)
    ]
    assert len(true_branches) == len(roots) <= 3
    for found, expected in zip(sorted(true_branches), sorted(roots)):
        assert abs(found - expected) < 1e-6 * (1 + abs(expected))


@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_coherent_orientation_gives_exactly_one_reaction(data):
    """If every piece of the rod's f has a slope of one sign, every load has exactly one equilibrium."""
    s, params, f, branches = numeric("painleve-klein-rod")
    sample = data.draw(sample_strategy([str(p) for p in params]))
    values = [sample[str(p)] for p in params]
    assume(off_the_switching_surfaces(branches, values))
    slopes = rod_kinks_and_slopes()[1](values)
    assume(all(abs(slope) > 1e-6 for slope in slopes))
    count = sum(condition_value(branch.condition, params, values) for branch, _, _ in branches)
    if all(slope > 0 for slope in slopes) or all(slope < 0 for slope in slopes):
        assert count == 1
    else:
        assert count in (0, 1, 2, 3)


def test_brake_branch_requires_both_pads_to_push():
    s = cs.scene("brake")
    (branch,) = s.equilibria()
    assert branch.signs == (1, 1)
    expected = sp.And(*[sp.Gt(value, 0) for value in branch.u_star])
    # same condition up to the form of each inequality: check on samples
    free = sorted(branch.condition.free_symbols, key=str)
    for i in range(20):
        numbers = {p: ((-1) ** i * (i % 7 + 0.5) if not p.is_positive else 0.1 + (i * 0.37) % 1.4) for p in free}
        assert bool(branch.condition.subs(numbers)) == bool(expected.subs(numbers))


# --- singular and nonlinear pieces --------------------------------------------------------


def test_piece_with_singular_jacobian_raises():
    """y'' = N - |N| + Y: on N > 0 the reaction drops out, det A = 0."""
    s = cs.Scene.from_accelerations([x, y], [X, N - sp.Abs(N) + Y], [cs.Contact(coordinate=y, reaction=N)])
    with pytest.raises(SingularJacobianError) as info:
        s.equilibria().branches  # noqa: B018
    message = str(info.value)
    assert "det A = 0 on the piece with signs (1,)" in message
    assert "not isolated" in message and "det A != 0" in message
    # the other piece is regular: u* = -Y/2, where -Y/2 < 0
    (branch,) = s.equilibria(signs=(-1,)).branches
    assert branch.u_star == (-Y / 2,)
    assert branch.condition.subs(Y, 1) == sp.true and branch.condition.subs(Y, -1) == sp.false


def test_two_contacts_with_a_singular_jacobian():
    contacts = [cs.Contact(coordinate=y, reaction=N1), cs.Contact(coordinate=z, reaction=N2)]
    s = cs.Scene.from_accelerations([x, y, z], [X, N1 + N2 + X, N1 + N2 - Y], contacts)
    with pytest.raises(SingularJacobianError, match=r"det A = 0 on the piece with signs \(\)"):
        s.equilibria().branches  # noqa: B018
    with pytest.raises(SingularJacobianError, match="det A = 0"):
        s.stability().hurwitz  # noqa: B018


def test_nonlinear_piece_gives_one_branch_per_root():
    b = sp.Symbol("b", positive=True)
    s = cs.Scene.from_accelerations([x, y], [X, N**2 - b**2], [cs.Contact(coordinate=y, reaction=N)])
    roots = sorted((branch.u_star[0] for branch in s.equilibria()), key=str)
    assert set(roots) == {b, -b}
    assert all(branch.condition == sp.true for branch in s.equilibria())


def test_nonlinear_piece_without_closed_form_roots_says_so():
    s = cs.Scene.from_accelerations([x, y], [X, N**5 + N + a], [cs.Contact(coordinate=y, reaction=N)])
    with pytest.raises(ContactsymError) as info:
        s.equilibria().branches  # noqa: B018
    message = str(info.value)
    assert "no closed-form root" in message and "numerically" in message


def test_non_polynomial_piece_is_solved_in_closed_form_when_sympy_can():
    s = cs.Scene.from_accelerations([x, y], [X, N + sp.exp(N) + a], [cs.Contact(coordinate=y, reaction=N)])
    (branch,) = s.equilibria().branches
    f = s.fast_subsystem().f[0]
    for a_value in (-3, 0.5, 2):
        u_star = complex(branch.u_star[0].subs(a, a_value))
        assert abs(u_star.imag) < 1e-12
        assert abs(float(f.subs({s.fast_subsystem().u[0]: u_star.real, a: a_value}))) < 1e-9


@pytest.mark.parametrize(
    "count, values",
    [
        (0, [4.4, -1.1, -1.9, -1.7, 1.0, 2.5, 1.35]),
        (1, [-3.7, 3.5, 2.6, -2.4, 1.5, 1.4, 1.0]),
        (2, [-4.8, 3.4, 0.56, 1.4, 0.6, 3.0, 1.3]),
        (3, [1.7, -2.0, 0.9, 3.8, 2.5, 1.5, 0.9]),
    ],
)
def test_painleve_klein_rod_has_zero_to_three_reactions(count, values):
    """Fold (0 or 2 reactions: the impact-type catastrophe when 0) and cusp (1 or 3), values (X1, X2, Y1, Y2, mu1, mu2, phi)."""
    s, params, f, branches = numeric("painleve-klein-rod")
    assert [str(p) for p in params] == ["X_1", "X_2", "Y_1", "Y_2", "mu_1", "mu_2", "phi"]
    true_branches = [
        u_star(values)[0] for branch, u_star, _ in branches if condition_value(branch.condition, params, values)
    ]
    assert len(true_branches) == count
    roots = piecewise_linear_roots(lambda value: f(values, [value])[0], rod_kinks_and_slopes()[0](values))
    assert sorted(roots) == pytest.approx(sorted(true_branches))
    # the exact conditions agree with the compiled ones
    numbers = dict(zip(params, map(sp.Float, values)))
    assert sum(bool(branch.condition.subs(numbers)) for branch in s.equilibria()) == count


@pytest.mark.parametrize("piece", [N**2 + 1, N**2 + a**2 + 1, N**4 + N**2 + 1])
def test_polynomial_piece_without_real_roots_has_no_branch(piece):
    s = cs.Scene.from_accelerations([x, y], [X, piece], [cs.Contact(coordinate=y, reaction=N)])
    assert s.equilibria().branches == ()
    # independently: the piece is positive for every real N (its minimum over a grid)
    grid = np.linspace(-10, 10, 2001)
    values = sp.lambdify(N, piece.subs(a, 0.7), "numpy")(grid)
    assert np.min(values) > 0


def test_non_polynomial_piece_without_a_found_root_still_says_so():
    s = cs.Scene.from_accelerations([x, y], [X, sp.exp(N) - N - 2], [cs.Contact(coordinate=y, reaction=N)])
    try:
        branches = s.equilibria().branches
    except ContactsymError as error:
        assert "no closed-form root" in str(error)
    else:
        assert len(branches) >= 1  # two real roots exist: never reported as none
