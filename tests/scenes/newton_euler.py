"""A rigid body in space by Newton–Euler, in numpy: the independent derivation the spatial scenes are tested against.

The body turns with the body-fixed yaw psi, pitch theta, roll phi (R = Rz(psi) Ry(theta) Rx(phi));
its angular velocity is psi' e_z + theta' Rz e_y + phi' Rz Ry e_x, written out here, not taken
from sympy.physics.mechanics. A unit force F at a point r from the centre of mass accelerates
a point r' of the body by F/m + (I^-1 (r x F)) x r' (the rates frozen: the fast time).
"""

from __future__ import annotations

import numpy as np


def rotation(psi: float, theta: float, phi: float) -> np.ndarray:
    cz, sz, cy, sy, cx, sx = np.cos(psi), np.sin(psi), np.cos(theta), np.sin(theta), np.cos(phi), np.sin(phi)
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    Ry = np.array([[cy, 0, sy], [0, 1, 0], [-sy, 0, cy]])
    Rx = np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]])
    return Rz @ Ry @ Rx


def jacobians(psi: float, theta: float, phi: float) -> tuple[np.ndarray, np.ndarray]:
    """(d v_centre / d q', d omega / d q') for q = (x, y, z, psi, theta, phi)."""
    cz, sz = np.cos(psi), np.sin(psi)
    Rz = np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])
    Ry = rotation(0, theta, 0)
    omega = np.column_stack([[0, 0, 1], Rz @ [0, 1, 0], Rz @ Ry @ [1, 0, 0]])
    return np.hstack([np.eye(3), np.zeros((3, 3))]), np.hstack([np.zeros((3, 3)), omega])


def mass_matrix(mass: float, inertia_body: np.ndarray, angles) -> np.ndarray:
    R = rotation(*angles)
    Jv, Jw = jacobians(*angles)
    return mass * Jv.T @ Jv + Jw.T @ (R @ inertia_body @ R.T) @ Jw


def generalized_force(force: np.ndarray, arm: np.ndarray, angles) -> np.ndarray:
    """The generalized force of a unit force at the arm r from the centre: Jv^T F + Jw^T (r x F)."""
    Jv, Jw = jacobians(*angles)
    return Jv.T @ force + Jw.T @ np.cross(arm, force)


def delassus(mass: float, inertia_body: np.ndarray, angles, arms, normals, forces) -> np.ndarray:
    """n_i . (acceleration of contact i's point by a unit ``forces[j]`` at contact j), in Cartesian form."""
    R = rotation(*angles)
    inverse = np.linalg.inv(R @ inertia_body @ R.T)
    k = len(arms)
    out = np.zeros((k, k))
    for i in range(k):
        for j in range(k):
            spin = inverse @ np.cross(arms[j], forces[j])
            out[i, j] = normals[i] @ (forces[j] / mass + np.cross(spin, arms[i]))
    return out
