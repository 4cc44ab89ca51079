"""The argument checks of ``contactsym.arguments``: each hint refuses what it rules out, with a clear message."""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Literal

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from benchmarks import boundary
from contactsym.arguments import between, checked, describe, fits
from contactsym.errors import ArgumentError

WRONG = boundary.wrong_values()
HINTS = [int, float, bool, str, sp.Expr, sp.Symbol, sp.Poly, sp.Matrix, np.ndarray, dict, Mapping, Sequence, tuple]
HINTS += [list[sp.Expr], tuple[int, ...], Sequence[int] | None, Mapping[str, float], Callable, Literal["a", "b"]]


def test_a_value_the_probe_rules_out_is_refused():
    """The checks are at least as strict as the probe's judge: no wrong type can pass them silently.
    Every pair of the probe's wrong values and these hints (a sample of them missed pairs that other
    seeds found: an array against a Literal, an array as a Sequence)."""
    passed = [
        (value, hint) for value in WRONG for hint in HINTS if not boundary.matches(value, hint) and fits(value, hint)
    ]
    assert not passed, passed[:5]


@pytest.mark.parametrize(
    ("value", "hint", "expected"),
    [
        (3, int, True),
        (True, int, False),
        (10**30, int, False),
        (2.5, float, True),
        (float("nan"), float, False),
        (float("inf"), float, False),
        ("x", sp.Expr, False),
        (sp.Symbol("a") + 1, sp.Expr, True),
        (sp.oo * sp.Symbol("a"), sp.Expr, False),
        (sp.Symbol("a") > 0, sp.Expr, True),
        (sp.Tuple(1, 2), sp.Expr, False),
        ([sp.Symbol("a"), 2], list[sp.Expr], True),
        (["a"], list[sp.Expr], False),
        ("ab", Sequence, False),
        ((1, -1), tuple[int, ...], True),
        ((1, 0.5), tuple[int, ...], False),
        (np.array([1.5]), Sequence[int], False),
        ("a", Literal["a", "b"], True),
        ("c", Literal["a", "b"], False),
        (5, between(1, 8), True),
        (9, between(1, 8), False),
        (print, Callable, True),
        (3, Callable, False),
    ],
)
def test_fits_judges_each_kind_of_hint(value, hint, expected):
    assert fits(value, hint) is expected


def test_a_checked_function_names_the_parameter_what_it_got_and_what_to_pass():
    @checked(scene="Scene")
    def stages(scene, signs: tuple[int, ...] | None = None, *, depth: int = 1) -> int:
        return depth

    assert stages(cs.scene("brake"), (1, 1), depth=3) == 3
    with pytest.raises(ArgumentError, match=r"stages: scene = 3 \(int\) is not accepted; pass a Scene\."):
        stages(3)
    with pytest.raises(ArgumentError, match="signs = 'no'.*a tuple, each item a whole number, or None"):
        stages(cs.scene("brake"), "no")
    with pytest.raises(ArgumentError, match="depth = 1.5"):
        stages(cs.scene("brake"), depth=1.5)
    assert "scene" not in stages.__annotations__  # the annotations stay as written: get_type_hints still works
    assert isinstance(ArgumentError("x"), (cs.ContactsymError, TypeError))


def test_a_checked_dataclass_checks_its_fields_and_numbers_become_sympy_numbers():
    @checked
    @dataclass(frozen=True)
    class Pair:
        left: sp.Expr
        right: str = "x"

    assert Pair(2).left == sp.Integer(2) and isinstance(Pair(2).left, sp.Integer)
    with pytest.raises(ArgumentError, match="Pair: left"):
        Pair("2 + 2")
    assert describe(Mapping[str, float]) == "a mapping (a dict) from text to a finite real number"


def test_no_user_text_reaches_sympify_in_hurwitz():
    os.environ.pop(boundary.FLAG, None)
    with pytest.raises(ArgumentError, match="Hurwitz: poly"):
        cs.algebra.Hurwitz(boundary.SENTINEL)
    assert boundary.FLAG not in os.environ


def test_a_region_asked_without_its_values_raises_a_package_error():
    region = cs.scene("brake").regions()
    some = next(iter(region.values()))
    with pytest.raises(cs.ContactsymError, match="give values for"):
        some.contains()
    with pytest.raises(cs.ContactsymError, match="give values for"):
        some.evaluate()


def test_counts_that_would_run_for_ever_are_refused_at_once():
    from contactsym.algebra import sign_symbols
    from contactsym.counts import orthant_patterns
    from contactsym.stages import generic_minors

    for call in (lambda: sign_symbols(10**30), lambda: orthant_patterns(10**6), lambda: generic_minors(10**9)):
        with pytest.raises(ArgumentError, match="from"):
            call()


def test_an_array_against_a_literal_is_refused_not_compared():
    """Found with --hypothesis-seed=11: ``array == 'a'`` has no truth value; the type is asked first."""
    assert not fits(np.array([[1.0, 2.0]]), Literal["a", "b"])
    assert fits("a", Literal["a", "b"]) and not fits(True, Literal[1, -1])
