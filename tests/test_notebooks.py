"""The notebooks in notebooks/: each runs top to bottom, and each is committed clean.

Execution uses nbclient with an ipykernel kernel of *this* interpreter: a kernel spec
for ``sys.executable`` is written to a temporary directory put first on JUPYTER_PATH,
so a user's own ``python3`` kernel spec (another Python, another contactsym) is never
picked up. The kernel imports contactsym from this checkout (PYTHONPATH), as the tests do.
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"
NOTEBOOKS = sorted(NOTEBOOK_DIR.glob("*.ipynb")) + sorted((NOTEBOOK_DIR / "solutions").glob("*.ipynb"))
CELL_TIMEOUT = 120  # seconds per cell; a notebook is meant to finish in well under 60 s
KERNEL = "python3"


def _ids(path: Path) -> str:
    return str(path.relative_to(NOTEBOOK_DIR).with_suffix(""))


@pytest.fixture(scope="module")
def kernel_env(tmp_path_factory):
    """Environment for a kernel of this interpreter that imports this checkout."""
    pytest.importorskip("nbclient")
    kernelspec = pytest.importorskip("ipykernel.kernelspec")
    prefix = tmp_path_factory.mktemp("jupyter")
    kernelspec.install(kernel_name=KERNEL, prefix=str(prefix))  # argv[0] = sys.executable
    saved = {name: os.environ.get(name) for name in ("JUPYTER_PATH", "PYTHONPATH", "MPLBACKEND")}
    os.environ["JUPYTER_PATH"] = os.pathsep.join(
        p for p in (str(prefix / "share" / "jupyter"), saved["JUPYTER_PATH"]) if p
    )
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in (str(ROOT), saved["PYTHONPATH"]) if p)
    os.environ["MPLBACKEND"] = "Agg"
    yield
    for name, value in saved.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value


def _execute(nb, path: Path):
    from nbclient import NotebookClient

    client = NotebookClient(
        nb,
        timeout=CELL_TIMEOUT,
        kernel_name=KERNEL,
        resources={"metadata": {"path": str(path.parent)}},
    )
    return client.execute()


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


def test_the_kernel_is_this_interpreter(kernel_env):
    nbformat = pytest.importorskip("nbformat")
    nb = nbformat.v4.new_notebook(
        cells=[nbformat.v4.new_code_cell("import sys, contactsym\nprint(sys.executable)\nprint(contactsym.__file__)")]
    )
    _execute(nb, NOTEBOOK_DIR)
    executable, package = nb.cells[0].outputs[0]["text"].split()
    assert os.path.realpath(executable) == os.path.realpath(sys.executable)
    assert Path(package).resolve().is_relative_to(ROOT)


@pytest.mark.parametrize("path", NOTEBOOKS, ids=_ids)
def test_notebook_runs_top_to_bottom(path, kernel_env):
    """A failing cell raises CellExecutionError, which fails the test with the cell's traceback."""
    nbformat = pytest.importorskip("nbformat")
    nb = nbformat.read(path, as_version=4)
    start = time.perf_counter()
    _execute(nb, path)
    elapsed = time.perf_counter() - start
    print(f"{path.name}: {elapsed:.1f} s")
    assert elapsed < 120, f"{path.name} took {elapsed:.0f} s; notebooks must stay well under a minute"


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
