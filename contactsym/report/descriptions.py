"""Descriptions of the long expressions a report names (``H_1``: "a polynomial with 513 terms in ...").

The sizes are counted in sparse polynomial rings (SymPy's ``ring``) whose generators are the symbols and
their sines and cosines, not by ``expand``: a four-link arm's named expressions took ~21 s that way,
~5 s this way. What would take minutes to count is described by what its tree shows.

Examples
--------
>>> import sympy as sp
>>> x, y = sp.symbols("x y")
>>> describe((x + y) ** 3 - x**3)
'a polynomial with 3 terms of total degree 3 in $x$, $y$'
"""

from __future__ import annotations

import sympy as sp

from ..algebra.basic import node_count as _nodes
from ..algebra.hurwitz import expansion_bound
from ..printing.latex_output import tex

__all__ = ["DESCRIBE_NODES", "DESCRIBE_TERMS", "describe", "sparse_polynomial"]

#: Long expressions beyond this many nodes are described by their size as derived, not expanded.
DESCRIBE_NODES = 20000
#: A polynomial that may have more terms than this once expanded (read off its tree) is described by that bound:
#: expanding a fixed-value four-link arm's Hurwitz determinant to its 148762 terms to count them took 8 s.
DESCRIBE_TERMS = 10**6


def describe(expr: sp.Expr) -> str:
    """A short description of a long expression: its kind, number of terms and symbols."""
    large = _nodes(expr, DESCRIBE_NODES) > DESCRIBE_NODES
    # a large one is read once per distinct part (a four-link arm's largest, 10^6 nodes as a tree, has 3000)
    symbols = ", ".join(f"${tex(s)}$" for s in sorted(_symbols_once(expr) if large else expr.free_symbols, key=str))
    if not isinstance(expr, sp.Expr):  # a condition (And, Or, Not of relations): nothing to expand
        return f"a condition of {_nodes(expr, 10**6)} nodes in {symbols}"
    if large:  # expanding it could take minutes: its size as derived
        return f"an expression of more than {DESCRIBE_NODES} nodes in {symbols}"
    # terms counted in the sparse ring of the symbols and their sines and cosines: no expand (and for a
    # polynomial no together), each ~1 s on the conditions of a four-link arm
    gens = sorted(expr.free_symbols, key=str) + sorted(expr.atoms(sp.Function), key=sp.default_sort_key)
    if expr.is_polynomial(*gens) and (bound := expansion_bound(expr)) > DESCRIBE_TERMS:
        return f"a polynomial of up to {bound} terms once expanded (a product of long sums, kept whole) in {symbols}"
    kind, numerator, poly = "a polynomial", expr, sparse_polynomial(expr, gens)
    if poly is None:
        numerator, denominator = sp.fraction(expr)  # already P/Q (a product), or a sum to bring together
        if (poly := sparse_polynomial(numerator, gens)) is None or sparse_polynomial(denominator, gens) is None:
            poly, denominator = _over_one_denominator(expr, gens) or (None, None)
        if poly is None:
            numerator, denominator = sp.fraction(sp.together(expr))
            poly = sparse_polynomial(numerator, gens)
        kind = "a polynomial" if denominator.is_number else "a rational function, numerator"
    if poly is not None:
        functions = len(gens) > len(expr.free_symbols)  # a degree in sines and cosines would mislead
        degree = "" if functions else f" of total degree {max((sum(m) for m in poly.monoms()), default=0)}"
        return f"{kind} with {len(poly)} terms{degree} in {symbols}"
    terms = len(sp.Add.make_args(sp.expand(numerator)))
    try:
        size = f"{terms} terms of total degree {sp.Poly(sp.expand(numerator), *sorted(expr.free_symbols, key=str)).total_degree()}"
    except sp.PolynomialError:
        size = f"{terms} terms"
    return f"{kind} with {size} in {symbols}"


def _symbols_once(expr: sp.Basic) -> set:
    """The symbols of ``expr`` (it binds none), each distinct subexpression visited once."""
    seen, found, stack = set(), set(), [expr]
    while stack:
        node = stack.pop()
        if id(node) not in seen:
            seen.add(id(node))
            if node.is_Symbol:
                found.add(node)
            else:
                stack.extend(node.args)
    return found


def _over_one_denominator(expr: sp.Expr, gens: list):
    """(numerator in the sparse ring, Q) of a sum of fractions P_i / (c_i Q), numbers c_i: the numerator
    ``together`` gives, added in the ring (together took ~1 s for each of a four-link arm's f_j); or None."""
    if not isinstance(expr, sp.Add) or not gens:
        return None
    parts = [sp.fraction(term) for term in expr.args]
    denominator = parts[0][1]
    numerator = sparse_polynomial(sp.S.Zero, gens)
    for p, q in parts:
        ratio, poly = denominator / q, sparse_polynomial(p, gens)
        if poly is None or not ratio.is_Rational:
            return None
        numerator += poly * poly.ring.domain.convert(ratio)
    return numerator, denominator


def sparse_polynomial(expr: sp.Expr, gens: list):
    """``expr`` expanded in the sparse polynomial ring QQ[gens] (in C-like time where ``expand`` and the
    dense ``Poly`` take seconds: the stool's Delta_5, 16414 terms, 1.9 s), or None when it is not such a polynomial."""
    if not gens or not expr.is_polynomial(*gens):  # a failed conversion prints all of expr into its message
        return None
    try:
        ring = sp.ring(gens, sp.QQ)[0]
        return ring(expr)
    except (sp.polys.polyerrors.PolynomialError, sp.polys.polyerrors.CoercionFailed, ValueError, TypeError):
        return None
