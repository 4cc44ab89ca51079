"""The regularized system (1.6)-(1.9) and the comparison (reduced) system (2.2)."""

from __future__ import annotations

import random

import pytest
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.algebra.basic import PaperSymbol
from contactsym.errors import ContactsymError
from contactsym.stages.regularize import ReducedSystem, Regularized

t = dynamicsymbols._t
x, y, z = dynamicsymbols("x y z")
N, N1, N2 = sp.symbols("N N_1 N_2", real=True)
X, Y = sp.symbols("X Y", real=True)
mu, k, d, c, w = sp.symbols("mu k d c w", positive=True)
xs, xdot = sp.Symbol("x", real=True), sp.Symbol("xdot", real=True)


def coupled_scene(compliance) -> cs.Scene:
    """x'' = X - mu|N| - c y',  y'' = N + Y - w^2 y + x' y': the contact coordinate y enters the forces."""
    contact = cs.Contact(coordinate=y, reaction=N, compliance=compliance)
    return cs.Scene.from_accelerations(
        [x, y],
        [X - mu * sp.Abs(N) - c * y.diff(t), N + Y - w**2 * y + x.diff(t) * y.diff(t)],
        [contact],
    )


def zero_matrix(M: sp.Matrix) -> bool:
    return M.applyfunc(lambda e: sp.simplify(sp.expand(e))) == sp.zeros(*M.shape)


# --- Regularized ------------------------------------------------------------------------


def test_sliding_point_regularized():
    s = cs.scene("sliding-point")
    reg = s.regularized()
    assert isinstance(reg, Regularized) and reg is s.regularized()
    fast = s.fast_subsystem()
    u, v = fast.u[0], fast.v[0]
    Xf = sp.Function("X")(xs, xdot)
    m = sp.Symbol("m", positive=True)
    assert reg.eps == s.eps and reg.tau.is_positive
    assert reg.slow_coordinates == (s.coordinates[0],)
    assert reg.x == sp.Matrix([PaperSymbol("t", real=True), xs, xdot])
    assert reg.y == sp.Matrix([u, v])
    assert zero_matrix(reg.X - sp.Matrix([1, xdot, (Xf - mu * sp.Abs(u)) / m]))
    assert reg.Y.subs(reg.eps, 0) == fast.rhs


def test_kelvin_voigt_deformation_inverts_the_law():
    """(1.6): u = N(q, q') at q = deformation(u, v), q' = eps v, for the paper's law (1.11)."""
    s = cs.scene("sliding-point")
    eps = s.eps
    b = sp.Symbol("b", positive=True)
    u, v = s.fast_subsystem().u[0], s.fast_subsystem().v[0]
    deformation = s.contacts[0].compliance.deformation(u, v, eps, None)
    # N = -y/eps^2 - 2 b y'/eps (c = 1/eps in (1.11))
    assert sp.expand(-deformation / eps**2 - 2 * b * (eps * v) / eps - u) == 0


@pytest.mark.parametrize(
    "compliance",
    [
        cs.KelvinVoigt(k, d),
        cs.Generic(),
        cs.Law(
            -k * sp.Symbol("q", real=True) / sp.Symbol("e", positive=True) ** 2
            - d * sp.atan(sp.Symbol("qd", real=True) / sp.Symbol("e", positive=True)),
            sp.Symbol("q", real=True),
            sp.Symbol("qd", real=True),
            sp.Symbol("e", positive=True),
        ),
    ],
    ids=["kelvin-voigt", "generic", "law"],
)
def test_Y_at_eps_zero_is_the_fast_subsystem(compliance):
    s = coupled_scene(compliance)
    reg = s.regularized()
    fast = s.fast_subsystem()
    assert reg.Y.has(reg.eps)  # the deformation and its rate enter at eps > 0
    assert zero_matrix(reg.Y.subs(reg.eps, 0) - fast.rhs)
    assert sp.expand(fast.f[0] - (fast.u[0] + Y)) == 0


def test_X_is_the_slow_motion_in_stretched_time():
    s = coupled_scene(cs.KelvinVoigt(k, d))
    reg = s.regularized()
    u, v = s.fast_subsystem().u[0], s.fast_subsystem().v[0]
    assert reg.x == sp.Matrix([PaperSymbol("t", real=True), xs, xdot])
    assert zero_matrix(reg.X - sp.Matrix([1, xdot, X - mu * sp.Abs(u) - c * reg.eps * v]))
    assert zero_matrix(reg.X.subs(reg.eps, 0) - sp.Matrix([1, xdot, X - mu * sp.Abs(u)]))


def test_Y_contains_the_deformation_of_the_kelvin_voigt_law():
    s = coupled_scene(cs.KelvinVoigt(k, d))
    reg = s.regularized()
    eps = reg.eps
    u, v = s.fast_subsystem().u[0], s.fast_subsystem().v[0]
    G = u + Y + w**2 * eps**2 * (u + d * v) / k + xdot * eps * v
    assert zero_matrix(reg.Y - sp.Matrix([-k * v - d * G, G]))


def test_regularized_painleve_klein_rod_is_the_fast_subsystem_at_eps_zero():
    s = cs.scene("painleve-klein-rod")
    reg = s.regularized()
    assert zero_matrix(reg.Y.subs(reg.eps, 0) - s.fast_subsystem().rhs)


def numeric_difference(a: sp.Matrix, b: sp.Matrix, seed: int = 0) -> float:
    rng = random.Random(seed)
    free = sorted((a.free_symbols | b.free_symbols), key=str)
    values = {s: (rng.uniform(0.1, 1.4) if s.is_positive else rng.uniform(-2, 2)) for s in free}
    return max(abs(complex((ai - bi).subs(values).evalf())) for ai, bi in zip(a, b))


def test_regularized_brake_is_the_fast_subsystem_at_eps_zero():
    s = cs.scene("brake")
    reg = s.regularized()
    assert numeric_difference(reg.Y.subs(reg.eps, 0), s.fast_subsystem().rhs) < 1e-9


def test_regularized_guides_is_the_fast_subsystem_at_eps_zero():
    s = cs.scene("painleve-klein-guides")
    reg = s.regularized()
    for seed in range(3):
        assert numeric_difference(reg.Y.subs(reg.eps, 0), s.fast_subsystem().rhs, seed) < 1e-9


# --- ReducedSystem --------------------------------------------------------------------


def test_sliding_point_reduced_system_is_the_classical_law():
    s = cs.scene("sliding-point")
    reduced = s.reduced_system()
    assert isinstance(reduced, ReducedSystem) and reduced is s.reduced_system()
    Xf, Yf = sp.Function("X")(xs, xdot), sp.Function("Y")(xs, xdot)
    m = sp.Symbol("m", positive=True)
    assert reduced.coordinates == (xs,)
    assert reduced.reactions == {N: -Yf}
    assert reduced.condition == sp.true
    (acceleration,) = reduced.accelerations.values()
    assert sp.expand(acceleration - (Xf - mu * sp.Abs(Yf)) / m) == 0
    # (2.2): the slow equation of the regularized system with u = u*
    reg = s.regularized()
    assert sp.expand(reg.X[-1].subs(s.fast_subsystem().u[0], -Yf) - acceleration) == 0


def test_reduced_system_needs_one_branch():
    s = cs.scene("painleve-klein-guides")
    with pytest.raises(ContactsymError) as info:
        s.reduced_system().accelerations  # noqa: B018
    message = str(info.value)
    assert "has 4 equilibrium branches" in message
    assert "reduced_system(signs=...)" in message


def sample(rng: random.Random, symbols) -> dict:
    return {s: (rng.uniform(0.05, 1.5) if s.is_positive else rng.uniform(-4, 4)) for s in symbols}


def check_reduced_numerically(s: cs.Scene, signs, expected_of, samples: int = 6, seed: int = 1):
    """On samples where the branch exists, each reduced acceleration equals expected_of(u*) with true Abs."""
    reduced = s.reduced_system(signs)
    free = set().union(*(e.free_symbols for e in reduced.accelerations.values()), reduced.condition.free_symbols)
    free |= set().union(*(e.free_symbols for e in reduced.branch.u_star))
    free = sorted(free, key=str)
    exists = sp.lambdify([free], reduced.condition, "math")
    rng = random.Random(seed)
    checked = tries = 0
    while checked < samples:
        tries += 1
        assert tries < 2000, "no sample where the branch exists"
        values = sample(rng, free)
        if not exists([values[p] for p in free]):
            continue
        checked += 1
        u_star = [float(e.subs(values)) for e in reduced.branch.u_star]
        for q, expected in expected_of(u_star).items():
            got = float(reduced.accelerations[q].subs(values))
            assert abs(got - float(sp.sympify(expected).subs(values))) < 1e-8 * (1 + abs(got))
    return reduced


def test_guides_reduced_system_on_one_branch():
    s = cs.scene("painleve-klein-guides")
    mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
    Xg = sp.Symbol("X", real=True)
    reduced = check_reduced_numerically(s, (1, -1), lambda u: {xs: Xg - mu1 * abs(u[0]) - mu2 * abs(u[1])})
    assert reduced.coordinates == (xs,)
    assert set(reduced.reactions) == {N1, N2}


def test_brake_reduced_system_turns_the_disc():
    s = cs.scene("brake")
    r, J = sp.symbols("r J", positive=True)
    theta = sp.Symbol("theta", real=True)
    reduced = check_reduced_numerically(s, None, lambda u: {theta: mu * r * (abs(u[0]) + abs(u[1])) / J})
    assert reduced.coordinates == (theta,)


def test_painleve_klein_rod_reduced_system():
    s = cs.scene("painleve-klein-rod")
    phi = sp.Symbol("phi", positive=True)
    mu1 = sp.Symbol("mu_1", positive=True)
    X1, Y1 = sp.symbols("X_1 Y_1", real=True)
    x1 = sp.Symbol("x_1", real=True)
    for signs in s.sign_patterns()[:3]:
        check_reduced_numerically(
            s,
            signs,
            lambda u: {x1: X1 - mu1 * sp.Abs(Y1 - u[0] * sp.sin(phi)) - u[0] * sp.cos(phi)},
            samples=3,
        )


@pytest.mark.parametrize("name", ["sliding-point", "brake", "painleve-klein-guides"])
def test_regularized_is_derived_from_the_scene_not_from_the_fast_subsystem(name, monkeypatch):
    """(1.9) comes first: its fast variables and laws are its own, and at eps = 0 it gives (2.1)."""
    scene = cs.scene(name)
    reg = Regularized(scene)  # a fresh stage, not the scene's cached one

    def tripwire():
        raise AssertionError("Regularized asked the scene for its fast subsystem")

    monkeypatch.setattr(scene, "fast_subsystem", tripwire)
    y, Y = reg.y, reg.Y
    monkeypatch.undo()
    fast = scene.fast_subsystem()
    assert y == fast.state
    assert numeric_difference(Y.subs(reg.eps, 0), fast.rhs) < 1e-9


def test_the_slow_time_is_the_packages_own_beside_a_users_t():
    """A parameter t declared real is not the slow state's time t (it was the same Symbol("t", real=True))."""
    t = sp.Symbol("t", real=True)
    N = sp.Symbol("N", real=True)
    x, y = dynamicsymbols("x y")
    s = cs.Scene.from_accelerations([x, y], [0, N - t], [cs.Contact(coordinate=y, reaction=N)], parameters=[t])
    time = s.regularized().x[0]
    assert time != t and str(time) == "that" and sp.latex(time) == r"\hat{t}"
