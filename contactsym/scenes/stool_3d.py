"""Beyond the paper: a three-legged stool sliding on a rough floor (k = 3), a rigid body in space.

The stool (mass 1, principal inertias 2/5, 1/2, 7/10 about its centre of mass G) turns with
the body-fixed yaw psi, pitch theta and roll phi (``zyx``) from the floor's frame O. Its feet
are at (1, 0), (-1/2, 1) and (-1/2, -1) in its own frame, at the depth h below G, and G sits
above the point (3/20, -1/10) of that frame. Standing level (theta = phi = psi = 0), it slides
in the direction (3/5, 4/5) of the floor, so Coulomb friction mu ``|N_j|`` at each foot opposes
that direction; gravity acts at G. The feet are held to the floor (N_j of either sign).
The robustness of each equilibrium to the law is classified for numbers by
:func:`contactsym.robustness.classify.decide_robustness` (certificates or witness laws).

The same scene is ``examples/stool-3d.toml`` (built by the scene-file reader).
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..mechanism.files.reader import FigurePlan
from ..mechanism.scene import Contact, Scene

#: The feet in the stool's frame, and the point below the centre of mass.
FEET = ((1, 0), (sp.Rational(-1, 2), 1), (sp.Rational(-1, 2), -1))
CENTRE = (sp.Rational(3, 20), sp.Rational(-1, 10))
#: The principal inertias about the centre of mass, the sliding direction on the floor.
INERTIA = (sp.Rational(2, 5), sp.Rational(1, 2), sp.Rational(7, 10))
SLIDING = (sp.Rational(3, 5), sp.Rational(4, 5))
GRAVITY = sp.Rational(981, 100)

#: The report's region maps: friction against the height of the centre of mass, every foot sliding forward (s_j = 1).
PLAN = FigurePlan("mu", "h", (0.0, 2.0), (0.1, 2.0), {"mu": 0.5, "h": 0.75, "s_1": 1, "s_2": 1, "s_3": 1})


#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "a three-legged stool sliding on a rough floor"


def build() -> Scene:
    """The stool (see the module's documentation).

    Examples
    --------
    Without friction A is the Delassus matrix W^T M^-1 W, symmetric:

    >>> A = build().linearization(signs=(1, 1, 1)).A
    >>> A.shape, A.subs(sp.Symbol("mu", positive=True), 0)
    ((3, 3), Matrix([
    [247/100,  17/100, -33/100],
    [ 17/100, 487/100, -63/100],
    [-33/100, -63/100, 387/100]]))
    """
    x, y, z, psi, theta, phi = dynamicsymbols("x y z psi theta phi")
    mu, h = sp.symbols("mu h", positive=True)
    O, origin = ReferenceFrame("O"), Point("O")
    origin.set_vel(O, 0)
    stool = ReferenceFrame("stool")
    stool.orient_body_fixed(O, (psi, theta, phi), "zyx")
    centre = origin.locatenew("G", x * O.x + y * O.y + z * O.z)
    centre.set_vel(O, centre.pos_from(origin).dt(O))
    sliding = SLIDING[0] * O.x + SLIDING[1] * O.y
    contacts = []
    for j, (a, b) in enumerate(FEET, 1):
        foot = centre.locatenew(f"P{j}", (a - CENTRE[0]) * stool.x + (b - CENTRE[1]) * stool.y - h * stool.z)
        foot.v2pt_theory(centre, O, stool)
        height = sp.expand(foot.pos_from(origin).dot(O.z))
        N = sp.Symbol(f"N_{j}", real=True)
        contacts.append(Contact(coordinate=height, reaction=N, friction=Coulomb(mu, sliding, foot)))
    body = RigidBody("stool", centre, stool, 1, (inertia(stool, *INERTIA), centre))
    return Scene.from_lagrangian(
        Lagrangian(O, body),
        [x, y, z, psi, theta, phi],
        contacts,
        loads=[(centre, -GRAVITY * O.z)],
        frame=O,
        at={theta: 0, phi: 0, psi: 0},  # standing level
        name="stool-3d",
        figure_plan=PLAN,
        description=DESCRIPTION,
    )
