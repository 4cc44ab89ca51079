"""Signs that follow from the mechanics: every sign known_sign claims is checked at random points, and
the cases it must prove (multiples of det M, dominated trigonometric polynomials) are proved."""

import random

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.reductions import SignSymbol, known_sign, quotient_sign

q1, q2, q3 = sp.symbols("q1 q2 q3", real=True)
m1, m2, l1 = sp.symbols("m1 m2 l1", positive=True)
x = sp.Symbol("x", real=True)
Phi = sp.Symbol("Phi", negative=True)
s = SignSymbol("s")
ANGLES = (q1, q2, q3)
TRIG = [sp.sin(q1), sp.cos(q1), sp.sin(q2), sp.cos(q2), sp.cos(q1 - q2), sp.sin(2 * q1 - q3), sp.cos(q3) ** 2]


def sampled_signs(expr, count=200, seed=0) -> set:
    """The signs of ``expr`` at random real angles and positive parameters (an independent check)."""
    rng = random.Random(seed)
    symbols = sorted(expr.free_symbols, key=str)
    function = sp.lambdify(symbols, expr, modules="math")  # compiled once, evaluated at every point
    found = set()
    for _ in range(count):
        values = {}
        for symbol in symbols:
            if isinstance(symbol, SignSymbol):
                values[symbol] = rng.choice((-1, 1))
            elif symbol.is_positive:
                values[symbol] = rng.uniform(0.01, 5)
            elif symbol.is_negative:
                values[symbol] = -rng.uniform(0.01, 5)
            else:
                values[symbol] = rng.uniform(-7, 7)
        value = float(function(*(values[symbol] for symbol in symbols)))
        found.add((value > 0) - (value < 0))
    return found


def trig_term(draw_index, coefficient):
    return coefficient * TRIG[draw_index % len(TRIG)] * TRIG[(draw_index // len(TRIG)) % len(TRIG)]


@settings(max_examples=50, deadline=None)
@given(
    st.lists(st.tuples(st.integers(0, 48), st.integers(-5, 5)), min_size=1, max_size=5),
    st.integers(0, 3),
    st.sampled_from([m1, m2 * l1, m1**2, Phi**2]),
)
def test_a_constant_that_outweighs_the_bounded_terms_is_proved_positive(terms, slack, scale):
    bounded = sp.Add(*[trig_term(i, c) for i, c in terms])
    constant = sum(abs(c) for _, c in terms) + slack + 1  # each product of two sines or cosines lies in [-1, 1]
    expr = sp.expand(scale * (constant + bounded))
    assert known_sign(expr) == 1
    assert known_sign(-expr) == -1
    assert sampled_signs(expr, count=40) == {1}


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 48), st.integers(-5, 5)), min_size=1, max_size=6), st.integers(-6, 6))
def test_every_claimed_sign_holds_at_random_points(terms, constant):
    expr = sp.expand(constant + m1 * sp.Add(*[trig_term(i, c) for i, c in terms]) + s * sp.cos(q2) + x**2)
    claimed = known_sign(expr)
    if claimed is not None:  # a proof, never a guess: no sample may contradict it
        assert sampled_signs(expr, count=60) == {claimed}


def test_multiples_of_a_listed_positive_expression_in_any_trigonometric_form():
    det = 8 * m1 - 9 * m2 * sp.cos(2 * q1 - 2 * q2) + 15 * m2  # det M of a two-link arm of rods, over m2 l1^2 l2^2
    p2 = sp.Rational(1, 2) * m2 * det
    expanded = sp.expand(sp.expand_trig(sp.expand(p2)))  # the same polynomial in sin q_i, cos q_i
    assert expanded != p2 and known_sign(expanded, [det]) == 1
    assert known_sign(-3 * l1 * expanded, [det]) == -1
    assert known_sign(sp.sin(q1) * det, [det]) is None  # sin q1 has no sign
    # det itself is dominated: 15 m2 - 9 m2 |cos| > 0
    assert known_sign(det) == 1 and sampled_signs(det) == {1}


def test_no_sign_is_claimed_for_an_expression_that_vanishes_or_changes_sign():
    for expr in (
        1 - sp.sin(q1) ** 2 - sp.cos(q1) ** 2 + sp.cos(q2) - sp.cos(q2),  # zero
        m1 * (sp.sin(q1) - sp.cos(q1)),  # changes sign
        m1 * sp.sin(q1 - q2) ** 2,  # >= 0, but zero at q1 = q2
        m1 - m2 * sp.cos(q1),  # the sign depends on m1/m2
        x * m1 + 1,
    ):
        assert known_sign(expr) is None, expr
        assert known_sign(-expr) is None, expr
    assert 1 in sampled_signs(m1 - m2 * sp.cos(q1)) and -1 in sampled_signs(m1 - m2 * sp.cos(q1))


def test_declared_positive_sines_narrow_the_range():
    theta = sp.Symbol("theta", real=True)
    expr = 3 * sp.sin(theta) * sp.cos(theta) + 1  # positive for 0 < theta < pi/2 only
    assert known_sign(expr) is None
    assert known_sign(expr, [sp.sin(theta), sp.cos(theta)]) == 1
    rng = random.Random(2)
    assert all(expr.subs(theta, rng.uniform(0, 1.5707)) > 0 for _ in range(50))
    assert expr.subs(theta, -0.5) < 0  # outside the interval the sign changes: the declaration is needed


def test_quotient_sign_divides_modulo_sin_squared_plus_cos_squared():
    b = (sp.sin(q1) ** 2 * m1 - m1 + m2 * sp.cos(q2)) / (m2 * (2 + sp.cos(q1 - q2)))
    multiple = Phi * l1 * (-m1 * sp.cos(q1) ** 2 + m2 * sp.cos(q2))  # Phi l1 times the numerator of b
    assert sp.cancel(multiple / b).has(sp.cos(q1)) and known_sign(sp.cancel(multiple / b)) is None
    assert quotient_sign(multiple, b) == -1
    ratio = sp.lambdify((q1, q2, m1, m2, l1, Phi), multiple / b)
    rng = random.Random(1)
    for _ in range(50):
        value = ratio(rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(0.1, 3), rng.uniform(0.1, 3), 1.0, -1.0)
        assert value < 0
    assert quotient_sign(multiple + m1, b) is None
