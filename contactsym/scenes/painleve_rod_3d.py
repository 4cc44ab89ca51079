"""Beyond the paper: Painlevé's rod in space, its lower end sliding at an angle to the rod's vertical plane (k = 1).

A uniform rod (mass m, length 2 l) with its centre at (x, y, z) turns with the body-fixed
yaw psi, pitch theta and roll phi (``zyx``) from the floor's frame O; the rod lies along the
turned x axis, so theta (0 < theta < pi/2) is its inclination to the floor z = 0 and psi
the direction of its vertical plane. Its inertia about the centre is m l^2/3 across the rod and
J about its own axis. The lower end A, the centre plus l along the rod, slides on the rough
floor in the horizontal direction at the angle beta (0 < beta < pi/2) to the rod's vertical
plane; Coulomb friction mu ``|N|`` opposes it. Gravity g acts at the centre; the floor only
pushes (the end may lift off). This is the setting of Zhao, Liu and Chen's study of the
Painlevé paradox for a slender rod in space: the pipeline derives the critical friction as
a function of the inclination theta and the sliding direction beta; in the rod's plane
(beta = 0) it is the planar rod's, least (4/3) at tan(theta) = 2.

The same scene is ``examples/painleve-rod-3d.toml`` (built by the scene-file reader).
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..mechanism.files.reader import FigurePlan
from ..mechanism.scene import Contact, Scene

#: The report's region map: inclination against friction at beta = 0.5, J = 0.01.
PLAN = FigurePlan(
    "theta",
    "mu",
    (0.05, 1.5),
    (0.0, 4.0),
    {
        "m": 1,
        "l": 1,
        "J": 0.01,
        "g": 9.81,
        "beta": 0.5,
        "thetadot": 1,
        "psidot": 0,
        "phidot": 0,
        "theta": 0.5,
        "mu": 0.5,
    },
)


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "Painleve rod in space: one end sliding on a rough floor at an angle beta to the rod's vertical plane"


def build() -> Scene:
    """The rod in space (see the module's documentation).

    Examples
    --------
    >>> build().linearization().A
    Matrix([[-3*mu*sin(theta)*cos(beta)*cos(theta)/m - 3*sin(theta)**2/m + 4/m]])
    """
    x, y, z, psi, theta, phi = dynamicsymbols("x y z psi theta phi")
    m, l, J, g, mu = sp.symbols("m l J g mu", positive=True)
    beta = sp.Symbol("beta", positive=True)  # an interval (0, pi/2) in the file: a positive real symbol
    N = sp.Symbol("N", real=True)
    O, origin = ReferenceFrame("O"), Point("O")
    origin.set_vel(O, 0)
    rod = ReferenceFrame("rod")
    rod.orient_body_fixed(O, (psi, theta, phi), "zyx")
    centre = origin.locatenew("C", x * O.x + y * O.y + z * O.z)
    centre.set_vel(O, centre.pos_from(origin).dt(O))
    end = centre.locatenew("A", l * rod.x)
    end.v2pt_theory(centre, O, rod)
    height = sp.expand(end.pos_from(origin).dot(O.z))
    sliding = sp.cos(psi + beta) * O.x + sp.sin(psi + beta) * O.y
    contact = Contact(coordinate=height, reaction=N, friction=Coulomb(mu, sliding, end), unilateral=True)
    body = RigidBody("rod", centre, rod, m, (inertia(rod, J, m * l**2 / 3, m * l**2 / 3), centre))
    plain = {q: sp.Symbol(str(q.func), real=True) for q in (theta,)}
    return Scene.from_lagrangian(
        Lagrangian(O, body),
        [x, y, z, psi, theta, phi],
        [contact],
        loads=[(centre, -m * g * O.z)],
        frame=O,
        name="painleve-rod-3d",
        # 0 < beta < pi/2 and 0 < theta < pi/2, in the order a scene file lists them
        positive=(sp.sin(beta), sp.cos(beta), sp.sin(plain[theta]), sp.cos(plain[theta])),
        solve_for=mu,
        figure_plan=PLAN,
        description=DESCRIPTION,
    )
