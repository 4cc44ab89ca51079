"""TOML text with positions: the line of a key, in tables, arrays of tables and inline tables."""

from __future__ import annotations

import pytest

from contactsym.mechanism.files.toml_source import SceneFileError, TomlSource

TEXT = """[scene]
name = "a"
[[contacts]]
gap = "y"
[[contacts]]
gap = "x"
friction = { mu = "mu", direction = ["1", "0"] }
[figures]
x = "m"
values = { m = 1, "x'" = 2 }
"""


@pytest.mark.parametrize(
    "table, key, line",
    [
        ("scene", "name", 2),
        ("contacts.0", "gap", 4),
        ("contacts.1", "gap", 6),
        ("contacts.1", "friction", 7),
        ("figures", "x", 9),
        ("figures.values", "m", 10),  # an inline table: the line of its key
        ("figures.values", "x'", 10),
        ("figures", None, 8),
        ("nowhere", None, 1),
    ],
)
def test_every_key_is_found_on_its_line(table, key, line):
    assert TomlSource(TEXT, "t.toml").line(table, key) == line


def test_unknown_keys_get_the_nearest_allowed_one_and_missing_keys_the_fix():
    doc = TomlSource(TEXT, "t.toml")
    with pytest.raises(SceneFileError, match=r"^t.toml:3: unknown key 'gapp' in \[contacts.0\]; did you mean 'gap'\?"):
        doc.keys({"gapp": 1}, "contacts.0", ("gap", "reaction"))
    with pytest.raises(SceneFileError, match=r"^t.toml:3: \[contacts.0\] needs 'reaction'; add reaction = \.\.\."):
        doc.keys({"gap": 1}, "contacts.0", ("gap", "reaction"), ("reaction",))
    doc.keys({"gap": 1}, "contacts.0", ("gap", "reaction"))  # a valid table passes


def test_bad_toml_is_one_line_with_its_position():
    with pytest.raises(SceneFileError, match=r"^t.toml:2:\d+: not valid TOML"):
        TomlSource('[scene]\nname = "a\n', "t.toml")
