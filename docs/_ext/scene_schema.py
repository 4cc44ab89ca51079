"""The ``scene-file-schema`` directive: the scene-file reference, generated from the reader's schema.

It renders :data:`contactsym.mechanism.files.spec.SCHEMA` (every table, its keys, their kinds,
which are required) and the caps of :class:`~contactsym.mechanism.files.spec.Limits`, so the
reference page cannot drift from what the reader accepts.
"""

from __future__ import annotations

import inspect
from dataclasses import fields

from docutils import nodes
from docutils.statemachine import StringList
from sphinx.util.docutils import SphinxDirective


def _title(table: str) -> str:
    if not table:
        return "The file"
    head, _, entry = table.partition(".")
    array = head in _arrays()
    name = f"[[{head}]]" if array else f"[{head}]"
    return f"{name}, each entry" if entry == "entry" else (f"{name} {entry}" if entry else name)


def _arrays() -> set[str]:
    from contactsym.mechanism.files.spec import SCHEMA

    return {key for key, kind in (SCHEMA[""].keys or {}).items() if kind == "tables"}


def schema_lines() -> list[str]:
    """The reference as MyST-free reStructuredText lines."""
    from contactsym.mechanism.files.spec import SCHEMA, Limits, TableSchema

    # the kinds, as the schema's own docstring explains them
    lines = [*inspect.cleandoc(TableSchema.__doc__).splitlines()[2:], ""]
    for table, schema in SCHEMA.items():
        lines += [f".. rubric:: {_title(table)}", ""]
        if schema.keys is None:
            lines += [f"Free names, each a ``{schema.entries}``.", ""]
            continue
        lines += [".. list-table::", "   :header-rows: 1", "", "   * - key", "     - kind", "     - required"]
        for key, kind in schema.keys.items():
            lines += [f"   * - ``{key}``", f"     - {kind}", f"     - {'yes' if key in schema.required else ''}"]
        lines.append("")
    lines += [".. rubric:: Limits", "", inspect.cleandoc(Limits.__doc__).splitlines()[0], ""]
    for cap in fields(Limits):
        lines.append(f"- ``{cap.name}``: {cap.default}")
    return lines + [""]


class SceneFileSchema(SphinxDirective):
    has_content = False

    def run(self) -> list[nodes.Node]:
        container = nodes.section()
        self.state.nested_parse(StringList(schema_lines(), "scene-file-schema"), self.content_offset, container)
        return container.children


def setup(app):
    app.add_directive("scene-file-schema", SceneFileSchema)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
