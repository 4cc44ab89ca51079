"""The inequality engine (contactsym.inequalities) on random conditions.

Every rewrite must describe the same set: each is checked exactly at random rational points
(a relation between rationals evaluates to True or False exactly, boundaries included), with
the assumptions of the symbols respected (m > 0). Proofs (implied, infeasible) must be sound
at every point, and must be found where a short proof was built into the conditions.
"""

from __future__ import annotations

import itertools
import math
from fractions import Fraction

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from contactsym.algebra.basic import SignSymbol, known_sign
from contactsym.inequalities import (
    Condition,
    Facts,
    arrange,
    boolean,
    closed_conjuncts,
    closed_form,
    drop_known_factors,
    half_angles,
    merge_and,
    merge_or,
    merge_pair,
    positive_part,
    pythagorean,
    solve_for,
    tidy,
)
from tests.helpers import small_fractions

x, y = sp.symbols("x y", real=True)
m = sp.Symbol("m", positive=True)
RELATIONS = (sp.Gt, sp.Ge, sp.Lt, sp.Le)
SETTINGS = settings(max_examples=20, deadline=None)

coefficients = st.integers(-3, 3)
rationals = small_fractions(-3, 3, max_denominator=6).map(sp.Rational)
positives = small_fractions(Fraction(1, 6), 3, max_denominator=6).map(sp.Rational)  # the positive ones


@st.composite
def polynomials(draw, symbols=(x, y, m), max_terms=3):
    """A small polynomial: a sum of integer multiples of monomials of degree <= 2 in each symbol."""
    terms = []
    for _ in range(draw(st.integers(1, max_terms))):
        monomial = sp.Mul(*[s ** draw(st.integers(0, 2)) for s in symbols])
        terms.append(draw(coefficients) * monomial)
    return sp.Add(*terms)


#: Factors whose sign the engine knows (m > 0): they must be dropped, flipping the relation when negative.
KNOWN = [m, -m, m**2 + 1, -(m + 2), sp.Integer(3), sp.Integer(-2)]


@st.composite
def products(draw):
    """A product of one or two unknown polynomials, a factor of known sign, maybe a square."""
    factors = [draw(polynomials()) for _ in range(draw(st.integers(1, 2)))]
    factors.append(draw(st.sampled_from(KNOWN)))
    if draw(st.booleans()):
        factors.append((x - draw(coefficients)) ** 2)
    return sp.Mul(*factors)


@st.composite
def relations(draw):
    return draw(st.sampled_from(RELATIONS))(draw(products()), draw(polynomials(max_terms=2)))


@st.composite
def booleans(draw):
    """And/Or of a few random relations, nested at most once."""
    parts = [draw(relations()) for _ in range(draw(st.integers(1, 3)))]
    if len(parts) > 1 and draw(st.booleans()):
        parts = [sp.Or(*parts[:2]), *parts[2:]] if draw(st.booleans()) else [sp.And(*parts[:2]), *parts[2:]]
    return draw(st.sampled_from([sp.And, sp.Or]))(*parts)


@st.composite
def points(draw):
    return [{x: draw(rationals), y: draw(rationals), m: draw(positives)} for _ in range(12)]


def holds(condition, point) -> bool:
    value = sp.sympify(condition).xreplace(point)
    assert value in (sp.true, sp.false), (condition, point, value)
    return bool(value)


def same_set(a, b, sample) -> None:
    for point in sample:
        assert holds(a, point) == holds(b, point), (a, b, point)


# --- one relation ------------------------------------------------------------------------------


@SETTINGS
@given(products(), st.sampled_from(RELATIONS), points())
def test_dropping_factors_of_known_sign_keeps_the_set(expr, relation, sample):
    op = {sp.Gt: sp.StrictGreaterThan, sp.Ge: sp.GreaterThan, sp.Lt: sp.StrictLessThan, sp.Le: sp.LessThan}[relation]
    rest, new_op, nonzero = drop_known_factors(expr, op, (), 200)
    assert known_sign(rest) is None or rest.is_number  # every factor of known sign is gone
    same_set(op(expr, 0), sp.And(new_op(rest, 0), *nonzero), sample)


def test_dropping_factors_flips_for_a_negative_factor_and_keeps_squares_as_nonzero():
    rest, op, nonzero = drop_known_factors(-m * (x - 1) * (y + 2) ** 2, sp.StrictGreaterThan, (), 200)
    assert (rest, op, nonzero) == (x - 1, sp.StrictLessThan, [sp.Ne(y + 2, 0)])


@SETTINGS
@given(polynomials(), st.sampled_from([sp.StrictGreaterThan, sp.GreaterThan]), points())
def test_arrangement_keeps_the_set_and_puts_known_positive_terms_right(expr, op, sample):
    arranged = arrange(sp.expand(expr), op, (), 200)
    same_set(op(expr, 0), arranged, sample)
    if isinstance(arranged, (sp.StrictLessThan, sp.LessThan)) and not arranged.lhs.has(x, y):
        assert arranged.rhs == 0 or not arranged.rhs.could_extract_minus_sign()


@SETTINGS
@given(booleans(), points())
def test_closed_form_of_a_random_boolean_is_the_same_set(condition, sample):
    reduced = closed_form(condition, (), None)
    same_set(condition, reduced, sample)


@SETTINGS
@given(booleans(), points())
def test_size_limits_keep_the_set(condition, sample):
    same_set(condition, closed_form(condition, raw_ops=3, factor_terms=1), sample)


def test_a_square_may_vanish_where_the_relation_is_not_strict():
    weak = m * (x - 1) ** 2 * (y - x) >= 0
    assert closed_form(weak).xreplace({x: 1, y: -5}) == sp.true  # (x - 1)^2 = 0 there
    assert closed_form(m * (x - 1) ** 2 * (y - x) > 0) == sp.And(sp.Ne(x - 1, 0), x - y < 0)


def test_a_relation_that_cancels_to_zero_is_decided():
    zero = (x + 1) ** 2 - x**2 - 2 * x - 1
    assert closed_form(sp.Gt(zero, 0)) == sp.false
    assert closed_form(sp.Ge(zero, 0)) == sp.true


def test_a_relation_past_the_operation_limit_is_kept_as_given():
    relation = sp.Gt((x + y) ** 3 - x * y, 0)
    assert closed_form(relation, raw_ops=3) == relation
    assert closed_form(relation) != relation


@SETTINGS
@given(st.integers(1, 4), st.integers(-4, 4), st.sampled_from(RELATIONS), positives, positives)
def test_solving_for_a_positive_symbol_keeps_the_set(a, c, relation, value, scale):
    mu = sp.Symbol("mu", positive=True)
    for expr in (a * mu**2 + c * m, a * m * mu + c, -a * mu + c * m**2):
        rel = relation(expr, 0)
        solved = solve_for(rel, mu)
        assert solved == rel or solved in (sp.true, sp.false) or solved.lhs == mu
        point = {mu: value, m: scale}
        assert holds(rel, point) == holds(solved, point), (rel, solved, point)


def test_solving_needs_a_coefficient_of_known_sign():
    mu = sp.Symbol("mu", positive=True)
    assert solve_for(x * mu - 1 > 0, mu) == (x * mu - 1 > 0)
    assert solve_for(m * mu - 1 > 0, mu) == (mu > 1 / m)


@SETTINGS
@given(polynomials(max_terms=2), positives, st.sampled_from(RELATIONS), points())
def test_tidy_keeps_the_set(expr, c, relation, sample):
    rel = relation(expr - x, -c)
    same_set(rel, tidy(rel, ()), sample)


def test_positive_part_and_condition_of_a_relation():
    assert positive_part(x < 2) == (2 - x, True)
    assert positive_part(x >= y) == (x - y, False)
    assert positive_part(sp.Eq(x, 2)) is None
    assert Condition.of(x <= 1) == Condition(1 - x, 1 - x, False)


# --- proofs ------------------------------------------------------------------------------------


@st.composite
def conditions(draw):
    return Condition(sp.expand(draw(polynomials())), sp.S.Zero, draw(st.booleans()))


def satisfied(condition: Condition, point) -> bool:
    value = condition.raw.xreplace(point)
    return value > 0 if condition.strict else value >= 0


@SETTINGS
@given(st.lists(conditions(), min_size=1, max_size=3), points())
def test_infeasible_is_sound_and_finds_built_in_clashes(parts, sample):
    parts = [Condition(c.raw, c.raw, c.strict) for c in parts]
    facts = Facts()
    if facts.infeasible(parts):
        assert not any(all(satisfied(c, p) for c in parts) for p in sample)
    # a condition that the others contradict by a sum: -(sum) - m > 0 cannot hold with them
    clash = Condition(sp.expand(-sp.Add(*[c.raw for c in parts]) - m), sp.S.Zero, False)
    assert facts.infeasible([*parts, clash])


@SETTINGS
@given(st.lists(conditions(), min_size=1, max_size=3), conditions(), points())
def test_implied_is_sound_and_finds_built_in_implications(premises, conclusion, sample):
    premises = [Condition(c.raw, c.raw, c.strict) for c in premises]
    conclusion = Condition(conclusion.raw, conclusion.raw, conclusion.strict)
    facts = Facts()
    if facts.implied(premises, conclusion):
        for p in sample:
            if all(satisfied(c, p) for c in premises):
                assert satisfied(conclusion, p)
    implied = Condition(sp.expand(sp.Add(*[c.raw for c in premises]) + m * x**2), sp.S.Zero, True)
    if any(c.strict for c in premises):  # the slack m x^2 is only >= 0: enough with a strict premise
        assert facts.implied(premises, implied)


def test_a_slack_known_only_non_negative_needs_strictness():
    weak, strict, conclusion = Condition.of(x >= 0), Condition.of(x > 0), Condition.of(x + m * y**2 > 0)
    assert not Facts().implied([weak], conclusion)  # x = y = 0
    assert Facts().implied([strict], conclusion)
    assert not Facts(nonnegative_slack=False).implied([strict], conclusion)
    assert Facts(nonnegative_slack=False).implied([strict], Condition.of(x + m > 0))


@SETTINGS
@given(st.lists(conditions(), min_size=2, max_size=3), points())
def test_dropping_implied_conditions_keeps_the_conjunction(parts, sample):
    parts = [Condition(c.raw, c.raw, c.strict) for c in parts]
    parts.append(Condition(sp.expand(parts[0].raw + m), sp.S.Zero, parts[0].strict))  # implied by parts[0]
    kept = Facts().drop_implied(parts)
    assert len(kept) < len(parts)
    for p in sample:
        assert all(satisfied(c, p) for c in parts) == all(satisfied(c, p) for c in kept)


def test_facts_try_the_presentation_and_the_trigonometric_rewrites():
    q = sp.Symbol("q", real=True)
    kappa = sp.Symbol("kappa", positive=True)
    facts = Facts((), present=lambda e: sp.sympify(e).xreplace({y: kappa**2}))
    assert facts.sign(facts.condition(y + 1)) == 1  # y = kappa**2 in the presentation
    assert Facts().sign(Condition(y + 1, y + 1)) is None
    assert facts.sign(Condition(4 - 3 * sp.sin(q) ** 2, 4 - 3 * sp.sin(q) ** 2)) == 1  # 1 + 3 cos^2
    weak = Condition(m * sp.cos(2 * q) - m, sp.S.Zero, False)  # -2 m sin(q)^2 >= 0 holds at q = 0
    assert not facts.infeasible([weak])
    assert facts.infeasible([Condition(weak.raw, sp.S.Zero, True)])  # -2 m sin(q)^2 > 0 never holds


@given(st.floats(-6, 6), st.integers(1, 3))
@settings(max_examples=20, deadline=None)
def test_trigonometric_rewrites_are_identities(angle, n):
    q = sp.Symbol("q", real=True)
    for expr in (4 - 3 * sp.sin(q) ** (2 * n), m * sp.cos(2 * q) - m + sp.cos(q) ** n):
        for rewritten in (pythagorean(expr), half_angles(expr)):
            at = {q: angle, m: 1.5}
            assert math.isclose(float(expr.subs(at)), float(rewritten.subs(at)), abs_tol=1e-9)


# --- merges ------------------------------------------------------------------------------------


@SETTINGS
@given(polynomials(symbols=(x, y), max_terms=2), positives, st.booleans(), points())
def test_abs_merges_are_the_same_set(expr, c, strict, sample):
    relation = sp.Gt if strict else sp.Ge
    expr = sp.expand(expr)
    both = [relation(c - expr, 0), relation(c + expr, 0)]
    merged = merge_and(both)
    same_set(sp.And(*both), sp.And(*merged), sample)
    if not any(isinstance(r, sp.logic.boolalg.BooleanAtom) for r in both):  # sympy decides y**2 + 1 > 0 itself
        assert len(merged) == 1 and merged[0].has(sp.Abs)
    pair = merge_pair(relation(expr - c, 0), relation(-expr - c, 0))
    if pair is not None:
        same_set(sp.Or(relation(expr - c, 0), relation(-expr - c, 0)), pair, sample)


@SETTINGS
@given(st.lists(st.lists(relations(), min_size=1, max_size=2), min_size=1, max_size=3), points())
def test_or_merges_are_the_same_set(disjuncts, sample):
    sets = [frozenset(d) for d in disjuncts]
    complement = [frozenset({*d[1:], sp.Not(d[0])}) for d in disjuncts]  # d[0] or not d[0]: mergeable
    for case in (sets, sets + complement):
        same_set(boolean(case), boolean(merge_or(case)), sample)


def test_closed_conjuncts_present_and_merge():
    kappa = sp.Symbol("kappa", positive=True)
    facts = Facts((), present=lambda e: sp.sympify(e).xreplace({m: kappa**2}))
    parts = closed_conjuncts([facts.condition(m - x), facts.condition(m + x)], [sp.Eq(y, m)], facts)
    assert parts == frozenset({sp.Abs(x) < kappa**2, sp.Eq(y - kappa**2, 0)})


def test_no_implication_is_tried_with_a_relation_past_the_size_limit():
    """Past raw_ops a relation is kept as given and not used to drop another (proving it would expand it):
    the same set, less reduced."""
    x, y = sp.symbols("x y", real=True)
    implied_disjunct = sp.Or(x > y, x > y + 1)
    implied_conjunct = sp.And(x > y + 1, sp.Or(x > y, x < y - 2))
    assert closed_form(implied_disjunct) == (x - y > 0)
    assert closed_form(implied_disjunct, raw_ops=0) == implied_disjunct
    assert closed_form(implied_conjunct) == (x - y > 1)
    assert closed_form(implied_conjunct, raw_ops=0) == implied_conjunct


_SIGNS = tuple(SignSymbol(f"s_{i}") for i in (1, 2, 3))


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.integers(-4, 4), min_size=3, max_size=3),
    st.integers(-6, 6),
    st.sampled_from((*RELATIONS, sp.Eq, sp.Ne)),
    st.booleans(),
)
def test_a_relation_in_signs_alone_is_decided_over_every_pattern(coefficients, constant, relation, scaled):
    """sum c_j s_j + c op 0 (times a positive m, which the closed form removes): its closed form holds at
    each +-1 pattern exactly where the relation does, and is true or false when all patterns agree."""
    lhs = sum(c * s for c, s in zip(coefficients, _SIGNS)) + constant
    condition = relation(m * lhs if scaled else lhs, 0)
    if condition in (sp.true, sp.false):
        return
    reduced = closed_form(condition)
    answers = set()
    for pattern in itertools.product((-1, 1), repeat=3):
        point = dict(zip(_SIGNS, map(sp.Integer, pattern)))
        expected = condition.xreplace({**point, m: sp.Integer(2)})
        assert reduced.xreplace({**point, m: sp.Integer(2)}) == expected
        answers.add(expected)
    if len(answers) == 1:
        assert reduced == answers.pop()


@SETTINGS
@given(
    products(), polynomials(max_terms=2), st.lists(relations(), max_size=2), st.sampled_from([sp.And, sp.Or]), points()
)
def test_a_relation_with_its_strict_or_weak_twin_keeps_the_set(lhs, rhs, others, junction, sample):
    """P > 0 beside P >= 0 (written in either order or sides): one of the pair is kept, the set is the same,
    and the two never both stay side by side (as parts of the same And or Or)."""
    condition = junction(sp.Gt(lhs, rhs), sp.Le(rhs, lhs), *others)
    reduced = closed_form(condition)
    same_set(condition, reduced, sample)
    parts = reduced.args if isinstance(reduced, (sp.And, sp.Or)) else (reduced,)
    kept = [positive_part(r) for r in parts if isinstance(r, sp.core.relational.Relational)]
    kept = [(sp.expand(p), strict) for p, strict in filter(None, kept)]
    assert not any((p, not strict) in kept for p, strict in kept)


@SETTINGS
@given(
    st.lists(polynomials(max_terms=2), min_size=2, max_size=3),
    st.lists(st.booleans(), min_size=6, max_size=6),
    points(),
)
def test_a_disjunct_that_implies_another_part_by_part_goes_and_the_set_stays(sides, strict, sample):
    """(P > 0 & Q > 0) | (P >= 0 & Q >= 0) | ...: the disjuncts differ only in strictness, so the weakest
    one is the whole Or; the closed form is the same set and has no two disjuncts where one implies the other
    part by part."""
    ops = [sp.Gt if s else sp.Ge for s in strict]
    disjuncts = [sp.And(*[op(side, 0) for op, side in zip(ops[i : i + len(sides)], sides)]) for i in (0, 2, 3)]
    condition = sp.Or(*disjuncts)
    reduced = closed_form(condition)
    same_set(condition, reduced, sample)
    if isinstance(reduced, sp.Or):
        from contactsym.inequalities.closed import _implied_parts

        keys = [_implied_parts(d) for d in reduced.args]
        for i, a in enumerate(keys):
            for j, b in enumerate(keys):
                if i != j and a is not None and b is not None:
                    assert not all(P in a and (a[P] or not s) for P, s in b.items()), (reduced, i, j)
