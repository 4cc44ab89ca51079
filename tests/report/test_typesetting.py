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
