"""The presented form of a trigonometric fraction (algebra.trig_field)."""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.trig_field import _roots_back, _split_monomial, to_fraction

q1, q2, m, l = sp.symbols("q1 q2 m l", positive=True)
ATOMS = [sp.sin(q1), sp.cos(q1), sp.cos(q2), m, l, sp.sqrt(m), m ** sp.Rational(1, 3)]
MONOMIALS = [sp.S.One, sp.S(2), sp.Rational(3, 2) * m, m**2 * l, 3 * l * sp.sin(q1), 4 * sp.sqrt(m)]
POINT = {q1: sp.Rational(3, 7), q2: sp.Rational(-5, 4), m: sp.Rational(9, 5), l: sp.Rational(2, 3)}

terms = st.tuples(st.integers(-5, 5), st.lists(st.sampled_from(ATOMS), max_size=4)).map(lambda t: t[0] * sp.Mul(*t[1]))


@settings(max_examples=80)
@given(st.lists(terms, min_size=1, max_size=6), st.sampled_from(MONOMIALS))
def test_a_fraction_over_a_monomial_reads_as_its_expanded_quotient(numerator, monomial):
    """Shown term by term, it is the expression that expanding numerator / monomial gives, and
    it has the value of what was written."""
    written = sp.Add(*numerator) / monomial
    fraction = to_fraction(written)
    divisor, rest = _split_monomial(fraction.denom)
    if rest != 1:
        return
    shown = fraction.as_expr()
    assert shown == _roots_back(sp.expand(fraction.numer.as_expr() / divisor.as_expr()))
    assert abs(sp.N((shown - written).subs(POINT), 30)) < 1e-25
