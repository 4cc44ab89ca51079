"""Descriptions of named long expressions (contactsym.report.descriptions): term counts checked against
SymPy's expand and together, computed independently in each test."""

from __future__ import annotations

import sympy as sp


def test_a_long_expression_is_described_by_its_expanded_size():
    from contactsym.report.descriptions import describe as _describe

    x, y, z = sp.symbols("x y z")
    product = (x + y + z + 1) ** 4 * (x - 2 * y) - 3 * (x * y - z) ** 3  # expanded by Poly, not by expand
    terms = len(sp.Add.make_args(sp.expand(product)))  # the count, independently
    assert _describe(product) == f"a polynomial with {terms} terms of total degree 6 in $x$, $y$, $z$"
    assert _describe(product / (x - z)).startswith(f"a rational function, numerator with {terms} terms")
    assert _describe(sp.sqrt(2) * x + x) == "a polynomial with 2 terms of total degree 1 in $x$"
    assert _describe(product / 6).startswith(f"a polynomial with {terms} terms")  # a number below is no denominator


def test_a_polynomial_in_sines_and_cosines_is_described_by_its_terms():
    from contactsym.report.descriptions import describe as _describe

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


def test_a_very_long_expression_names_its_symbols_from_its_distinct_parts():
    from contactsym.report.descriptions import DESCRIBE_NODES
    from contactsym.report.descriptions import describe as _describe
    from contactsym.report.typesetting import _nodes

    x, y, z, w = sp.symbols("x y z w")
    shared = sp.Add(*[(x + k * y) ** 3 for k in range(50)])  # one part repeated: a tree of many more nodes
    expr = sp.Add(*[shared * sp.sin(k * z) for k in range(1, 300)]) + w
    assert _nodes(expr, DESCRIBE_NODES) > DESCRIBE_NODES
    listed = ", ".join(f"${s}$" for s in sorted(map(str, expr.free_symbols)))
    assert _describe(expr) == f"an expression of more than {DESCRIBE_NODES} nodes in {listed}"


def test_a_product_of_long_sums_is_described_by_its_bound_not_expanded():
    from contactsym.algebra.hurwitz import expansion_bound
    from contactsym.report.descriptions import DESCRIBE_TERMS
    from contactsym.report.descriptions import describe as _describe

    xs = sp.symbols("x_1:9")
    factors = [sp.Add(*[(k + j) * x for j, x in enumerate(xs)], k) for k in range(1, 8)]
    product = sp.Mul(*factors)  # 9^7 products of terms: more than DESCRIBE_TERMS before they combine
    assert expansion_bound(product) > DESCRIBE_TERMS
    assert _describe(product).startswith(f"a polynomial of up to {expansion_bound(product)} terms once expanded")
    small = sp.Mul(*factors[:3])  # 729 products, expanded and counted
    terms = len(sp.Add.make_args(sp.expand(small)))
    assert _describe(small).startswith(f"a polynomial with {terms} terms of total degree 3")
