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

import sys

from . import _aliases
from .algebra.basic import SignSymbol
from .errors import (
    AtlasError,
    ComplianceError,
    ContactsymError,
    HopfError,
    NumericsError,
    SceneError,
    SignPatternError,
    SingularJacobianError,
    UsageError,
)
from .laws import Compliance, Coulomb, Generic, KelvinVoigt, Law, Viscous
from .laws.library import CubicStiffening, Hertz, HuntCrossley, with_laws
from .mechanism.files.reader import FigurePlan, SceneFileError, load_scene, read_scene
from .mechanism.scene import Contact, Scene
from .parse import ParseError, parse_expression
from .printing.latex_output import latex
from .report import ReportError, ReportResult, conditions, report_tex, write_report
from .scenes import DEFAULT_SCENE, scene, scene_names
from .stages import Equilibria, FastSubsystem, Linearization, Regularized, Stability
from .stages.linear import lam
from .stages.regions import Region, closed_form

__all__ = [
    "AtlasError",
    "Compliance",
    "ComplianceError",
    "Contact",
    "ContactsymError",
    "Coulomb",
    "CubicStiffening",
    "DEFAULT_SCENE",
    "Equilibria",
    "FastSubsystem",
    "FigurePlan",
    "Generic",
    "Hertz",
    "HopfError",
    "HuntCrossley",
    "KelvinVoigt",
    "Law",
    "Linearization",
    "NumericsError",
    "ParseError",
    "Region",
    "Regularized",
    "ReportError",
    "ReportResult",
    "Scene",
    "SceneError",
    "SceneFileError",
    "SignPatternError",
    "SignSymbol",
    "SingularJacobianError",
    "Stability",
    "UsageError",
    "Viscous",
    "closed_form",
    "conditions",
    "lam",
    "latex",
    "load_scene",
    "parse_expression",
    "read_scene",
    "report_tex",
    "scene",
    "scene_names",
    "with_laws",
    "write_report",
]

__version__ = "0.1.0"

_aliases.install(sys.modules[__name__])
