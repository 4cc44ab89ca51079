"""``import contactsym`` loads no display or numerics code; every public name still resolves on use."""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import contactsym

ROOT = Path(__file__).resolve().parents[1]
DISPLAY_AND_NUMERICS = [
    "contactsym.report",
    "contactsym.plotting",
    "contactsym.numerics",
    "contactsym.atlas",
    "scipy.ndimage",
    "scipy.optimize",
    "matplotlib",
]


def _loaded_after(code: str) -> dict[str, bool]:
    """Which of DISPLAY_AND_NUMERICS a fresh interpreter has loaded after running ``code``."""
    probe = f"import json, sys\n{code}\nprint(json.dumps({{m: m in sys.modules for m in {DISPLAY_AND_NUMERICS!r}}}))"
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    run = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=120, check=True
    )
    return json.loads(run.stdout.strip().splitlines()[-1])


def test_import_loads_no_report_plotting_numerics_or_matplotlib():
    loaded = _loaded_after("import contactsym")
    assert not any(loaded.values()), f"import contactsym loaded {[m for m, yes in loaded.items() if yes]}"


def test_a_name_loads_its_module_on_first_use():
    """The probe can see a load: asking for ``write_report`` brings the report in."""
    loaded = _loaded_after("import contactsym\ncontactsym.write_report")
    assert loaded["contactsym.report"]
    assert not loaded["matplotlib"]


@pytest.mark.parametrize("name", sorted(contactsym.__all__))
def test_every_public_name_resolves_and_stays(name):
    value = getattr(contactsym, name)
    assert getattr(contactsym, name) is value
    assert name in dir(contactsym)


def test_star_import_gives_every_public_name():
    namespace: dict = {}
    exec("from contactsym import *", namespace)
    assert set(contactsym.__all__) <= set(namespace)


def test_an_unknown_name_is_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'no_such_name'"):
        contactsym.no_such_name  # noqa: B018


def test_subpackages_and_old_module_paths_load_as_attributes():
    """``cs.numerics`` and the 0.1 path ``cs.regions`` work without an import statement, as in notebooks."""
    loaded = _loaded_after("import contactsym as cs\ncs.regions.closed_form\ncs.numerics.simulate_full")
    assert loaded["contactsym.numerics"] and not loaded["matplotlib"]
    assert cs_module("regions") is sys.modules["contactsym.stages.regions"]


def cs_module(name):
    return getattr(contactsym, name)


def test_the_old_scene_path_keeps_the_function():
    """Importing the 0.1 module path ``contactsym.scene`` never replaces the function ``contactsym.scene``."""
    import importlib

    importlib.import_module("contactsym.scene")
    assert callable(contactsym.scene) and contactsym.scene("brake").name
