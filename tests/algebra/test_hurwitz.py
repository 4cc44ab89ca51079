"""Hurwitz matrix and minors, Liénard–Chipart conditions, Hopf frequency."""

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, event, given, settings
from hypothesis import strategies as st

from contactsym.algebra.hurwitz import Hurwitz, hopf_omega_squared, hurwitz_matrix, hurwitz_minors, lienard_chipart
from tests.helpers import small_fractions

x = sp.Symbol("x")


def generic(n):
    return sp.symbols(f"c_0:{n + 1}")


def generic_poly(n):
    c = generic(n)
    return sp.Poly(sum(c[i] * x ** (n - i) for i in range(n + 1)), x)


def textbook_hurwitz(coefficients):
    """Row i (0-based) holds a_1, a_3, a_5, ... on odd rows shifted right; built row by row."""
    a = list(coefficients)
    n = len(a) - 1
    rows = []
    for i in range(n):
        # row i: a_(2j + 1 - i) for j = 0..n-1, i.e. odd coefficients on even rows, even on odd rows
        rows.append([a[2 * j + 1 - i] if 0 <= 2 * j + 1 - i <= n else 0 for j in range(n)])
    return sp.Matrix(rows)


# --- hurwitz_matrix / hurwitz_minors ----------------------------------------------


def test_hurwitz_matrix_cubic():
    a = sp.symbols("a0:4")
    assert hurwitz_matrix(a) == sp.Matrix([[a[1], a[3], 0], [a[0], a[2], 0], [0, a[1], a[3]]])


def test_hurwitz_matrix_quintic():
    a = sp.symbols("a0:6")
    expected = sp.Matrix(
        [
            [a[1], a[3], a[5], 0, 0],
            [a[0], a[2], a[4], 0, 0],
            [0, a[1], a[3], a[5], 0],
            [0, a[0], a[2], a[4], 0],
            [0, 0, a[1], a[3], a[5]],
        ]
    )
    assert hurwitz_matrix(a) == expected


@pytest.mark.parametrize("n", range(1, 9))
def test_hurwitz_matrix_matches_row_construction(n):
    c = generic(n)
    assert hurwitz_matrix(c) == textbook_hurwitz(c)


@pytest.mark.parametrize("n", range(1, 7))
def test_hurwitz_minors_are_leading_principal_minors(n):
    c = generic(n)
    H = hurwitz_matrix(c)
    minors = hurwitz_minors(generic_poly(n))
    assert len(minors) == n
    for m, minor in enumerate(minors, 1):
        assert sp.expand(minor - H[:m, :m].det()) == 0
    assert sp.expand(minors[0] - c[1]) == 0
    # the last column holds only a_n: Delta_n = a_n Delta_(n-1)
    if n > 1:
        assert sp.expand(minors[-1] - c[n] * minors[-2]) == 0


def test_hurwitz_minors_quadratic_and_numeric():
    a, b = sp.symbols("a b")
    assert hurwitz_minors(sp.Poly(x**2 + a * x + b, x)) == [a, a * b]
    # (x + 1)(x + 2)(x + 3) = x^3 + 6 x^2 + 11 x + 6: Delta_2 = 6*11 - 6 = 60
    assert hurwitz_minors(sp.Poly((x + 1) * (x + 2) * (x + 3), x)) == [6, 60, 360]


@pytest.mark.parametrize("n", range(2, 7))
def test_orlando_formula(n):
    """Delta_(n-1) = (-1)^(n(n-1)/2) a_0^(n-1) prod_(i<j) (r_i + r_j) for monic polynomials with roots r."""
    roots = [sp.Rational(r) for r in (-1, 2, -3, sp.Rational(1, 2), 5, -sp.Rational(7, 3))[:n]]
    p = sp.Poly(sp.Mul(*[x - r for r in roots]), x)
    product = sp.Mul(*[roots[i] + roots[j] for i in range(n) for j in range(i + 1, n)])
    assert hurwitz_minors(p)[n - 2] == (-1) ** (n * (n - 1) // 2) * product


# --- lienard_chipart -------------------------------------------------------------


def test_lienard_chipart_examples():
    a, b, c, d = sp.symbols("a b c d")
    assert lienard_chipart(sp.Poly(x**3 + a * x**2 + b * x + c, x)) == [a, b, c, a * b - c]
    assert lienard_chipart(sp.Poly(x**2 + a * x + b, x)) == [a, b]
    assert lienard_chipart(sp.Poly(x + a, x)) == [a]
    quartic = lienard_chipart(sp.Poly(x**4 + a * x**3 + b * x**2 + c * x + d, x))
    assert quartic[:4] == [a, b, c, d]
    assert len(quartic) == 5
    assert sp.expand(quartic[4] - (a * b * c - a**2 * d - c**2)) == 0


def test_lienard_chipart_keeps_a_symbolic_leading_coefficient():
    a0, a1, a2 = sp.symbols("a0 a1 a2")
    assert lienard_chipart(sp.Poly(a0 * x**2 + a1 * x + a2, x)) == [a0, a1, a2]


def test_lienard_chipart_drops_positive_numbers_keeps_others():
    a = sp.Symbol("a")
    assert lienard_chipart(sp.Poly(x**3 + 2 * x**2 + a * x + 1, x)) == [a, 2 * a - 1]
    conditions = lienard_chipart(sp.Poly(x**3 - 2 * x**2 + 3 * x + 1, x))
    assert -2 in conditions
    assert not all(c > 0 for c in conditions)


@pytest.mark.parametrize("n", range(1, 9))
def test_lienard_chipart_uses_every_second_minor_from_n_minus_1(n):
    p = generic_poly(n)
    minors = hurwitz_minors(p)
    conditions = lienard_chipart(p)
    c = generic(n)
    assert conditions[: n + 1] == list(c)
    expected = [minors[m - 1] for m in range(n - 1, 1, -2)]
    assert conditions[n + 1 :] == expected


# --- Liénard–Chipart <=> roots in the left half-plane (property tests) --------------


@st.composite
def integer_polynomials(draw):
    """Random integer coefficients, leading coefficient positive."""
    n = draw(st.integers(1, 8))
    lead = draw(st.integers(1, 6))
    rest = draw(st.lists(st.integers(-12, 20), min_size=n, max_size=n))
    return [lead] + rest


@st.composite
def polynomials_from_roots(draw):
    """Products of (x - r) and (x^2 - 2 a x + a^2 + b^2), with small rational a, b, r."""
    parts = sp.Integer(draw(st.integers(1, 4)))
    degree = 0
    target = draw(st.integers(1, 8))
    small = small_fractions(min_value=-4, max_value=4, max_denominator=3)
    # mostly stable factors, sometimes unstable ones
    while degree < target:
        flip = draw(st.integers(0, 5)) == 0
        if target - degree >= 2 and draw(st.booleans()):
            a = -abs(Fraction(draw(small))) or Fraction(1, 2)
            b = Fraction(draw(small)) or Fraction(1)
            a = -a if flip else a
            a, b = sp.Rational(a.numerator, a.denominator), sp.Rational(b.numerator, b.denominator)
            parts *= x**2 - 2 * a * x + a**2 + b**2
            degree += 2
        else:
            r = -abs(Fraction(draw(small))) or Fraction(-1)
            r = -r if flip else r
            parts *= x - sp.Rational(r.numerator, r.denominator)
            degree += 1
    return [int(c) if c.is_Integer else c for c in sp.Poly(parts, x).all_coeffs()]


@st.composite
def float_polynomials(draw):
    """Float coefficients, made exact (every binary float is a rational)."""
    n = draw(st.integers(1, 8))
    lead = draw(st.floats(0.1, 10))
    rest = draw(st.lists(st.floats(-5, 20, allow_nan=False, allow_infinity=False), min_size=n, max_size=n))
    return [sp.Rational(c) for c in [lead] + rest]


def numpy_stable(coefficients):
    """True/False from numpy roots, or None when a root is near the imaginary axis."""
    roots = np.roots([float(c) for c in coefficients])
    if len(roots) < len(coefficients) - 1:
        return None  # numpy dropped a leading zero: should not happen here
    scale = max(1.0, float(np.abs(roots).max()))
    if np.abs(roots.real).min() < 1e-6 * scale:
        return None
    return bool((roots.real < 0).all())


def check_lienard_chipart(coefficients):
    expected = numpy_stable(coefficients)
    assume(expected is not None)
    event("stable" if expected else "unstable")
    n = len(coefficients) - 1
    p = sp.Poly(sum(sp.sympify(c) * x ** (n - i) for i, c in enumerate(coefficients)), x)
    conditions = lienard_chipart(p)
    assert all(c.is_number for c in conditions)
    assert all((c > 0) == (c.is_positive) for c in conditions)
    assert all(c > 0 for c in conditions) == expected


@settings(max_examples=150, deadline=None)
@given(integer_polynomials())
def test_lienard_chipart_iff_stable_integer_coefficients(coefficients):
    check_lienard_chipart(coefficients)


@settings(max_examples=150, deadline=None)
@given(polynomials_from_roots())
def test_lienard_chipart_iff_stable_from_roots(coefficients):
    check_lienard_chipart(coefficients)


@settings(max_examples=100, deadline=None)
@given(float_polynomials())
def test_lienard_chipart_iff_stable_float_coefficients(coefficients):
    check_lienard_chipart(coefficients)


@pytest.mark.parametrize(
    ("expr", "stable"),
    [
        ((x + 1) ** 8, True),
        ((x + 1) ** 7 * (x - sp.Rational(1, 10)), False),
        ((x**2 + x + 5) ** 3 * (x + 2) ** 2, True),
        ((x**2 - sp.Rational(1, 100) * x + 5) * (x + 1) ** 4, False),
        (x**4 + x**3 + x**2 + x + 1, False),  # roots on the unit circle, two with Re > 0
        ((x + 3) * (x + 1) * (x**2 + 4), False),  # a pair on the imaginary axis: not asymptotically stable
    ],
)
def test_lienard_chipart_known_polynomials(expr, stable):
    conditions = lienard_chipart(sp.Poly(expr, x))
    assert all(c > 0 for c in conditions) == stable


# --- hopf_omega_squared -------------------------------------------------------------


def test_hopf_omega_squared_examples():
    a = sp.Symbol("a", positive=True)
    assert hopf_omega_squared(sp.Poly(x**4 + 2 * x**3 + 3 * x**2 + a * x + 1, x)) == a / 2
    b, c = sp.symbols("b c", positive=True)
    assert hopf_omega_squared(sp.Poly(b * x**2 + c, x)) == c / b
    assert hopf_omega_squared(sp.Poly(x + 1, x)) is None


def test_hopf_omega_squared_symbolic_cubic():
    w, c = sp.symbols("w c", positive=True)
    p = sp.Poly(sp.expand((x**2 + w**2) * (x + c)), x)
    assert sp.simplify(hopf_omega_squared(p) - w**2) == 0
    assert sp.expand(hurwitz_minors(p)[1]) == 0


@st.composite
def stable_factors(draw):
    """A Hurwitz-stable polynomial of degree 0..6 with rational coefficients."""
    degree = draw(st.integers(0, 6))
    poly = sp.Integer(draw(st.integers(1, 3)))
    positive = small_fractions(min_value=Fraction(1, 4), max_value=4, max_denominator=4).map(
        lambda f: sp.Rational(f.numerator, f.denominator)
    )
    d = 0
    while d < degree:
        if degree - d >= 2 and draw(st.booleans()):
            a, b = draw(positive), draw(positive)
            poly *= x**2 + 2 * a * x + a**2 + b**2
            d += 2
        else:
            poly *= x + draw(positive)
            d += 1
    return sp.expand(poly)


@settings(max_examples=80, deadline=None)
@given(stable_factors(), small_fractions(min_value=Fraction(1, 5), max_value=5, max_denominator=5))
def test_hopf_omega_squared_recovers_the_imaginary_pair(q, w):
    w = sp.Rational(w.numerator, w.denominator)
    p = sp.Poly(sp.expand((x**2 + w**2) * q), x)
    n = p.degree()
    # distinct roots: the pair +-i w must not also be a root of q (q is stable, so it is not)
    assert hopf_omega_squared(p) == w**2
    minors = hurwitz_minors(p)
    assert minors[n - 2] == 0  # Delta_(n-1) vanishes on the Hopf set
    if n > 2:  # x^2 + w^2 alone has a zero lam-coefficient
        assert all(c > 0 for c in p.all_coeffs())
    H = Hurwitz(p)
    assert H.minors == minors
    # one imaginary pair, the other roots in the left half-plane: on the Hopf set (degree >= 3)
    assert H.hopf_set == (sp.true if n > 2 else sp.false)
    assert H.omega_squared == w**2
    roots = np.roots([float(c) for c in p.all_coeffs()])
    assert np.isclose(np.abs(roots - 1j * float(w)).min(), 0, atol=1e-6)


def test_hurwitz_class():
    a, b = sp.symbols("a b")
    H = Hurwitz(sp.Poly(x**2 + a * x + b, x))
    assert H.coefficients == [1, a, b]
    assert H.minors == [a, a * b]
    assert H.conditions == [a, b]
    assert H.hopf_set == sp.false  # degree 2: no Delta_(n-1) among the conditions
    assert H.omega_squared == b
    H1 = Hurwitz(sp.Poly(2 * x + a, x))
    assert H1.hopf_set == sp.false
    assert H1.omega_squared is None


def test_hurwitz_hopf_set_quartic():
    a, b, c, d = sp.symbols("a b c d")
    H = Hurwitz(sp.Poly(x**4 + a * x**3 + b * x**2 + c * x + d, x))
    delta3 = a * b * c - a**2 * d - c**2
    expected = sp.And(sp.Eq(delta3, 0), a > 0, b > 0, c > 0, d > 0)
    assert H.hopf_set == expected
    # (x^2 + 1)(x^2 + x + 1) = x^4 + x^3 + 2 x^2 + x + 1 is on it; (x^2 + 1)(x^2 - x + 1) is not
    assert H.hopf_set.xreplace({a: 1, b: 2, c: 1, d: 1}) == sp.true
    assert H.hopf_set.xreplace({a: -1, b: 2, c: -1, d: 1}) == sp.false
    assert H.hopf_set.xreplace({a: 1, b: 3, c: 1, d: 1}) == sp.false  # stable, Delta_3 > 0


@settings(max_examples=30, deadline=None)
@given(st.integers(2, 5), st.lists(st.sampled_from(["symbol", "positive"]), min_size=6, max_size=6))
def test_labels_name_each_lienard_chipart_condition(n, kinds):
    lam_ = sp.Symbol("lambda")
    coefficients = [1] + [sp.Symbol(f"c_{i}") if kind == "symbol" else i + 2 for i, kind in enumerate(kinds[:n])]
    poly = sp.Poly(sum(c * lam_ ** (n - i) for i, c in enumerate(coefficients)), lam_)
    h = Hurwitz(poly)
    assert len(h.labels) == len(h.conditions)
    matrix = hurwitz_matrix(coefficients)
    for (kind, index), condition in zip(h.labels, h.conditions):
        if kind == "p":  # the coefficient of lambda^s
            expected = poly.coeff_monomial(lam_**index)
        else:  # the leading principal minor of order m, computed here directly
            expected = matrix[:index, :index].det()
        assert sp.expand(condition - expected) == 0


# --- omega^2 over Delta_(n-3); expansion_bound ---------------------------------------------


@pytest.mark.parametrize("n", [4, 5, 6])
def test_generic_omega_squared_is_a_root_of_p_on_delta_n_minus_1(n):
    """Symbolic identity: for omega^2 = N / Delta_(n-3), the form the library returns, the
    numerators of Re p(i omega) and Im p(i omega) / omega are multiples of Delta_(n-1): they
    vanish on the Hopf set. (One polynomial is a Groebner basis of its ideal, so ``reduced``
    decides divisibility.)"""
    p = generic_poly(n)
    c = generic(n)
    minors = [sp.expand(m) for m in hurwitz_minors(p)]
    w2 = hopf_omega_squared(p)
    assert 0 in (sp.expand(sp.fraction(w2)[1] - minors[n - 4]), sp.expand(sp.fraction(w2)[1] + minors[n - 4]))
    z = sp.Symbol("z")
    even = sum((-1) ** i * c[n - 2 * i] * z**i for i in range(n // 2 + 1))
    odd = sum((-1) ** i * c[n - 2 * i - 1] * z**i for i in range((n - 1) // 2 + 1))
    for part in (even, odd):
        numerator = sp.fraction(sp.together(part.xreplace({z: w2})))[0]
        assert sp.reduced(sp.expand(numerator), [minors[n - 2]], *c)[1] == 0


def test_generic_omega_squared_equals_the_subresultant_root():
    """The quotient over Delta_(n-3) is the root of SymPy's own first subresultant, exactly."""
    z = sp.Symbol("z")
    for n in range(4, 9):
        c = generic(n)
        even = sp.Poly(sum((-1) ** i * c[n - 2 * i] * z**i for i in range(n // 2 + 1)), z)
        odd = sp.Poly(sum((-1) ** i * c[n - 2 * i - 1] * z**i for i in range((n - 1) // 2 + 1)), z)
        linear = [s for s in sp.subresultants(even, odd) if sp.Poly(s, z).degree() == 1][0]
        root = -sp.Poly(linear, z).coeff_monomial(1) / sp.Poly(linear, z).coeff_monomial(z)
        assert sp.cancel(hopf_omega_squared(generic_poly(n)) - root) == 0


_symbols = sp.symbols("u v w")


@st.composite
def expressions(draw, depth=3):
    if depth == 0 or draw(st.integers(0, 3)) == 0:
        return draw(st.sampled_from([*_symbols, sp.Integer(2), sp.Rational(1, 3), sp.sin(_symbols[0])]))
    kind = draw(st.sampled_from(["add", "mul", "pow", "div"]))
    a, b = draw(expressions(depth - 1)), draw(expressions(depth - 1))
    if kind == "add":
        return a + b
    if kind == "mul":
        return a * b
    if kind == "pow":
        return a ** draw(st.integers(2, 3))
    return a / (b + _symbols[2])


@settings(max_examples=60, deadline=None)
@given(expressions())
def test_expansion_bound_bounds_the_expanded_numerator(expr):
    from contactsym.algebra.hurwitz import expansion_bound

    numerator = sp.fraction(sp.together(expr))[0]
    assert len(sp.Add.make_args(sp.expand(numerator))) <= expansion_bound(expr)


def test_long_omega_squared_is_kept_as_derived_and_equal():
    """Past EXPAND_TERMS the quotient is not cancelled; it is the same function as the cancelled one."""
    from contactsym.algebra import hurwitz

    rng = np.random.default_rng(5)
    y = sp.symbols("y1:7")
    coefficients = [1] + [
        sum(int(rng.integers(1, 9)) * y[int(rng.integers(6))] * y[int(rng.integers(6))] for _ in range(8))
        for _ in range(6)
    ]
    p = sp.Poly(sum(cf * x ** (6 - i) for i, cf in enumerate(coefficients)), x)
    kept = hopf_omega_squared(p)
    assert hurwitz.expansion_bound(kept) > hurwitz.EXPAND_TERMS
    numerator, denominator = sp.fraction(kept)
    assert 0 in (
        sp.expand(denominator - hurwitz_minors(p)[2]),
        sp.expand(denominator + hurwitz_minors(p)[2]),
    )  # +-Delta_3
    for _ in range(5):
        point = {s: sp.Rational(int(rng.integers(1, 30)), int(rng.integers(1, 7))) for s in y}
        expected = sp.cancel(hurwitz._generic_omega_squared(6).xreplace(dict(zip(hurwitz._generic(6), p.all_coeffs()))))
        assert kept.xreplace(point) == expected.xreplace(point)
