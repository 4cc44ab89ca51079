"""The notebooks in notebooks/: each is committed clean, ends with exercises, and runs top to bottom.

Each notebook is executed here, one test per notebook (so the two workers of ``pytest -n auto``
share them), in a kernel of *this* interpreter importing this checkout, as the documentation
site's build executes them (myst-nb runs them with nbclient too, in the notebook's folder). The
suite's site build (tests/docs/test_site.py) renders them as committed, so each runs once per suite.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("*.ipynb")) + sorted((NOTEBOOK_DIR / "solutions").glob("*.ipynb"))


def _ids(path: Path) -> str:
    return str(path.relative_to(NOTEBOOK_DIR).with_suffix(""))


EXPECTED = (
    "00_quickstart",
    "01_sliding_point",
    "02_separation_of_motions",
    "03_painleve_klein_rod",
    "04_two_contacts",
    "05_painleve_klein_guides",
    "06_brake_squeal",
    "07_errata",
)


def test_there_are_notebooks():
    names = {p.stem for p in NOTEBOOK_DIR.glob("*.ipynb")}
    assert set(EXPECTED) <= names, f"missing notebooks: {sorted(set(EXPECTED) - names)}"


@pytest.mark.parametrize("path", NOTEBOOKS, ids=_ids)
def test_notebook_is_committed_without_outputs(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    dirty = [
        i
        for i, cell in enumerate(nb["cells"])
        if cell["cell_type"] == "code" and (cell.get("outputs") or cell.get("execution_count") is not None)
    ]
    assert not dirty, f"{path.name}: cells {dirty} have outputs or execution counts; clear them before committing"
    assert "widgets" not in nb.get("metadata", {}), f"{path.name}: stored widget state; clear it"


@pytest.mark.parametrize("path", [p for p in NOTEBOOKS if p.parent == NOTEBOOK_DIR], ids=_ids)
def test_notebook_ends_with_exercises_and_solutions(path):
    nb = json.loads(path.read_text(encoding="utf-8"))
    text = ["".join(cell["source"]) for cell in nb["cells"]]
    tail = "\n".join(text[-3:])
    assert "Try this" in tail, f"{path.name} should end with a 'Try this' list of exercises"
    hidden = any(cell.get("metadata", {}).get("jupyter", {}).get("source_hidden") for cell in nb["cells"][-3:])
    assert hidden or "solutions/" in tail, f"{path.name}: put the solutions in a collapsed cell or in solutions/"


@pytest.fixture(scope="module")
def kernel_env(tmp_path_factory) -> dict:
    """The environment of a kernel of this interpreter importing this checkout: a kernel spec for
    ``sys.executable`` first on JUPYTER_PATH (a system-wide "python3" spec may name another Python)."""
    kernelspec = pytest.importorskip("ipykernel.kernelspec")
    prefix = tmp_path_factory.mktemp("kernel")
    kernelspec.install(kernel_name="python3", prefix=str(prefix))
    jupyter_path = os.pathsep.join(p for p in (str(prefix / "share" / "jupyter"), os.environ.get("JUPYTER_PATH")) if p)
    return {**os.environ, "PYTHONPATH": str(ROOT), "MPLBACKEND": "Agg", "JUPYTER_PATH": jupyter_path}


@pytest.mark.parametrize("path", [p for p in NOTEBOOKS if p.parent == NOTEBOOK_DIR], ids=_ids)
def test_notebook_runs_top_to_bottom(path, kernel_env, monkeypatch):
    """Every cell runs without an error, and every code cell that shows something has its output."""
    nbformat = pytest.importorskip("nbformat")
    nbclient = pytest.importorskip("nbclient")
    monkeypatch.setenv("JUPYTER_PATH", kernel_env["JUPYTER_PATH"])  # where the kernel spec is looked up
    notebook = nbformat.read(path, as_version=4)
    # shutdown_kernel="immediate": the kernel is killed once the last cell has run; the default graceful
    # shutdown waits ~1 s per notebook for an interpreter whose outputs are already collected
    client = nbclient.NotebookClient(
        notebook,
        timeout=600,
        kernel_name="python3",
        shutdown_kernel="immediate",
        resources={"metadata": {"path": str(NOTEBOOK_DIR)}},
    )
    client.execute(env=kernel_env)  # a failing cell raises CellExecutionError with its traceback
    code = [cell for cell in notebook.cells if cell.cell_type == "code"]
    assert code and all(cell.execution_count is not None for cell in code), f"{path.name}: a cell did not run"
    assert any(cell.outputs for cell in code), f"{path.name}: no cell has an output"
    errors = [o for cell in code for o in cell.outputs if o.get("output_type") == "error"]
    assert not errors, f"{path.name}: {errors[0]}"
