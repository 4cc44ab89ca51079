"""§6, (6.1)-(6.4), Fig. 2: a rotating disc braked by two identical pads.

The pads' inward normals n1, n2 make n1 . n2 = -cos(alpha) (pads at angle alpha to
each other). The disc turns clockwise, so at pad j its surface slides along z x n_j
and Coulomb friction mu |N_j| opposes that. The gaps q_j = n_j . r are minus the pad
deformations; external forces press the disc on the pads, so the contacts are
unilateral with N_j > 0.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..scene import Contact, Scene
from ._planar import planar_body

#: The paper's numbers of this example, by formula key (see :func:`contactsym.scenes.paper_knowledge`).
EQUATIONS = {
    "contact accelerations": (("6.1",), ""),
    "A": (("6.2",), ""),
    "stable for every law": (("6.3",), "with equality allowed: erratum 12"),
    "Hopf line": ((), "for Phi_j = Phi, Psi_j = Psi, alpha = 90 deg it is (6.4), with the mass: erratum 13"),
    "hopf frequency": ((), "the frequency after (6.4), with the mass: erratum 14"),
}


def build() -> Scene:
    x, y, theta = dynamicsymbols("x y theta")
    m, J, r, mu, alpha = sp.symbols("m J r mu alpha", positive=True)
    Fx, Fy = sp.symbols("F_x F_y", real=True)
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    O, disc, centre = planar_body(x, y, theta, "D")
    normals = [O.y, -sp.sin(alpha) * O.x - sp.cos(alpha) * O.y]  # n1 . n2 = -cos(alpha)
    contacts = []
    for j, (n, N) in enumerate(zip(normals, (N1, N2)), 1):
        spot = centre.locatenew(f"P_{j}", -r * n)
        spot.v2pt_theory(centre, O, disc)
        sliding = O.z.cross(n)  # surface velocity direction for a clockwise disc
        gap = n.dot(x * O.x + y * O.y)
        contacts.append(Contact(coordinate=gap, reaction=N, friction=Coulomb(mu, sliding, spot), unilateral=True))
    body = RigidBody("disc", centre, disc, m, (inertia(disc, 0, 0, J), centre))
    F1, F2 = sp.symbols("F_1 F_2", real=True)
    presentation = {Fy: F1, Fx: -(F2 + sp.cos(alpha) * F1) / sp.sin(alpha)}  # F_j = n_j . F
    return Scene.from_lagrangian(
        lagrangian_of(O, body),
        [x, y, theta],
        contacts,
        loads=[(centre, Fx * O.x + Fy * O.y)],
        frame=O,
        name="brake",
        equations=EQUATIONS,
        presentation=presentation,
        positive=(sp.sin(alpha),),  # 0 < alpha < pi
        solve_for=mu,
        description="(6.1)-(6.4): disc braked by two pads at angle alpha",
    )
