"""Friction at a point from Python: a unit direction, and a gap that is the distance of the point.

A rod pinned at O, its tip A = l (sin theta, -cos theta) dragged on a rough floor through A at the
angle a (direction (cos a, sin a), unit normal n = (-sin a, cos a)): the gap n . A + h is the
distance, and only a friction direction along the floor of length 1 with that gap is accepted.
"""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

import contactsym as cs
from contactsym.mechanism.friction_geometry import sample_points, unit_vector_problem, vanishes

theta = dynamicsymbols("theta")
m, l, g, h, mu = sp.symbols("m l g h mu", positive=True)
N = sp.Symbol("N", real=True)


def pinned(direction=None, scale=1, law=cs.Coulomb, floor=0):
    """The pinned rod on a floor at the angle ``floor``; ``direction`` defaults to (cos a, sin a)."""
    O = ReferenceFrame("O")
    rod = O.orientnew("B", "Axis", [theta, O.z])
    pivot = Point("O")
    pivot.set_vel(O, 0)
    G = pivot.locatenew("G", l / 2 * (sp.sin(theta) * O.x - sp.cos(theta) * O.y))
    G.v2pt_theory(pivot, O, rod)
    A = pivot.locatenew("A", l * (sp.sin(theta) * O.x - sp.cos(theta) * O.y))
    A.v2pt_theory(pivot, O, rod)
    body = RigidBody("rod", G, rod, m, (inertia(rod, 0, 0, m * l**2 / 12), G))
    body.potential_energy = m * g * G.pos_from(pivot).dot(O.y)
    normal = -sp.sin(floor) * O.x + sp.cos(floor) * O.y
    distance = A.pos_from(pivot).dot(normal) + h
    direction = sp.cos(floor) * O.x + sp.sin(floor) * O.y if direction is None else direction(O)
    contact = cs.Contact(coordinate=scale * distance, reaction=N, unilateral=True, friction=law(mu, direction, A))
    at = {h: -A.pos_from(pivot).dot(normal)}
    return cs.Scene.from_lagrangian(Lagrangian(O, body), [theta], [contact], frame=O, at=at)


def test_the_probe_s_rod_with_a_unit_direction_and_the_distance_is_accepted():
    scene = pinned()
    theta_ = sp.Symbol("theta", real=True)
    stable = scene.stability().robustly_stable
    values = {m: 1, mu: sp.Rational(1, 2)}
    assert stable.subs({**values, theta_: 1}) is sp.true  # mu cos(theta) < sin(theta)
    assert stable.subs({**values, theta_: sp.Rational(1, 3)}) is sp.false


def test_a_direction_of_length_2_is_refused():
    with pytest.raises(cs.SceneError, match=r"friction direction \[2, 0, 0\] of contact 1 is not a unit vector"):
        pinned(lambda O: 2 * O.x)


def test_a_direction_not_along_the_floor_is_refused():
    with pytest.raises(cs.SceneError, match=r"is not along its surface.*tangent"):
        pinned(lambda O: sp.cos(theta) * O.x + sp.sin(theta) * O.y)


def test_a_gap_twice_the_distance_is_refused_with_the_factor_and_the_fix():
    with pytest.raises(cs.SceneError) as error:
        pinned(scale=2)
    assert "grows 2 times as fast as the distance of A" in str(error.value)
    assert "divide it by 2" in str(error.value) and error.value.contact == 0 and error.value.key == "gap"


def sliding_point(direction, gap, law=cs.Coulomb):
    """A particle P = (x, y) on the floor y = 0 (two coordinates: the normal is fixed by the motion)."""
    x, y = dynamicsymbols("x y")
    O, origin = ReferenceFrame("O"), Point("o")
    P = origin.locatenew("P", x * O.x + y * O.y)
    P.set_vel(O, P.pos_from(origin).dt(O))
    contact = cs.Contact(coordinate=gap(y), reaction=N, friction=law(mu, direction(O), P))
    return cs.Scene.from_lagrangian(Lagrangian(O, Particle("p", P, m)) - m * g * y, [x, y], [contact], frame=O)


def test_viscous_friction_needs_a_tangent_direction_but_not_the_distance():
    assert pinned(scale=3, law=cs.Viscous).k == 1
    assert sliding_point(lambda O: -O.x, lambda y: 5 * y, cs.Viscous).k == 1
    with pytest.raises(cs.SceneError, match=r"friction direction \[0, 1\] of contact 1 is not along its surface"):
        sliding_point(lambda O: O.y, lambda y: y, cs.Viscous)
    with pytest.raises(cs.SceneError, match="not along its surface"):
        sliding_point(lambda O: (3 * O.x + 4 * O.y) / 5, lambda y: y)
    with pytest.raises(cs.SceneError, match="grows 5 times as fast"):
        sliding_point(lambda O: -O.x, lambda y: 5 * y)


floor_angles = st.integers(-6, 6).map(lambda k: sp.Rational(k, 5))


@settings(max_examples=8)
@given(floor_angles, st.sampled_from([1, -1]), st.sampled_from([1, -1]))
def test_unit_directions_along_a_random_floor_are_accepted(a, side, sense):
    """Either sense of sliding, either side of the floor (the gap's sign): each is the distance."""
    scene = pinned(lambda O: sense * (sp.cos(a) * O.x + sp.sin(a) * O.y), scale=side, floor=a)
    assert scene.k == 1


@settings(max_examples=8)
@given(floor_angles, st.sampled_from([2, 3, sp.Rational(1, 2), sp.Rational(7, 5), -2, -sp.Rational(1, 3)]))
def test_random_scale_factors_are_refused_and_named(a, scale):
    with pytest.raises(cs.SceneError) as error:
        pinned(scale=scale, floor=a)
    assert f"grows {abs(scale)} times as fast" in str(error.value)


@settings(max_examples=8)
@given(floor_angles, st.sampled_from([2, 3, sp.Rational(1, 2), sp.Rational(7, 5)]))
def test_random_lengths_of_a_direction_along_the_floor_are_refused(a, length):
    with pytest.raises(cs.SceneError, match="is not a unit vector"):
        pinned(lambda O: length * (sp.cos(a) * O.x + sp.sin(a) * O.y), floor=a)


def test_a_symbolic_floor_angle_with_a_tan_gap_is_refused_with_the_factor():
    """The probe's incline: the gap h - l cos(theta) - tan(a) l sin(theta) is the distance over cos(a)."""
    a = sp.Symbol("a", positive=True)
    with pytest.raises(cs.SceneError, match=r"grows 1/cos\(a\) times.*multiply it by cos\(a\)"):
        pinned(scale=1 / sp.cos(a), floor=a)  # a > 0 of either sign of cos(a): the factor up to sign


def test_identities_are_decided_exactly_or_at_random_points_of_the_domain():
    a, x = sp.Symbol("a", real=True), sp.Symbol("x", positive=True)
    assert vanishes(sp.tan(a) * sp.cos(a) - sp.sin(a)) and vanishes(sp.sqrt(x**2) - x)
    assert not vanishes(sp.sqrt(x**2) + x) and not vanishes(sp.cos(a) - 1)
    assert vanishes(sp.Abs(sp.sin(a)) - sp.sin(a), positive=[sp.sin(a)])  # zero on the declared domain only
    points = sample_points([a], positive=[sp.sin(a), sp.cos(a)], count=4)
    assert len(points) == 4 and all(0 < p[a] < sp.pi / 2 for p in points)
    assert unit_vector_problem([sp.cos(a) ** 2, sp.sin(a)]) is not None
    assert unit_vector_problem([sp.cos(a), sp.sin(a), 0]) is None
