"""A planar block on two legs sliding on a rough floor (k = 2).

The block (mass m, moment of inertia J about its centre) stands on legs at the body
points (-a, -b) and (a, -b) and slides to the right on the floor y = 0, so Coulomb
friction mu_j ``|N_j|`` acts along -x at leg j. The gaps are the heights of the leg tips;
rigid contact holds the block level (theta = 0) at height b. Loads: a vertical force Y
at the centre (weight included) and a moment M.

The built-in ``two-leg-block`` is ``build(unilateral=False)``: bilateral legs (N_j of
either sign, as the orthant counts of the paper's §5 assume). ``build(unilateral=True)``
makes the legs push only, so a leg can lift off (named ``two-leg-block-unilateral``).
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
DESCRIPTION = "a block on two legs sliding on a rough floor"


def build(unilateral: bool = False) -> Scene:
    x, y, theta = dynamicsymbols("x y theta")
    m, J, a, b = sp.symbols("m J a b", positive=True)
    mu1, mu2 = sp.symbols("mu_1 mu_2", positive=True)
    X, Y, M = sp.symbols("X Y M", real=True)
    N1, N2 = sp.symbols("N_1 N_2", real=True)
    O, block, centre = planar_body(x, y, theta)
    contacts = []
    for j, (side, N, mu) in enumerate(((-1, N1, mu1), (1, N2, mu2)), 1):
        leg = centre.locatenew(f"P_{j}", side * a * block.x - b * block.y)
        leg.v2pt_theory(centre, O, block)
        height = leg.pos_from(centre).dot(O.y) + y
        contacts.append(Contact(coordinate=height, reaction=N, friction=Coulomb(mu, O.x, leg), unilateral=unilateral))
    body = RigidBody("block", centre, block, m, (inertia(block, 0, 0, J), centre))
    scene = Scene.from_lagrangian(
        lagrangian_of(O, body),
        [x, y, theta],
        contacts,
        loads=[(centre, X * O.x + Y * O.y), (block, M * O.z)],
        frame=O,
        at={sp.Symbol("theta", real=True): 0},
        name="two-leg-block-unilateral" if unilateral else "two-leg-block",
        description="a block on two legs sliding on a rough floor" + (", legs that can lift off" if unilateral else ""),
    )
    return scene


#: A point of the region 2a < b(mu_1 + mu_2), |b(mu_1 - mu_2)| < 2a: one orthant determinant is
#: negative, yet the degree is 0, so the loads give two equilibria or none.
POINT = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)
_CAPTION = (
    r"Number of equilibria over the loads $(Y, M)$ at $m = 1.838$, $J = 0.5558$, $a = 0.6912$, $b = 0.5569$, "
    r"$\mu = (1.5555, 1.3973)$."
)


def figures(scene, directory, *, resolution: int = 400, dpi: int = 150) -> list:
    """The map of the number of equilibria (lift-off included) over two parameters."""
    return [(_count_figure(scene, directory), _CAPTION)]


def _count_figure(scene, directory):
    return count_map_figure(scene, directory / "block_counts.png", "Y", "M", (-30, 30), (-10, 10), **POINT)
