"""Signs at exact sample points never contradict a proof, and the disproof changes no answer of known_sign."""

from __future__ import annotations

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra import reductions
from contactsym.algebra.reductions import SignSymbol, known_sign
from contactsym.algebra.sign_samples import sampled_signs

m, k = sp.symbols("m k", positive=True)
x = sp.Symbol("x", real=True)
q1, q2 = sp.symbols("q1 q2", real=True)
s = SignSymbol("s")
ATOMS = [m, k, x, s, sp.sin(q1), sp.cos(q1), sp.cos(q1 - q2), sp.sin(2 * q2), sp.S.One]

terms = st.tuples(st.integers(-4, 6), st.lists(st.sampled_from(ATOMS), max_size=3)).map(lambda t: t[0] * sp.Mul(*t[1]))
expressions = st.lists(terms, min_size=1, max_size=5).map(lambda ts: sp.Add(*ts))
squares = st.lists(st.sampled_from(ATOMS), min_size=1, max_size=2).map(lambda ts: sp.Add(*ts) ** 2)


def without_samples(expr, positive):
    reductions._known_sign.cache_clear()
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reductions, "sampled_signs", lambda *args: set())
        found = known_sign(expr, positive)
    reductions._known_sign.cache_clear()
    return found


@settings(max_examples=60)
@given(st.one_of(expressions, st.tuples(expressions, squares).map(lambda p: p[0] ** 2 + p[1] + 1)))
def test_known_sign_is_the_same_with_and_without_the_sampled_disproof(expr):
    positive = (m - k,)
    proved = without_samples(expr, positive)
    assert known_sign(expr, positive) == proved
    if proved is not None:  # a proved sign is the only one any point of the domain shows
        assert reductions._sampled(expr, positive) <= {proved}  # angles expanded, s a unit


def test_points_outside_the_declared_positive_expressions_do_not_count():
    assert sampled_signs(k - m, positive=[m - k]) <= {-1}
    assert sampled_signs(x, positive=[x]) == {1}
