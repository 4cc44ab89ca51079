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


def test_a_polynomial_of_hundreds_of_terms_is_shown_as_derived():
    from contactsym.report.typesetting import TIDY_TERMS, _tidy

    x = sp.symbols("x_1:11")
    long = sp.Add(*x) ** 2 * sp.Add(*x[:5]) ** 2 - 3 * sp.Add(*x[3:]) ** 3  # hundreds of terms expanded
    assert len(sp.Add.make_args(sp.expand(long))) > TIDY_TERMS
    assert _tidy(long) is long  # not cancelled, expanded or factored for a page it cannot fit
    short = (x[0] ** 2 - x[1] ** 2) / (x[0] + x[1])
    assert _tidy(short) == x[0] - x[1]  # a small one is still cancelled


def test_a_fraction_whose_cancelled_numerator_has_hundreds_of_terms_is_shown_as_derived():
    from contactsym.report.typesetting import TIDY_TERMS, _tidy

    x = sp.symbols("x_1:10")
    long = sp.Add(*x) ** 3 / (x[0] + 1) - sp.Add(*x[2:]) ** 3 / (x[1] - 2)  # one fraction: hundreds of terms
    numerator = sp.fraction(sp.cancel(long))[0]
    assert len(sp.Add.make_args(numerator)) > TIDY_TERMS
    assert sp.cancel(_tidy(long) - long) == 0
    assert _tidy(long) is long
    shorter = x[0] / (x[0] + 1) - x[1] / (x[1] - 2)
    assert _tidy(shorter) != shorter and sp.cancel(_tidy(shorter) - shorter) == 0  # a short one is still joined


def test_a_long_fraction_with_a_common_factor_is_still_cancelled():
    """The cheap rule (a long numerator proved coprime to the denominator is shown as derived) does
    not fire where numerator and denominator share a factor: cancel shortens that one."""
    from contactsym.report.typesetting import TIDY_TERMS, _tidy

    x = sp.symbols("x_0:10")
    total = sp.Add(*x[1:])
    numerator = total**3 * (x[0] + 2)  # the same factor written two ways: SymPy does not cancel it
    denominator = sp.expand(total**2) * total * (x[1] - 2)
    assert len(sp.Add.make_args(sp.expand(numerator))) > TIDY_TERMS
    assert _tidy(numerator / denominator) == (x[0] + 2) / (x[1] - 2)
