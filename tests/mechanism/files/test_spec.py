"""The reader's boundary, generated from its schema: every key of every table with a value of a wrong kind.

One valid document holds every key of every table of ``SCHEMA``; each generated case puts a
value of another kind at one key (or a bad entry into a table of free names) and expects one
clear line naming the file and a line inside that table, never a raw exception.
"""

from __future__ import annotations

import copy
import json

import pytest

from contactsym.mechanism.files.reader import read_scene, read_spec
from contactsym.mechanism.files.spec import SCHEMA
from contactsym.mechanism.files.toml_source import SceneFileError
from contactsym.parse import ParseError

BASE = {
    "scene": {"name": "probe", "description": "every key", "coordinates": ["x", "y", "theta"], "solve_for": "mu"},
    "parameters": {
        "m": "positive",
        "mu": "positive",
        "J": {"assume": "positive", "symbol": "J", "interval": [0, 5]},
        "F": "real",
        "G": "real",
    },
    "intervals": {"theta": [0, "pi/2"]},
    "functions": {"X": ["x", "x'"]},
    "points": {"C": ["x", "y"], "P": {"position": ["x", "y - 1"], "body": "C", "angle": "theta"}},
    "masses": [{"point": "C", "mass": "m"}],
    "bodies": [{"point": "C", "angle": "theta", "mass": "m", "inertia": "J"}],
    "energy": {"kinetic": "m*x'^2/2", "potential": "m*y"},
    "loads": [{"point": "C", "force": ["X", "F"]}, {"angle": "theta", "moment": "F"}],
    "contacts": [
        {
            "gap": "y",
            "reaction": "N",
            "unilateral": True,
            "law": {"name": "kelvin-voigt", "stiffness": 1, "damping": 2},
            "friction": {"mu": "mu", "point": "P", "direction": ["-1", "0"]},
        },
        {
            "gap": "x",
            "reaction": "R",
            "law": "generic",
            "friction": {"viscous": "mu", "point": "C", "direction": ["0", "1"]},
        },
    ],
    "at": {"G": "F"},
    "presentation": {"F": "2*G"},
    "count_presentation": {"F": "2*G"},
    "figures": {"x": "theta", "y": "mu", "x_range": [0.1, 1.5], "y_range": [0, 2], "values": {"m": 1, "J": 1}},
    "values": {"J": "1/2"},
}

#: A spatial document (dimensions = 3) holding the keys only a scene in space has.
SPATIAL = {
    "scene": {"coordinates": ["x", "y", "z", "psi", "theta", "phi"], "dimensions": 3},
    "parameters": {"m": "positive", "l": "positive", "J": "positive", "mu": "positive", "F": "real"},
    "intervals": {"theta": [0, "pi/2"]},
    "frames": {
        "base": {"space_fixed": "zyx", "angles": ["0", "0", "0"]},
        "tilt": {"euler_parameters": ["1", "0", "0", "0"], "relative_to": "base"},
        "rod": {"body_fixed": "zyx", "angles": ["psi", "theta", "phi"], "relative_to": "tilt"},
    },
    "points": {
        "C": ["x", "y", "z"],
        "B": {"position": ["x", "y", "z"]},
        "P": {"body": "C", "frame": "rod", "offset": ["l", "0", "0"]},
    },
    "masses": [{"point": "B", "mass": "m"}],
    "bodies": [{"point": "C", "frame": "rod", "mass": "m", "inertia": ["J", "m*l^2/3", "m*l^2/3"]}],
    "loads": [{"point": "C", "force": ["0", "0", "-m"]}, {"frame": "rod", "moment": ["F", "0", "0"]}],
    "contacts": [
        {
            "gap": {"point": "P", "normal": ["0", "0", "1"], "distance": "0"},
            "reaction": "N",
            "friction": {"mu": "mu", "point": "P", "direction": ["1", "0", "0"]},
        }
    ],
}

#: Values of another kind than each kind of the schema (a formula gets text outside the grammar too).
WRONG = {
    "formula": [True, [1, 2], {"a": 1}, "x +", "nope", "1e400"],
    "names": ["x", [1], True, ["x +"]],
    "pair": ["x", ["1"], [True, 1], {"a": 1}, ["1", "2", "3"]],
    "numbers": ["x", [1], [True, 1], ["1", "nope"], [2, 1]],
    "number": ["1", True, [1], float("nan")],
    "bool": ["yes", 1],
    "text": [1, ["a"], True],
    "label": [1, ["a"], "a b/c"],
    "name": [1, "nosuch", ["C"], True],
    "new name": [1, "x", "2a", ["N"]],
    "table": [1, "x", [1]],
    "tables": [1, "x", {"a": 1}, [1]],
    "law": [1, "hertz", {"name": 1}, {"name": "law"}, {"name": "generic", "stiffness": 1}],
    "entry": [1, True, "x"],
    "formulas": ["x", [True], {"a": 1}, ["x +"]],
}

#: In space a pair is three formulas (x, y, z).
WRONG_IN_SPACE = {**WRONG, "pair": ["x", ["1"], [True, 1, 1], {"a": 1}, ["1", "2"]]}

#: Bad entries of the tables of free names.
WRONG_ENTRIES = {
    "parameters": [1, True, "postive", {"assume": 1}, {"symbol": "\\x"}, [2, 1], "x"],
    "intervals": ["x", [2, 1], [True, 1], "theta"],
    "functions": ["x", [1], ["nope"]],
    "points": [1, True, ["x"], {"position": ["x", "y"], "body": "Q", "angle": "theta"}],
    "at": [True, [1], "nope"],
    "presentation": [True, [1], "nope"],
    "count_presentation": [True, [1], "nope"],
    "figures.values": ["1", True, [1]],
    "frames": [1, True, "x", {"body_fixed": "zyx"}, {"body_fixed": "zyy", "angles": ["0", "0", "0"]}],
}


def _toml(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float) and value != value:
        return "nan"
    if isinstance(value, (int, float)):
        return repr(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return "{" + ", ".join(f"{json.dumps(k)} = {_toml(v)}" for k, v in value.items()) + "}"


def _is_tables(value) -> bool:
    return isinstance(value, list) and bool(value) and all(isinstance(v, dict) for v in value)


def dump(document: dict) -> tuple[str, dict]:
    """TOML text of a document and the lines (first, last) of each table, by the names TomlSource uses."""
    lines = [f"{k} = {_toml(v)}" for k, v in document.items() if not isinstance(v, dict) and not _is_tables(v)]
    blocks = {"": (1, max(len(lines), 1))}
    for key, value in document.items():
        entries = [(key, value, f"[{key}]")] if isinstance(value, dict) else []
        if _is_tables(value):
            entries = [(f"{key}.{i}", v, f"[[{key}]]") for i, v in enumerate(value)]
        for name, table, header in entries:
            first = len(lines) + 1
            lines += [header, *(f"{json.dumps(k)} = {_toml(v)}" for k, v in table.items())]
            blocks[name] = (first, len(lines))
    return "\n".join(lines) + "\n", blocks


def _where(schema: str, document: dict) -> tuple[list, str]:
    """(path of the table in the document, name of its block) for a table of the schema."""
    paths = {
        "": ([], ""),
        "parameters.entry": (["parameters", "J"], "parameters"),
        "points.entry": (["points", "P"], "points"),
        "contacts.friction": (["contacts", 0, "friction"], "contacts.0"),
        "figures.values": (["figures", "values"], "figures"),
        "frames.entry": (["frames", "rod"], "frames"),
        "contacts.gap": (["contacts", 0, "gap"], "contacts.0"),
    }
    if schema in paths:
        return paths[schema]
    if isinstance(document.get(schema), list):
        return [schema, 0], f"{schema}.0"
    return [schema], schema


def _holds(document: dict, schema: str, key: str | None) -> bool:
    try:
        table = _table_of(document, schema, key)[0]
    except (KeyError, IndexError, TypeError):
        return False
    return key is None or key in table


def _document(schema: str, key: str | None) -> dict:
    """BASE (a scene in the plane), or SPATIAL for the keys that only a scene in space has."""
    return BASE if _holds(BASE, schema, key) else SPATIAL


def _cases():
    for schema, rules in SCHEMA.items():
        if rules.keys is not None:
            for key, kind in rules.keys.items():
                if key == "accelerations":  # the other way to give the motion: see ACCELERATIONS
                    continue
                wrongs = WRONG if _document(schema, key) is BASE else WRONG_IN_SPACE
                for index, wrong in enumerate(wrongs[kind]):
                    yield pytest.param(schema, key, wrong, id=f"{schema or 'top'}.{key}={kind}#{index}")
        for index, wrong in enumerate(WRONG_ENTRIES.get(schema, ())):
            yield pytest.param(schema, None, wrong, id=f"{schema}.<entry>#{index}")


def _table_of(document: dict, schema: str, key: str | None):
    """The table of the document that the schema's table names (the entry of an array that holds ``key``)."""
    path, block = _where(schema, document)
    table = document
    for step in path:
        table = table[step]
    array = path[0] if path and isinstance(document.get(path[0]), list) else None
    if schema == "frames.entry" and key is not None and key not in table:  # the frame that has the key
        name = next((n for n, entry in document["frames"].items() if key in entry), path[1])
        return document["frames"][name], block
    if array and key is not None and key not in table:
        for index, entry in enumerate(document[array]):
            inner = entry.get(path[2]) if len(path) > 2 else entry
            if key in inner:
                return inner, f"{array}.{index}"
    return table, block


def test_the_base_documents_are_valid_and_hold_every_key_of_the_schema():
    text, _ = dump(BASE)
    scene = read_scene(text, "b.toml")
    assert scene.k == 2 and scene.figure_plan.x == "theta"
    assert read_spec(dump(SPATIAL)[0], "s.toml").space is not None
    for schema, rules in SCHEMA.items():
        if rules.keys is not None:
            present = {key for key in rules.keys if _holds(BASE, schema, key) or _holds(SPATIAL, schema, key)}
            assert set(rules.keys) - {"accelerations"} == present, schema


@pytest.mark.parametrize("schema, key, wrong", list(_cases()))
def test_a_wrong_kind_at_any_key_gives_one_line_at_its_table(schema, key, wrong):
    document = copy.deepcopy(_document(schema, key))
    table, block = _table_of(document, schema, key)
    table[key if key is not None else "zz" if schema != "figures.values" else "m"] = wrong
    text, blocks = dump(document)
    with pytest.raises((SceneFileError, ParseError)) as raised:
        read_spec(text, "b.toml")
    message = str(raised.value)
    assert message.startswith("b.toml:") and message.endswith(".") and "\n" not in message, message
    line = int(message.split(":")[1])
    if schema == "" and isinstance(wrong, dict):  # written as a table of its own
        block = key
    first, last = blocks[block]
    assert first <= line <= last, (message, blocks[block])


ACCELERATIONS = {
    "scene": {"coordinates": ["x", "y"]},
    "parameters": {"mu": "positive"},
    "accelerations": {"x": "0", "y": "N - 1"},
    "contacts": [{"gap": "y", "reaction": "N", "friction": {"mu": "mu", "direction": {"x": "1"}}}],
}


@pytest.mark.parametrize(
    "path, wrong",
    [(["accelerations"], w) for w in WRONG["table"]]
    + [(["accelerations", "y"], w) for w in WRONG["formula"]]
    + [(["accelerations", "z"], "0"), (["contacts", 0, "friction", "direction"], ["1", "0"])]
    + [(["contacts", 0, "friction", "direction"], {"mu": "1"}), (["contacts", 0, "gap"], "x + y")],
)
def test_a_wrong_kind_in_a_file_with_accelerations_gives_one_line(path, wrong):
    document = copy.deepcopy(ACCELERATIONS)
    assert read_scene(dump(document)[0], "b.toml").k == 1
    table = document
    for step in path[:-1]:
        table = table[step]
    table[path[-1]] = wrong
    with pytest.raises((SceneFileError, ParseError)) as raised:
        read_spec(dump(document)[0], "b.toml")
    message = str(raised.value)
    assert message.startswith("b.toml:") and message.endswith(".") and "\n" not in message, message
