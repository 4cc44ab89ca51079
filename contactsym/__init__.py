"""contactsym: exact stability of frictional compliant contacts.

Write a mechanical system with Coulomb friction once; contactsym derives the fast
subsystem of its contact reactions, its equilibria, the Jacobian A, the characteristic
polynomial, the Routh–Hurwitz conditions and their robustness to the contact law,
following A. P. Ivanov (PMM, 2005).

Examples
--------
>>> import contactsym as cs
>>> cs.scene("brake").linearization().det_A
mu**2*sin(alpha)**2/m**2 + sin(alpha)**2/m**2
"""

from .algebra import SignSymbol
from .errors import (
    ComplianceError,
    ContactsymError,
    SceneError,
    SignPatternError,
    SingularJacobianError,
)
from .latex import latex
from .laws import Compliance, Coulomb, Generic, KelvinVoigt, Law, Viscous
from .linear import lam
from .parse import ParseError, parse_expression
from .regions import Region, closed_form
from .scene import Contact, Scene
from .scenes import DEFAULT_SCENE, scene, scene_names

__all__ = [
    "Compliance",
    "ComplianceError",
    "Contact",
    "ContactsymError",
    "Coulomb",
    "DEFAULT_SCENE",
    "Generic",
    "KelvinVoigt",
    "Law",
    "ParseError",
    "Region",
    "Scene",
    "SceneError",
    "SignPatternError",
    "SignSymbol",
    "SingularJacobianError",
    "Viscous",
    "closed_form",
    "lam",
    "parse_expression",
    "latex",
    "scene",
    "scene_names",
]

__version__ = "0.1.0"
