"""The proved regions of Propositions 3-8, and the sign of a product read off its factors.

:func:`sign_equivalent` is checked on random products of random fractions (large ones, that take
the factored path) against the sign of the product at random rational points; the k = 2
classification of a symbolic A with large entries is checked at random points against the
classification of the numeric A there (the canonical-form path, checked against eigenvalues in
tests/stages/test_stability.py) and against eigenvalues of (4.5) over sampled laws.
"""

import random

import numpy as np
import pytest
import sympy as sp
from hypothesis import event, given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym.algebra.basic import SignSymbol
from contactsym.algebra.hurwitz import EXPAND_TERMS, expansion_bound
from contactsym.stages import classification as classification_module
from contactsym.stages import stability as stability_module
from contactsym.stages.classification import proved_regions, sign_equivalent
from contactsym.stages.stability import Stability
from tests.helpers import small_fractions
from tests.stages.test_stability import as_float, law_search_k2, spectra

x, y, z = sp.symbols("x y z", real=True)
m = sp.Symbol("m", positive=True)

#: Denominators: of known sign (a positive symbol, a sum of squares, a listed positive expression,
#: a negative number) and of unknown sign.
DENOMINATORS = [m, 1 + y**2, -(2 + z**2), 3 * m * (x**2 + 1), x - 2 * y + 1, (y - z) * m, sp.S(-3)]
#: A listed positive expression (as a scene's det M): proved positive by its listing only.
LISTED = x**4 - x**2 + 1


def polynomials(terms):
    """Random polynomials of about ``terms`` terms in x, y, z with small integer coefficients."""
    monomial = st.tuples(st.integers(0, 3), st.integers(0, 3), st.integers(0, 3))
    term = st.tuples(st.integers(-5, 5).filter(bool), monomial)
    return st.lists(term, min_size=terms, max_size=terms).map(
        lambda ts: sp.Add(*[c * x**a * y**b * z**d for c, (a, b, d) in ts])
    )


def fractions(terms):
    return st.builds(lambda p, d: p / d, polynomials(terms), st.sampled_from([*DENOMINATORS, LISTED, 1]))


points = st.tuples(*[small_fractions(-3, 3, max_denominator=4).map(sp.Rational)] * 3).map(
    lambda v: dict(zip((x, y, z), v))
)


def sign(value):
    return int(bool(value > 0)) - int(bool(value < 0))


@settings(max_examples=25, deadline=None)
@given(st.lists(fractions(24), min_size=1, max_size=3), st.lists(points, min_size=3, max_size=3))
def test_sign_equivalent_has_the_sign_of_the_product(factors, at):
    product = sp.Mul(*factors)
    equivalent = sign_equivalent(factors, [LISTED])
    if expansion_bound(product) > EXPAND_TERMS:
        event("factored")
        assert not any(isinstance(f, sp.Pow) and f.exp < 0 for f in sp.Mul.make_args(equivalent) if f.has(m))
    for values in at:
        values = {**values, m: sp.Rational(1, 2)}
        denominators = [sp.fraction(f)[1].xreplace(values) for f in factors]
        if any(d == 0 for d in denominators):
            continue
        assert sign(equivalent.xreplace(values)) == sign(product.xreplace(values))


def test_small_products_keep_the_canonical_form():
    a, b = sp.symbols("a b", real=True)
    assert sign_equivalent([a / m, b / m]) == a * b / m**2


big = st.builds(lambda c, p, d: c * p / d, st.integers(-3, 3), polynomials(22), st.sampled_from(DENOMINATORS[:3]))


@settings(max_examples=10, deadline=None)
@given(st.lists(big, min_size=4, max_size=4), st.lists(points, min_size=2, max_size=2))
def test_k2_regions_of_large_entries_agree_with_the_numeric_classification(entries, at):
    A = sp.Matrix(2, 2, entries)
    det = A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0]  # as given: the regions take det A from the caller
    regions = proved_regions(A, det, positive=[m])
    event("factored" if expansion_bound(A[0, 1] * A[1, 0]) > EXPAND_TERMS else "canonical form")
    for values in at:
        values = {**values, m: sp.Rational(1, 2)}
        numeric = A.xreplace(values)
        if numeric.det() == 0:
            continue
        ours = [region.xreplace(values) for region in regions]
        assert ours == list(proved_regions(numeric, numeric.det()))  # the canonical-form path at the point
        event(["robustly stable", "robustly unstable", "law-dependent"][ours.index(sp.true)])
        P, S = law_search_k2(numeric)
        top, _, tol = spectra(as_float(numeric), P, S)
        if ours[0] == sp.true:
            assert (top < tol).all()
        if ours[1] == sp.true:
            assert (top > -tol).all()
        if ours[2] == sp.true:
            assert (top < -tol).any() and (top > tol).any()


def test_k1_and_k3_regions():
    a = sp.Symbol("a", real=True)
    assert proved_regions(sp.Matrix([[a]]), a) == (a > 0, a < 0, sp.false)
    A = sp.Matrix([[2, 1, 0], [1, 2, 0], [0, 0, 1]])
    closed = {"unstable for every law": sp.false, "law-dependent": sp.false}
    stable, unstable, _ = proved_regions(A, A.det(), closed)
    assert (stable, unstable) == (sp.true, sp.false)
    assert np.all(np.linalg.eigvalsh(as_float(A)) > 0)  # Proposition 7: symmetric positive definite


@pytest.mark.parametrize("sign_of_det_m", ["proved", "not proved"])
@pytest.mark.parametrize("name", ["brake", "two-leg-block", "painleve-klein-guides"])
def test_the_factored_path_agrees_with_the_canonical_form_on_the_built_in_scenes(name, sign_of_det_m, monkeypatch):
    """With every k = 2 A sent through |det M| A (the path of the large arms), or, where the sign of det M
    is not proved, through a_11, a_22 and N_12 N_21 (N = det M A), each region of a built-in scene is
    the same set as with A's canonical entries: compared at random parameter points."""
    default = cs.scene(name).stability()
    expected = default._classification
    monkeypatch.setattr(stability_module, "EXPAND_TERMS", -1)
    monkeypatch.setattr(classification_module, "EXPAND_TERMS", -1)
    if sign_of_det_m == "not proved":
        monkeypatch.setattr(classification_module, "positive_multiple", lambda *args: None)
    forced = Stability(default.linearization)
    assert not forced._sign_matrix.has(sp.Pow(sp.Wild("d"), -1))  # |det M| A: no division
    got = forced._classification
    free = sorted(set().union(*[r.free_symbols for r in (*expected, *got)]), key=str)
    rng = random.Random(name)
    compared = 0
    for _ in range(12):
        values = {
            x: rng.choice([-1, 1]) if isinstance(x, SignSymbol) else sp.Rational(rng.randint(1, 40), 10) for x in free
        }
        ours, theirs = [r.xreplace(values) for r in got], [r.xreplace(values) for r in expected]
        if all(v in (sp.true, sp.false) for v in (*ours, *theirs)):
            assert ours == theirs, values
            compared += 1
    assert compared >= 8
