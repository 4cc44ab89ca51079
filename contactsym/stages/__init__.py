"""The pipeline's stages, each a frozen object built from the previous one:
regularization (1.6)-(1.9), the fast subsystem (2.1), its equilibria, the linearization
(4.3)-(4.6), stability (Routh–Hurwitz, the Hopf set) and closed-form regions.
"""

from .equilibria import Branch, Equilibria, LiftOff
from .fast import FastSubsystem, on_piece, solve_piece, switching_functions
from .linear import Linearization, charpoly, lam, principal_minors
from .regions import REGION_NAMES, Region, closed_form, known_sign, scene_regions
from .regularize import ReducedSystem, Regularized
from .stability import Stability, generic_minors, hurwitz_names, robustness_formulas

__all__ = [
    "Branch",
    "Equilibria",
    "FastSubsystem",
    "LiftOff",
    "Linearization",
    "REGION_NAMES",
    "ReducedSystem",
    "Region",
    "Regularized",
    "Stability",
    "charpoly",
    "closed_form",
    "generic_minors",
    "hurwitz_names",
    "known_sign",
    "lam",
    "on_piece",
    "principal_minors",
    "robustness_formulas",
    "scene_regions",
    "solve_piece",
    "switching_functions",
]
