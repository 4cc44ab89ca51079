"""The documentation site (docs/) builds with warnings as errors, and documents every public name.

The build is the command the README gives, ``python3 -m sphinx -W -b html docs docs/_build/html``,
run on a copy of docs/ in a temporary folder: a build writes into its source folder (the API
pages of api/generated, emptied first by conf.py; the intersphinx inventories), so a build of
the checkout's own docs/ at the same time (the README's command, an editor's preview, another
test run) cannot remove pages under this one. The notebooks are rendered as committed
(``CONTACTSYM_DOCS_EXECUTE=off``): tests/test_notebooks.py executes each notebook, one test per
notebook, in a kernel of this interpreter, as the README's build does with myst-nb. This folder
is collected early, so the longest test starts first.
"""

from __future__ import annotations

import importlib
import inspect
import os
import pkgutil
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import contactsym

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"

# one worker builds the site for all of them (once per run)
pytestmark = pytest.mark.xdist_group("site")

pytest.importorskip("sphinx")
pytest.importorskip("myst_nb")
pytest.importorskip("numpydoc")


def public_names() -> dict[str, object]:
    """``package.name`` -> object, for ``contactsym.__all__`` and every subpackage's ``__all__``."""
    packages = ["contactsym"] + [m.name for m in pkgutil.walk_packages(contactsym.__path__, "contactsym.") if m.ispkg]
    names = {}
    for package in packages:
        module = importlib.import_module(package)
        for name in getattr(module, "__all__", ()):
            names[f"{package}.{name}"] = getattr(module, name)
    return names


@pytest.fixture(scope="module")
def site(tmp_path_factory) -> Path:
    """The site, built once from this checkout, the notebooks not executed (they run in
    tests/test_notebooks.py)."""
    out = tmp_path_factory.mktemp("site")
    source = out / "docs"
    shutil.copytree(DOCS, source, ignore=shutil.ignore_patterns("_build", "generated", ".ipynb_checkpoints"))
    env = {**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg", "CONTACTSYM_DOCS_EXECUTE": "off"}
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "sphinx",
            "-W",
            "--keep-going",
            "-q",
            "-b",
            "html",
            str(source),
            str(out / "html"),
            "-d",
            str(out / "doctrees"),
        ],
        capture_output=True,
        text=True,
        env=env,
        cwd=ROOT,
        timeout=1200,
    )
    assert run.returncode == 0, f"the site does not build:\n{run.stderr[-6000:]}"
    return out / "html"


def test_the_site_builds_with_warnings_as_errors(site):
    assert (site / "index.html").exists()
    assert (site / "api" / "generated" / "contactsym.html").exists()


def test_every_public_name_has_an_api_page(site):
    """Every public name has its page: classes, functions and packages from autosummary, constants
    from their ``#:`` comments (docs/_ext/constants.py; tests/docs/test_constants.py runs their examples)."""
    generated = site / "api" / "generated"
    names = list(public_names())
    missing = [name for name in names if not (generated / f"{name}.html").exists()]
    assert not missing, f"public names without an API page: {missing}"


def test_every_notebook_is_in_the_site(site):
    for notebook in sorted((ROOT / "notebooks").glob("*.ipynb")):
        page = site / "notebooks" / f"{notebook.stem}.html"
        assert page.exists(), notebook.name
        assert "cell_input" in page.read_text(), f"{notebook.name} has no code cells in the site"


def _documentable(obj) -> bool:
    return inspect.isclass(obj) or inspect.isfunction(obj) or inspect.ismodule(obj)


def test_every_public_class_and_function_has_a_docstring_example():
    missing = sorted(
        name for name, obj in public_names().items() if _documentable(obj) and ">>>" not in (inspect.getdoc(obj) or "")
    )
    assert not missing, f"{len(missing)} public names without a docstring example: {missing}"
