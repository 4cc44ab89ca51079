"""The Hopf set and frequency as printed: each coefficient p_s in its shortest form, the same set and number."""

from __future__ import annotations

import random

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from benchmarks._derive_worker import generic_scene
from contactsym.stages.stability import shortest_form

a, b, c, d = sp.symbols("a b c d", real=True)
P, Q = sp.symbols("Phi Psi", negative=True)
SYMBOLS = (a, b, c, d, P, Q)


@st.composite
def polynomials(draw):
    terms = []
    for _ in range(draw(st.integers(1, 5))):
        chosen = draw(st.lists(st.sampled_from(SYMBOLS), max_size=3, unique=True))
        terms.append(draw(st.integers(-3, 3)) * sp.Mul(*chosen))
    return sp.expand(sp.Add(*terms) * draw(st.sampled_from([1, a, P, a + P, b * c - d])))


@settings(max_examples=20, deadline=None)
@given(polynomials())
def test_the_shortest_form_is_the_same_polynomial_and_never_longer(p):
    short = shortest_form(p, (P, Q))
    assert sp.expand(short - p) == 0
    assert sp.count_ops(short) <= sp.count_ops(p)


def test_generic_k2_hopf_set_and_frequency_as_printed_are_the_derived_ones():
    stability = generic_scene(2).stability()
    omega, printed = stability.hopf_frequency, stability.hopf_frequency_printed
    assert sp.count_ops(printed) <= sp.count_ops(omega)
    symbols = sorted(omega.free_symbols | stability.hopf.free_symbols, key=str)
    rng = random.Random(5)
    for _ in range(20):
        point = {}
        for s in symbols:
            value = sp.Rational(rng.randint(1, 40), rng.randint(1, 9))
            point[s] = -value if s.is_negative or (not s.is_positive and rng.random() < 0.5) else value
        assert omega.xreplace(point) ** 2 - printed.xreplace(point) ** 2 == 0
        assert stability.hopf.xreplace(point) == stability.hopf_printed.xreplace(point)
