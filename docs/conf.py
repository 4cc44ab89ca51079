"""Sphinx configuration of the contactsym documentation site.

Build it with ``python3 -m sphinx -W -b html docs docs/_build/html`` after
``python3 -m pip install ".[docs]"``. The site builds without network: intersphinx reads small
inventories written below (the names the pages link to); ``CONTACTSYM_DOCS_ONLINE=1`` fetches
the projects' full inventories first.
"""

from __future__ import annotations

import os
import re
import shutil
import sys
import zlib
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))  # document this checkout
sys.path.insert(0, str(HERE / "_ext"))  # the site's own directives

import contactsym  # noqa: E402

project = "contactsym"
author = "the contactsym developers"
copyright = "2026, the contactsym developers"  # noqa: A001
release = version = contactsym.__version__

extensions = [
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.intersphinx",
    "sphinx.ext.mathjax",
    "sphinx.ext.viewcode",
    "numpydoc",
    "myst_nb",
    "scene_schema",
    "constants",
]

source_suffix = {".rst": "restructuredtext", ".md": "myst-nb", ".ipynb": "myst-nb"}  # .rst first: autosummary writes it
exclude_patterns = ["_build", "**.ipynb_checkpoints", "notebooks/solutions"]
templates_path = ["_templates"]

html_theme = "pydata_sphinx_theme"
html_title = "contactsym"
html_theme_options = {"navigation_depth": 2, "show_toc_level": 2}

autosummary_generate = True
# generated anew on every build: a page left from a renamed name would be an orphan (a warning)
shutil.rmtree(HERE / "api" / "generated", ignore_errors=True)
autosummary_imported_members = False
autosummary_ignore_module_all = False  # a package documents the names of its __all__, imported or not
autodoc_default_options = {"members": True, "show-inheritance": True}
autodoc_typehints = "none"  # numpydoc's Parameters sections say the types
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_validation_checks: set[str] = set()

myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
# Notebooks are executed when the site is built, so their figures are this checkout's; a cell
# that fails fails the build. CONTACTSYM_DOCS_EXECUTE=off renders them as committed (the suite's
# build: tests/test_notebooks.py executes them, one test each).
nb_execution_mode = os.environ.get("CONTACTSYM_DOCS_EXECUTE", "force")
nb_execution_timeout = 300
nb_execution_raise_on_error = True
nb_execution_show_tb = True

# Links into the projects contactsym builds on. Without network a small inventory of the
# names the pages use is written here; CONTACTSYM_DOCS_ONLINE=1 tries the full one first.
_LINKED = {
    "python": ("https://docs.python.org/3/", [("pathlib.Path", "class", "library/pathlib.html#pathlib.Path")]),
    "sympy": (
        "https://docs.sympy.org/latest/",
        [
            ("sympy.core.expr.Expr", "class", "modules/core.html#sympy.core.expr.Expr"),
            ("sympy.core.symbol.Symbol", "class", "modules/core.html#sympy.core.symbol.Symbol"),
            ("sympy.polys.polytools.Poly", "class", "modules/polys/reference.html#sympy.polys.polytools.Poly"),
            ("sympy.logic.boolalg.Boolean", "class", "modules/logic.html#sympy.logic.boolalg.Boolean"),
        ],
    ),
    "numpy": ("https://numpy.org/doc/stable/", [("numpy.ndarray", "class", "reference/generated/numpy.ndarray.html")]),
    "scipy": (
        "https://docs.scipy.org/doc/scipy/",
        [("scipy.integrate.solve_ivp", "function", "reference/generated/scipy.integrate.solve_ivp.html")],
    ),
    "matplotlib": (
        "https://matplotlib.org/stable/",
        [
            ("matplotlib.axes.Axes", "class", "api/_as_gen/matplotlib.axes.Axes.html"),
            ("matplotlib.figure.Figure", "class", "api/_as_gen/matplotlib.figure.Figure.html"),
        ],
    ),
    "xarray": ("https://docs.xarray.dev/en/stable/", [("xarray.Dataset", "class", "generated/xarray.Dataset.html")]),
    "dask": (
        "https://distributed.dask.org/en/stable/",
        [("distributed.Client", "class", "api.html#distributed.Client")],
    ),
}


def _local_inventory(name: str, entries) -> str:
    """A Sphinx inventory (format 2) of ``entries`` written under _build; its path."""
    path = HERE / "_build" / "inventories" / f"{name}.inv"
    path.parent.mkdir(parents=True, exist_ok=True)
    header = f"# Sphinx inventory version 2\n# Project: {name}\n# Version: \n# The remainder is zlib-compressed.\n"
    body = "".join(f"{obj} py:{role} 1 {uri} -\n" for obj, role, uri in entries)
    path.write_bytes(header.encode() + zlib.compress(body.encode()))
    return str(path)


_ONLINE = os.environ.get("CONTACTSYM_DOCS_ONLINE") == "1"
intersphinx_mapping = {
    name: (url, ((None,) if _ONLINE else ()) + (_local_inventory(name, entries),))
    for name, (url, entries) in _LINKED.items()
}
intersphinx_timeout = 10


def _plain_text_math(app, what, name, obj, options, lines):
    """Docstrings write mathematics as plain text (|x|, a * b, mu_+), never reStructuredText
    substitutions, emphasis or references: escape those marks outside doctests and ``literals``."""
    for i, line in enumerate(lines):
        if line.lstrip().startswith((">>>", "...")):
            continue
        parts = re.split(r"(``[^`]*``)", line)
        for j, part in enumerate(parts):
            if not part.startswith("``"):
                part = part.replace("|", "\\|")
                part = re.sub(r"(?<=[\s(,])\*(?=[\s,)])", r"\\*", part)
                parts[j] = re.sub(r"(?<=\w)_(?=[^\w`]|$)", r"\\_", part)
        lines[i] = "".join(parts)


def setup(app):
    app.connect("autodoc-process-docstring", _plain_text_math)
