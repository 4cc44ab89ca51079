"""The import paths of contactsym 0.1, kept working after the move to subpackages.

0.1 had some fifty flat modules (``contactsym.canonical``, ``contactsym.contact_laws``, ...).
Each now lives in the subpackage of its domain; an import of the old path gives the module
at its new home (the same object, so ``contactsym.canonical is contactsym.algebra.canonical_form``).
Nothing is imported until an old path is asked for.

Examples
--------
>>> import importlib
>>> importlib.import_module("contactsym.contact_laws").__name__
'contactsym.laws.library'
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.util
import sys
import types

__all__ = ["MOVED", "install"]

#: Old module name (under ``contactsym.``) -> its new home.
MOVED = {
    "algebra": "algebra.basic",
    "canonical": "algebra.canonical_form",
    "compliance": "laws.compliance",
    "contact": "mechanism.contact",
    "contact_laws": "laws.library",
    "corners": "counts.corners",
    "count_conditions": "counts.conditions",
    "count_points": "plotting.counts",
    "counts": "counts.regions",
    "equilibria": "stages.equilibria",
    "errata": "report.errata",
    "fast": "stages.fast",
    "filecontacts": "mechanism.files.contacts",
    "filemechanics": "mechanism.files.bodies",
    "formula_law": "laws.formula",
    "fourier": "algebra.fourier",
    "friction": "laws.friction",
    "hopf": "numerics.hopf",
    "hopf_plots": "plotting.hopf",
    "hurwitz": "algebra.hurwitz",
    "intervals": "algebra.intervals",
    "latex": "printing.latex_output",
    "law_polynomials": "robustness.law_polynomials",
    "laws": "laws",
    "linear": "stages.linear",
    "lyapunov_form": "lyapunov.polynomial",
    "mechanics": "mechanism.contact_space",
    "numerics.integrate": "numerics.integration",
    "one_sided": "counts.one_sided",
    "orthants": "counts.orthants",
    "plmap": "counts.plmap",
    "reductions": "algebra.reductions",
    "regions": "stages.regions",
    "regularize": "stages.regularize",
    "robust_certificates": "robustness.certificates",
    "robustness": "robustness.classify",
    "scene": "mechanism.scene",
    "scenefigures": "plotting.plan_figures",
    "scenefile": "mechanism.files.reader",
    "sceneinput": "mechanism.checks",
    "stability": "stages.stability",
    "thresholds": "counts.thresholds",
    "tomlsource": "mechanism.files.toml_source",
    "unicodemath": "printing.unicode_math",
}


class _OldPathFinder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds ``contactsym.<old>`` and hands back the module at its new home."""

    def find_spec(self, fullname, path=None, target=None):
        prefix, _, name = fullname.partition(".")
        if prefix != "contactsym" or name not in MOVED:
            return None
        return importlib.util.spec_from_loader(fullname, self)

    def create_module(self, spec):
        parent = sys.modules[spec.name.rpartition(".")[0]]
        if type(parent) is types.ModuleType:
            parent.__class__ = _Package  # so that the import below cannot replace a function
        module = importlib.import_module("contactsym." + MOVED[spec.name.partition(".")[2]])
        self._spec = module.__spec__
        return module

    def exec_module(self, module):
        module.__spec__ = self._spec  # the import system stamped the old name's spec on it


class _Package(types.ModuleType):
    """A package in which importing an old module path never replaces a function.

    0.1's ``contactsym.scene``, ``contactsym.latex`` and ``contactsym.numerics.integrate`` were
    functions shadowing their modules; they stay the functions when the old path is imported.
    """

    def __setattr__(self, name, value):
        current = self.__dict__.get(name)
        old_path = f"{self.__name__}.{name}".partition(".")[2] in MOVED
        if old_path and isinstance(value, types.ModuleType) and current is not None:
            if not isinstance(current, types.ModuleType):
                return
        super().__setattr__(name, value)

    def __getattr__(self, name):
        # 0.1's ``cs.regions.closed_form``: an old module reached as an attribute of its package
        old = f"{self.__name__}.{name}".partition(".")[2]
        if old in MOVED:
            return importlib.import_module("contactsym." + MOVED[old])
        raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")


def install(package: types.ModuleType) -> None:
    """Serve the old paths (once per process)."""
    package.__class__ = _Package
    if not any(isinstance(finder, _OldPathFinder) for finder in sys.meta_path):
        sys.meta_path.append(_OldPathFinder())
