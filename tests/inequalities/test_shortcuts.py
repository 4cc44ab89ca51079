"""The engine's shortcuts against its plain path: each must give exactly the plain answer.

- ``factor_list`` (degree-1 variables split a polynomial) against ``sympy.factor_list``;
- ``Facts(refute=True)`` (a sign tried at exact points before SymPy's assumptions) against
  ``Facts(refute=False)``; ``refuted`` never refutes what SymPy proves;
- ``closed_form`` with a memo shared across calls against a fresh call;
- a scene's regions (one memo per scene) against closed forms computed one by one.
"""

from __future__ import annotations

from collections import Counter

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.basic import SignSymbol
from contactsym.inequalities import Condition, Facts, closed_form, factor_list, refuted, split_by_degree_one

x, y, z = sp.symbols("x y z", real=True)
m = sp.Symbol("m", positive=True)
n = sp.Symbol("n", negative=True)
s = SignSymbol("s_1")
SYMBOLS = (x, y, z, m, n, s)
SETTINGS = settings(max_examples=25, deadline=None)

coefficients = st.sampled_from(
    [sp.Integer(c) for c in (-6, -3, -2, -1, 1, 2, 3, 4)] + [sp.Rational(1, 2), sp.Rational(-2, 3)]
)


@st.composite
def polynomials(draw, max_terms=4, max_degree=2):
    terms = []
    for _ in range(draw(st.integers(1, max_terms))):
        chosen = draw(st.lists(st.sampled_from(SYMBOLS), min_size=0, max_size=3, unique=True))
        terms.append(draw(coefficients) * sp.Mul(*[v ** draw(st.integers(1, max_degree)) for v in chosen]))
    return sp.Add(*terms)


@st.composite
def products(draw):
    """Expanded products: the degree-1 splits (common coefficient gcds), monomials, squares, contents."""
    factors = [draw(polynomials(max_degree=draw(st.integers(1, 2)))) for _ in range(draw(st.integers(1, 3)))]
    if draw(st.booleans()):
        factors.append(draw(st.sampled_from(SYMBOLS)) ** draw(st.integers(1, 2)))
    if draw(st.booleans()):
        factors.append(factors[0])
    return sp.expand(draw(coefficients) * sp.Mul(*factors))


@SETTINGS
@given(products())
def test_factor_list_is_sympys(expr):
    ours, plain = factor_list(expr), sp.factor_list(expr)
    assert ours[0] == plain[0]
    assert Counter(ours[1]) == Counter(plain[1])


@st.composite
def unexpanded_products(draw):
    """Products left as products: each argument its own polynomial, some repeated, some sharing factors,
    a rational coefficient and now and then a power or a reciprocal (not a polynomial: SymPy's whole path)."""
    factors = [draw(polynomials(max_degree=draw(st.integers(1, 2)))) for _ in range(draw(st.integers(2, 3)))]
    if draw(st.booleans()):  # the same factor hidden in an expanded argument: merged only where SymPy merges
        factors.append(sp.expand(factors[0] * draw(polynomials(max_terms=2))))
    if draw(st.booleans()):
        factors[-1] = factors[-1] ** draw(st.integers(2, 3))
    if draw(st.integers(0, 5)) == 0:
        factors.append(1 / draw(st.sampled_from(SYMBOLS)))
    return sp.Mul(draw(coefficients), *factors)


@settings(max_examples=40, deadline=None)
@given(unexpanded_products())
def test_factor_list_of_a_product_is_sympys(expr):
    try:
        plain = sp.factor_list(expr)
    except sp.PolynomialError:  # a reciprocal: SymPy refuses it, and so does factor_list
        with pytest.raises(sp.PolynomialError):
            factor_list(expr)
        return
    ours = factor_list(expr)
    assert ours[0] == plain[0]
    assert Counter(ours[1]) == Counter(plain[1])


def test_degree_one_split_finds_each_factor_and_refuses_without_a_degree_one_variable():
    f = sp.Poly(sp.expand((x * y + z**2 + 1) * (y * z + 2) * (z + 3)), x, y, z)
    factors = split_by_degree_one(f)
    assert sorted(str(g.as_expr()) for g in factors) == ["x*y + z**2 + 1", "y*z + 2", "z + 3"]
    assert split_by_degree_one(sp.Poly(x**2 + y**2 - 1)) is None


@st.composite
def conditions(draw):
    return Condition(sp.expand(draw(polynomials(max_terms=3))), sp.S.Zero, draw(st.booleans()))


@SETTINGS
@given(st.lists(conditions(), min_size=1, max_size=3), conditions(), st.booleans())
def test_refuting_at_points_answers_as_the_assumptions(premises, conclusion, slack):
    premises = [Condition(c.raw, c.raw, c.strict) for c in premises]
    conclusion = Condition(conclusion.raw, conclusion.raw, conclusion.strict)
    quick, plain = Facts(nonnegative_slack=slack), Facts(nonnegative_slack=slack, refute=False)
    assert quick.implied(premises, conclusion) == plain.implied(premises, conclusion)
    assert quick.infeasible([*premises, conclusion]) == plain.infeasible([*premises, conclusion])


@SETTINGS
@given(polynomials(), st.sampled_from([1, -1]), st.booleans())
def test_a_refuted_sign_is_never_proved(expr, sign, strict):
    if refuted(expr, sign, strict):
        value = sign * expr
        assert not (value.is_positive if strict else value.is_nonnegative)


def test_refuted_uses_only_values_the_symbols_may_take():
    assert not refuted(m, 1, True) and not refuted(-n, 1, True) and not refuted(s**2, 1, True)
    assert refuted(s, 1, True) and refuted(x, 1, False)
    assert not refuted(sp.sin(x) - 2, -1, True)  # not a polynomial in symbols: nothing is tried


relations = st.builds(
    lambda op, a, b: op(a, b), st.sampled_from([sp.Gt, sp.Ge, sp.Lt, sp.Le]), polynomials(3), polynomials(2, 1)
)


@settings(max_examples=10, deadline=None)
@given(st.lists(st.lists(relations, min_size=1, max_size=3), min_size=1, max_size=2))
def test_a_shared_memo_gives_each_condition_its_fresh_closed_form(groups):
    memo: dict = {}
    conditions = [sp.And(*g) for g in groups] + [sp.Or(*g) for g in groups]
    for condition in conditions:
        assert closed_form(condition, (), memo=memo) == closed_form(condition, ())


def test_scene_regions_share_a_memo_and_match_closed_forms_one_by_one():
    import contactsym as cs
    from contactsym.stages import regions

    scene = cs.scene("brake")
    stability = scene.stability()
    shared = scene.regions()
    for name, attribute in regions.REGION_NAMES.items():
        raw = getattr(stability, attribute)
        condition = scene.present(raw)
        positive = tuple(getattr(scene, "positive_expressions", ()))
        alone = closed_form(condition, positive, getattr(scene, "solve_for", None))
        assert shared[name].condition == alone
