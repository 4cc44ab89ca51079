"""Shorter Booleans: ``|x| < c`` and ``|x| > c`` from pairs of relations, and merged disjunctions.

A disjunction is kept as a list of disjuncts, each a frozenset of conjuncts, so that two
disjuncts that differ in one conjunct are easy to find and merge.
"""

from __future__ import annotations

import itertools

import sympy as sp
from sympy.core.relational import Relational

from ..algebra.basic import known_sign
from ..arguments import checked
from .relations import positive_part

__all__ = ["split", "merge_and", "merge_abs", "merge_pair", "merge_or", "boolean"]


@checked(positive="Sequence[sp.Expr]")
def split(p1: sp.Expr, p2: sp.Expr, positive=()) -> tuple[sp.Expr, sp.Expr] | None:
    """(x, c) with p1 = c - x and p2 = c + x, when c is known positive and shares no symbol with x.

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> split(2 - x + y, 2 + x - y)
    (x - y, 2)
    >>> split(x - 1, 1 - x) is None
    True
    """
    c, x = sp.expand((p1 + p2) / 2), sp.expand((p2 - p1) / 2)
    if x == 0 or known_sign(c, positive) != 1 or x.free_symbols & c.free_symbols:
        return None
    return x, c


@checked(positive="Sequence[sp.Expr]")
def merge_and(conjuncts: list[sp.Basic], positive=()) -> list[sp.Basic]:
    """``c - x > 0`` and ``c + x > 0`` become ``|x| < c`` (c known positive, free of x's symbols).

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> merge_and([x - y < 1, y - x < 1, x > 0])
    [x > 0, Abs(x - y) < 1]
    """
    out = list(conjuncts)
    changed = True
    while changed:
        changed = False
        for a, b in itertools.combinations(out, 2):
            pa, pb = positive_part(a), positive_part(b)
            if pa is None or pb is None or pa[1] != pb[1]:
                continue
            found = split(pa[0], pb[0], positive)
            if found is None:
                continue
            x, c = found
            out.remove(a)
            out.remove(b)
            out.append((sp.Lt if pa[1] else sp.Le)(sp.Abs(x), c))
            changed = True
            break
    return out


@checked
def merge_abs(conditions: list[sp.Basic]) -> list[sp.Basic]:
    """Replace the pair ``x < c``, ``-x < c`` written so (c free of x, any sign) by ``|x| < c``.

    Unlike :func:`merge_and`, it keeps the sides as written and asks nothing of c.

    Examples
    --------
    >>> x, c = sp.symbols("x c", real=True)
    >>> merge_abs([x < c, -x < c])
    [Abs(x) < c]
    """
    out = list(conditions)
    for i, a in enumerate(conditions):
        for b in conditions[i + 1 :]:
            if not (isinstance(a, sp.StrictLessThan) and isinstance(b, sp.StrictLessThan)):
                continue
            if sp.expand(a.lhs + b.lhs) == 0 and sp.expand(a.rhs - b.rhs) == 0 and a in out and b in out:
                x = a.lhs if not a.lhs.could_extract_minus_sign() else b.lhs
                out[out.index(a)] = sp.Lt(sp.Abs(x), a.rhs)
                out.remove(b)
    return out


@checked(positive="Sequence[sp.Expr]")
def merge_pair(a: sp.Basic, b: sp.Basic, positive=()) -> sp.Basic | None:
    """One relational equivalent to ``a or b`` when a short one exists (True when they cover all).

    Examples
    --------
    >>> x = sp.Symbol("x", real=True)
    >>> merge_pair(x > 2, -x > 2), merge_pair(x > 0, x <= 0), merge_pair(x < 0, sp.Eq(x, 0))
    (Abs(x) > 2, True, x <= 0)
    >>> merge_pair(x >= 5, x > 5)
    x >= 5
    """
    pa = positive_part(a) if isinstance(a, Relational) else None
    pb = positive_part(b) if isinstance(b, Relational) else None
    if pa and pb:
        if sp.expand(pa[0] + pb[0]) == 0 and pa[1] != pb[1]:
            return sp.true  # P > 0 or P <= 0
        if pa[1] != pb[1] and sp.expand(pa[0] - pb[0]) == 0:
            return b if pa[1] else a  # P > 0 or P >= 0: the weak one
        if pa[1] == pb[1]:
            found = split(-pa[0], -pb[0], positive)  # p_a = x - c, p_b = -x - c
            if found is not None:
                x, c = found
                return (sp.Gt if pa[1] else sp.Ge)(sp.Abs(x), c)
        return None
    for strict, equal in ((a, b), (b, a)):
        ps = positive_part(strict) if isinstance(strict, Relational) else None
        if ps and ps[1] and isinstance(equal, sp.Equality):
            difference = sp.expand(equal.lhs - equal.rhs)
            if sp.expand(ps[0] - difference) == 0 or sp.expand(ps[0] + difference) == 0:
                weak = {sp.StrictLessThan: sp.Le, sp.StrictGreaterThan: sp.Ge}[type(strict)]
                return weak(strict.lhs, strict.rhs)
    return None


@checked(positive="Sequence[sp.Expr]")
def merge_or(disjuncts: list[frozenset], positive=()) -> list[frozenset]:
    """Merge disjuncts (sets of conjuncts) that differ in one conjunct; drop absorbed ones.

    Examples
    --------
    >>> x, c = sp.symbols("x c", real=True)
    >>> merge_or([frozenset({x <= 0, c > 1}), frozenset({x > 0, c > 1})])
    [frozenset({c > 1})]
    """
    out = list(dict.fromkeys(disjuncts))
    changed = True
    while changed:
        changed = False
        for d1, d2 in itertools.permutations(out, 2):
            if d1 <= d2:  # d2 implies d1
                out.remove(d2)
                changed = True
                break
            only1, only2 = d1 - d2, d2 - d1
            if len(only1) != 1 or len(only2) != 1:
                continue
            merged = merge_pair(next(iter(only1)), next(iter(only2)), positive)
            if merged is None:
                continue
            common = d1 & d2
            out[out.index(d1)] = frozenset(common if merged == sp.true else common | {merged})
            out.remove(d2)
            changed = True
            break
    return out


@checked
def boolean(disjuncts: list[frozenset]) -> sp.Basic:
    """The Boolean ``Or(And(*d) for d in disjuncts)``.

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> boolean([frozenset({x > 0, y > 0}), frozenset({x < -1})])
    (x < -1) | ((x > 0) & (y > 0))
    """
    return sp.Or(*[sp.And(*d) for d in disjuncts])
