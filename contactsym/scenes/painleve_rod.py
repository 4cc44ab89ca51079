"""The classical Painlevé rod: a uniform rod with one end sliding on a rough floor (k = 1).

The rod (mass m, length 2 l, moment of inertia m l^2/3 about its centre) makes the
angle theta with the floor y = 0, 0 < theta < pi/2; its lower end is at the centre minus
l (cos theta, sin theta) and slides to the left, away from under the centre, so Coulomb
friction mu ``|N|`` pushes it to the right. Gravity g acts at the centre. The gap is the
height of the end.

``build(unilateral=True)`` is the one-sided rod of the literature (the floor only
pushes, the end may lift off): the built-in ``painleve-rod``. ``build(unilateral=False)``
holds the end to the floor (N of either sign), named ``painleve-rod-bilateral``.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian as lagrangian_of
from sympy.physics.mechanics import RigidBody, dynamicsymbols, inertia

from ..laws import Coulomb
from ..mechanism.scene import Contact, Scene
from ..plotting.counts import count_map_figure
from ._planar import planar_body

#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "classical Painleve rod, one end sliding on a rough floor (one-sided: the end may lift off)"


def build(unilateral: bool = True) -> Scene:
    x, y, theta = dynamicsymbols("x y theta")
    m, l, g, mu = sp.symbols("m l g mu", positive=True)
    N = sp.Symbol("N", real=True)
    O, rod, centre = planar_body(x, y, theta)
    end = centre.locatenew("P", -l * rod.x)
    end.v2pt_theory(centre, O, rod)
    height = end.pos_from(centre).dot(O.y) + y
    contact = Contact(coordinate=height, reaction=N, friction=Coulomb(mu, -O.x, end), unilateral=unilateral)
    body = RigidBody("rod", centre, rod, m, (inertia(rod, 0, 0, m * l**2 / 3), centre))
    theta_ = sp.Symbol("theta", real=True)
    scene = Scene.from_lagrangian(
        lagrangian_of(O, body),
        [x, y, theta],
        [contact],
        loads=[(centre, -m * g * O.y)],
        frame=O,
        name="painleve-rod" if unilateral else "painleve-rod-bilateral",
        positive=(sp.sin(theta_), sp.cos(theta_)),  # 0 < theta < pi/2
        solve_for=mu,
        description="classical Painleve rod, one end sliding on a rough floor"
        + (" (one-sided: the end may lift off)" if unilateral else " (end held to the floor)"),
    )
    return scene


_CAPTION = (
    r"Number of equilibria, lift-off included, over $(\mu, \dot\theta)$ at $\tan\theta = 2$, $m = l = 1$, $g = 9.81$."
)


def figures(scene, directory, *, resolution: int = 400, dpi: int = 150) -> list:
    """The map of the number of equilibria (lift-off included) over two parameters."""
    return [(_count_figure(scene, directory), _CAPTION)]


def _count_figure(scene, directory):
    fixed = dict(m=1.0, l=1.0, g=9.81, theta=float(sp.atan(2)))
    return count_map_figure(scene, directory / "rod_counts.png", "mu", "thetadot", (0, 3), (0, 5), **fixed)
