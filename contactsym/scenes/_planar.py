"""A rigid body moving in a plane, shared by the Lagrangian scenes."""

from __future__ import annotations

from sympy.physics.mechanics import Point, ReferenceFrame


def planar_body(x, y, angle, frame_name: str = "B"):
    """Inertial frame O, body frame turned by ``angle``, and the centre at (x, y).

    Returns ``(O, body, centre)``; the centre's velocity in O is set.
    """
    O = ReferenceFrame("O")
    body = O.orientnew(frame_name, "Axis", [angle, O.z])
    origin = Point("O")
    origin.set_vel(O, 0)
    centre = origin.locatenew("C", x * O.x + y * O.y)
    centre.set_vel(O, centre.pos_from(origin).dt(O))
    return O, body, centre
