"""Beyond the paper: a planar chain of n links, pinned at one end, whose tip slides on a rough floor.

Link i has length l_i and carries a point mass m_i at its far end; q_i is its angle from the
downward vertical. The tip touches the floor y = -h (k = 1, bilateral); Coulomb friction
mu ``|N|`` acts at the tip along the floor, against its sliding, taken in +x. For n = 2 this is the
two-link arm of :mod:`contactsym.scenes.double_pendulum_tip`, the classical robotic setting of
Painlevé's paradox.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols

from ..laws import Coulomb
from ..mechanism.scene import Contact, Scene


def build_chain(n: int, name: str | None = None, **options) -> Scene:
    """The n-link chain with a frictional tip contact.

    Examples
    --------
    >>> build_chain(1).linearization().A
    Matrix([[-s*mu*sin(q)*cos(q)/m + sin(q)**2/m]])
    """
    suffix = (lambda i: "") if n == 1 else (lambda i: str(i + 1))
    q = [dynamicsymbols(f"q{suffix(i)}") for i in range(n)]
    m = [sp.Symbol(f"m{suffix(i)}", positive=True) for i in range(n)]
    l = [sp.Symbol(f"l{suffix(i)}", positive=True) for i in range(n)]
    g, h, mu = sp.symbols("g h mu", positive=True)
    N = sp.Symbol("N", real=True)
    O = ReferenceFrame("O")
    pivot = Point("O")
    pivot.set_vel(O, 0)
    particles, joint = [], pivot
    for i in range(n):
        joint = joint.locatenew(f"P{i + 1}", l[i] * (sp.sin(q[i]) * O.x - sp.cos(q[i]) * O.y))
        joint.set_vel(O, joint.pos_from(pivot).dt(O))
        particle = Particle(f"mass{i + 1}", joint, m[i])
        particle.potential_energy = m[i] * g * joint.pos_from(pivot).dot(O.y)
        particles.append(particle)
    tip_height = joint.pos_from(pivot).dot(O.y)
    contact = Contact(coordinate=tip_height + h, reaction=N, friction=Coulomb(mu, O.x, joint))
    return Scene.from_lagrangian(
        Lagrangian(O, *particles),
        q,
        [contact],
        frame=O,
        at={h: -tip_height},  # the floor's depth is where the tip is
        name=name or f"chain-{n}",
        solve_for=mu,
        description=f"a {n}-link chain whose tip slides on a rough floor",
        **options,  # e.g. a figure_plan
    )
