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

import importlib
import sys

from . import _aliases, _entry  # noqa: F401 - _entry first: a Ctrl-C while the command line imports
from .errors import (
    ArgumentError,
    AtlasError,
    ComplianceError,
    ContactsymError,
    HopfError,
    NumericsError,
    ParseError,
    ReportError,
    SceneError,
    SceneFileError,
    SignPatternError,
    SingularJacobianError,
    UsageError,
)

# Everything else loads on first use (module ``__getattr__``): ``import contactsym`` stays
# about as cheap as ``import sympy``; the report, plotting, numerics and matplotlib load only
# when a program asks for them. Name -> the module that defines it.
_LAZY = {
    "Compliance": ".laws",
    "Coulomb": ".laws",
    "Generic": ".laws",
    "KelvinVoigt": ".laws",
    "Law": ".laws",
    "Viscous": ".laws",
    "SignSymbol": ".algebra.basic",
    "FigurePlan": ".mechanism.files.reader",
    "load_scene": ".mechanism.files.reader",
    "read_scene": ".mechanism.files.reader",
    "Contact": ".mechanism.scene",
    "Scene": ".mechanism.scene",
    "parse_expression": ".parse",
    "latex": ".printing.latex_output",
    "ReportResult": ".report",
    "conditions": ".report",
    "report_tex": ".report",
    "write_report": ".report",
    "DEFAULT_SCENE": ".scenes",
    "scene": ".scenes",
    "scene_names": ".scenes",
    "lam": ".stages.linear",
    "Region": ".stages.regions",
    "closed_form": ".stages.regions",
    "Equilibria": ".stages",
    "FastSubsystem": ".stages",
    "Linearization": ".stages",
    "Regularized": ".stages",
    "Stability": ".stages",
    "CubicStiffening": ".laws.library",
    "Hertz": ".laws.library",
    "HuntCrossley": ".laws.library",
    "with_laws": ".laws.library",
}

__all__ = [
    "ArgumentError",
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


def __getattr__(name: str):
    """Import the module that defines ``name`` on first use, then keep the name here; a
    subpackage or a 0.1 module path (``cs.numerics``, ``cs.regions``) is imported when asked for."""
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name], __name__), name)
    elif not name.startswith("_"):
        try:
            value = importlib.import_module(f"{__name__}.{name}")
        except ModuleNotFoundError as error:
            if error.name != f"{__name__}.{name}":
                raise
            raise AttributeError(f"module 'contactsym' has no attribute {name!r}") from None
    else:
        raise AttributeError(f"module 'contactsym' has no attribute {name!r}")
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


_aliases.install(sys.modules[__name__])
