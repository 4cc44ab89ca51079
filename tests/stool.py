"""A three-legged stool sliding on a rough floor: a k = 3 mechanism for the robustness tests.

A rigid body (mass m, principal inertias I) stands on three legs at the corners of an
equilateral triangle of circumradius 1, its centre of mass at height h above the floor
and offset e from the centre of the triangle. It slides with velocity v (angle theta)
and spins with rate omega about the vertical, so leg j slides along t_j (the unit
horizontal velocity of its foot) and feels the friction -mu |N_j| t_j. The gap q_j of
leg j accelerates by the vertical acceleration of its foot:

    q_j'' = w_j^T M^-1 sum_i (w_i N_i - mu |N_i| tau_i) + b_j,

w_i = (e_z, r_i x e_z) and tau_i = (t_i, r_i x t_i) the wrenches of a unit normal and a unit
friction force at foot i (r_i from the centre of mass). A = df/du is derived by the pipeline.
"""

from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs

mu, h = sp.symbols("mu h", positive=True)


def _feet(offset):
    angles = 2 * np.pi * np.arange(3) / 3
    return [np.array([np.cos(a) - offset[0], np.sin(a) - offset[1], 0.0]) for a in angles]


def stool_scene(
    offset=(0.15, -0.1), inertia=(0.4, 0.5, 0.7), velocity_angle=0.3, spin=0.8, mass=1.0, symbolic: str = "numbers"
) -> cs.Scene:
    """The stool with symbolic friction coefficient mu and height h of the centre of mass.

    ``symbolic``: ``"numbers"`` (the rest numbers, 4-digit rationals), ``"masses"`` (mass m
    and inertias I_1..I_3 symbolic too) or ``"feet"`` (also the feet x_j, y_j and the unit
    slip directions (c_j, d_j) of the feet).
    """
    feet = _feet(offset)
    if symbolic == "numbers":
        Minv = sp.diag(*[sp.Rational(1) / sp.nsimplify(mass)] * 3, *[1 / sp.nsimplify(x) for x in inertia])
    else:
        m, *inertias = sp.symbols("m I_1:4", positive=True)
        Minv = sp.diag(*[1 / m] * 3, *[1 / x for x in inertias])
    v = np.array([np.cos(velocity_angle), np.sin(velocity_angle), 0.0])
    wrenches, frictions = [], []
    for j, foot in enumerate(feet, 1):
        r = sp.Matrix([sp.nsimplify(round(foot[0], 4)), sp.nsimplify(round(foot[1], 4)), -h])
        slip = v + spin * np.cross([0, 0, 1.0], foot)
        t = sp.Matrix([sp.nsimplify(round(x, 4)) for x in slip / np.linalg.norm(slip)])
        if symbolic == "feet":
            x, y, c, d = sp.symbols(f"x_{j} y_{j} c_{j} d_{j}", real=True)
            r, t = sp.Matrix([x, y, -h]), sp.Matrix([c, d, 0])
        ez = sp.Matrix([0, 0, 1])
        wrenches.append(sp.Matrix.vstack(ez, r.cross(ez)))
        frictions.append(sp.Matrix.vstack(t, r.cross(t)))
    q = dynamicsymbols("q_1:4")
    N = sp.symbols("N_1:4", real=True)
    b = sp.symbols("b_1:4", real=True)
    force = sum((wrenches[i] * N[i] - mu * sp.Abs(N[i]) * frictions[i] for i in range(3)), sp.zeros(6, 1))
    accelerations = [(wrenches[j].T * Minv * force)[0] + b[j] for j in range(3)]
    contacts = [cs.Contact(coordinate=q[j], reaction=N[j]) for j in range(3)]
    name = "stool" if symbolic == "numbers" else f"stool-{symbolic}"
    return cs.Scene.from_accelerations(q, accelerations, contacts, name=name)


def stool_A(scene: cs.Scene, signs, mu_value, h_value) -> sp.Matrix:
    """A on one sign pattern at numbers (exact rationals)."""
    A = scene.linearization(signs=signs).A
    return A.xreplace({mu: sp.nsimplify(mu_value), h: sp.nsimplify(h_value)})
