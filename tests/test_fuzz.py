"""Fuzz the public boundary: a seeded sample of the generated probe of ``benchmarks/fuzz.py``, and its hand cases.

Each generated call must end as a clear ContactsymError or, when no argument breaks its
type hint, as a result: no raw traceback, no silent acceptance of a wrong type, no hang
(each call runs in a worker process with a time limit). The entry points a user meets
first (``contactsym.__all__``, ``contactsym.atlas``, ``contactsym.report``, the command
line) must pass every call; for the rest of the boundary, ``benchmarks/boundary_known.txt``
lists the callables the full probe still catches (see docs/robustness.md), and any other
callable that fails here is a regression.
"""

from __future__ import annotations

import os
import random
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from benchmarks import boundary, fuzz

KNOWN = {
    line.split("#")[0].strip()
    for line in (Path(__file__).resolve().parent.parent / "benchmarks" / "boundary_known.txt").read_text().splitlines()
    if line.split("#")[0].strip()
}
TOP = {f"contactsym.{name}" for name in cs.__all__}


def first(label: str) -> bool:
    """An entry point a user meets first: held to zero failures, never listed in KNOWN."""
    return label in TOP or label.startswith(("contactsym.atlas.", "contactsym.report.", "cli "))


@pytest.fixture(scope="module")
def sample():
    """One call per public callable (seed 0), in two worker processes with a 20 s limit per call."""
    labels = fuzz.probe_targets()
    return fuzz.probe(len(labels), seed=0, seconds=20, workers=2)


def test_the_probe_covers_every_public_callable_and_the_cli():
    labels = fuzz.probe_targets()
    for package in boundary.PACKAGES:
        module = __import__(package, fromlist=["__all__"])
        for name in module.__all__:
            obj = getattr(module, name)
            if callable(obj) and not (isinstance(obj, type) and issubclass(obj, BaseException)):
                assert any(label.endswith(f".{name}") or label.startswith(f"{obj.__name__}.") for label in labels), name
    assert {"cli show", "cli conditions", "cli report", "cli atlas", "cli bench", "cli list"} <= set(labels)
    assert any(label.startswith("Scene.") for label in labels) and len(labels) > 250


def test_the_first_entry_points_give_a_clear_error_or_a_result(sample):
    totals, by_target, failures = sample
    found = [f for f in failures if first(f[0])]
    assert not found, "\n".join(f"{kind}: {target}: {detail}" for target, kind, detail in found[:20])
    assert not {label for label in KNOWN if first(label)}


def test_no_other_callable_fails_that_the_full_probe_did_not_catch(sample):
    totals, by_target, failures = sample
    new = sorted({target for target, kind, detail in failures} - KNOWN)
    assert not new, "\n".join(f"{k}: {t}: {d}" for t, k, d in failures if t in new)[:4000]


@pytest.mark.parametrize("make", fuzz.CASES, ids=[f.__name__ for f in fuzz.CASES])
@settings(max_examples=6, deadline=None)
@given(seed=st.integers(min_value=0, max_value=2**32 - 1))
def test_fuzz_gives_a_clear_error_or_a_sound_result(make, seed):
    case = make(random.Random(seed))
    kind, detail = fuzz.outcome(case, seconds=20)
    assert kind in ("clear error", "accepted"), f"{case.target}: {kind}: {detail}"


def test_type_hints_are_judged_as_written():
    assert not boundary.matches("no", bool) and boundary.matches(False, bool)
    assert not boundary.matches(True, int) and boundary.matches(3, float) and not boundary.matches("3", float)
    assert boundary.matches(None, "int | None") and not boundary.matches("x", "int | None")
    assert not boundary.matches(cs.scene("brake"), "str") and boundary.matches(cs.scene("brake"), "Scene")
    assert boundary.matches(object(), "Scene")  # a class the hint names but this process cannot see: not judged
    assert not boundary.matches(3.0, "Scene")


def test_the_fuzz_notices_each_kind_of_failure():
    """The harness itself: each outcome is reachable, so a passing fuzz run means something."""

    def raise_(error):
        raise error

    def evaluate():
        return sp.sympify(fuzz.SENTINEL)

    def spin():
        while True:
            pass

    assert fuzz.outcome(fuzz.Case("t", lambda: raise_(KeyError("k")), True))[0] == "raw traceback"
    assert fuzz.outcome(fuzz.Case("t", lambda: raise_(cs.SceneError("x\n" * 300)), True))[0] == "raw traceback"
    assert fuzz.outcome(fuzz.Case("t", lambda: 1, True))[0] == "silent acceptance"
    assert fuzz.outcome(fuzz.Case("t", lambda: 1, False, lambda r: False))[0] == "bad result"
    assert fuzz.outcome(fuzz.Case("t", evaluate, True))[0] == "evaluated text"
    assert fuzz.outcome(fuzz.Case("t", lambda: raise_(cs.SceneError("clear")), True))[0] == "clear error"
    assert fuzz.outcome(fuzz.Case("t", spin, False), seconds=0.2)[0] == "hang"
    assert fuzz.FLAG not in os.environ


def test_text_is_never_executed_where_expressions_are_taken():
    x, y = fuzz.x, fuzz.y
    contact = cs.Contact(coordinate=y, reaction=fuzz.N)
    calls = [
        lambda: cs.Scene.from_accelerations([x, y], [fuzz.SENTINEL, fuzz.N], [contact]),
        lambda: cs.Scene.from_accelerations([x, y], [0, fuzz.N], [contact], eps=fuzz.SENTINEL),
        lambda: cs.KelvinVoigt(fuzz.SENTINEL, 1),
    ]
    executed = [fuzz.outcome(fuzz.Case("text", call, True))[0] == "evaluated text" for call in calls]
    assert executed == [False, False, False]


def test_slow_valid_calls_get_their_measured_limit_and_wrong_calls_do_not():
    slow = next(iter(fuzz.SLOW_VALID))
    assert fuzz.call_limit(slow, [], 30.0) == fuzz.SLOW_VALID[slow] > 30.0
    assert fuzz.call_limit(slow, ["dpi"], 30.0) == 30.0  # a wrong argument must be refused at once
    assert fuzz.call_limit("contactsym.scene", [], 30.0) == 30.0
