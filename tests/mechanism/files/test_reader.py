"""Scene files: the examples give the built-ins' results; bad files give one clear line."""

from __future__ import annotations

import contextlib
import dataclasses
import os
import threading
import time
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym.mechanism.files.declarations import positive_on
from contactsym.mechanism.files.reader import (
    LIMITS,
    Limits,
    build_scene,
    load_scene,
    read_scene,
    read_spec,
    scene_or_file,
)
from contactsym.mechanism.files.toml_source import SceneFileError
from contactsym.parse import ParseError

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def _conditions(scene) -> dict:
    """Everything the pipeline derives that a report states, keyed for exact comparison."""
    fast = scene.fast_subsystem()
    return {
        "f": fast.f,
        "Phi": fast.Phi,
        "Psi": fast.Psi,
        "manifold": scene.manifold,
        "equilibria": [(b.signs, b.u_star, b.condition) for b in scene.equilibria().branches],
        "hurwitz": scene.stability().hurwitz,
        "regions": {name: region.condition for name, region in scene.regions().items()},
    }


def _inputs(scene) -> dict:
    """What the pipeline derives everything from (the equilibrium counts too, which take longest)."""
    return {
        "accelerations": scene.accelerations,
        "contacts": [(c.coordinate, c.reaction, c.compliance, c.unilateral) for c in scene.contacts],
        "at": scene.at,
        "presentation": scene.presentation,
        "count_presentation": getattr(scene, "count_presentation", None),
        "positive": scene.positive_expressions,
        "solve_for": scene.solve_for,
        "eps": scene.eps,
    }


@pytest.mark.parametrize("name", cs.scene_names())
def test_example_files_give_the_built_in_results_exactly(name):
    built_in = cs.scene(name)
    from_file = load_scene(EXAMPLES / f"{name}.toml")
    assert from_file is not built_in and from_file.name == f"{name}-file"
    assert _inputs(from_file) == _inputs(built_in)
    if built_in.k >= 3:  # the same contact space derives the same stages (deriving them again: ~9 s CPU)
        space, own = built_in.contact_space, from_file.contact_space
        assert (own.M, own.F, own.W, own.friction, own.reactions) == (
            space.M,
            space.F,
            space.W,
            space.friction,
            space.reactions,
        )
        assert from_file.manifold == built_in.manifold
    else:
        assert _conditions(from_file) == _conditions(built_in)


def test_guide_walkthrough_file_is_the_example_and_shows_painleves_bound():
    guide = (EXAMPLES.parent / "docs" / "guides" / "scene-files.md").read_text()
    block = guide.split("```toml\n", 1)[1].split("```", 1)[0]
    assert block == (EXAMPLES / "leaning-rod.toml").read_text()
    scene = read_scene(block, "leaning-rod.toml")
    stable = scene.regions()["stable for every law"].condition
    mu, theta = sp.Symbol("mu", positive=True), sp.Symbol("theta", real=True)
    # Painleve's bound 1 + 3 cos^2 - 3 mu sin cos > 0, by a second route: sampled both ways
    for m_value, t_value in [(0.5, 1.0), (2.0, 1.1), (1.4, 1.05), (3.0, 0.3)]:
        at = {mu: m_value, theta: t_value}
        classical = 1 + 3 * np.cos(t_value) ** 2 - 3 * m_value * np.sin(t_value) * np.cos(t_value) > 0
        assert bool(stable.subs(at)) == classical


def test_scene_or_file_tells_files_from_names(tmp_path):
    assert scene_or_file("brake") is cs.scene("brake")
    assert scene_or_file(str(EXAMPLES / "brake.toml")).name == "brake-file"
    with pytest.raises(SceneFileError, match="cannot read"):
        scene_or_file(str(tmp_path / "missing.toml"))


BASE = """[scene]
coordinates = ["x", "y"]
[parameters]
mu = "positive"
k = "positive"
[accelerations]
x = "0"
y = "N - 1"
[[contacts]]
gap = "y"
reaction = "N"
"""


@pytest.mark.parametrize(
    "text, error, start, words",
    [
        (BASE + 'law = {name = "kelvin-voigt"\n', SceneFileError, "a.toml:12:29: ", "not valid TOML"),
        (BASE.replace("[parameters]", "[parameter]"), SceneFileError, "a.toml:3: ", "did you mean 'parameters'"),
        (BASE.replace('reaction = "N"', 'reaction = "N"\nlaww = "generic"'), SceneFileError, "a.toml:12: ", "'law'"),
        (BASE.split("[[contacts]]")[0], SceneFileError, "a.toml:1: ", "no [[contacts]] table"),
        (BASE.replace('[scene]\ncoordinates = ["x", "y"]\n', ""), SceneFileError, "a.toml:1: ", "no [scene] table"),
        (BASE.replace('gap = "y"', 'gap = "mu"'), SceneFileError, "a.toml:10: ", "must be one of the coordinates"),
        (BASE + 'law = {name = "kelvin-voigt", stiffness = "-k"}\n', SceneFileError, "a.toml:12: ", "(1.5) fails"),
        (BASE + 'law = {name = "law", N = "k*q/eps^2 - q\'/eps"}\n', SceneFileError, "a.toml:12: ", "dN/dq < 0"),
        (BASE + 'law = "hertz"\n', SceneFileError, "a.toml:12: ", "unknown law 'hertz'"),
        (BASE.replace('k = "positive"', 'x = "positive"'), SceneFileError, "a.toml:5: ", "declared twice"),
        (BASE.replace('reaction = "N"', 'reaction = "mu"'), SceneFileError, "a.toml:11: ", "declared twice"),
        (BASE.replace('k = "positive"', 'k = "postive"'), SceneFileError, "a.toml:5: ", "unknown assumption"),
        (BASE.replace('k = "positive"', 'k = {symbol = "\\\\input{x}"}'), SceneFileError, "a.toml:5: ", "mu_+"),
        (BASE.replace('y = "N - 1"', 'y = "N - mu*kk"'), ParseError, "a.toml:8:13: ", "did you mean 'k'"),
        (BASE.replace('x = "0"', "x = true"), SceneFileError, "a.toml:7: ", "a formula in quotes"),
        (BASE.replace('x = "0"\n', ""), SceneFileError, "a.toml:6: ", "no acceleration for x"),
    ],
)
def test_bad_files_give_one_line_with_file_line_and_fix(text, error, start, words):
    with pytest.raises(error) as raised:
        read_scene(text, "a.toml")
    message = str(raised.value)
    assert message.startswith(start) and words in message and "\n" not in message


def test_gap_without_the_coordinates_in_a_lagrangian_file():
    text = """[scene]
coordinates = ["y"]
[parameters]
m = "positive"
h = "positive"
[energy]
kinetic = "m*y'^2/2"
[[contacts]]
gap = "h"
reaction = "N"
"""
    with pytest.raises(SceneFileError, match=r"^a.toml:9: the gap h does not depend on the coordinates y"):
        read_scene(text, "a.toml")
    scene = read_scene(text.replace('gap = "h"', 'gap = "y - h"'), "a.toml")
    assert list(scene.accelerations.values()) == [sp.Symbol("N", real=True) / sp.Symbol("m", positive=True)]


@pytest.mark.parametrize(
    "formula",
    ["__import__('os').system('touch {marker}')", "x.__class__", "(lambda: 1)()", "[i for i in (1,)]", "a" * 20000],
)
def test_formulas_in_files_are_never_evaluated(formula, tmp_path):
    marker = tmp_path / "pwned"
    text = BASE.replace('y = "N - 1"', f'y = "{formula.format(marker=marker)}"')
    with pytest.raises(ParseError, match=r"^a.toml:8:"):
        read_scene(text, "a.toml")
    assert not marker.exists()


@settings(max_examples=40, deadline=None)
@given(st.integers(-12, 12), st.integers(1, 12), st.integers(1, 6))
def test_interval_positivity_holds_at_sampled_points(low, width, denominator):
    """sin/cos declared positive on an interval are positive at many points of it; the others change sign."""
    phi = sp.Symbol("phi", real=True)
    a, b = sp.pi * sp.Rational(low, denominator), sp.pi * sp.Rational(low + width, denominator)
    declared = positive_on(phi, a, b)
    inside = np.linspace(float(a), float(b), 401)[1:-1]
    for function, numeric in ((sp.sin, np.sin), (sp.cos, np.cos)):
        values = numeric(inside)
        if function(phi) in declared:
            assert values.min() > 0
        else:
            assert values.min() <= 1e-12


def _direct_point_on_line(a: int, b: int, c: int):
    """A point mass on the rough line a x + b y = 0, built with the Python API directly."""
    from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

    x, y = dynamicsymbols("x y")
    m, mu = sp.symbols("m mu", positive=True)
    X, Y, N = sp.symbols("X Y N", real=True)
    frame, origin = ReferenceFrame("O"), Point("O")
    origin.set_vel(frame, 0)
    point = origin.locatenew("P", x * frame.x + y * frame.y)
    point.set_vel(frame, x.diff() * frame.x + y.diff() * frame.y)
    length = sp.sqrt(a**2 + b**2)  # a unit direction along the line, a gap that is the distance from it
    friction = cs.Coulomb(mu, c * (b * frame.x - a * frame.y) / length, point)
    contact = cs.Contact((a * x + b * y) / length, N, cs.KelvinVoigt(1, 2), friction, unilateral=False)
    L = Lagrangian(frame, Particle("P", point, m))
    return cs.Scene.from_lagrangian(L, [x, y], [contact], loads=[(point, X * frame.x + Y * frame.y)], frame=frame)


@settings(max_examples=5, deadline=None)
@given(st.integers(-3, 3), st.integers(-3, 3).filter(bool), st.sampled_from([1, -1]))
def test_random_lines_from_a_file_equal_the_python_api(a, b, c):
    text = f"""[scene]
coordinates = ["x", "y"]
[parameters]
m = "positive"
mu = "positive"
X = "real"
Y = "real"
[points]
P = ["x", "y"]
[[masses]]
point = "P"
mass = "m"
[[loads]]
point = "P"
force = ["X", "Y"]
[[contacts]]
gap = "({a}*x + {b}*y)/sqrt({a * a + b * b})"
reaction = "N"
law = {{ name = "kelvin-voigt", stiffness = 1, damping = 2 }}
friction = {{ mu = "mu", point = "P", direction = ["{c * b}/sqrt({a * a + b * b})", "{-c * a}/sqrt({a * a + b * b})"] }}
"""
    from_file, direct = read_scene(text, "line.toml"), _direct_point_on_line(a, b, c)
    assert from_file.accelerations == direct.accelerations  # the rest of the pipeline follows from these
    assert from_file.gaps == direct.gaps


def test_user_law_in_a_file_matches_the_python_law_and_shadows_q():
    text = BASE.replace('["x", "y"]', '["q", "y"]').replace('x = "0"', 'q = "0"')
    text += 'law = { name = "law", N = "-k*q/eps^2 - q\'/eps - (q\'/eps)^3" }\n'
    scene = read_scene(text, "a.toml")
    q, qd = sp.symbols("q qdot", real=True)
    eps, k = sp.Symbol("epsilon", positive=True), sp.Symbol("k", positive=True)
    law = cs.Law(-k * q / eps**2 - qd / eps - (qd / eps) ** 3, q, qd, eps)
    u, v = sp.symbols("u v", real=True)
    assert scene.contacts[0].compliance.phi_psi(u, v, None) == law.phi_psi(u, v, None) == (-k, -3 * v**2 - 1)
    with pytest.raises(SceneFileError, match=r"^a.toml:4: the interval \(2, 1\) is empty"):
        read_scene(BASE.replace('mu = "positive"', "mu = [2, 1]"), "a.toml")


# --- the spec: data first, then the Scene --------------------------------------------------------------


def test_a_file_is_read_into_a_frozen_spec_and_built_from_it_alone():
    text = (EXAMPLES / "painleve-klein-guides.toml").read_text()
    spec = read_spec(text, "guides.toml")
    with pytest.raises(dataclasses.FrozenInstanceError):
        spec.name = "other"
    assert [c.name for c in spec.coordinates] == ["x", "y", "phi"] and len(spec.contacts) == 2
    assert spec.lagrangian and [p.name for p in spec.points] == ["C", "P_1", "P_2"]
    scene = build_scene(spec)
    built_in = cs.scene("painleve-klein-guides")
    assert scene.count_presentation == built_in.count_presentation  # a constructor argument, as for the built-in
    assert scene.figure_plan is spec.figures and scene.figure_plan.x == "v_1"


def test_count_presentation_and_figure_plan_are_scene_arguments():
    x, y = sp.symbols("x y", cls=sp.Function)
    t = sp.Symbol("t")
    N, mu, kappa = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True), sp.Symbol("kappa", positive=True)
    contact = cs.Contact(coordinate=y(t), reaction=N)
    plan = cs.FigurePlan("mu", "kappa", (0, 1), (0, 1), {})
    scene = cs.Scene.from_accelerations(
        [x(t), y(t)], [0, N - 1], [contact], count_presentation={mu: kappa}, figure_plan=plan
    )
    assert scene.count_presentation == {mu: kappa} and scene.figure_plan is plan
    assert cs.Scene.from_accelerations([x(t), y(t)], [0, N - 1], [contact]).count_presentation is None
    for options, words in (
        ({"count_presentation": [mu]}, "count_presentation must be a dict"),
        ({"figure_plan": 3}, "FigurePlan"),
    ):
        with pytest.raises(cs.SceneError, match=words):
            cs.Scene.from_accelerations([x(t), y(t)], [0, N - 1], [contact], **options)


def test_with_accelerations_the_tables_of_a_lagrangian_are_refused():
    with pytest.raises(SceneFileError, match=r"^a.toml:12: \[energy\] is for a Lagrangian"):
        read_scene(BASE + '[energy]\nkinetic = "x\'^2"\n', "a.toml")


# --- limits: files and scenes beyond a cap are refused at once, naming the cap --------------------------


def test_a_fifo_is_refused_without_waiting(tmp_path):
    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)

    def unblock():  # should the reader wait for a writer, this ends the wait, and the test fails instead of hanging
        time.sleep(5)
        with contextlib.suppress(OSError):  # no reader waiting (ENXIO): nothing to end
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))

    threading.Thread(target=unblock, daemon=True).start()
    with pytest.raises(SceneFileError, match=r"a pipe; a scene file must be a regular file"):
        load_scene(fifo)
    with pytest.raises(SceneFileError, match=r"a directory; a scene file must be a regular file"):
        load_scene(tmp_path)


def test_a_file_beyond_the_size_cap_is_refused_and_the_cap_can_be_raised(tmp_path):
    path = tmp_path / "big.toml"
    path.write_text(BASE + "# " + "x" * 2000 + "\n")
    with pytest.raises(SceneFileError, match=r"bytes, more than the cap of 1000 \(Limits.max_bytes\).*limits=Limits"):
        load_scene(path, limits=Limits(max_bytes=1000))
    assert load_scene(path, limits=Limits(max_bytes=3000)).k == 1
    path.write_bytes(b"\xff\xfe" + BASE.encode())
    with pytest.raises(SceneFileError, match="not UTF-8 text"):
        load_scene(path)


@pytest.mark.parametrize(
    "what, cap, edit",
    [
        ("coordinates", "max_coordinates", lambda n: BASE.replace('["x", "y"]', str([f"q{i}" for i in range(n)]))),
        ("contacts", "max_contacts", lambda n: BASE + '[[contacts]]\ngap = "x"\nreaction = "R"\n' * n),
        ("points", "max_points", lambda n: BASE + "[points]\n" + "".join(f'P{i} = ["x", "y"]\n' for i in range(n))),
        (
            "parameters, functions and intervals",
            "max_names",
            lambda n: BASE.replace("[parameters]\n", "[parameters]\n" + "".join(f'p{i} = "real"\n' for i in range(n))),
        ),
    ],
)
def test_a_scene_beyond_a_size_cap_is_refused_naming_the_cap(what, cap, edit):
    count = getattr(LIMITS, cap) + 3
    with pytest.raises(SceneFileError) as raised:
        read_scene(edit(count), "a.toml")
    message = str(raised.value)
    assert f"{what}, more than the cap of {getattr(LIMITS, cap)} (Limits.{cap})" in message
    assert f"limits=Limits({cap}=" in message and "\n" not in message


def test_a_larger_scene_is_read_once_its_cap_is_raised():
    text = BASE + '[[contacts]]\ngap = "x"\nreaction = "R"\n'
    with pytest.raises(SceneFileError, match="max_contacts"):
        read_spec(text, "a.toml", limits=Limits(max_contacts=1))
    assert len(read_spec(text, "a.toml", limits=Limits(max_contacts=2)).contacts) == 2


@pytest.mark.parametrize(
    "formula, cap",
    [
        ("N*(1+mu)^3000", "MAX_DEGREE"),
        ("(N+mu)^(10^9)", "MAX_DEGREE"),
        ("N - " + "*".join(["1e300"] * 30), "MAX_DIGITS"),
        ("N - exp(exp(exp(exp(10))))", "MAX_EXPONENT"),
    ],
)
def test_formula_bombs_in_a_file_are_refused_at_their_line(formula, cap):
    with pytest.raises(ParseError) as raised:
        read_scene(BASE.replace('y = "N - 1"', f'y = "{formula}"'), "a.toml")
    assert str(raised.value).startswith("a.toml:8:") and f"contactsym.parse.{cap}" in str(raised.value)


def test_numbers_written_as_toml_numbers_meet_the_same_caps():
    law = 'law = {name = "kelvin-voigt", stiffness = 1e300, damping = 1e-300}\n'
    assert read_scene(BASE + law, "a.toml").contacts[0].compliance.phi_psi(None, None, None)[0] == -(10**300)
    with pytest.raises(ParseError, match="MAX_EXPONENT"):
        read_scene(BASE + law.replace("1e-300", "5e-324"), "a.toml")


@pytest.mark.parametrize("value", [0, -1, 1.5, "10", True, None])
def test_a_cap_is_a_whole_number(value):
    with pytest.raises(cs.SceneError, match=r"Limits\(max_contacts=.*a cap is a whole number >= 1"):
        Limits(max_contacts=value)
    assert Limits(max_contacts=7).max_contacts == 7


@pytest.mark.parametrize("argument", [None, 3, ["brake"]])
def test_scene_or_file_refuses_what_is_neither_a_name_nor_a_path(argument):
    with pytest.raises(SceneFileError, match="give a scene's name or a scene file's path"):
        scene_or_file(argument)
