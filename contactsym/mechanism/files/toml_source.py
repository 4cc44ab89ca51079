"""TOML text with positions: every error in a scene file names the file, the line and the fix.

``tomllib`` gives values without positions, so :class:`TomlSource` scans the text once
for table headers and keys and answers "on which line is this key, in which column does
this formula start". The scan is only used for messages; the values come from ``tomllib``.
"""

from __future__ import annotations

import difflib
import re
import sys

from ...arguments import checked
from ...errors import SceneFileError
from ...validate import cut, shorten

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

__all__ = ["SceneFileError", "TomlSource", "shown"]

_KEY = re.compile(r"""\s*(?:"([^"]*)"|'([^']*)'|([A-Za-z0-9_\-]+))\s*=""")


@checked
def shown(value) -> str:
    """A value as a message shows it: its repr, cut as every message cuts it (:func:`contactsym.validate.shorten`).

    Examples
    --------
    >>> shown("y")
    "'y'"
    """
    return shorten(value)


@checked
class TomlSource:
    """A parsed TOML document and where its keys are.

    Tables are named as in the file (``scene``, ``figures.values``); the n-th table of
    an array of tables ``[[contacts]]`` is ``contacts.n`` (from 0).

    Examples
    --------
    >>> doc = TomlSource('[scene]\\nname = "a"\\n[[contacts]]\\ngap = "y"\\n', "my.toml")
    >>> doc.data["contacts"][0]["gap"], doc.line("contacts.0", "gap")
    ('y', 4)
    >>> doc.fail("contacts.0", "gapp", "unknown key")
    Traceback (most recent call last):
    ...
    contactsym.errors.SceneFileError: my.toml:3: unknown key.
    """

    def __init__(self, text: str, source: str):
        self.source, self.lines = source, text.splitlines()
        try:
            self.data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as error:
            where = re.search(r"line (\d+), column (\d+)", str(error))
            line = f"{where.group(1)}:{where.group(2)}" if where else "1"
            reason = re.sub(r"\s*\(at .*\)$", "", str(error))
            raise SceneFileError(
                f"{source}:{line}: not valid TOML ({reason}); write key = value with formulas in quotes, "
                'e.g. gap = "y".'
            ) from None
        self._keys: dict = {}
        header, counts = "", {}
        for index, line in enumerate(self.lines):
            stripped = line.strip()
            if stripped.startswith("[["):
                name = stripped[2:].split("]]")[0].strip()
                counts[name] = counts.get(name, -1) + 1
                header = f"{name}.{counts[name]}"
            elif stripped.startswith("["):
                header = stripped[1:].split("]")[0].strip()
            else:
                match = _KEY.match(line)
                if match:
                    key = next(g for g in match.groups() if g is not None)
                    self._keys.setdefault((header, key), index)
                continue
            self._keys.setdefault((header, None), index)

    def line(self, table: str, key: str | None = None) -> int:
        """1-based line of ``key`` in ``table`` (of the table's header without a key; 1 if unknown)."""
        nested = f"{table}.{key}" if table else key
        parent = tuple(table.rsplit(".", 1)) if "." in table else (table, None)  # an inline table: its key's line
        for probe in ((table, key), (nested, None), (f"{nested}.0", None), (table, None), parent):
            if probe in self._keys:
                return self._keys[probe] + 1
        return 1

    def position(self, table: str, key: str | None, text: str) -> tuple[int, int]:
        """(1-based line, 0-based column) where the formula ``text`` starts, at or after the key."""
        first = self.line(table, key) - 1
        for index in range(first, min(first + 30, len(self.lines))):
            for quote in ('"', "'"):
                column = self.lines[index].find(quote + text + quote)
                if column >= 0:
                    return index + 1, column + 1
        return first + 1, 0

    def fail(self, table: str, key: str | None, message: str):
        """Raise a one-line SceneFileError at the key's line."""
        raise SceneFileError(f"{self.source}:{self.line(table, key)}: {message}.")

    def table(self, parent: dict, name: str, where: str, required: bool = False, kind=dict):
        """``parent[name]`` checked to be a table (or an array of tables with ``kind=list``)."""
        if name not in parent:
            if required:
                header = f"[[{name}]]" if kind is list else f"[{name}]"
                raise SceneFileError(f"{self.source}:1: no {header} table; add one (see examples/ for the format).")
            return kind()
        value = parent[name]
        if not isinstance(value, kind):
            shape = f"[[{name}]] tables" if kind is list else f"a [{name}] table"
            self.fail(where, name, f"'{name}' must be {shape}, not {type(value).__name__}")
        return value

    def keys(self, table: dict, where: str, allowed, required=()) -> None:
        """Unknown keys and missing keys of a table, each with the fix."""
        for key in table:
            if key not in allowed:
                close = difflib.get_close_matches(key, list(allowed), n=1)
                hint = f"did you mean '{close[0]}'? " if close else ""
                what = f"key '{cut(key)}' in [{where}]" if where else f"table [{cut(key)}]"
                self.fail(where, key, f"unknown {what}; {hint}allowed: {', '.join(allowed)}")
        for key in required:
            if key not in table:
                fix = f"[{where}] needs '{key}'; add {key} = ..." if where else f"no [{key}] table; add one"
                self.fail(where, None, fix)
