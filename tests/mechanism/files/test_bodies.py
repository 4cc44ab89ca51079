"""Points of a body in the plane: the velocities of material points, derived by Plane, checked by hand;
a position that does not move with its body (the probe's ladder, theta clockwise) refused with the fix."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

from contactsym.mechanism.files.bodies import Plane, turning_problem
from contactsym.mechanism.files.reader import read_scene
from contactsym.mechanism.files.spec import PointSpec
from contactsym.mechanism.files.toml_source import SceneFileError

x, y, theta = dynamicsymbols("x y theta")
t = sp.Symbol("t")


@settings(max_examples=20, deadline=None)
@given(st.integers(-4, 4), st.integers(-4, 4))
def test_a_material_point_moves_with_its_body(a, b):
    """P = C + (a, b) now, on the body turning with theta: v_P = v_C + theta' z x (a, b)."""
    plane = Plane((PointSpec("C", (x, y), None, None, 1), PointSpec("P", (x + a, y + b), "C", theta, 2)))
    velocity = plane.points["P"].vel(plane.frame)
    by_hand = (x.diff(t) - b * theta.diff(t), y.diff(t) + a * theta.diff(t))
    components = (velocity.dot(plane.frame.x), velocity.dot(plane.frame.y))
    assert all(sp.expand(c - h) == 0 for c, h in zip(components, by_hand))


def test_a_point_of_the_plane_moves_with_its_position_and_one_frame_per_angle():
    plane = Plane((PointSpec("Q", (x * sp.cos(theta), y), None, None, 1),))
    assert plane.points["Q"].vel(plane.frame).dot(plane.frame.x) == (x * sp.cos(theta)).diff(t)
    assert plane.turning(theta) is plane.turning(theta) and plane.turning(2 * theta).name == "B2"


# --- a material point's position must move with its body, turning counter-clockwise by its angle

LADDER = """[scene]
coordinates = ["x", "y", "theta"]
[intervals]
theta = [0, "pi/2"]
[parameters]
m = "positive"
l = "positive"
g = "positive"
mu_1 = "positive"
mu_2 = "positive"
[points]
G = ["x", "y"]
A = POINT_A
B = POINT_B
[[bodies]]
point = "G"
angle = "theta"
mass = "m"
inertia = "m*l^2/3"
[energy]
potential = "m*g*y"
[[contacts]]
gap = "y - l*sin(theta)"
reaction = "N_1"
unilateral = true
friction = { mu = "mu_1", point = "A", direction = ["1", "0"] }
[[contacts]]
gap = "x - l*cos(theta)"
reaction = "N_2"
unilateral = true
friction = { mu = "mu_2", point = "B", direction = ["0", "-1"] }
"""  # the probe's ladder between a rough floor and a rough wall, theta measured clockwise (line 13: A)


def ladder(angle: str | None):
    positions = ('"x + l*cos(theta)", "y - l*sin(theta)"', '"x - l*cos(theta)", "y + l*sin(theta)"')
    if angle is None:
        a, b = (f"[{p}]" for p in positions)
    else:
        a, b = (f'{{ position = [{p}], body = "G", angle = "{angle}" }}' for p in positions)
    return read_scene(LADDER.replace("POINT_A", a).replace("POINT_B", b), "ladder.toml")


def test_a_point_turning_the_other_way_is_refused_with_the_fix():
    with pytest.raises(SceneFileError) as error:
        ladder("theta")
    message = str(error.value)
    assert message.startswith("ladder.toml:13: the rate of the position of A is not the velocity of the body turning")
    assert 'write angle = "-theta"' in message and "plain position [x, y]" in message


def test_the_point_turning_with_minus_theta_is_the_plain_point():
    """The friction's generalized directions (what the probe's wrong A changed) agree with plain positions."""
    turning, plain = ladder("-theta").contact_space.friction, ladder(None).contact_space.friction
    assert all(sp.simplify(a[0] - b[0]) == sp.zeros(3, 1) for a, b in zip(turning, plain))
    assert turning[0][0][2] == -sp.Symbol("l", positive=True) * sp.sin(theta)  # d(A_x)/d(theta)


def test_a_spot_at_a_fixed_offset_is_a_material_point_passing_through_it():
    """The brake's pads: the disc's material point at the pad, whose position does not turn."""
    r = sp.Symbol("r", positive=True)
    assert turning_problem("P", (x, y - r), (x, y), theta) is None
    problem = turning_problem("P", (x + r * sp.cos(2 * theta), y), (x, y), theta, "C")
    assert "its offset from C moves, but not as a point fixed in that body" in problem and "-theta" not in problem


@settings(max_examples=20, deadline=None)
@given(st.integers(-4, 4), st.integers(-4, 4), st.sampled_from([1, -1]))
def test_random_points_of_a_body_are_accepted_turning_counter_clockwise_only(a, b, sense):
    """P = C + R(sense theta) (a, b): a point of the body turning by sense * theta, counter-clockwise."""
    c, s = sp.cos(sense * theta), sp.sin(sense * theta)
    position = (x + a * c - b * s, y + a * s + b * c)
    assert turning_problem("P", position, (x, y), sense * theta) is None
    problem = turning_problem("P", position, (x, y), -sense * theta)
    assert (problem is None) == (a == b == 0)
    fix = 'write angle = "theta"' if sense == 1 else 'write angle = "-theta"'  # minus the angle given
    assert problem is None or fix in problem
