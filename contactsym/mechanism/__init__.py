"""The mechanical input: scenes, contacts, their checks, the contact-space derivation of
Lagrange's equations, and scene files (:mod:`contactsym.mechanism.files`).
"""

from .checks import check_eps, check_equations, check_scene, with_friction
from .contact import Contact, contact_manifold, plain_symbol, solve_linear
from .contact_space import ContactSpace, lagrangian_accelerations, mass_determinant, mass_determinant_is_zero, t
from .files import (
    COMPLIANCE_LAWS,
    FigurePlan,
    SceneFileError,
    TomlSource,
    load_scene,
    read_scene,
    scene_or_file,
    shown,
)
from .scene import Scene, paper_equations

__all__ = [
    "COMPLIANCE_LAWS",
    "Contact",
    "ContactSpace",
    "FigurePlan",
    "Scene",
    "SceneFileError",
    "TomlSource",
    "check_eps",
    "check_equations",
    "check_scene",
    "contact_manifold",
    "lagrangian_accelerations",
    "load_scene",
    "mass_determinant",
    "mass_determinant_is_zero",
    "paper_equations",
    "plain_symbol",
    "read_scene",
    "scene_or_file",
    "shown",
    "solve_linear",
    "t",
    "with_friction",
]
