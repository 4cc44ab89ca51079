"""Fuzz the public API and the command line (the cases of ``benchmarks/fuzz.py``, fewer of them).

Each generated input must end as a clear ContactsymError or, when valid, as a sound
result: no raw traceback, no silent acceptance of a bad input, no nan in a result that
says "ok", no claim from a non-finite input, no hang (each call has a time limit).
"""

from __future__ import annotations

import os
import random

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from benchmarks import fuzz


@pytest.mark.parametrize("make", fuzz.CASES, ids=[f.__name__ for f in fuzz.CASES])
@settings(max_examples=15, deadline=None)
@given(seed=st.integers(min_value=0, max_value=2**32 - 1))
def test_fuzz_gives_a_clear_error_or_a_sound_result(make, seed):
    case = make(random.Random(seed))
    kind, detail = fuzz.outcome(case, seconds=20)
    assert kind in ("clear error", "accepted"), f"{case.target}: {kind}: {detail}"


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
