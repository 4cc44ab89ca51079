"""[figures] checked against the scene: axes, ranges, values; each refusal names file, line and fix."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.mechanism.files.figures import pipeline_names
from contactsym.mechanism.files.reader import read_scene, read_spec
from contactsym.mechanism.files.toml_source import SceneFileError
from contactsym.parse import ParseError

SCENE = """[scene]
coordinates = ["x", "y"]
[intervals]
x = [0, 2]
[parameters]
m = "positive"
mu = "positive"
alpha = [0, "pi"]
s = "sign"
c = "real"
d = "negative"
[functions]
X = ["x", "x'"]
[accelerations]
x = "X - c + d"
y = "N/m - 1"
[[contacts]]
gap = "y"
reaction = "N"
friction = {mu = "mu", direction = {x = "1"}}
[figures]
"""
FIGURES = """x = "alpha"
y = "mu"
x_range = [0.1, 3]
y_range = [0, 2]
values = { m = 1, c = 0.5, d = -1, s = 1, "x'" = 1, x = 1, X = 0, Phi = -1, Psi = -1 }
"""


def test_the_valid_plan_is_read_with_the_printed_names():
    plan = read_scene(SCENE + FIGURES, "f.toml").figure_plan
    assert (plan.x, plan.y, plan.x_range, plan.y_range) == ("alpha", "mu", (0.1, 3.0), (0.0, 2.0))
    assert plan.values == {"m": 1, "c": 0.5, "d": -1, "s": 1, "xdot": 1, "x": 1, "X": 0, "Phi": -1, "Psi": -1}


@pytest.mark.parametrize(
    "old, new, key, words",
    [
        ('x = "alpha"', 'x = "N"', "x", "'N' is a reaction, not an axis"),
        ('x = "alpha"', 'x = "x\'"', "x", "is a rate, not an axis"),
        ('x = "alpha"', 'x = "X"', "x", "is a load function, not an axis"),
        ('x = "alpha"', 'x = "s"', "x", "is a sign, not an axis"),
        ('x = "alpha"', 'x = "alpah"', "x", "did you mean 'alpha'?"),
        ('x = "alpha"', "x = 3", "x", "3 is not a parameter or coordinate"),
        ('y = "mu"', 'y = "alpha"', "y", "x and y are both alpha"),
        ("y_range = [0, 2]", "y_range = [-1, 2]", "y_range", "leaves the sign declared for mu (mu is positive)"),
        ("x_range = [0.1, 3]", "x_range = [0.1, 4]", "x_range", "leaves the interval (0, pi) declared for alpha"),
        ('x = "alpha"', 'x = "d"', "x_range", "leaves the sign declared for d (d is negative)"),
        ("x_range = [0.1, 3]", "x_range = [3, 0.1]", "x_range", "low < high"),
        ("x_range = [0.1, 3]", 'x_range = ["pi", "nope"]', "x_range", "unknown name 'nope'"),
        ("y_range = [0, 2]", "y_rnage = [0, 2]", "y_rnage", "did you mean 'y_range'?"),
        ("m = 1", "m = -1", "values", "m = -1 is not admissible: m is positive, so give m > 0"),
        ("d = -1", "d = 0", "values", "d is negative, so give d < 0"),
        ("s = 1", "s = 2", "values", "s is a sign symbol, so give s 1 or -1"),
        ("Phi = -1", "Phi = 1", "values", "Phi is a law's, so give Phi < 0"),
        ("x = 1", "x = 3", "values", "x = 3 is outside the interval (0, 2)"),
        ("m = 1", "mm = 1", "values", "'mm' is not a name of the scene; did you mean 'm'?"),
        ("m = 1", "N = 1", "values", "'N' is a reaction"),
        ("Phi = -1", "Phi_1 = -1", "values", "'Phi_1' is not a name of the scene"),
        ("m = 1", 'm = "1"', "values", "the value of m must be a finite number"),
        ("m = 1", "m = nan", "values", "the value of m must be a finite number"),
    ],
)
def test_a_bad_plan_is_refused_at_its_line_with_the_fix(old, new, key, words):
    figures = FIGURES.replace(old, new, 1)
    assert figures != FIGURES
    text = SCENE + figures
    with pytest.raises((SceneFileError, ParseError)) as raised:
        read_spec(text, "f.toml")
    message = str(raised.value)
    assert words in message and "\n" not in message, message
    line = next(i for i, row in enumerate(text.splitlines(), 1) if i > SCENE.count("\n") and row.startswith(key + " "))
    assert message.startswith(f"f.toml:{line}:"), (message, line)


def test_an_axis_may_be_a_coordinate_within_its_interval():
    figures = FIGURES.replace('x = "alpha"', 'x = "x"').replace("x_range = [0.1, 3]", "x_range = [0, 2]")
    assert read_spec(SCENE + figures, "f.toml").figures.x == "x"
    with pytest.raises(SceneFileError, match=r"leaves the interval \(0, 2\) declared for x"):
        read_spec(SCENE + figures.replace("x_range = [0, 2]", "x_range = [-1, 1]"), "f.toml")


@settings(max_examples=60, deadline=None)
@given(st.integers(-5, 5), st.integers(1, 5), st.integers(-7, 7), st.integers(1, 7))
def test_a_range_is_accepted_exactly_within_the_declared_interval(low, width, start, length):
    """For a parameter on (low, high): the range [start, start + length] is accepted iff it lies in [low, high]."""
    high = low + width
    text = (SCENE + FIGURES).replace('alpha = [0, "pi"]', f"alpha = [{low}, {high}]")
    text = text.replace("x_range = [0.1, 3]", f"x_range = [{start}, {start + length}]")
    inside = low <= start and start + length <= high
    if inside:
        assert read_spec(text, "f.toml").figures.x_range == (start, start + length)
    else:
        with pytest.raises(SceneFileError, match="leaves the interval"):
            read_spec(text, "f.toml")


def test_pipeline_names_follow_the_contacts_and_switching_functions():
    assert pipeline_names(1, 0) == {"Phi": "law", "Psi": "law"}
    assert set(pipeline_names(3, 2)) == {f"{n}_{j}" for n in ("Phi", "Psi") for j in (1, 2, 3)} | {"s", "s_1", "s_2"}


def test_the_example_plans_use_the_printed_names_and_match_the_built_in_plan():
    from pathlib import Path

    import contactsym as cs

    examples = Path(__file__).resolve().parents[3] / "examples"
    rod = read_spec((examples / "painleve-klein-rod.toml").read_text(), "rod.toml").figures
    assert (rod.x, rod.y) == ("mu_+", "mu_-") and {"X^*", "Y^*_1", "Y^*_2", "Phi", "Psi"} <= set(rod.values)
    tip = read_spec((examples / "double-pendulum-tip.toml").read_text(), "tip.toml").figures
    assert tip == cs.scene("double-pendulum-tip").figure_plan  # the built-in passes its plan to the constructor
