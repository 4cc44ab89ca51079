"""One module holds every error, and one surface (``contactsym.__all__``) shows them with the stages and laws."""

import ast
import importlib
import inspect
import pathlib

import pytest

import contactsym as cs
from contactsym import errors

PACKAGE = pathlib.Path(cs.__file__).parent

#: Where 0.1 users import each error from, besides ``contactsym.errors``.
OLD_PATHS = {
    "ParseError": "contactsym.parse",
    "ReportError": "contactsym.report",
    "AtlasError": "contactsym.atlas",
    "UsageError": "contactsym.atlas.cli",
    "SceneFileError": "contactsym.mechanism.files.toml_source",
    "NumericsError": "contactsym.numerics",
}

ERRORS = sorted(name for name, obj in vars(errors).items() if inspect.isclass(obj) and issubclass(obj, Exception))


def _classes_deriving_from_an_error(path: pathlib.Path) -> list[str]:
    """Public classes named like an error or derived from one of contactsym's errors. A private
    exception that carries control flow inside one module (``_Budget``) is no user's error."""
    tree = ast.parse(path.read_text())
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef) and not node.name.startswith("_"):
            bases = [b.id if isinstance(b, ast.Name) else getattr(b, "attr", "") for b in node.bases]
            if node.name.endswith("Error") or any(base in ERRORS or base.endswith("Error") for base in bases):
                found.append(f"{path.relative_to(PACKAGE)}: {node.name}")
    return found


def test_the_error_finder_finds_an_error_class():
    module = PACKAGE / "errors.py"
    assert any(line.endswith(": SceneFileError") for line in _classes_deriving_from_an_error(module))


def test_every_error_class_lives_in_errors_py():
    outside = [
        found
        for path in sorted(PACKAGE.rglob("*.py"))
        if path.name != "errors.py"
        for found in _classes_deriving_from_an_error(path)
    ]
    assert not outside, f"error classes outside contactsym/errors.py: {outside}"


def test_every_error_is_a_contactsym_error_and_exported():
    assert len(ERRORS) >= 12
    assert all(issubclass(getattr(errors, name), errors.ContactsymError) for name in ERRORS)
    assert set(ERRORS) <= set(cs.__all__), sorted(set(ERRORS) - set(cs.__all__))
    assert all(getattr(cs, name) is getattr(errors, name) for name in ERRORS)


@pytest.mark.parametrize("name", sorted(OLD_PATHS))
def test_an_error_still_imports_from_where_it_was(name):
    assert getattr(importlib.import_module(OLD_PATHS[name]), name) is getattr(errors, name)


def test_the_public_surface_has_the_stages_and_the_law_library():
    stages = ["Regularized", "FastSubsystem", "Equilibria", "Linearization", "Stability", "Region"]
    laws = ["Hertz", "HuntCrossley", "CubicStiffening", "with_laws", "Law", "KelvinVoigt"]
    assert set(stages + laws) <= set(cs.__all__)
    brake = cs.scene("brake")
    assert isinstance(brake.stability(), cs.Stability) and isinstance(brake.linearization(), cs.Linearization)
    assert isinstance(brake.equilibria(), cs.Equilibria) and isinstance(brake.fast_subsystem(), cs.FastSubsystem)
    assert isinstance(brake.regularized(), cs.Regularized)


def test_repr_latex_is_written_once_for_the_stages():
    from contactsym.printing.latex_output import LatexReprMixin

    for cls in (cs.Regularized, cs.FastSubsystem, cs.Equilibria, cs.Linearization, cs.Stability, cs.Scene):
        assert issubclass(cls, LatexReprMixin) and "_repr_latex_" not in vars(cls), cls
    shown = cs.scene("sliding-point").fast_subsystem()._repr_latex_()
    assert shown == f"$\\displaystyle {cs.latex(cs.scene('sliding-point').fast_subsystem(), tags=True)}$"
    assert "\\text{(3.1)" in shown  # with its citations
