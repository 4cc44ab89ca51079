"""Accelerations from a Lagrangian, and the end-to-end user scene: Painleve's rod on a rough floor."""

from __future__ import annotations

import math
import random
from functools import cache

import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import (
    Lagrangian,
    Particle,
    Point,
    ReferenceFrame,
    RigidBody,
    dynamicsymbols,
    inertia,
)

import contactsym as cs
from contactsym.mechanism.contact_space import lagrangian_accelerations

t = dynamicsymbols._t
N = sp.Symbol("N", real=True)
m, g, mu, l, J = sp.symbols("m g mu l J", positive=True)


def random_values(exprs, rng: random.Random) -> dict:
    """Random numbers for every symbol, function of time and derivative in exprs (positive where assumed)."""
    values = {}
    for expr in exprs:
        for atom in sp.sympify(expr).atoms(sp.Derivative) | sp.sympify(expr).atoms(sp.core.function.AppliedUndef):
            values.setdefault(atom, sp.Float(rng.uniform(-2, 2)))
    derivatives = dict(
        sorted(
            ((a, b) for a, b in values.items() if isinstance(a, sp.Derivative)), key=lambda p: -p[0].derivative_count
        )
    )
    functions = {a: b for a, b in values.items() if not isinstance(a, sp.Derivative)}
    symbols = {}
    for expr in exprs:
        for s in sp.sympify(expr).free_symbols - {t}:
            symbols.setdefault(s, sp.Float(rng.uniform(0.2, 2) if s.is_positive else rng.uniform(-2, 2)))
    return {"derivatives": derivatives, "functions": functions, "symbols": symbols}


def evaluate(expr, values) -> complex:
    expr = sp.sympify(expr).subs(values["derivatives"]).subs(values["functions"]).subs(values["symbols"])
    return complex(expr.evalf())


def assert_same(a, b, samples: int = 5, seed: int = 0, exact: bool = True):
    """a == b: exactly (expand of the difference is 0) and at random numeric points."""
    if exact:
        assert sp.expand(a - b) == 0, sp.expand(a - b)
    rng = random.Random(seed)
    for _ in range(samples):
        values = random_values([a, b], rng)
        assert abs(evaluate(a, values) - evaluate(b, values)) < 1e-9


# --- lagrangian_accelerations on small examples ---------------------------------------


def test_point_mass_on_the_floor():
    y = dynamicsymbols("y")
    L = m * y.diff() ** 2 / 2 - m * g * y
    (a,) = lagrangian_accelerations(L, [y], [cs.Contact(coordinate=y, reaction=N)])
    assert_same(a, N / m - g)


def test_particle_in_polar_coordinates_against_a_circular_wall():
    """r'' = r theta'^2 - g sin(theta) + N/m, theta'' = -(2 r' theta' + g cos(theta))/r."""
    r, th = dynamicsymbols("r theta")
    R = sp.Symbol("R", positive=True)
    L = m * (r.diff() ** 2 + r**2 * th.diff() ** 2) / 2 - m * g * r * sp.sin(th)
    a_r, a_th = lagrangian_accelerations(L, [r, th], [cs.Contact(coordinate=r - R, reaction=N)])
    assert_same(a_r, r * th.diff() ** 2 - g * sp.sin(th) + N / m)
    assert_same(a_th, -(2 * r.diff() * th.diff() + g * sp.cos(th)) / r)


def test_gap_function_between_two_masses_acts_along_its_gradient():
    x1, x2 = dynamicsymbols("x_1 x_2")
    m1, m2, kk = sp.symbols("m_1 m_2 k", positive=True)
    L = m1 * x1.diff() ** 2 / 2 + m2 * x2.diff() ** 2 / 2 - kk * (x2 - x1) ** 2 / 2
    a1, a2 = lagrangian_accelerations(L, [x1, x2], [cs.Contact(coordinate=x2 - x1, reaction=N)])
    assert_same(a1, (kk * (x2 - x1) - N) / m1)
    assert_same(a2, (N - kk * (x2 - x1)) / m2)


def test_two_contacts_on_a_particle_in_a_corner():
    x, y = dynamicsymbols("x y")
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    L = m * (x.diff() ** 2 + y.diff() ** 2) / 2 - m * g * y
    contacts = [cs.Contact(coordinate=y, reaction=N1), cs.Contact(coordinate=x + y, reaction=N2)]
    ax, ay = lagrangian_accelerations(L, [x, y], contacts)
    assert_same(ax, N2 / m)
    assert_same(ay, (N1 + N2) / m - g)


def test_loads_and_torques_on_a_rigid_body():
    """A disc in the plane: force F at its centre, torque M, contact gap y."""
    x, y, th = dynamicsymbols("x y theta")
    F, M = sp.symbols("F M", real=True)
    O = ReferenceFrame("O")
    D = O.orientnew("D", "Axis", [th, O.z])
    C = Point("C")
    C.set_vel(O, x.diff() * O.x + y.diff() * O.y)
    disc = RigidBody("disc", C, D, m, (inertia(D, 0, 0, J), C))
    loads = [(C, F * O.x - m * g * O.y), (D, M * O.z)]
    ax, ay, ath = lagrangian_accelerations(
        Lagrangian(O, disc), [x, y, th], [cs.Contact(coordinate=y, reaction=N)], loads, O
    )
    assert_same(ax, F / m)
    assert_same(ay, N / m - g)
    assert_same(ath, M / J)


def test_coulomb_friction_on_a_sliding_point():
    x, y = dynamicsymbols("x y")
    X, Y = sp.symbols("X Y", real=True)
    O = ReferenceFrame("O")
    P = Point("P")
    P.set_vel(O, x.diff() * O.x + y.diff() * O.y)
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, direction=O.x, point=P))
    ax, ay = lagrangian_accelerations(
        Lagrangian(O, Particle("P", P, m)), [x, y], [contact], [(P, X * O.x + Y * O.y)], O
    )
    assert_same(ax, (X - mu * sp.Abs(N)) / m)
    assert_same(ay, (Y + N) / m)


def test_viscous_friction_uses_the_slip_velocity_along_the_direction():
    x, y = dynamicsymbols("x y")
    c = sp.Symbol("c", positive=True)
    O = ReferenceFrame("O")
    P = Point("P")
    P.set_vel(O, x.diff() * O.x + y.diff() * O.y)
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Viscous(c, direction=O.x, point=P))
    ax, ay = lagrangian_accelerations(Lagrangian(O, Particle("P", P, m)), [x, y], [contact], [(P, -m * g * O.y)], O)
    assert_same(ax, -c * x.diff() / m)
    assert_same(ay, N / m - g)


def test_builtin_sliding_point_accelerations():
    s = cs.scene("sliding-point")
    x, y = s.coordinates
    X, Y = sp.Function("X")(x, x.diff()), sp.Function("Y")(x, x.diff())
    assert sp.expand(s.accelerations[x] - (X - mu * sp.Abs(N)) / m) == 0
    assert sp.expand(s.accelerations[y] - (Y + N) / m) == 0


# --- Painleve's rod: a rigid body touching a rough floor at one point -------------------
#
# A uniform rod, mass m, half-length l, centre C = (x, y), lower end E = C + l (cos th, -sin th)
# (the rod slopes down to the right and its lower end leads), the end sliding in +x on the floor
# y_E = 0. Gap g = y - l sin(th); Coulomb friction -mu |N| x opposes the sliding.

x, y, th = dynamicsymbols("x y theta")
theta, thetadot = sp.Symbol("theta", real=True), sp.Symbol("thetadot", real=True)
ON_FLOOR = {y: l * sp.sin(th), y.diff(): l * sp.cos(th) * th.diff()}


def rod_scene(inertia_value=J, coordinates=(x, y, th), at=ON_FLOOR, unilateral=True) -> cs.Scene:
    O = ReferenceFrame("O")
    B = O.orientnew("B", "Axis", [-th, O.z])  # B.x = cos(th) O.x - sin(th) O.y
    origin = Point("o")
    origin.set_vel(O, 0)
    C = origin.locatenew("C", x * O.x + y * O.y)
    C.set_vel(O, C.pos_from(origin).dt(O))
    E = C.locatenew("E", l * B.x)
    E.v2pt_theory(C, O, B)
    rod = RigidBody("rod", C, B, m, (inertia(B, 0, 0, inertia_value), C))
    contact = cs.Contact(
        coordinate=y - l * sp.sin(th),
        reaction=N,
        friction=cs.Coulomb(mu, direction=O.x, point=E),
        unilateral=unilateral,
    )
    options = {"at": at} if at is not None else {}
    return cs.Scene.from_lagrangian(
        Lagrangian(O, rod),
        list(coordinates),
        [contact],
        loads=[(C, -m * g * O.y)],
        frame=O,
        name="painleve-rod",
        **options,
    )


@cache
def rod() -> cs.Scene:
    return rod_scene()


@cache
def uniform_rod() -> cs.Scene:
    return rod_scene(m * l**2 / 3)


def newton_euler(inertia_value=J) -> tuple[dict, sp.Expr]:
    """Accelerations and the frozen gap acceleration f(u), derived here by Newton-Euler."""
    e = sp.Matrix([sp.cos(th), -sp.sin(th)])  # C -> E
    force = sp.Matrix([-mu * sp.Abs(N), N])  # at E: friction opposes +x sliding, normal +y
    torque = l * (e[0] * force[1] - e[1] * force[0])  # z-moment about C
    # the body angle is -theta: J (-theta)'' = torque
    accelerations = {x.diff(t, 2): force[0] / m, y.diff(t, 2): force[1] / m - g, th.diff(t, 2): -torque / inertia_value}
    gap_acceleration = (y - l * sp.sin(th)).diff(t, 2).subs(accelerations)
    frozen = gap_acceleration.subs({th.diff(): thetadot}).subs({th: theta})
    return accelerations, frozen


def simplified_zero(expr) -> bool:
    return sp.simplify(expr) == 0


def test_rod_accelerations_match_newton_euler():
    s = rod()
    accelerations, _ = newton_euler()
    for q in (x, y, th):
        assert_same(s.accelerations[q], accelerations[q.diff(t, 2)])


def test_rod_manifold_keeps_the_rod_on_the_floor():
    ys, ydot = sp.Symbol("y", real=True), sp.Symbol("ydot", real=True)
    assert rod().manifold == {ys: l * sp.sin(theta), ydot: l * thetadot * sp.cos(theta)}


def test_rod_fast_subsystem_matches_newton_euler():
    s = rod()
    fast = s.fast_subsystem()
    (u,) = fast.u
    _, f_ne = newton_euler()
    f_ne = f_ne.subs(N, u)
    assert simplified_zero(fast.f[0] - f_ne)
    assert_same(fast.f[0], f_ne, exact=False)
    assert fast.switching == (u,)
    assert s.sign_patterns() == [(1,)]
    # Phi, Psi of the generic law; rhs (3.1)
    (Phi,), (Psi,) = fast.Phi, fast.Psi
    assert (str(Phi), str(Psi)) == ("Phi", "Psi") and Phi.is_negative and Psi.is_negative
    assert fast.rhs == sp.Matrix([Phi * fast.v[0] + Psi * fast.f[0], fast.f[0]])


def test_rod_normal_force_coefficient_and_centripetal_term():
    """f(u) = u (1/m + l^2 cos(th)(cos(th) - mu sin(th))/J) - g + l sin(th) th'^2 on u > 0."""
    s = rod()
    fast = s.fast_subsystem()
    (u,) = fast.u
    piece = fast.piece((1,))[0]
    coefficient = 1 / m + l**2 * sp.cos(theta) * (sp.cos(theta) - mu * sp.sin(theta)) / J
    assert simplified_zero(sp.diff(piece, u) - coefficient)
    assert simplified_zero(s.linearization().A[0] - coefficient)
    assert simplified_zero(piece.subs(u, 0) - (-g + l * sp.sin(theta) * thetadot**2))
    # the other side of the switching surface: friction reverses with the sign of N
    other = fast.piece((-1,))[0]
    assert simplified_zero(
        sp.diff(other, u) - (1 / m + l**2 * sp.cos(theta) * (sp.cos(theta) + mu * sp.sin(theta)) / J)
    )


def test_rod_coordinate_order_does_not_matter_when_the_gap_is_solvable():
    """Coordinates [x, theta, y]: the manifold solves the gap for y without at=."""
    s = rod_scene(coordinates=(x, th, y), at=None)
    assert simplified_zero(s.fast_subsystem().f[0] - rod().fast_subsystem().f[0])


def test_rod_with_coordinates_x_y_theta_needs_no_at():
    s = rod_scene(coordinates=(x, y, th), at=None)
    assert simplified_zero(s.fast_subsystem().f[0] - rod().fast_subsystem().f[0])


def painleve(theta_value: float, mu_value: float) -> float:
    """The classic paradox expression for I = m l^2/3: 1 + 3 cos^2 - 3 mu sin cos (< 0: paradox)."""
    return 1 + 3 * math.cos(theta_value) ** 2 - 3 * mu_value * math.sin(theta_value) * math.cos(theta_value)


@settings(max_examples=60, deadline=None)
@given(
    st.floats(0.05, math.pi / 2 - 0.05),
    st.floats(0, 6),
    st.floats(0.1, 5),
    st.floats(0.1, 5),
)
def test_painleve_condition_is_proposition_3(theta_value, mu_value, m_value, l_value):
    """f'(u) < 0 (Prop. 3: unstable for every law) iff mu > (1 + 3 cos^2)/(3 sin cos)."""
    classic = painleve(theta_value, mu_value)
    assume(abs(classic) > 1e-6)
    s = uniform_rod()
    values = {theta: theta_value, mu: mu_value, m: m_value, l: l_value}
    slope = float(s.linearization().A[0].subs(values))
    assert (slope < 0) == (classic < 0)
    st_ = s.stability()
    assert bool(st_.robustly_unstable.subs(values)) == (classic < 0)
    assert bool(st_.robustly_stable.subs(values)) == (classic > 0)


def test_painleve_threshold_is_mu_four_thirds_at_tan_theta_two():
    """The paradox region's tip: A = 0 exactly at mu = 4/3, tan(theta) = 2; below 4/3 there is no paradox."""
    A = uniform_rod().linearization().A[0]
    assert sp.simplify(A.subs({mu: sp.Rational(4, 3), theta: sp.atan(2)})) == 0
    for theta_value in [0.1 * i for i in range(1, 16)]:
        assert float(A.subs({mu: 1.3, theta: theta_value, m: 1, l: 1})) > 0
    assert float(A.subs({mu: 1.4, theta: math.atan(2), m: 1, l: 1})) < 0


def test_frictionless_rod_is_stable_for_every_law():
    st_ = rod().stability()
    for theta_value in [0.1, 0.7, 1.2, 1.5]:
        values = {mu: 0, theta: theta_value, m: 1.3, l: 0.7, J: 0.2}
        assert st_.robustly_stable.subs(values) == sp.true


@settings(max_examples=30, deadline=None)
@given(st.floats(0.05, 1.5), st.floats(0, 5), st.floats(-3, -0.1), st.floats(-3, -0.1))
def test_rod_hurwitz_conditions_agree_with_proposition_3(theta_value, mu_value, Phi_value, Psi_value):
    """k = 1 with Phi, Psi < 0: all Hurwitz conditions > 0 iff f' > 0, for any such Phi, Psi."""
    assume(abs(painleve(theta_value, mu_value)) > 1e-6)
    s = uniform_rod()
    (Phi,), (Psi,) = s.fast_subsystem().Phi, s.fast_subsystem().Psi
    values = {theta: theta_value, mu: mu_value, m: 1, l: 1, Phi: Phi_value, Psi: Psi_value}
    hurwitz = [float(h.subs(values)) for h in s.stability().hurwitz]
    slope = float(s.linearization().A[0].subs(values))
    assert all(h > 0 for h in hurwitz) == (slope > 0)
    assert s.stability().hopf == sp.false
    assert s.stability().propositions["Proposition 5 (no cycles)"] == sp.true


def test_rod_equilibrium_is_the_newton_euler_reaction():
    s = rod()
    (branch,) = s.equilibria().branches
    assert branch.signs == (1,)
    coefficient = 1 / m + l**2 * sp.cos(theta) * (sp.cos(theta) - mu * sp.sin(theta)) / J
    expected = (g - l * sp.sin(theta) * thetadot**2) / coefficient
    assert simplified_zero(branch.u_star[0] - expected)
    # it solves its piece exactly
    (u,) = s.fast_subsystem().u
    assert sp.cancel(s.fast_subsystem().piece((1,))[0].subs(u, branch.u_star[0])) == 0


@settings(max_examples=40, deadline=None)
@given(st.floats(0.05, 1.5), st.floats(0, 5), st.floats(-3, 3), st.floats(0.1, 3))
def test_rod_equilibrium_exists_iff_the_reaction_pushes(theta_value, mu_value, thetadot_value, g_value):
    s = uniform_rod()
    (branch,) = s.equilibria().branches
    values = {theta: theta_value, mu: mu_value, thetadot: thetadot_value, g: g_value, m: 1.5, l: 0.8}
    u_star = float(branch.u_star[0].subs(values))
    assume(abs(u_star) > 1e-6 and abs(painleve(theta_value, mu_value)) > 1e-6)
    assert bool(branch.condition.subs(values)) == (u_star > 0)
    if painleve(theta_value, mu_value) < 0 and g_value > 0.8 * math.sin(theta_value) * thetadot_value**2:
        # the paradox: the only candidate reaction pulls, no consistent contact force (Painleve's non-existence)
        assert not branch.condition.subs(values)


def test_rod_reduced_system_is_the_classical_sliding_motion():
    s = rod()
    reduced = s.reduced_system()
    assert reduced.coordinates == (sp.Symbol("x", real=True), theta)
    u_star = reduced.reactions[N]
    expected = {
        sp.Symbol("x", real=True): -mu * u_star / m,
        theta: -l * (sp.cos(theta) - mu * sp.sin(theta)) * u_star / J,
    }
    rng = random.Random(3)
    checked = 0
    while checked < 8:
        values = {
            theta: rng.uniform(0.05, 1.5),
            thetadot: rng.uniform(-2, 2),
            mu: rng.uniform(0, 3),
            m: rng.uniform(0.5, 2),
            l: rng.uniform(0.5, 2),
            J: rng.uniform(0.1, 2),
            g: rng.uniform(0.5, 10),
        }
        if not reduced.condition.subs(values):
            continue
        checked += 1
        for q, a in expected.items():
            assert abs(float(reduced.accelerations[q].subs(values)) - float(a.subs(values))) < 1e-9


def test_rod_latex():
    s = rod()
    scene_tex = cs.latex(s)
    assert scene_tex.startswith(r"\begin{aligned}") and scene_tex.endswith(r"\end{aligned}")
    for piece in (r"\ddot{x}", r"\ddot{y}", r"\ddot{\theta}", r"\left|{N}\right|", r"\mu"):
        assert piece in scene_tex
    fast_tex = cs.latex(s.fast_subsystem())
    assert "u' &=" in fast_tex and "v' &=" in fast_tex and r"\dot{\theta}^{2}" in fast_tex
    lin_tex = cs.latex(s.linearization())
    assert r"\det A" in lin_tex and r"p(\lambda)" in lin_tex
    st_tex = cs.latex(s.stability())
    assert "p_{1} &=" in st_tex and "p_{0} &=" in st_tex and r"p_{1}, p_{0} &> 0" in st_tex  # (4.6), (4.7)
    expr = s.fast_subsystem().f[0]
    assert cs.latex(expr) == sp.latex(expr)
    assert s._repr_latex_() == f"$\\displaystyle {cs.latex(s, tags=True)}$"


def test_rod_equilibria_latex():
    s = rod()
    tex = cs.latex(s.equilibria())
    assert r"\mathtt" not in tex
    assert sp.latex(s.equilibria().branches[0].u_star[0]) in tex


# --- contact space: fraction-free adjugate, Delassus matrices -------------------------


def test_faddeev_adjugate_and_det_match_sympy_on_random_integer_matrices():
    import random

    from contactsym.mechanism.contact_space import adjugate_and_det

    rng = random.Random(7)
    for n in range(1, 6):
        M = sp.Matrix(n, n, lambda i, j: rng.randint(-5, 5))
        adj, det = adjugate_and_det(M.tolist(), sp.expand)
        assert det == M.det()
        assert sp.Matrix(adj) == M.adjugate()


def test_faddeev_on_a_symbolic_matrix_is_exact():
    from contactsym.mechanism.contact_space import adjugate_and_det

    a, b, c, d, e = sp.symbols("a b c d e")
    M = sp.Matrix([[a, b, 0], [b, c, d], [0, d, e]])
    adj, det = adjugate_and_det(M.tolist(), sp.expand)
    assert sp.expand(det - M.det()) == 0
    assert (sp.Matrix(adj) - M.adjugate()).applyfunc(sp.expand).is_zero_matrix


def test_solve_fraction_free_agrees_with_lu_at_random_points():
    import random

    from contactsym.mechanism.contact_space import solve_fraction_free

    q1, q2 = sp.symbols("q1 q2", real=True)
    m1, m2 = sp.symbols("m1 m2", positive=True)
    M = sp.Matrix([[m1 + m2, m2 * sp.cos(q1 - q2)], [m2 * sp.cos(q1 - q2), m2]])
    load = sp.Matrix([sp.sin(q1), m1 * sp.cos(q2)])
    rows = sp.Matrix([[sp.sin(q1)], [sp.sin(q2)]])
    (ours,) = solve_fraction_free(M, [load], rows)
    naive = (rows.T * M.LUsolve(load))[0]
    rng = random.Random(3)
    for _ in range(10):
        point = {q1: rng.uniform(-3, 3), q2: rng.uniform(-3, 3), m1: rng.uniform(0.1, 3), m2: rng.uniform(0.1, 3)}
        assert abs(float(ours[0].subs(point)) - float(naive.subs(point))) < 1e-9


def test_a_singular_mass_matrix_names_the_coordinates():
    x, y = dynamicsymbols("x y")
    L = m * x.diff() ** 2 / 2  # y has no inertia
    with pytest.raises(cs.SceneError, match=r"singular.*\['y'\]"):
        cs.Scene.from_lagrangian(L, [x, y], [cs.Contact(coordinate=y, reaction=N)])
    coupled = m * (x.diff() + y.diff()) ** 2 / 2  # only x + y has inertia: det M = 0
    with pytest.raises(cs.SceneError, match=r"det M = 0.*\['x', 'y'\]"):
        cs.Scene.from_lagrangian(coupled, [x, y], [cs.Contact(coordinate=y, reaction=N)])


def _naive_contact_accelerations(scene):
    """g'' with the accelerations of an LU solve of the symbolic mass matrix, unsimplified."""
    from contactsym.mechanism.scene import t

    space = scene.contact_space
    accelerations = space.M.LUsolve(space.forcing)
    second = {sp.diff(q, t, 2): a for q, a in zip(space.coordinates, accelerations)}
    to_u = dict(zip(scene.reactions, scene.fast_subsystem().u))
    return [scene.freeze(sp.diff(g, t, 2).subs(second)).subs(to_u) for g in scene.gaps]


def test_stepladder_contact_accelerations_match_the_unsimplified_derivation():
    """Four coordinates, three contacts: f(u) from the contact space equals g'' of the LU-solved
    equations at random points (a wrong simplification would be a wrong result)."""
    from contactsym.scenes.stepladder import build

    scene = build()
    fast = scene.fast_subsystem()
    naive = _naive_contact_accelerations(scene)
    symbols = sorted(set().union(*(e.free_symbols for e in list(fast.f) + naive)), key=str)
    ours_f = sp.lambdify(symbols, list(fast.f), "math")
    naive_f = sp.lambdify(symbols, naive, "math")
    rng = random.Random(5)
    for _ in range(20):
        values = [rng.uniform(-2, 2) if s.is_positive is not True else rng.uniform(0.3, 2) for s in symbols]
        expected = naive_f(*values)
        assert ours_f(*values) == pytest.approx(expected, rel=1e-9, abs=1e-9)


# --- the mass determinant: one exact point, one symbolic adjugate --------------------


def _random_mass_matrix(rng: random.Random, n: int, rank: int):
    """B B^T with B n x rank: entries mix q_i(t), sin q_i, cos q_i, q_i', t, masses and an
    opaque generator I(l); singular when rank < n."""
    q = dynamicsymbols(" ".join(f"q{i}" for i in range(n)))
    atoms = [m, l, t, sp.Function("I")(l), *q, *(qi.diff() for qi in q)]
    atoms += [f(qi) for qi in q for f in (sp.sin, sp.cos)]

    def entry():
        return rng.randint(1, 3) * rng.choice(atoms) * rng.choice(atoms) + rng.randint(-2, 2)

    B = sp.Matrix(n, rank, lambda i, j: entry())
    return B * B.T


@pytest.mark.parametrize("seed", range(6))
def test_the_point_test_agrees_with_the_symbolic_determinant_with_coordinates_and_time(seed):
    """Generators q(t), q'(t), t and opaque ones beside sin q, cos q: the point verdict is the
    symbolic one (Faddeev-LeVerrier in the reduced field), on singular and regular random matrices."""
    from contactsym.algebra.canonical_form import TrigField
    from contactsym.algebra.fraction_free import adjugate_and_det
    from contactsym.mechanism import contact_space as module

    rng = random.Random(seed)
    n = 2 + seed % 2
    for rank in (n - 1, n):
        M = _random_mass_matrix(rng, n, rank)
        field = TrigField(list(M))
        assert any(isinstance(g, sp.core.function.AppliedUndef) for g in field.ring.symbols)
        entries = [[field.element(x) for x in row] for row in M.tolist()]
        symbolic_zero = not adjugate_and_det(entries, field.reduce)[1]
        assert symbolic_zero == (rank < n)
        assert module.mass_determinant_is_zero(M) == symbolic_zero
        if rank == n:  # decided at the point, without the symbolic determinant
            assert module._value_at_a_point(field, entries) != 0


def test_a_sign_symbol_takes_a_value_of_a_sign_at_the_point():
    """det [[s, 1], [1, s]] = s^2 - 1 = 0 for a sign s = +-1: a rational value for s would say otherwise."""
    from contactsym.algebra.basic import SignSymbol
    from contactsym.mechanism.contact_space import mass_determinant_is_zero

    s = SignSymbol("s")
    assert mass_determinant_is_zero(sp.Matrix([[s, 1], [1, s]]))
    assert not mass_determinant_is_zero(sp.Matrix([[s, 1], [1, 2 * s]]))


def test_a_chain_computes_one_symbolic_adjugate_of_its_mass_matrix(monkeypatch):
    """The singularity check decides at a point, det M > 0 takes det M alone (by minors), and adj(M)
    is computed once, for A's entries, when they are asked for."""
    from contactsym.algebra import fraction_free
    from contactsym.scenes.link_chain import build_chain

    fraction_free.polynomial_adjugate.cache_clear()
    sizes = []
    original = fraction_free.adjugate_and_det

    def counted(M, reduce):
        sizes.append(len(M))
        return original(M, reduce)

    monkeypatch.setattr(fraction_free, "adjugate_and_det", counted)
    scene = build_chain(2)
    scene.fast_subsystem()
    assert scene.positive_expressions
    assert sizes == []
    assert scene.linearization().A.free_symbols and scene.fast_subsystem().f.free_symbols
    assert sizes == [2]
