"""Closed forms of Booleans of relations: each relation reduced, implied parts dropped, pairs merged.

A relation left in sign symbols alone is decided over their +-1 patterns where all agree; of
P > 0 and P >= 0 in a conjunction the strict one stays, and a disjunct that implies another part by
part goes (so of the two in a disjunction, the weak one).

Size limits. A fully symbolic scene with k >= 3 has Hurwitz minors no reader can use in
closed form: for q_i'' = sum_j a_ij N_j + b_i with k = 3, Delta_5 of the Hopf line is 2665
operations unexpanded and 19390 terms expanded, and ``factor_list`` of its 306-term
Delta_3 alone takes seconds (it is irreducible). Past ``raw_ops`` operations a relation is
kept exactly as given (no expansion, no factoring); past ``factor_terms`` terms a numerator
is kept unfactored and its sides are not regrouped by common factors (the other steps still
apply to it as a whole). Both only skip rewriting: the relation kept is the given one or an
equivalent multiple of it, so the condition means the same; only its presentation is less
reduced. The built-in scenes stay far below both defaults (at most 986 operations, 130 terms).
"""

from __future__ import annotations

import itertools

import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import BooleanFunction

from ..algebra.basic import SignSymbol, normalize
from ..arguments import checked
from .facts import Facts
from .merges import merge_abs, merge_and
from .relations import (
    Condition,
    arrange,
    as_positive_relation,
    drop_known_factors,
    positive_part,
    solve_for,
    tidy,
    univariate,
)

__all__ = ["RAW_OPS", "FACTOR_TERMS", "closed_form", "closed_conjuncts"]

#: Relations with more operations (unexpanded) are kept as given: see the module docstring.
#:
#: >>> from contactsym.inequalities import RAW_OPS
#: >>> RAW_OPS > 0
#: True
RAW_OPS = 1500
#: A relation in sign symbols alone (s_j = +-1) is decided by trying every +-1 pattern, up to this many
#: patterns: true or false when all of them agree (71 s_1 = 61 s_2 never holds), else kept.
#:
#: >>> from contactsym.inequalities.closed import SIGN_PATTERNS
#: >>> 2**3 <= SIGN_PATTERNS
#: True
SIGN_PATTERNS = 2**10
#: Numerators with more terms are not factored: see the module docstring.
#:
#: >>> from contactsym.inequalities import FACTOR_TERMS
#: >>> FACTOR_TERMS > 0
#: True
FACTOR_TERMS = 200


@checked(positive="Sequence[sp.Expr]")
def closed_form(
    condition: sp.Basic,
    positive=(),
    solve_for_symbol: sp.Symbol | None = None,
    *,
    raw_ops: float = RAW_OPS,
    factor_terms: float = FACTOR_TERMS,
    memo: dict | None = None,
) -> sp.Basic:
    """The simplest equivalent form of a Boolean of relations, in the variables it is written in.

    Each relation ``P op 0`` loses the factors of known sign (flipping op for negative ones),
    is written as ``small < big`` with the terms of known positive sign on the right, and is
    solved for ``solve_for_symbol`` when it is ``a x**2 + c`` or ``a x + c`` in it; in a
    conjunction ``x < c, -x < c`` merge into ``|x| < c`` and parts the others imply are dropped.

    ``memo`` (a dict the caller keeps, e.g. one per scene) holds each relation's closed form and
    each proof tried, for the next call: a scene's regions share most of their relations.
    The answer is the same with or without it.

    Examples
    --------
    >>> kappa = sp.Symbol("kappa", positive=True)
    >>> v1, v2 = sp.symbols("v_1 v_2", real=True)
    >>> closed_form(kappa**2 * (2 * kappa**2 - v1 - v2) > 0)
    v_1 + v_2 < 2*kappa**2
    >>> closed_form(sp.And(v1 > 0, v2 > 0, sp.Or(v1 + v2 > 0, v1 < -1)))  # the Or follows from the rest
    (v_1 > 0) & (v_2 > 0)
    """
    limits = (raw_ops, factor_terms)
    positive = tuple(positive)
    memo = {} if memo is None else memo
    # a disjunct is dropped on a slack known > 0 only: a slack known >= 0 would drop more, as
    # correctly, but change the closed forms the scenes have printed so far
    facts = memo.setdefault(("facts", positive), Facts(positive, nonnegative_slack=False))
    reduced = _reduce(condition, facts, solve_for_symbol, limits)
    if len(reduced.free_symbols) == 1 and isinstance(reduced, BooleanFunction):
        return univariate(reduced)
    return reduced


def _reduce(condition, facts: Facts, symbol, limits) -> sp.Basic:
    if condition in (sp.true, sp.false):
        return condition
    if isinstance(condition, Relational):
        reduced = facts.cached(
            ("relation", condition, symbol, limits), _reduce_relation, condition, facts, symbol, limits
        )
        # a known positive factor gone (h mu (71 s_1 - 61 s_2) = 0), what is left may be in signs alone
        relations = [reduced] if isinstance(reduced, Relational) else reduced.atoms(Relational)
        decided = {r: _over_sign_patterns(r) for r in relations}
        return reduced.xreplace({r: d for r, d in decided.items() if d is not None})
    if isinstance(condition, BooleanFunction):
        args = [_reduce(arg, facts, symbol, limits) for arg in condition.args]
        if isinstance(condition, sp.And):
            flat = [c for arg in args for c in sp.And.make_args(arg)]
            return sp.And(*_drop_implied_conjuncts(merge_abs(_strict_twins_kept(flat)), facts, limits[0]))
        if isinstance(condition, sp.Or):
            return sp.Or(*_drop_implied_disjuncts(_absorbed(args), facts, limits[0]))
        return condition.func(*args)
    return condition


def _strict_twins_kept(conjuncts: list) -> list:
    """``conjuncts`` without ``P >= 0`` where ``P > 0`` is a conjunct too: the strict one says both. (In a
    disjunction the weak one stays; :func:`_absorbed` does that, as one case of a part implying another.)

    >>> x = sp.Symbol("x", real=True)
    >>> _strict_twins_kept([x >= 5, x > 5, x < 9])
    [x > 5, x < 9]
    """
    keys = [positive_part(c) if isinstance(c, Relational) else None for c in conjuncts]  # P expanded
    strict = {k[0] for k in keys if k is not None and k[1]}
    return [c for c, k in zip(conjuncts, keys) if k is None or k[1] or k[0] not in strict]


def _implied_parts(part) -> dict | None:
    """{P: strict} of a conjunction of relations P > 0 / P >= 0 (None when a part is of another kind)."""
    found = {}
    for conjunct in sp.And.make_args(part):
        positive = positive_part(conjunct) if isinstance(conjunct, Relational) else None
        if positive is None:
            return None
        P = positive[0]  # expanded
        found[P] = found.get(P, False) or positive[1]
    return found


def _absorbed(disjuncts: list) -> list:
    """``disjuncts`` without each one that implies another part by part (D: P > 0 and Q >= 0 implies E:
    P >= 0): D is a subset of E, so ``D or E`` is E. Of two that say the same, the first stays.

    >>> x, y = sp.symbols("x y", real=True)
    >>> _absorbed([(x > 1) & (y > 2), (x >= 1) & (y >= 2), x > 5])
    [(x >= 1) & (y >= 2), x > 5]
    """
    keys = [_implied_parts(d) for d in disjuncts]

    def implies(i: int, j: int) -> bool:  # every part of disjunct j follows from disjunct i's part on its P
        a, b = keys[i], keys[j]
        return a is not None and b is not None and all(P in a and (a[P] or not strict) for P, strict in b.items())

    kept = []
    for i in range(len(disjuncts)):
        # i goes when it implies a j that stays: a j after i that does not imply i, or a kept j before it
        if not any(
            implies(i, j) and (j in kept or (j > i and not implies(j, i))) for j in range(len(disjuncts)) if j != i
        ):
            kept.append(i)
    return [disjuncts[i] for i in kept]


def _over_sign_patterns(relation: Relational) -> sp.Basic | None:
    """true or false when ``relation``'s symbols are all sign symbols and every +-1 pattern of them gives that
    answer (each pattern is a value the symbols take, so this is the relation's value); else None.

    >>> s1, s2 = SignSymbol("s_1"), SignSymbol("s_2")
    >>> _over_sign_patterns(sp.Eq(71 * s1 - 61 * s2, 0)), _over_sign_patterns(s1 + s2 < 3), _over_sign_patterns(s1 > s2)
    (False, True, None)
    """
    symbols = relation.free_symbols
    if not symbols or not all(isinstance(s, SignSymbol) for s in symbols) or 2 ** len(symbols) > SIGN_PATTERNS:
        return None
    symbols = sorted(symbols, key=str)
    values = set()
    for pattern in itertools.product((-1, 1), repeat=len(symbols)):
        values.add(relation.xreplace(dict(zip(symbols, map(sp.Integer, pattern)))))
        if len(values) > 1:
            return None
    (value,) = values
    return value if value in (sp.true, sp.false) else None


def _reduce_relation(relation: Relational, facts: Facts, symbol, limits) -> sp.Basic:
    raw_ops, factor_terms = limits
    expr, op = as_positive_relation(relation)
    if sp.count_ops(expr) > raw_ops:  # too large to expand: kept as given (module docstring)
        return relation
    # P < 0 and -P > 0 are one relation: reduced once
    return facts.cached(
        ("positive relation", expr, op, symbol, limits), _reduce_positive, expr, op, facts, symbol, limits
    )


def _reduce_positive(expr: sp.Expr, op: type, facts: Facts, symbol, limits) -> sp.Basic:
    positive, factor_terms = facts.positive, limits[1]
    rest, op, nonzero = drop_known_factors(normalize(expr), op, positive, factor_terms)
    arranged = arrange(rest, op, positive, factor_terms)
    if symbol is not None:
        arranged = solve_for(arranged, symbol, positive)
    return sp.And(arranged, *nonzero)


def _conditions(relations) -> list[Condition] | None:
    """The conditions of relations ``<, <=, >, >=``; None when one is another kind (==, !=)."""
    conditions = [Condition.of(r) for r in relations]
    return None if any(c is None for c in conditions) else conditions


def _small(condition: sp.Basic, raw_ops: float) -> bool:
    """Every relation of ``condition`` within ``raw_ops`` operations: one past it is kept as given,
    and no implication is tried with it either (proving one expands it)."""
    relations = [condition] if isinstance(condition, Relational) else condition.atoms(Relational)
    return all(sp.count_ops(r.lhs - r.rhs) <= raw_ops for r in relations)


def _drop_implied_conjuncts(conjuncts: list[sp.Basic], facts: Facts, raw_ops: float = RAW_OPS) -> list[sp.Basic]:
    """Remove an Or of relationals that the relational conjuncts imply (premises and its negation clash)."""
    premises = [c for c in conjuncts if isinstance(c, Relational) and _small(c, raw_ops)]
    kept = []
    for c in conjuncts:
        if isinstance(c, sp.Or) and all(isinstance(d, Relational) for d in c.args) and _small(c, raw_ops):
            clash = _conditions(premises + [sp.Not(d) for d in c.args])
            if clash is not None and facts.infeasible(clash):
                continue
        kept.append(c)
    return kept


def _drop_implied_disjuncts(disjuncts: list[sp.Basic], facts: Facts, raw_ops: float = RAW_OPS) -> list[sp.Basic]:
    """Remove a disjunct that implies another one (it adds nothing to the Or)."""
    kept = list(disjuncts)
    for d in disjuncts:
        if not _small(d, raw_ops):
            continue
        premises = _conditions(sp.And.make_args(d))
        others = [Condition.of(o) for o in kept if o is not d and isinstance(o, Relational) and _small(o, raw_ops)]
        if premises is not None and any(o is not None and facts.implied(premises, o) for o in others):
            kept.remove(d)
    return kept


@checked
def closed_conjuncts(conditions: list[Condition], equalities: list[sp.Basic], facts: Facts) -> frozenset:
    """Closed forms of conditions and equations (presented by ``facts``), merged into ``|x| < c``.

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> facts = Facts()
    >>> sorted(closed_conjuncts([facts.condition(1 - x + y), facts.condition(1 + x - y)], [], facts), key=str)
    [Abs(x - y) < 1]
    """
    present = facts.present or (lambda e: e)
    parts = []
    for c in conditions:
        relation = sp.Gt(c.raw, 0) if c.strict else sp.Ge(c.raw, 0)
        reduced = facts.cached(("closed", relation), closed_form, present(relation), facts.positive)
        parts.extend(sp.And.make_args(reduced))
    for e in equalities:
        parts.extend(sp.And.make_args(closed_form(present(e), facts.positive)))
    parts = [tidy(p, facts.positive) for p in parts if p != sp.true]
    return frozenset(merge_and(parts, facts.positive))
