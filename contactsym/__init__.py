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

from . import _aliases, _entry  # noqa: F401 - _entry first: a Ctrl-C while the command line imports
from .algebra.basic import SignSymbol
from .errors import (
    ComplianceError,
    ContactsymError,
    SceneError,
    SignPatternError,
    SingularJacobianError,
)
from .laws import Compliance, Coulomb, Generic, KelvinVoigt, Law, Viscous
from .mechanism.files.reader import FigurePlan, SceneFileError, load_scene, read_scene
from .mechanism.scene import Contact, Scene
from .parse import ParseError, parse_expression
from .printing.latex_output import latex
from .report import ReportError, ReportResult, conditions, report_tex, write_report
from .scenes import DEFAULT_SCENE, scene, scene_names
from .stages.linear import lam
from .stages.regions import Region, closed_form

__all__ = [
    "Compliance",
    "ComplianceError",
    "Contact",
    "ContactsymError",
    "Coulomb",
    "DEFAULT_SCENE",
    "FigurePlan",
    "Generic",
    "KelvinVoigt",
    "Law",
    "ParseError",
    "Region",
    "ReportError",
    "ReportResult",
    "Scene",
    "SceneError",
    "SceneFileError",
    "SignPatternError",
    "SignSymbol",
    "SingularJacobianError",
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
    "write_report",
]

__version__ = "0.1.0"

_aliases.install(sys.modules[__name__])
