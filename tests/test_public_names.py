"""Every public name of contactsym 0.1 still imports from its 0.1 path (``contactsym/_aliases.py``).

``tests/data/public_names_0_1.json`` was written from the 0.1 tree (commit 1c67354): for each
module, its ``__all__``, or else the callables it defines.
"""

import importlib
import json
import subprocess
import sys
import types
from pathlib import Path

import pytest

import contactsym as cs
from contactsym import _aliases

NAMES = json.loads((Path(__file__).parent / "data" / "public_names_0_1.json").read_text())


@pytest.mark.parametrize("module", sorted(NAMES))
def test_every_public_name_of_0_1_imports_from_its_old_path(module):
    old = importlib.import_module(module)
    missing = [name for name in NAMES[module] if not hasattr(old, name)]
    assert not missing, f"{module} lost {missing}"


def test_an_old_path_is_the_module_at_its_new_home():
    import contactsym.canonical as old

    assert old is importlib.import_module("contactsym.algebra.canonical_form")
    assert old.__spec__.name == "contactsym.algebra.canonical_form"
    assert cs.regions is importlib.import_module("contactsym.stages.regions")  # 0.1's attribute access


def test_old_paths_never_replace_the_functions_of_the_same_name():
    from contactsym.latex import tex  # noqa: F401  (0.1's module path)
    from contactsym.numerics.integrate import integrate
    from contactsym.scene import Scene

    assert isinstance(cs.scene, types.FunctionType) and isinstance(cs.latex, types.FunctionType)
    assert cs.numerics.integrate is integrate and isinstance(integrate, types.FunctionType)
    assert Scene is cs.Scene


def test_every_alias_points_at_an_existing_module_and_no_old_name_is_a_module_again():
    for old, new in _aliases.MOVED.items():
        assert importlib.util.find_spec("contactsym." + new) is not None, new
        assert not (Path(cs.__file__).parent / (old.replace(".", "/") + ".py")).exists(), old


def test_unknown_attributes_still_raise_attribute_error():
    with pytest.raises(AttributeError, match="no_such_name"):
        cs.no_such_name  # noqa: B018


def test_importing_contactsym_loads_no_old_path():
    code = "import sys, contactsym; print(sorted(m for m in sys.modules if m.startswith('contactsym.canonical')))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
