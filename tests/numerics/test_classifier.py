"""The certified vectorised classifier: cheap one-signed forms, sound signs, clear errors."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym import numerics as nm
from contactsym.numerics.buffered import through_tan

a, b, c = sp.symbols("a b c", positive=True)
p, q = sp.symbols("p q", negative=True)
x = sp.Symbol("x", real=True)
SYMBOLS = (a, b, c, p, q)
BRAKE = cs.scene("brake").stability()
BRAKE_PARAMETERS = [
    {str(s): s for s in set().union(*[h.free_symbols for h in BRAKE.hurwitz])}[n]
    for n in ["alpha", "m", "mu", "Phi_1", "Phi_2", "Psi_1", "Psi_2"]
]
BRAKE_CLASSIFIER = nm.PointClassifier(BRAKE.hurwitz, BRAKE_PARAMETERS)


monomials = st.tuples(
    st.integers(1, 5), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2)
)


def _polynomial(terms) -> sp.Expr:
    return sp.Add(*[k * a**i * b**j * c**l * p**r * q**s for k, i, j, l, r, s in terms])


def _exact_sign(expr: sp.Expr, point, symbols=SYMBOLS) -> int:
    value = expr.xreplace({s: sp.Rational(Fraction(float(v))) for s, v in zip(symbols, point)})
    return int(sp.sign(value))


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(monomials, min_size=1, max_size=6), st.lists(st.floats(0.25, 4.0), min_size=5, max_size=5))
def test_signs_are_never_wrong_even_on_the_boundary(terms, point):
    """F = A(a, b) - A(b, a) vanishes on a = b; points on it and one ulp away."""
    A = _polynomial(terms)
    F = A - A.xreplace({a: b, b: a})
    classifier = nm.PointClassifier([F], list(SYMBOLS))
    base = [point[0], point[1], point[2], -point[3], -point[4]]
    on_line = [point[1], *base[1:]]
    next_to = [math.nextafter(point[1], 5.0), *base[1:]]
    arrays = [np.array(column) for column in zip(base, on_line, next_to)]
    result = classifier(*arrays)
    for k in range(3):
        exact = _exact_sign(F, [arrays[i][k] for i in range(5)])
        assert result.signs[0, k] == exact, (F, k)


def test_points_straddling_a_boundary_at_every_distance_get_the_exact_sign():
    F = a**2 * p**2 - 2 * b * c * p**2 - 3 * q**2 * c  # zero where a^2 = 2 b c + 3 q^2 c / p^2
    classifier = nm.PointClassifier([F], list(SYMBOLS))
    rng = np.random.default_rng(7)
    n = 400
    B, C, P, Q = rng.uniform(0.5, 2, n), rng.uniform(0.5, 2, n), -rng.uniform(0.5, 2, n), -rng.uniform(0.5, 2, n)
    root = np.sqrt(2 * B * C + 3 * Q**2 * C / P**2)
    relative = 10.0 ** rng.uniform(-17, -1, n) * rng.choice([-1, 1], n)
    A = root * (1 + relative)
    result = classifier(A, B, C, P, Q)
    for k in range(n):
        assert result.signs[0, k] == _exact_sign(F, [A[k], B[k], C[k], P[k], Q[k]])
    assert result.exact_points > 0  # the closest ones took the exact path
    assert not result.in_band[np.abs(relative) > 1e-6].any()


def test_underflow_and_overflow_points_are_decided_exactly_and_only_they():
    F = a * b - c**2
    classifier = nm.PointClassifier([F], [a, b, c])
    A = np.array([1e-160, 1e-160, 1e160, 3.0])
    B = np.array([1e-160, 2e-160, 2e160, 4.0])
    C = np.array([1.1e-160, 1e-160, 1e160, 3.0])
    result = classifier(A, B, C)
    exact = [_exact_sign(F, point, (a, b, c)) for point in zip(A, B, C)]
    assert result.signs[0].tolist() == exact
    assert result.in_band[:3].all()  # under- and overflowing points went the exact way
    assert not result.in_band[3]  # the healthy point of the same chunk did not


@pytest.mark.parametrize(
    "values, message",
    [
        ([np.array([1.0, np.nan]), np.array([1.0, 1.0])], "not all finite"),
        ([np.array([1.0, np.inf]), np.array([1.0, 1.0])], "not all finite"),
        ([np.array([1.0, -1.0]), np.array([1.0, 1.0])], "declared positive"),
    ],
)
def test_bad_values_get_a_clear_error(values, message):
    classifier = nm.PointClassifier([a - b], [a, b])
    with pytest.raises(nm.NumericsError, match=message):
        classifier(*values)


@pytest.mark.parametrize(
    "where, value, message",
    [
        (900, np.inf, "not all finite"),
        (901, np.nan, "not all finite"),
        (902, -np.inf, "not all finite"),
        (903, 0.0, "declared positive"),
    ],
)
def test_bad_values_anywhere_in_any_chunk_get_a_clear_error(where, value, message):
    """The float32 pass checks all of a chunk's arrays in two reductions; one value for all points is checked too."""
    classifier = nm.PointClassifier([a * b - c**2 + p], [a, b, c, p])
    values = [np.ones(1000), np.ones(1000), np.full(1000, 0.5), np.broadcast_to(-0.5, (1000,))]
    values[1] = values[1].copy()
    values[1][where] = value
    with pytest.raises(nm.NumericsError, match=message):
        classifier(*values, chunk=256)
    with pytest.raises(nm.NumericsError, match="declared negative"):
        classifier(np.ones(1000), np.ones(1000), np.ones(1000), np.broadcast_to(0.5, (1000,)), chunk=256)


def test_a_function_of_a_rounded_argument_is_refused_with_a_fix():
    with pytest.raises(nm.NumericsError, match="introduce a parameter"):
        nm.PointClassifier([sp.sin(a / 3) - b], [a, b])


def test_exact_functions_of_parameters_are_accepted():
    classifier = nm.PointClassifier([sp.sin(2 * x) ** 2 - b], [x, b])
    result = classifier(np.array([0.5, 0.5]), np.array([0.5, 0.9]))
    assert result.stable.tolist() == [1 if math.sin(1.0) ** 2 > 0.5 else -1, -1]


@settings(max_examples=40, deadline=None)
@given(st.floats(-20, 20), st.integers(1, 3))
def test_even_powers_of_sin_and_cos_through_tan_are_the_same_numbers(angle, half):
    for function in (sp.sin, sp.cos):
        expr = a * function(x) ** (2 * half) + b
        code = through_tan(expr)
        assert not code.has(function)
        if abs(math.cos(angle)) > 1e-6:  # tan is finite
            point = {a: 1.5, b: 0.25, x: angle}
            assert math.isclose(float(code.subs(point)), float(expr.subs(point)), rel_tol=1e-12, abs_tol=1e-15)
    assert through_tan(sp.sin(x) ** 3) == sp.sin(x) ** 3  # odd powers keep their sign: left alone


def test_bisection_isolates_the_few_points_that_underflow():
    classifier = nm.PointClassifier([a * b - c**2], [a, b, c])
    rng = np.random.default_rng(3)
    A, B, C = rng.uniform(1, 2, (3, 5000))
    bad = np.arange(0, 5000, 250)
    A[bad], B[bad], C[bad] = 1e-160, 1e-160, 2e-160
    result = classifier(A, B, C, chunk=1024)
    assert result.in_band[bad].all() and (result.signs[0, bad] == -1).all()
    assert result.exact_points == len(bad)  # every other point stayed in floats


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0.01, 3.13), st.lists(st.floats(-8, 8), min_size=6, max_size=6))
def test_brake_parameters_from_1e_minus_8_to_1e8_get_the_exact_signs(angle, exponents):
    m_, mu_, *laws = (10.0**e for e in exponents)
    values = [angle, m_, mu_, -laws[0], -laws[1], -laws[2], -laws[3]]
    result = BRAKE_CLASSIFIER(*[np.array([v]) for v in values])
    point = dict(zip(BRAKE_PARAMETERS, values))
    assert result.signs[:, 0].tolist() == [nm.certified_sign(h, point)[0] for h in BRAKE.hurwitz]


def test_many_brake_points_get_the_exact_signs_of_the_hurwitz_conditions():
    rng = np.random.default_rng(11)
    n = 200
    values = [rng.uniform(0.05, 3.0, n), rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n)]
    values += list(-np.exp(rng.normal(0, 1.5, (4, n))))
    result = BRAKE_CLASSIFIER(*values)
    for k in range(0, n, 10):
        point = dict(zip(BRAKE_PARAMETERS, [v[k] for v in values]))
        assert result.signs[:, k].tolist() == [nm.certified_sign(h, point)[0] for h in BRAKE.hurwitz]


def test_float64_inputs_are_read_in_place_and_never_written():
    """real_array hands a float64 array back as a read-only view (no copy); other real types are converted."""
    from contactsym import validate

    values = np.linspace(0.0, 1.0, 7)
    seen = validate.real_array(values, "x")
    assert np.shares_memory(seen, values) and not seen.flags.writeable
    assert values.flags.writeable  # the caller's array is untouched
    converted = validate.real_array(np.arange(3, dtype=np.int32), "n")
    assert converted.dtype == np.float64 and converted.tolist() == [0.0, 1.0, 2.0]
    with pytest.raises(cs.errors.NumericsError, match="complex"):
        validate.real_array(np.array([1j]), "z")


def _brake_points(rng, n, on_line):
    """Random brake points, the first ``on_line`` of them put on the Hopf line of the (6.4) slice in floats."""
    values = [rng.uniform(0.05, 3.0, n), rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n)]
    values += list(-np.exp(rng.normal(0, 1.5, (4, n))))
    alpha, m_, mu_, phi1, phi2, psi1, psi2 = values
    alpha[:on_line], psi2[:on_line] = math.pi / 2, psi1[:on_line]
    phi1[:on_line] = phi2[:on_line] = (
        -(1 + mu_[:on_line] ** 2) * psi1[:on_line] ** 2 / (m_[:on_line] * mu_[:on_line] ** 2)
    )
    return values


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**32 - 1), st.integers(1, 300))
def test_chunks_of_any_size_and_function_values_given_change_no_result(seed, chunk):
    """The chunked pass, the whole array at once, and sin(alpha) given by the caller: the same verdicts,
    signs and band, also for points on the Hopf line (decided exactly; their signs: the tests above)."""
    values = _brake_points(np.random.default_rng(seed), 300, on_line=2)
    whole = BRAKE_CLASSIFIER(*values, chunk=300)
    assert whole.exact_points >= 1  # the band is exercised
    given = [getattr(np, ufunc)(values[index]) for index, ufunc in BRAKE_CLASSIFIER.functions]
    assert BRAKE_CLASSIFIER.functions == ((0, "sin"),) or BRAKE_CLASSIFIER.functions == ((0, "tan"),)
    for result in (
        BRAKE_CLASSIFIER(*values, chunk=chunk),
        BRAKE_CLASSIFIER(*values, chunk=chunk, function_values=given),
    ):
        assert np.array_equal(result.stable, whole.stable)
        assert np.array_equal(result.signs, whole.signs)
        assert np.array_equal(result.in_band, whole.in_band)


def test_function_values_of_the_wrong_number_or_length_are_refused():
    values = [np.full(3, v) for v in (1.0, 1.0, 1.0, -1.0, -1.0, -1.0, -1.0)]
    with pytest.raises(nm.NumericsError, match="function_values"):
        BRAKE_CLASSIFIER(*values, function_values=[])
    with pytest.raises(nm.NumericsError, match="one value per point"):
        BRAKE_CLASSIFIER(*values, function_values=[np.zeros(2)] * len(BRAKE_CLASSIFIER.functions))


def test_numpys_float32_sine_and_cosine_are_within_the_prepass_bound():
    from contactsym.numerics.float_stage import _CHEAP_ABSOLUTE, _CHEAP_RANGE

    rng = np.random.default_rng(5)
    x = np.concatenate([np.linspace(-_CHEAP_RANGE, _CHEAP_RANGE, 400_001), rng.uniform(-4, 4, 200_000)])
    x32 = x.astype(np.float32)
    for function in (np.sin, np.cos):
        assert np.max(np.abs(function(x32).astype(float) - function(x32.astype(float)))) <= _CHEAP_ABSOLUTE / 4


@pytest.mark.parametrize("given", [False, True])
def test_the_float32_pass_gives_the_float64_result_and_leaves_the_close_points_to_it(given):
    """sin(alpha) computed by the float32 pass or given by the caller (then rounded to float32 as an input)."""
    import copy

    values = _brake_points(np.random.default_rng(8), 3000, on_line=3000)
    phi1 = values[3]
    phi1 *= 1 + 10.0 ** np.random.default_rng(9).uniform(-9, -1, 3000) * np.resize([1, -1], 3000)  # both sides
    functions = [np.sin(values[0])] if given else None
    float64 = copy.copy(BRAKE_CLASSIFIER)
    float64._single = False
    single = copy.copy(BRAKE_CLASSIFIER)
    assert single._single and all(w is not None for w in single._single_widths)
    again = []  # points evaluated in float64
    stage = single._float_stage
    single._float_stage = lambda *args: (again.append(len(args[0][0])), stage(*args))
    for chunk in (3000, 256):
        again.clear()
        ours = single(*values, chunk=chunk, function_values=functions)
        theirs = float64(*values, chunk=chunk, function_values=functions)
        assert np.array_equal(ours.stable, theirs.stable) and np.array_equal(ours.signs, theirs.signs)
        assert np.array_equal(ours.in_band, theirs.in_band)
        assert 0 < sum(again) < 3000  # the close points, and only a part of the others


def test_the_float32_pass_steps_aside_outside_float32s_range():
    """A chunk with a value that under- or overflows float32 is evaluated in float64 (the others in float32)."""
    F = a * b - c**2
    classifier = nm.PointClassifier([F], [a, b, c])
    assert classifier._single
    A, B, C = np.random.default_rng(4).uniform(1, 2, (3, 64))
    A[40], B[40], C[40] = 1e-50, 2e-50, 1e-50
    A[50], B[50], C[50] = 1e50, 2e50, 1e50
    result = classifier(A, B, C, chunk=16)
    exact = [_exact_sign(F, point, (a, b, c)) for point in zip(A, B, C)]
    assert result.signs[0].tolist() == exact and result.exact_points == 0


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(0, 2**32 - 1), st.integers(1, 97), st.lists(st.booleans(), min_size=7, max_size=7), st.booleans())
def test_the_float32_pass_of_any_layout_gives_the_float64_result(seed, chunk, lone, given):
    """Chunks of any length (a last chunk of one point too), any parameters of one value for every point
    (stride 0), sin(alpha) computed or given: the float32 pass's layouts give the float64 result."""
    import copy

    n = 3 * chunk + 1
    values = _brake_points(np.random.default_rng(seed), n, on_line=3)
    values = [np.broadcast_to(v[:1], (n,)) if one else v for v, one in zip(values, lone)]
    functions = [np.sin(values[0])] if given else None
    float64 = copy.copy(BRAKE_CLASSIFIER)
    float64._single = False
    ours = BRAKE_CLASSIFIER(*values, chunk=chunk, function_values=functions)
    theirs = float64(*values, chunk=chunk, function_values=functions)
    assert np.array_equal(ours.stable, theirs.stable) and np.array_equal(ours.signs, theirs.signs)
    assert np.array_equal(ours.in_band, theirs.in_band)
