"""The notebooks in notebooks/: each is committed clean and ends with exercises.

Each runs top to bottom when the documentation site is built (tests/docs/test_site.py, with a
kernel of *this* interpreter importing this checkout): that build fails on a failing cell and
checks every notebook's page has its outputs, so the notebooks are executed once per suite.
"""

from __future__ import annotations

import json
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
