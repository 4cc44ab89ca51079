"""Beyond the paper: a two-link arm whose tip slides on a rough floor (k = 1).

The pinned double pendulum of :func:`contactsym.scenes.link_chain.build_chain` with n = 2:
links l1, l2 at angles q1, q2 from the downward vertical, point masses m1, m2 at the joint and
the tip, Coulomb friction mu |N| at the tip.
"""

from __future__ import annotations

from ..scene import Scene
from .link_chain import build_chain


def build() -> Scene:
    return build_chain(2, name="double-pendulum-tip")
