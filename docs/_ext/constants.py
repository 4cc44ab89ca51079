"""API pages for the public constants: every name of an ``__all__`` that is data, not code.

autosummary documents classes and functions from their docstrings; a constant (``lam``,
``SCHEMA``, ``REGION_NAMES``, ...) has none of its own, and a package that re-exports it has no
comment for it either. Each constant is documented where it is defined, by a ``#:`` comment
above its assignment (what it is, with a ``>>>`` example); this extension finds that comment
and writes one page per public constant, ``api/generated/<package>.<NAME>.rst``, next to
autosummary's pages. A public constant without such a comment is a build warning, so ``-W``
fails. ``tests/docs/test_constants.py`` runs the comments' examples.
"""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import pkgutil
import re
from functools import cache
from pathlib import Path

import contactsym

VALUE_SHOWN = 70  # characters of a constant's repr on its page; longer values are described, not shown


def packages() -> list[str]:
    """``contactsym`` and every subpackage, the modules whose ``__all__`` is public."""
    return ["contactsym"] + [m.name for m in pkgutil.walk_packages(contactsym.__path__, "contactsym.") if m.ispkg]


def is_constant(obj) -> bool:
    """Data rather than code: not a class, function, module or other callable."""
    return not (inspect.isclass(obj) or inspect.ismodule(obj) or callable(obj))


def constants() -> dict[str, list[str]]:
    """Package -> its public constants, in ``__all__`` order."""
    found = {}
    for package in packages():
        module = importlib.import_module(package)
        names = [name for name in getattr(module, "__all__", ()) if is_constant(getattr(module, name))]
        if names:
            found[package] = names
    return found


@cache
def _attribute_comments(module_name: str) -> dict[str, str]:
    from sphinx.pycode import ModuleAnalyzer

    try:
        docs = ModuleAnalyzer.for_module(module_name).find_attr_docs()
    except Exception:  # a module without source: nothing to read
        return {}
    return {name: "\n".join(lines).strip() for (scope, name), lines in docs.items() if scope == ""}


@cache
def _source(module_name: str) -> str:
    spec = importlib.util.find_spec(module_name)
    try:
        return Path(spec.origin).read_text(encoding="utf-8") if spec and spec.origin else ""
    except OSError:
        return ""


def _may_document(module_name: str, name: str) -> bool:
    """Whether the module's source has a ``#:`` comment and a line starting with ``name``."""
    text = _source(module_name)
    return "#:" in text and re.search(rf"^{re.escape(name)}\b", text, re.MULTILINE) is not None


def comment(package: str, name: str) -> tuple[str, str] | None:
    """(defining module, ``#:`` comment) of ``package.name``: the module of ``contactsym`` that
    documents an attribute of that name holding the same object; None when no module does."""
    obj = getattr(importlib.import_module(package), name)
    modules = [package] + [m.name for m in pkgutil.walk_packages(contactsym.__path__, "contactsym.")]
    for module_name in modules:
        if not _may_document(module_name, name):  # a parse of every module's source took ~5 s of the build
            continue
        text = _attribute_comments(module_name).get(name)
        if text and getattr(importlib.import_module(module_name), name, None) is obj:
            return module_name, text
    return None


def page(package: str, name: str) -> str:
    """The page of one constant, reStructuredText."""
    obj = getattr(importlib.import_module(package), name)
    home, text = comment(package, name) or ("", "")
    title = f"{package}.{name}"
    lines = [title, "=" * len(title), "", f".. currentmodule:: {package}", "", f".. py:data:: {name}"]
    shown = repr(obj)
    if len(shown) <= VALUE_SHOWN and "\n" not in shown:
        lines.append(f"   :value: {shown}")
    lines.append(f"   :type: {type(obj).__module__}.{type(obj).__qualname__}")
    lines.append("")
    lines += [f"   {line}" if line else "" for line in text.splitlines()]
    if home and home != package:
        lines += ["", f"   Defined in ``{home}``."]
    return "\n".join(lines) + "\n"


def _write_pages(app) -> None:
    out = Path(app.srcdir) / "api" / "generated"
    out.mkdir(parents=True, exist_ok=True)
    for package, names in constants().items():
        for name in names:
            if comment(package, name) is None:
                from sphinx.util import logging

                logging.getLogger(__name__).warning(
                    "public constant %s.%s has no '#:' comment where it is defined; add one with an example",
                    package,
                    name,
                )
            (out / f"{package}.{name}.rst").write_text(page(package, name))


def _summary(package: str, name: str) -> str:
    found = comment(package, name)
    return found[1].split("\n\n")[0].replace("\n", " ") if found else ""


def _context(app, config) -> None:
    """The module template's "Data" table: each package's constants and their one-line summaries."""
    found = constants()
    config.autosummary_context["constants"] = found
    config.autosummary_context["constant_summaries"] = {
        f"{package}.{name}": _summary(package, name) for package, names in found.items() for name in names
    }


def setup(app):
    # after conf.py emptied api/generated, before Sphinx lists the sources
    app.connect("config-inited", _context)
    app.connect("builder-inited", _write_pages)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
