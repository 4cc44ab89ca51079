"""The documentation site (docs/) builds with warnings as errors, and documents every public name.

The build is the command the README gives, ``python3 -m sphinx -W -b html docs docs/_build/html``
(here into a temporary folder). It executes every notebook (myst-nb), so a failing cell fails
it: this is where the notebooks run in the suite (tests/test_notebooks.py checks how they are
committed). This folder is collected early, so the longest test starts first.
"""

from __future__ import annotations

import importlib
import inspect
import os
import pkgutil
import subprocess
import sys
from pathlib import Path

import pytest

import contactsym

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"

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
    """The site, built once; the notebooks run in a kernel of *this* interpreter (a kernel spec
    for ``sys.executable`` first on JUPYTER_PATH), importing this checkout."""
    kernelspec = pytest.importorskip("ipykernel.kernelspec")
    out = tmp_path_factory.mktemp("site")
    kernelspec.install(kernel_name="python3", prefix=str(out / "kernel"))
    jupyter_path = os.pathsep.join(
        p for p in (str(out / "kernel" / "share" / "jupyter"), os.environ.get("JUPYTER_PATH")) if p
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg", "JUPYTER_PATH": jupyter_path}
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
            str(DOCS),
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


def test_every_notebook_is_in_the_site_with_its_outputs(site):
    for notebook in sorted((ROOT / "notebooks").glob("*.ipynb")):
        page = site / "notebooks" / f"{notebook.stem}.html"
        assert page.exists(), notebook.name
        assert "cell_output" in page.read_text(), f"{notebook.name} has no executed output in the site"


def _documentable(obj) -> bool:
    return inspect.isclass(obj) or inspect.isfunction(obj) or inspect.ismodule(obj)


def test_every_public_class_and_function_has_a_docstring_example():
    missing = sorted(
        name for name, obj in public_names().items() if _documentable(obj) and ">>>" not in (inspect.getdoc(obj) or "")
    )
    assert not missing, f"{len(missing)} public names without a docstring example: {missing}"
