"""Interval signs: proven where nonzero, silent where exactly zero, and classify() decides the guides case."""

from __future__ import annotations

import numpy as np
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym import numerics as nm
from contactsym.algebra.intervals import interval_sign

x = sp.Symbol("x")
rationals = st.fractions(min_value=-50, max_value=50, max_denominator=10**6).map(sp.Rational)
small_ints = st.integers(min_value=-5, max_value=5)


def _reference_sign(expr) -> int:
    """The sign at 1000 digits (mpmath, not the interval code)."""
    value = sp.N(expr, 1000)
    assert abs(value) > sp.Float(10, 1000) ** -700, "too close to zero for the reference"
    return 1 if value > 0 else -1


@settings(max_examples=25, deadline=None)
@given(rationals, st.lists(small_ints, min_size=4, max_size=4), st.integers(min_value=0, max_value=40))
def test_interval_sign_agrees_with_high_precision_on_random_trigonometric_polynomials(angle, coefficients, shift):
    a, b, c, d = coefficients
    expr = a * sp.sin(angle) ** 2 + b * sp.cos(angle) ** 3 + c * sp.tan(angle / 7) + d * sp.exp(angle / 50)
    expr += sp.Rational(1, 2**shift)  # near-cancellation at small scales
    if sp.N(expr, 1000) == 0:
        return
    assert interval_sign(expr) == _reference_sign(expr)


@settings(max_examples=30, deadline=None)
@given(rationals, st.integers(min_value=7, max_value=60))  # |offset| <= 50 < 2**bits
def test_interval_sign_near_pi_over_2_where_cancellation_is_deep(offset, bits):
    angle = sp.pi / 2 + offset / 2**bits  # exact: sin(angle) - 1 < 0 unless offset = 0
    if offset == 0:
        assert interval_sign(sp.sin(angle) - 1) is None  # sin(pi/2) - 1 = 0 exactly: no sign
        return
    assert interval_sign(sp.sin(angle) - 1) == -1
    assert interval_sign(sp.cos(angle) * offset) == -1  # cos(pi/2 + e) = -sin e


@settings(max_examples=20, deadline=None)
@given(rationals)
def test_exact_zeros_get_no_sign(angle):
    assert interval_sign(sp.sin(angle) ** 2 + sp.cos(angle) ** 2 - 1) is None
    assert interval_sign(sp.sqrt(angle**2) - abs(angle)) is None


def test_unsupported_expressions_are_left_to_the_caller():
    assert interval_sign(x + 1) is None  # a symbol
    assert interval_sign(sp.Float(0.1) - sp.Rational(1, 10)) is None  # floats are not exact here
    assert interval_sign(sp.gamma(sp.Rational(1, 3))) is None


GUIDES_POINT = {
    "phi": 1.5707962237941302,
    "mu_1": 2.5432882095324048,
    "mu_2": 2.543288003530872,
    "Phi_1": -13741932.09,
    "Phi_2": -50652.81,
    "Psi_1": -2.0426,
    "Psi_2": -666.845,
}


def test_classify_decides_the_guides_point_of_issue_14():
    """evalf(strict=True) gave up here ("agrees with 0 to 300 digits"); the intervals decide it."""
    st_ = cs.scene("painleve-klein-guides").stability((1, 1))
    verdict = nm.classify(st_, GUIDES_POINT)
    # independent check: every Hurwitz condition in 1000-digit mpmath from the same binary inputs
    exact = {sp.Symbol(k, real=True): sp.Rational(v) for k, v in GUIDES_POINT.items()}
    by_name = {str(s): s for c in st_.hurwitz for s in c.free_symbols}
    at = {by_name[str(k)]: v for k, v in exact.items() if str(k) in by_name}
    reference = tuple(_reference_sign(c.xreplace(at)) for c in st_.hurwitz)
    assert verdict.signs == reference
    assert verdict.stable == 1
    # and the fast PointClassifier agrees (the issue's third witness)
    names = sorted(by_name, key=str)
    pc = nm.PointClassifier(st_.hurwitz, [by_name[n] for n in names])
    out = pc(*[np.array([GUIDES_POINT[n]]) for n in names])
    assert out.stable.tolist() == [1]
