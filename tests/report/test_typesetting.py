"""Typesetting for the report: long expressions broken at their sums, or named when they would not fit."""

import sympy as sp

from contactsym.printing.latex_output import Formula
from contactsym.report.typesetting import WIDTH, _display, _Named, width


def test_long_expressions_are_broken_or_named():
    x = sp.symbols("x_1:40")
    long_sum = sp.Add(*[(i + 1) * s**2 for i, s in enumerate(x[:24])])
    named = _Named()
    shown = _display(Formula("f", "f", long_sum, "=", ("4.6",)), named)
    assert r"\begin{split}" in shown and named.items == []
    lines = shown.split("\\\\\n")
    assert len(lines) > 1 and all(width(line) <= WIDTH + 8 for line in lines)
    huge = sp.expand(sp.Add(*x) ** 2)  # 780 terms: too long for any page
    named = _Named()
    shown = _display(Formula("g", "", sp.Eq(huge * (x[0] - 1), 0), "", ()), named)
    assert "H_{1}" in shown and len(named.items) == 1 and named.items[0][1] == huge


def test_line_filling_stops_at_the_first_line_too_many():
    from contactsym.report.typesetting import MAX_LINES, _fill

    x = sp.symbols("x_1:400")
    printed = []

    def terms():
        for s in x:
            printed.append(s)
            yield f"{s}^{{2}}"

    assert _fill("", terms(), "", WIDTH) is None  # 399 terms: far more than MAX_LINES lines
    assert 0 < len(printed) < 30 * (MAX_LINES + 1)  # stopped after about MAX_LINES + 1 lines
    few = [f"{s}^{{2}}" for s in x[:30]]
    lines = _fill("", iter(few), "", WIDTH)
    assert lines is not None and "".join(lines).count("^{2}") == 30  # a sum that fits: every term placed


def test_the_trial_factors_only_small_sums(monkeypatch):
    from contactsym.report import typesetting

    a, b, c, d = sp.symbols("a b c d")
    p1, p2 = sp.expand((a + b + 1) ** 3 * (c - d)), sp.expand((a - c + 2) ** 3 * (b + d))
    expr = p1 * p2 - (a + b + 1) * (a - c + 2) * p1 + 3 * p2 * (c - d)  # a sum of three long products
    factored = []
    real = sp.factor_list
    monkeypatch.setattr(typesetting.sp, "factor_list", lambda e: factored.append(e) or real(e))
    numerator = sp.expand(expr)
    shown = typesetting._trial_factored(expr, numerator, sp.factor_terms(numerator))
    assert factored and all(typesetting._nodes(e, 10**4) <= typesetting.TRIAL_NODES for e in factored)
    assert expr not in factored
    assert sp.expand(shown - expr) == 0  # the same polynomial, its common factors divided out
    common = {f for f, _ in sp.factor_list(expr)[1] if sp.total_degree(f) == 1}  # found by factor, for the test
    assert common == {c - d, a - c + 2} and common <= set(sp.Mul.make_args(shown))


def test_a_long_expression_is_described_by_its_expanded_size():
    from contactsym.report.typesetting import _describe

    x, y, z = sp.symbols("x y z")
    product = (x + y + z + 1) ** 4 * (x - 2 * y) - 3 * (x * y - z) ** 3  # expanded by Poly, not by expand
    terms = len(sp.Add.make_args(sp.expand(product)))  # the count, independently
    assert _describe(product) == f"a polynomial with {terms} terms of total degree 6 in $x$, $y$, $z$"
    assert _describe(product / (x - z)).startswith(f"a rational function, numerator with {terms} terms")
    assert _describe(sp.sqrt(2) * x + x) == "a polynomial with 2 terms of total degree 1 in $x$"
    assert _describe(product / 6).startswith(f"a polynomial with {terms} terms")  # a number below is no denominator


def test_a_polynomial_in_sines_and_cosines_is_described_by_its_terms():
    from contactsym.report.typesetting import _describe

    q, m = sp.symbols("q m")
    trig = (sp.sin(q) + m * sp.cos(q) + 1) ** 3 / 4 - m * sp.sin(q) ** 2
    terms = len(sp.Add.make_args(sp.expand(trig)))  # expand keeps sin and cos as they are: the same terms
    assert _describe(trig) == f"a polynomial with {terms} terms in $m$, $q$"
    assert _describe(trig / (m + sp.cos(q))).startswith("a rational function, numerator with")
    # a sum of fractions over one denominator (up to numbers), added in the ring: the count together gives
    d = m + sp.cos(q)
    sum_ = trig / d + (sp.sin(q) * m - 1) / (3 * d) - sp.cos(q) ** 2 * m / (2 * d)
    together = len(sp.Add.make_args(sp.expand(sp.fraction(sp.together(sum_))[0])))
    assert _describe(sum_).startswith(f"a rational function, numerator with {together} terms in")


def test_a_polynomial_of_hundreds_of_terms_is_shown_as_derived():
    from contactsym.report.typesetting import TIDY_TERMS, _tidy

    x = sp.symbols("x_1:11")
    long = sp.Add(*x) ** 2 * sp.Add(*x[:5]) ** 2 - 3 * sp.Add(*x[3:]) ** 3  # hundreds of terms expanded
    assert len(sp.Add.make_args(sp.expand(long))) > TIDY_TERMS
    assert _tidy(long) is long  # not cancelled, expanded or factored for a page it cannot fit
    short = (x[0] ** 2 - x[1] ** 2) / (x[0] + x[1])
    assert _tidy(short) == x[0] - x[1]  # a small one is still cancelled


def test_a_very_long_expression_names_its_symbols_from_its_distinct_parts():
    from contactsym.report.typesetting import DESCRIBE_NODES, _describe, _nodes

    x, y, z, w = sp.symbols("x y z w")
    shared = sp.Add(*[(x + k * y) ** 3 for k in range(50)])  # one part repeated: a tree of many more nodes
    expr = sp.Add(*[shared * sp.sin(k * z) for k in range(1, 300)]) + w
    assert _nodes(expr, DESCRIBE_NODES) > DESCRIBE_NODES
    listed = ", ".join(f"${s}$" for s in sorted(map(str, expr.free_symbols)))
    assert _describe(expr) == f"an expression of more than {DESCRIBE_NODES} nodes in {listed}"


def test_a_product_of_long_sums_is_described_by_its_bound_not_expanded():
    from contactsym.algebra.hurwitz import expansion_bound
    from contactsym.report.typesetting import DESCRIBE_TERMS, _describe

    xs = sp.symbols("x_1:9")
    factors = [sp.Add(*[(k + j) * x for j, x in enumerate(xs)], k) for k in range(1, 8)]
    product = sp.Mul(*factors)  # 9^7 products of terms: more than DESCRIBE_TERMS before they combine
    assert expansion_bound(product) > DESCRIBE_TERMS
    assert _describe(product).startswith(f"a polynomial of up to {expansion_bound(product)} terms once expanded")
    small = sp.Mul(*factors[:3])  # 729 products, expanded and counted
    terms = len(sp.Add.make_args(sp.expand(small)))
    assert _describe(small).startswith(f"a polynomial with {terms} terms of total degree 3")
