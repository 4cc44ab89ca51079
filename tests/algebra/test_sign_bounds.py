"""The term-by-term ranges behind known_sign's last test: a claimed sign holds at every sampled point."""

from __future__ import annotations

from fractions import Fraction

from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.sign_bounds import group_ranges, ranges_sign
from tests.helpers import small_fractions

# symbol 0: x > 0; symbol 1: y real of unknown sign; symbol 2: a sign symbol s = -+1
SCALE, REAL, BOUNDED = {0: 1, 1: None}, {0: True, 1: True, 2: True}, {2}
fractions = small_fractions(min_value=-5, max_value=5, max_denominator=7)
terms = st.lists(
    st.tuples(
        st.tuples(st.integers(0, 2), st.integers(0, 2), st.integers(0, 1)),
        fractions,
        fractions.map(abs),
    ),
    min_size=1,
    max_size=5,
)
points = st.tuples(
    st.floats(1e-3, 10),
    st.floats(-10, 10),
    st.sampled_from([-1, 1]),
    st.lists(st.floats(-1, 1), min_size=5, max_size=5),
)


def value(terms, point) -> float:
    """The sum of the terms at (x, y, s), each range's coefficient taken at centre + t * spread."""
    x, y, s, ts = point
    return sum(
        float(centre + Fraction(t) * spread) * x**a * y**b * s**c for ((a, b, c), centre, spread), t in zip(terms, ts)
    )


@settings(max_examples=100)
@given(terms, st.lists(points, min_size=8, max_size=8))
def test_a_claimed_sign_holds_at_every_sampled_point(terms, samples):
    sign = ranges_sign(group_ranges(terms, BOUNDED), SCALE, REAL)
    if sign is None:
        return
    for point in samples:
        assert sign * value(terms, point) > 0, (terms, point)


def test_an_odd_power_of_a_sign_symbol_makes_a_term_symmetric():
    # 1 + 2 s: s = -1 gives -1, so no sign; 3 + 2 s is positive for both signs
    assert ranges_sign(group_ranges([((0, 0, 0), 1, 0), ((0, 0, 1), 2, 0)], BOUNDED), SCALE, REAL) is None
    assert ranges_sign(group_ranges([((0, 0, 0), 3, 0), ((0, 0, 1), 2, 0)], BOUNDED), SCALE, REAL) == 1
