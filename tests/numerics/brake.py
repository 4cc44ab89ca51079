"""The brake beyond its Hopf line, shared by the numerics tests: the (6.4) slice and its Hopf line, derived."""

import math

import numpy as np
import sympy as sp

import contactsym as cs

brake = cs.scene("brake")
stab = brake.stability()
Phi, Psi = sp.symbols("Phi Psi", negative=True)
m, mu, alpha = sp.symbols("m mu alpha", positive=True)
(P1, P2), (S1, S2) = stab.linearization.Phi, stab.linearization.Psi
right_angle = {alpha: sp.pi / 2, P1: Phi, P2: Phi, S1: Psi, S2: Psi}


def hopf_line(values):
    """Phi on the Hopf line, derived: the root of the last Hurwitz condition (Delta_3)."""
    roots = [r for r in sp.solve(sp.factor(stab.hurwitz[-1].subs(right_angle)), Phi) if r != 0]
    assert len(roots) == 1
    return roots[0].subs(values)


def brake_values(phi, psi, mass, friction, F=(2, -4)):
    return {
        "m": mass,
        "mu": friction,
        "alpha": math.pi / 2,
        "F_x": F[0],
        "F_y": F[1],
        "J": 1,
        "r": 1,
        "Phi_1": phi,
        "Phi_2": phi,
        "Psi_1": psi,
        "Psi_2": psi,
    }


def crossing_frequency(times, signal) -> float:
    """Angular frequency from upward zero crossings (linear fit over the second half)."""
    i = np.nonzero((signal[:-1] < 0) & (signal[1:] >= 0))[0]
    crossings = times[i] - signal[i] * (times[i + 1] - times[i]) / (signal[i + 1] - signal[i])
    half = crossings[len(crossings) // 2 :]
    period = np.polyfit(np.arange(half.size), half, 1)[0]
    return 2 * math.pi / period
