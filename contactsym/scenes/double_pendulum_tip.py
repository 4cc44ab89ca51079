"""Beyond the paper: a two-link arm whose tip slides on a rough floor (k = 1).

The pinned double pendulum of :func:`contactsym.scenes.link_chain.build_chain` with n = 2:
links l1, l2 at angles q1, q2 from the downward vertical, point masses m1, m2 at the joint and
the tip, Coulomb friction mu ``|N|`` at the tip.
"""

from __future__ import annotations

from ..mechanism.files.reader import FigurePlan
from ..mechanism.scene import Scene
from .link_chain import build_chain

#: What ``contactsym list`` prints for the built-in scene (read without building it).
DESCRIPTION = "a 2-link chain whose tip slides on a rough floor"


def build() -> Scene:
    # the report's region map: the arm's angles at equal masses, mu = 0.8, the tip pressed (s = sign N = 1)
    plan = FigurePlan("q1", "q2", (-1.5, 1.5), (-1.5, 1.5), {"m1": 1, "m2": 1, "mu": 0.8, "s": 1})
    return build_chain(2, name="double-pendulum-tip", figure_plan=plan)
