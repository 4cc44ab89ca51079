"""Scenes: built-in scenes, user scenes from accelerations, the contact manifold, bad input."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

import contactsym as cs
from contactsym.errors import ContactsymError, SceneError, SignPatternError

NAMES = [
    "sliding-point",
    "painleve-klein-rod",
    "painleve-klein-guides",
    "brake",
    "double-pendulum-tip",
    "painleve-rod",
    "two-leg-block",
    "painleve-rod-3d",
    "stool-3d",
]

x, y, z = dynamicsymbols("x y z")
t = dynamicsymbols._t
N, N1, N2 = sp.symbols("N N_1 N_2", real=True)
X, Y, mu, c = sp.symbols("X Y mu c", real=True)


def point_on_line(**options) -> cs.Scene:
    """The class docstring's example: x'' = X - mu|N|, y'' = N + Y, contact y = 0."""
    return cs.Scene.from_accelerations(
        [x, y], [X - mu * sp.Abs(N), N + Y], [cs.Contact(coordinate=y, reaction=N)], **options
    )


# --- built-in scenes ----------------------------------------------------------------


def test_scene_names_are_the_paper_examples_and_beyond():
    assert cs.scene_names() == NAMES
    assert cs.DEFAULT_SCENE in cs.scene_names()


def test_scene_names_returns_a_copy():
    names = cs.scene_names()
    names.append("mine")
    assert cs.scene_names() == NAMES


@pytest.mark.parametrize(
    "name, coordinates, k",
    [("sliding-point", 2, 1), ("painleve-klein-rod", 2, 1), ("painleve-klein-guides", 3, 2), ("brake", 3, 2)],
)
def test_builtin_scene_shape(name, coordinates, k):
    s = cs.scene(name)
    assert isinstance(s, cs.Scene)
    assert s.name == name
    assert len(s.coordinates) == coordinates
    assert s.k == k == len(s.contacts) == len(s.reactions)
    assert repr(s) == f"<Scene '{name}': {coordinates} coordinates, k = {k} contacts>"
    assert s.description
    fast = s.fast_subsystem()
    assert len(fast.f) == k
    assert all(fj.has(*fast.u) for fj in fast.f)


@pytest.mark.parametrize("name", NAMES)
def test_builtin_scene_is_built_once_and_stages_are_cached(name):
    s = cs.scene(name)
    assert cs.scene(name) is s
    assert s.fast_subsystem() is s.fast_subsystem()
    assert s.equilibria() is s.equilibria()
    assert s.linearization() is s.linearization()


@pytest.mark.parametrize("name", NAMES)
def test_builtin_parameters_are_symbols_with_assumptions(name):
    s = cs.scene(name)
    fast = s.fast_subsystem()
    assert s.parameters == tuple(sorted(s.parameters, key=str))
    assert all(isinstance(p, sp.Symbol) for p in s.parameters)
    assert not set(s.parameters) & (set(fast.u) | set(fast.v))
    exprs = list(fast.f) + list(fast.Phi) + list(fast.Psi)
    used = set().union(*(e.free_symbols for e in exprs)) - set(fast.u) - set(fast.v)
    assert set(s.parameters) == used
    assert all(p.is_real for p in s.parameters)


def test_brake_parameters_keep_their_assumptions():
    by_name = {str(p): p for p in cs.scene("brake").parameters}
    assert {"F_x", "F_y", "m", "mu", "alpha", "Phi_1", "Phi_2", "Psi_1", "Psi_2"} <= set(by_name)
    for name in ("m", "mu", "alpha"):
        assert by_name[name].is_positive
    for name in ("Phi_1", "Phi_2", "Psi_1", "Psi_2"):
        assert by_name[name].is_negative
    assert by_name["F_x"].is_positive is None


def test_brake_contacts_are_unilateral_so_only_one_sign_pattern():
    s = cs.scene("brake")
    assert all(contact.unilateral for contact in s.contacts)
    u1, u2 = s.fast_subsystem().u
    assert s.fixed_signs == {u1: 1, u2: 1}
    assert s.sign_patterns() == [(1, 1)]


def test_open_sign_patterns_enumerate_every_orthant():
    assert cs.scene("painleve-klein-guides").sign_patterns() == [(1, 1), (1, -1), (-1, 1), (-1, -1)]
    assert cs.scene("sliding-point").sign_patterns() == [()]


# --- user scenes from accelerations -------------------------------------------------


def test_from_accelerations_docstring_example():
    s = point_on_line()
    u = s.fast_subsystem().u[0]
    assert s.fast_subsystem().f == sp.Matrix([Y + u])
    assert s.k == 1 and s.name == "user"
    assert s.accelerations == {x: X - mu * sp.Abs(N), y: N + Y}


def test_from_accelerations_attaches_coulomb_friction_along_direction():
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1, z: -2}))
    s = cs.Scene.from_accelerations([x, y, z], [X, N + Y, 0], [contact])
    assert sp.expand(s.accelerations[x] - (X - mu * sp.Abs(N))) == 0
    assert sp.expand(s.accelerations[z] - 2 * mu * sp.Abs(N)) == 0
    assert s.accelerations[y] == N + Y


def test_from_accelerations_attaches_viscous_friction_with_the_slip_speed():
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Viscous(c, {x: 1}))
    s = cs.Scene.from_accelerations([x, y], [X, N + Y], [contact])
    assert sp.expand(s.accelerations[x] - (X - c * x.diff(t))) == 0
    # viscous friction does not depend on N: the frozen acceleration of x sees only xdot
    assert s.freeze(s.accelerations[x]) == X - c * sp.Symbol("xdot", real=True)


def test_contact_defaults():
    contact = cs.Contact(coordinate=y, reaction=N)
    assert isinstance(contact.compliance, cs.Generic)
    assert contact.friction is None and contact.unilateral is False
    assert repr(contact) == "Contact(y(t), N, Generic())"
    assert "unilateral" in repr(cs.Contact(coordinate=y, reaction=N, unilateral=True))


def test_contact_is_immutable():
    contact = cs.Contact(coordinate=y, reaction=N)
    with pytest.raises(AttributeError):
        contact.reaction = N1


# --- the contact manifold and freeze --------------------------------------------------


def test_manifold_of_a_coordinate_contact():
    s = point_on_line()
    ys, ydot = sp.Symbol("y", real=True), sp.Symbol("ydot", real=True)
    assert s.manifold == {ys: 0, ydot: 0}
    frozen = s.frozen_symbols
    assert frozen[x] == sp.Symbol("x", real=True)
    assert frozen[x.diff(t)] == sp.Symbol("xdot", real=True)


def test_freeze_puts_the_slow_state_on_the_manifold_with_plain_symbols():
    s = point_on_line()
    xs, xdot = sp.Symbol("x", real=True), sp.Symbol("xdot", real=True)
    expr = x * y + x.diff(t) + y.diff(t) ** 2 + sp.sin(x) * N + y
    frozen = s.freeze(expr)
    assert frozen == xdot + sp.sin(xs) * N
    assert not frozen.has(t)
    # derivatives are frozen before their coordinates (no Derivative(x, t) -> Derivative(x_plain))
    assert s.freeze(x.diff(t) * x) == xdot * xs


def test_manifold_of_a_gap_function_is_solved_for_a_coordinate():
    slope = sp.Symbol("k", positive=True)
    m, g = sp.symbols("m g", positive=True)
    O = ReferenceFrame("O")
    origin = Point("o")
    origin.set_vel(O, 0)
    P = origin.locatenew("P", x * O.x + y * O.y)
    P.set_vel(O, x.diff(t) * O.x + y.diff(t) * O.y)
    L = Lagrangian(O, Particle("P", P, m))
    s = cs.Scene.from_lagrangian(
        L, [x, y], [cs.Contact(coordinate=y - slope * x, reaction=N)], loads=[(P, -m * g * O.y)], frame=O
    )
    xs, ys = sp.Symbol("x", real=True), sp.Symbol("y", real=True)
    xdot, ydot = sp.Symbol("xdot", real=True), sp.Symbol("ydot", real=True)
    manifold = s.manifold
    # on the line y = k x, one of each pair is eliminated and the gap and its rate vanish
    assert sp.expand((ys - slope * xs).subs(manifold)) == 0
    assert sp.expand((ydot - slope * xdot).subs(manifold)) == 0
    assert len(manifold) == 2
    # f is the normal acceleration of the gap: (1 + k^2)/m * u - g
    u = s.fast_subsystem().u[0]
    assert sp.expand(s.fast_subsystem().f[0] - ((1 + slope**2) * u / m - g)) == 0


def test_at_fixes_parameters_at_contact():
    s = cs.scene("painleve-klein-guides")
    h, l, phi = sp.Symbol("h", positive=True), sp.Symbol("l", positive=True), sp.Symbol("phi", real=True)
    assert s.manifold[h] == l * sp.sin(phi)
    assert s.manifold[sp.Symbol("phidot", real=True)] == 0
    assert s.manifold[sp.Symbol("ydot", real=True)] == 0


def test_manifold_that_cannot_be_reached_says_to_pass_at():
    s = cs.Scene([x, y], [X, N + Y], [cs.Contact(coordinate=y**2 + 1, reaction=N)])
    with pytest.raises(SceneError, match=r"cannot place the state on the contact manifold.*pass at=\{"):
        _ = s.manifold


# --- bad input: clear errors ---------------------------------------------------------


@pytest.mark.parametrize(
    "typo, meant",
    [
        ("break", "brake"),
        ("slidingpoint", "sliding-point"),
        ("painleve-klein-guide", "painleve-klein-guides"),
        ("painleve_klein_rod", "painleve-klein-rod"),
    ],
)
def test_unknown_scene_name_suggests_a_close_name(typo, meant):
    with pytest.raises(SceneError) as info:
        cs.scene(typo)
    message = str(info.value)
    assert f"unknown scene '{typo}'" in message
    assert f"did you mean '{meant}'" in message
    for name in NAMES:
        assert name in message


def test_unknown_scene_name_without_a_close_match_lists_the_known_ones():
    with pytest.raises(SceneError) as info:
        cs.scene("xyz")
    message = str(info.value)
    assert "did you mean" not in message
    assert "Known scenes: " + ", ".join(NAMES) in message


def test_errors_are_value_errors():
    assert issubclass(SceneError, ContactsymError)
    assert issubclass(SignPatternError, ContactsymError)
    assert issubclass(ContactsymError, ValueError)
    with pytest.raises(ValueError):
        cs.scene("nope")


def test_contact_coordinate_not_among_the_coordinates():
    with pytest.raises(SceneError) as info:
        cs.Scene.from_accelerations([x, y], [X, N + Y], [cs.Contact(coordinate=z, reaction=N)])
    message = str(info.value)
    assert "z(t) is not among the coordinates" in message
    assert "[x(t), y(t)]" in message
    assert "add it" in message and "from_lagrangian" in message


def test_gap_function_that_does_not_depend_on_the_coordinates():
    m = sp.Symbol("m", positive=True)
    L = m * x.diff(t) ** 2 / 2 + m * y.diff(t) ** 2 / 2
    with pytest.raises(SceneError, match=r"the gap z\(t\) does not depend on the coordinates"):
        cs.Scene.from_lagrangian(L, [x, y], [cs.Contact(coordinate=z, reaction=N)])


def test_accelerations_that_do_not_depend_on_any_reaction():
    with pytest.raises(SceneError) as info:
        cs.Scene.from_accelerations([x, y], [X, Y], [cs.Contact(coordinate=y, reaction=N)])
    message = str(info.value)
    assert "no acceleration depends on the reactions ['N']" in message
    assert "check the reaction symbols" in message


def test_reaction_that_misses_its_contact_direction():
    """N acts on x only: the scene builds, but the contact acceleration f has no u."""
    s = cs.Scene.from_accelerations([x, y], [X + N, Y], [cs.Contact(coordinate=y, reaction=N)])
    with pytest.raises(SceneError) as info:
        s.fast_subsystem().f  # noqa: B018
    message = str(info.value)
    assert "do not depend on any reaction" in message
    assert "normal" in message


def test_duplicate_reaction_symbols():
    contacts = [cs.Contact(coordinate=x, reaction=N), cs.Contact(coordinate=y, reaction=N)]
    with pytest.raises(SceneError, match="share one reaction symbol; give each contact its own"):
        cs.Scene.from_accelerations([x, y], [X + N, Y + N], contacts)


def test_undeclared_parameters_are_named():
    with pytest.raises(SceneError) as info:
        point_on_line(parameters=[X, mu])
    message = str(info.value)
    assert "['Y']" in message
    assert "not among the declared parameters" in message
    assert "declare them or fix the spelling" in message


def test_misspelt_parameter_is_caught():
    mu_typo = sp.Symbol("mu_", real=True)
    with pytest.raises(SceneError, match=r"\['mu_'\]"):
        cs.Scene.from_accelerations(
            [x, y], [X - mu_typo * sp.Abs(N), N + Y], [cs.Contact(coordinate=y, reaction=N)], parameters=[X, Y, mu]
        )


def test_declared_parameters_accept_the_scene():
    s = point_on_line(parameters=[X, Y, mu])
    assert s.fast_subsystem().f[0] == Y + s.fast_subsystem().u[0]


def test_wrong_number_of_accelerations():
    with pytest.raises(SceneError, match="got 1 accelerations for 2 coordinates; give one per coordinate"):
        cs.Scene.from_accelerations([x, y], [N], [cs.Contact(coordinate=y, reaction=N)])


def test_scene_without_contacts():
    with pytest.raises(SceneError, match="at least one Contact"):
        cs.Scene.from_accelerations([x, y], [X, N + Y], [])


def test_reaction_must_be_a_symbol():
    with pytest.raises(SceneError, match="must be a sympy Symbol"):
        cs.Contact(coordinate=y, reaction=N + 1)


def test_coulomb_direction_must_be_a_dict_for_from_accelerations():
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, direction=1))
    with pytest.raises(SceneError, match=r"\{coordinate: coefficient\}"):
        cs.Scene.from_accelerations([x, y], [X, N + Y], [contact])


def test_coulomb_direction_on_an_unknown_coordinate():
    contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {z: 1}))
    with pytest.raises(SceneError, match=r"z\(t\)"):
        cs.Scene.from_accelerations([x, y], [X, N + Y], [contact])


def test_lagrangian_friction_needs_a_point_and_a_frame():
    m = sp.Symbol("m", positive=True)
    O = ReferenceFrame("O")
    L = m * x.diff(t) ** 2 / 2 + m * y.diff(t) ** 2 / 2
    bad = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1}))
    with pytest.raises(SceneError, match=r"point=<the sliding Point>"):
        cs.Scene.from_lagrangian(L, [x, y], [bad], frame=O)
    P = Point("P")
    no_frame = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, O.x, P))
    with pytest.raises(SceneError, match=r"frame=<the inertial ReferenceFrame>"):
        cs.Scene.from_lagrangian(L, [x, y], [no_frame])


# --- sign patterns ---------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(st.lists(st.sampled_from([1, -1]), max_size=5).filter(lambda signs: len(signs) != 2))
def test_sign_pattern_of_the_wrong_length(signs):
    s = cs.scene("painleve-klein-guides")
    with pytest.raises(SignPatternError) as info:
        s.linearization(signs=signs)
    message = str(info.value)
    assert f"has length {len(signs)}" in message
    assert "2 switching functions [u_1, u_2]" in message
    assert "give one sign (+1 or -1) each" in message


@settings(max_examples=40, deadline=None)
@given(st.tuples(st.integers(-5, 5), st.integers(-5, 5)).filter(lambda pair: any(v not in (1, -1) for v in pair)))
def test_sign_pattern_with_values_other_than_plus_minus_one(signs):
    s = cs.scene("painleve-klein-guides")
    bad = next(value for value in signs if value not in (1, -1))
    with pytest.raises(SignPatternError) as info:
        s.linearization(signs=signs)
    message = str(info.value)
    assert f"sign {bad!r}" in message
    assert "must be +1 or -1" in message


@pytest.mark.parametrize("signs", [("+", 1), (1, None), (0.5, 1), (1, sp.Rational(1, 2))])
def test_sign_pattern_with_non_integer_values(signs):
    with pytest.raises(SignPatternError, match="must be \\+1 or -1"):
        cs.scene("painleve-klein-guides").linearization(signs=signs)


@pytest.mark.parametrize("stage", ["linearization", "equilibria", "stability", "reduced_system"])
def test_every_stage_checks_the_sign_pattern(stage):
    s = cs.scene("painleve-klein-guides")
    with pytest.raises(SignPatternError, match="has length 3"):
        getattr(s, stage)(signs=(1, 1, 1))
    with pytest.raises(SignPatternError, match="must be \\+1 or -1"):
        getattr(s, stage)(signs=(1, 0))


def test_sign_pattern_must_respect_unilateral_contacts():
    with pytest.raises(SignPatternError, match=r"u_1 > 0 on the unilateral contact; its sign must be \+1"):
        cs.scene("brake").linearization(signs=(-1, 1))


def test_scene_without_switching_functions_takes_the_empty_pattern():
    s = cs.scene("sliding-point")
    assert s.linearization(signs=()).A == s.linearization().A
    with pytest.raises(SignPatternError, match="0 switching functions"):
        s.linearization(signs=(1,))


def test_valid_sign_patterns_as_lists_and_sympy_integers():
    s = cs.scene("painleve-klein-guides")
    assert s.linearization(signs=[1, -1]) is s.linearization(signs=(1, -1))
    assert s.linearization(signs=(sp.Integer(1), sp.Integer(-1))).A == s.linearization(signs=(1, -1)).A


def test_boolean_sign_is_rejected():
    with pytest.raises(SignPatternError):
        cs.scene("painleve-klein-guides").linearization(signs=(True, 1)).A  # noqa: B018


def test_a_scene_pays_only_for_what_it_asks():
    from contactsym.scenes import brake, painleve_klein_rod

    rod = painleve_klein_rod.build()  # fresh: nothing cached
    rod.fast_subsystem()
    assert [key for key in rod._stage_cache if key != "fast"] == []
    stability = rod.stability()
    assert stability.routh_hurwitz.poly.degree() == 2  # k = 1: a quadratic, never a quartic
    assert not any(isinstance(key, tuple) and key[0] == "equilibria" for key in rod._stage_cache)

    disc = brake.build()
    assert disc.sign_patterns() == [(1, 1)]  # unilateral pads: the only pattern
    assert disc.linearization().sign_values == (1, 1)  # no sign symbols to carry
    assert disc.equilibria().patterns == [(1, 1)]


def test_plain_freezes_by_replacement_as_subs_did_and_falls_back_to_subs():
    s = point_on_line()
    rates = {d: v for d, v in s.frozen_symbols.items() if isinstance(d, sp.Derivative)}

    def by_subs(e):  # the substitution plain stands for, done the slow way
        return e.subs(rates).subs(s.frozen_symbols)

    ordinary = X * x.diff(t) ** 2 + sp.sin(y) * y.diff(t) - mu * sp.Abs(N) * x
    assert s.plain(ordinary) == by_subs(ordinary) and not s.plain(ordinary).has(t)
    compound = sp.Derivative(x * y, t, evaluate=False) + x  # a derivative xreplace cannot enter
    assert s.plain(compound) == by_subs(compound)
    assert s.freeze(ordinary) == by_subs(ordinary).subs(s.manifold)


def test_the_report_derives_only_the_slow_part_of_the_regularization():
    from contactsym.report.derivation import _chain
    from contactsym.report.typesetting import _Named

    s = point_on_line(name="own")
    text = "\n".join(_chain(s, _Named()))
    regularized = s.regularized()
    assert "Y" not in vars(regularized) and "X" in vars(regularized)  # Y (cached when derived) never was
    assert all(f.body in text or f.lhs in text for f in regularized.slow_formulas())
    assert len(regularized.formulas()) == len(regularized.slow_formulas()) + 2 * s.k
