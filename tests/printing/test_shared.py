"""Shared printing (contactsym.printing.shared): the same text as SymPy's printers, on random expressions
whose parts repeat, printed one after another so that the memo is full of their parts."""

from __future__ import annotations

import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.printing.latex import LatexPrinter

from contactsym.printing import shared
from contactsym.printing.latex_output import tex
from contactsym.printing.shared import sstr_shared

x, y = sp.symbols("x y", real=True)
phi, eps = sp.symbols("phi epsilon", positive=True)
LEAVES = [x, y, phi, eps, sp.Integer(2), sp.Rational(-3, 4), sp.Float(0.25), sp.Float(1.5, 30), sp.pi]


def _combine(children):
    pair = st.tuples(children, children)
    return st.one_of(
        pair.map(lambda p: p[0] + p[1]),
        pair.map(lambda p: p[0] * p[1]),
        pair.map(lambda p: p[0] - 2 * p[1]),
        pair.map(lambda p: p[0] / (p[1] + 3)),
        children.map(lambda c: c**2),
        children.map(lambda c: sp.sin(c) ** 2),  # a function under a power: printed with a keyword argument
        children.map(sp.cos),
        children.map(lambda c: sp.sqrt(c**2 + 1)),
    )


EXPRESSIONS = st.recursive(st.sampled_from(LEAVES), _combine, max_leaves=12)


class _Plain(LatexPrinter):  # the paper's letters, without the memo: the reference
    def _deal_with_super_sub(self, string, style="plain"):
        return tex(sp.Symbol(string)) if string in ("phi", "epsilon") else super()._deal_with_super_sub(string, style)


@settings(max_examples=150, deadline=None)
@given(st.lists(EXPRESSIONS, min_size=2, max_size=4), st.sampled_from([None, "none"]))
def test_shared_printing_gives_the_text_of_sympys_printers(parts, order):
    whole = [sp.Add(*parts), parts[0] * parts[-1], *parts]
    try:  # a relation, where both sides are real (a quotient may be infinite)
        whole.append(sp.Lt(parts[0], parts[1]) & sp.Ge(parts[-1], 0))
    except TypeError:
        pass
    for expr in whole:
        assert sstr_shared(expr, order=order) == sp.sstr(expr, order=order)
        assert tex(expr, order=order) == _Plain({"order": order}).doprint(expr)


def test_the_memo_stays_bounded(monkeypatch):
    monkeypatch.setattr(shared, "MEMO_SIZE", 5)
    for k in range(20):
        sstr_shared((x + k) ** 2 * sp.sin(y + k))
    assert len(shared._MEMO) <= 5
