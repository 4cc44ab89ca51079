"""Points of a body in the plane: the velocities of material points, derived by Plane, checked by hand."""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

from contactsym.mechanism.files.bodies import Plane
from contactsym.mechanism.files.spec import PointSpec

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
