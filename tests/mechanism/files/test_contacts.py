"""The table of laws a file may name: its entries, a new entry, and a law's true/false flags."""

from __future__ import annotations

import pytest
import sympy as sp

import contactsym as cs
from contactsym.mechanism.files.contacts import COMPLIANCE_LAWS, LawKind
from contactsym.mechanism.files.reader import read_scene
from contactsym.mechanism.files.toml_source import SceneFileError

BASE = """[scene]
coordinates = ["y"]
[parameters]
k = "positive"
[accelerations]
y = "N - 1"
[[contacts]]
gap = "y"
reaction = "N"
"""


def test_a_new_law_in_the_table_is_available_to_files(monkeypatch):
    monkeypatch.setitem(
        COMPLIANCE_LAWS,
        "stiff",
        LawKind(lambda formulas, flags, eps: cs.KelvinVoigt(formulas["k"], formulas["k"]), {"k": None}),
    )
    scene = read_scene(BASE + 'law = {name = "stiff", k = "2*k"}\n', "a.toml")
    k = sp.Symbol("k", positive=True)
    assert scene.contacts[0].compliance.phi_psi(None, None, None) == (-2 * k, -2 * k)
    with pytest.raises(SceneFileError, match=r"^a.toml:10: \[contacts.0.law\] needs 'k'"):
        read_scene(BASE + 'law = {name = "stiff"}\n', "a.toml")


def test_a_flag_of_a_law_is_true_or_false():
    law = 'law = {name = "law", N = "-k*q/eps^2 - q\'/eps", check = %s}\n'
    assert read_scene(BASE + law % "false", "a.toml").k == 1
    with pytest.raises(SceneFileError, match=r"^a.toml:10: check must be true or false, not 'no'"):
        read_scene(BASE + law % '"no"', "a.toml")


def test_friction_and_law_errors_are_placed_at_their_keys():
    text = BASE.replace('["y"]', '["x", "y"]').replace('y = "N - 1"', 'x = "0"\ny = "N - 1"')
    with pytest.raises(SceneFileError, match=r"^a.toml:11: direction names \['k'\] must be coordinates"):
        read_scene(text + 'friction = {mu = "k", direction = {k = "1"}}\n', "a.toml")
    assert read_scene(text + 'friction = {mu = "k", direction = {x = "1"}}\n', "a.toml").k == 1
