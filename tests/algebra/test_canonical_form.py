"""The canonical rational form: exact identities, canonicity, numeric agreement on random expressions."""

from __future__ import annotations

import random

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.basic import SignSymbol
from contactsym.algebra.canonical_form import canonical, present_factor, to_fraction

a, b, c = sp.symbols("a b c", real=True)
m, k = sp.symbols("m k", positive=True)
s = SignSymbol("s")

ATOMS = [sp.sin(a), sp.cos(a), sp.sin(b), sp.cos(b), sp.cos(a - b), sp.sin(2 * a), m, k, s]


def _value(expr, point):
    return complex(expr.subs(point).evalf(30))


def _random_point(rng):
    return {
        a: rng.uniform(-3, 3),
        b: rng.uniform(-3, 3),
        m: rng.uniform(0.5, 2),
        k: rng.uniform(0.5, 2),
        s: rng.choice([1, -1]),
    }


def test_trigonometric_identities_vanish_exactly():
    assert canonical(sp.sin(a) ** 2 + sp.cos(a) ** 2 - 1) == 0
    assert canonical(sp.cos(a - b) - sp.cos(a) * sp.cos(b) - sp.sin(a) * sp.sin(b)) == 0
    assert canonical(sp.sin(2 * a) - 2 * sp.sin(a) * sp.cos(a)) == 0
    assert canonical(sp.cos(3 * a) - 4 * sp.cos(a) ** 3 + 3 * sp.cos(a)) == 0
    assert canonical(s**2 - 1) == 0


def test_equal_fractions_read_the_same():
    first = (1 - sp.cos(a - b) ** 2) / (m * sp.sin(a - b) ** 2 + m * k)
    second = sp.sin(a - b) ** 2 / (m * (k + 1) - m * sp.cos(a - b) ** 2)
    assert canonical(first) == canonical(second)


def test_signs_leave_the_denominator():
    assert canonical(1 / s) == s
    assert canonical(m / (s * k)) == s * m / k


def test_the_two_link_denominator_reads_in_multiple_angles():
    # m + k sin^2(a - b) (the two-link mass determinant's factor) is shorter in the double angle
    fraction = to_fraction(1 / (m + k * sp.sin(a - b) ** 2))
    form, scale = present_factor(fraction.denom, fraction.pairs)
    assert sp.expand(form - (2 * m + k - k * sp.cos(2 * a - 2 * b))) == 0
    assert canonical(scale * form - fraction.denom.as_expr()) == 0


@st.composite
def _rational_trig(draw):
    def poly():
        terms = draw(
            st.lists(
                st.tuples(st.integers(-3, 3), st.lists(st.sampled_from(ATOMS), max_size=3)), min_size=1, max_size=4
            )
        )
        return sp.Add(*[coef * sp.Mul(*atoms) for coef, atoms in terms])

    numerator, denominator = poly(), poly()
    return numerator, denominator


@settings(max_examples=60, deadline=None)
@given(_rational_trig(), st.integers(0, 10**6))
def test_canonical_equals_the_input_at_random_points(pair, seed):
    numerator, denominator = pair
    if canonical(denominator) == 0:
        return
    expr = numerator / denominator
    rng = random.Random(seed)
    result = canonical(expr)
    for _ in range(3):
        point = _random_point(rng)
        d = _value(denominator, point)
        if abs(d) < 1e-6:
            continue
        assert abs(_value(expr, point) - _value(result, point)) <= 1e-9 * (1 + abs(_value(expr, point)))


@settings(max_examples=40, deadline=None)
@given(_rational_trig())
def test_canonical_is_idempotent(pair):
    numerator, denominator = pair
    if canonical(denominator) == 0:
        return
    once = canonical(numerator / denominator)
    assert canonical(once) == once
