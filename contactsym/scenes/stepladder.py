"""Beyond the paper: a stepladder, four coordinates and three rough contacts (k = 3).

A rigid body (mass m, moment of inertia J, centre (x, y), tilt theta) stands on two feet at
body points (-a, -b) and (a, -b) on a rough floor; an arm hinged at the body point (c, 0),
length L, angle psi from the downward vertical, carries a point mass m_2 at its tip, which
leans on a rough vertical wall. Coulomb friction mu_1, mu_2 at the feet (sliding in +x) and
mu_3 at the wall (sliding in +y). The body stands level at contact (theta = 0).
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..mechanism.scene import Contact, Scene
from ._planar import planar_body


def build() -> Scene:
    x, y, theta, psi = dynamicsymbols("x y theta psi")
    m, m2, J, a, b, c, L, g, w = sp.symbols("m m_2 J a b c L g w", positive=True)
    mus = sp.symbols("mu_1:4", positive=True)
    N = sp.symbols("N_1:4", real=True)
    O, frame, centre = planar_body(x, y, theta)
    contacts = []
    for j, side in enumerate((-a, a)):
        foot = centre.locatenew(f"F{j + 1}", side * frame.x - b * frame.y)
        foot.v2pt_theory(centre, O, frame)
        height = foot.pos_from(centre).dot(O.y) + y
        contacts.append(Contact(coordinate=height, reaction=N[j], friction=Coulomb(mus[j], O.x, foot)))
    hinge = centre.locatenew("H", c * frame.x)
    hinge.v2pt_theory(centre, O, frame)
    tip = hinge.locatenew("T", L * (sp.sin(psi) * O.x - sp.cos(psi) * O.y))
    tip.set_vel(O, hinge.vel(O) + L * psi.diff() * (sp.cos(psi) * O.x + sp.sin(psi) * O.y))
    reach = tip.pos_from(centre).dot(O.x) + x
    contacts.append(Contact(coordinate=w - reach, reaction=N[2], friction=Coulomb(mus[2], O.y, tip)))
    body = RigidBody("body", centre, frame, m, (inertia(frame, 0, 0, J), centre))
    body.potential_energy = m * g * y
    arm = Particle("arm", tip, m2)
    arm.potential_energy = m2 * g * (y + tip.pos_from(centre).dot(O.y))
    return Scene.from_lagrangian(
        Lagrangian(O, body, arm),
        [x, y, theta, psi],
        contacts,
        frame=O,
        at={theta: 0},
        name="stepladder",
        description="a body on two feet with an arm leaning on a wall: 4 coordinates, 3 contacts",
    )
