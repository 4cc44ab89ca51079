"""The table of laws a file may name: its entries, a new entry, and a law's true/false flags; friction at
a point in the plane: a unit direction along the surface, and a gap that is the distance of the point."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym.mechanism.files.contacts import COMPLIANCE_LAWS, LawKind
from contactsym.mechanism.files.reader import read_scene
from contactsym.mechanism.files.toml_source import SceneFileError

BASE = """[scene]
coordinates = ["y"]
[parameters]
k = "positive"
[accelerations]
y = "N - 1"
[[contacts]]
gap = "y"
reaction = "N"
"""


def test_a_new_law_in_the_table_is_available_to_files(monkeypatch):
    monkeypatch.setitem(
        COMPLIANCE_LAWS,
        "stiff",
        LawKind(lambda formulas, flags, eps: cs.KelvinVoigt(formulas["k"], formulas["k"]), {"k": None}),
    )
    scene = read_scene(BASE + 'law = {name = "stiff", k = "2*k"}\n', "a.toml")
    k = sp.Symbol("k", positive=True)
    assert scene.contacts[0].compliance.phi_psi(None, None, None) == (-2 * k, -2 * k)
    with pytest.raises(SceneFileError, match=r"^a.toml:10: \[contacts.0.law\] needs 'k'"):
        read_scene(BASE + 'law = {name = "stiff"}\n', "a.toml")


def test_a_flag_of_a_law_is_true_or_false():
    law = 'law = {name = "law", N = "-k*q/eps^2 - q\'/eps", check = %s}\n'
    assert read_scene(BASE + law % "false", "a.toml").k == 1
    with pytest.raises(SceneFileError, match=r"^a.toml:10: check must be true or false, not 'no'"):
        read_scene(BASE + law % '"no"', "a.toml")


def test_friction_and_law_errors_are_placed_at_their_keys():
    text = BASE.replace('["y"]', '["x", "y"]').replace('y = "N - 1"', 'x = "0"\ny = "N - 1"')
    with pytest.raises(SceneFileError, match=r"^a.toml:11: direction names \['k'\] must be coordinates"):
        read_scene(text + 'friction = {mu = "k", direction = {k = "1"}}\n', "a.toml")
    assert read_scene(text + 'friction = {mu = "k", direction = {x = "1"}}\n', "a.toml").k == 1


# --- friction at a point in the plane: a unit direction along the surface, a gap that is the distance

PINNED = """[scene]
coordinates = ["theta"]
[intervals]
theta = [0, "pi/2"]
[parameters]
m = "positive"
l = "positive"
g = "positive"
h = "positive"
mu = "positive"
a = [0, "pi/4"]
[points]
G = ["l/2*sin(theta)", "-l/2*cos(theta)"]
A = ["l*sin(theta)", "-l*cos(theta)"]
[[bodies]]
point = "G"
angle = "theta"
mass = "m"
inertia = "m*l^2/12"
[energy]
potential = "m*g*(-l/2*cos(theta))"
[[contacts]]
gap = "GAP"
reaction = "N"
unilateral = true
friction = { mu = "mu", point = "A", direction = DIRECTION }
[at]
h = "AT"
"""  # a rod pinned at O, its tip A dragged on a floor through A at an angle (line 23: the gap, 26: friction)


def pinned(direction='["1", "0"]', gap="h - l*cos(theta)", at="l*cos(theta)", floor="0"):
    text = PINNED.replace("DIRECTION", direction).replace("GAP", gap).replace("AT", at)
    return read_scene(text.replace("FLOOR", floor), "rod.toml")


def floor_gap(floor: str, scale: str = "1") -> tuple[str, str]:
    """The distance of A above the floor through (0, -h) at the angle ``floor``, times ``scale``, and h there."""
    distance = f"({scale})*(cos({floor})*(h - l*cos(theta)) - sin({floor})*l*sin(theta))"
    return distance, f"l*cos(theta) + l*sin(theta)*sin({floor})/cos({floor})"


@pytest.mark.parametrize(
    "direction, message",
    [
        ('["2", "0"]', r"rod.toml:26: the friction direction \[2, 0\] is not a unit vector \(its length is 2\)"),
        (
            '["1", "1"]',
            r"rod.toml:26: the friction direction \[1, 1\] is not a unit vector \(its length is sqrt\(2\)\)",
        ),
        ('["cos(theta)", "sin(theta)"]', r"rod.toml:26: the friction direction .* is not along its surface"),
    ],
)
def test_a_direction_that_is_not_a_unit_vector_along_the_floor_is_refused_at_its_key(direction, message):
    with pytest.raises(SceneFileError, match=message):
        pinned(direction)


def test_a_gap_that_is_not_the_distance_is_refused_at_its_key_with_the_factor():
    with pytest.raises(SceneFileError, match=r"rod.toml:23: the gap .* grows 2 times as fast .* divide it by 2\.$"):
        pinned(gap="2*h - 2*l*cos(theta)")
    incline = "h - l*cos(theta) - tan(a)*l*sin(theta)"  # the probe's incline: the distance over cos(a)
    direction, at = '["cos(a)", "sin(a)"]', "l*cos(theta) + tan(a)*l*sin(theta)"
    with pytest.raises(SceneFileError, match=r"grows 1/cos\(a\) times as fast.* multiply it by cos\(a\)"):
        pinned(direction, incline, at)
    assert pinned(direction, *floor_gap("a")).k == 1


def test_a_frictionless_contact_may_scale_its_gap():
    text = (
        PINNED.replace("DIRECTION", '["1", "0"]').replace("GAP", "2*h - 2*l*cos(theta)").replace("AT", "l*cos(theta)")
    )
    assert read_scene(text.replace('friction = { mu = "mu", point = "A", direction = ["1", "0"] }\n', ""), "a").k == 1


def test_the_file_and_the_python_api_agree_on_the_pinned_rod():
    from tests.mechanism.test_friction_geometry import pinned as by_hand  # noqa: PLC0415  (the same rod in Python)

    assert pinned().stability().robustly_stable == by_hand().stability().robustly_stable


floor_angles = st.integers(-6, 6).map(lambda k: f"{k}/10")


@settings(max_examples=8)
@given(floor_angles, st.sampled_from(["1", "-1"]), st.sampled_from(["", "-"]))
def test_unit_directions_along_a_random_floor_are_accepted(floor, side, sense):
    direction = f'["{sense}cos({floor})", "{sense}sin({floor})"]'
    assert pinned(direction, *floor_gap(floor, side)).k == 1


@settings(max_examples=8)
@given(floor_angles, st.sampled_from(["2", "3", "1/2", "7/5", "-2", "-1/3"]))
def test_random_scale_factors_of_the_distance_are_refused(floor, scale):
    factor = str(abs(sp.Rational(scale)))
    with pytest.raises(SceneFileError, match=rf"rod.toml:23: the gap .* grows {factor} times as fast"):
        pinned(f'["cos({floor})", "sin({floor})"]', *floor_gap(floor, scale))


@settings(max_examples=8)
@given(floor_angles, st.sampled_from(["2", "3", "1/2", "7/5"]))
def test_random_lengths_of_a_direction_along_the_floor_are_refused(floor, length):
    with pytest.raises(SceneFileError, match=r"rod.toml:26: the friction direction .* is not a unit vector"):
        pinned(f'["{length}*cos({floor})", "{length}*sin({floor})"]', *floor_gap(floor))
