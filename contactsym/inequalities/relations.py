"""One relation ``P op 0`` at a time: orientation, factors of known sign, a reader's arrangement.

Every function here returns a relation equivalent to its input under the assumptions of
the symbols and the expressions listed as positive; none calls ``simplify``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp
from sympy.core.relational import Relational

from ..algebra.basic import known_sign
from ..arguments import checked, require
from .factors import factor_list

__all__ = [
    "FLIP",
    "Condition",
    "as_positive_relation",
    "positive_part",
    "drop_known_factors",
    "arrange",
    "solve_for",
    "tidy",
    "univariate",
]

#: The relation that holds after multiplying both sides by a negative number.
#:
#: >>> import sympy as sp
#: >>> from contactsym.inequalities import FLIP
#: >>> FLIP[sp.StrictGreaterThan](1, 2)
#: True
FLIP = {
    sp.StrictGreaterThan: sp.StrictLessThan,
    sp.GreaterThan: sp.LessThan,
    sp.StrictLessThan: sp.StrictGreaterThan,
    sp.LessThan: sp.GreaterThan,
    sp.Equality: sp.Equality,
    sp.Unequality: sp.Unequality,
}

_ORDER = (sp.StrictGreaterThan, sp.GreaterThan, sp.StrictLessThan, sp.LessThan)


@checked
@dataclass(frozen=True)
class Condition:
    """``raw > 0`` (strict) or ``raw >= 0``; ``presented`` is the same number in other variables.

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> Condition.of(x < 1)
    Condition(raw=1 - x, presented=1 - x, strict=True)
    >>> Condition.of(sp.Eq(x, 1)) is None
    True
    """

    raw: sp.Expr
    presented: sp.Expr
    strict: bool = True

    @classmethod
    def of(cls, rel: sp.Basic) -> Condition | None:
        """The condition a relational ``<, <=, >, >=`` states; None for anything else."""
        part = positive_part(rel) if isinstance(rel, Relational) else None
        return None if part is None else cls(part[0], part[0], part[1])


@checked
def as_positive_relation(rel: Relational) -> tuple[sp.Expr, type]:
    """``P op 0`` with op in {>, >=, ==, !=}.

    Examples
    --------
    >>> x = sp.Symbol("x")
    >>> as_positive_relation(x < 2)
    (2 - x, <class 'sympy.core.relational.StrictGreaterThan'>)
    """
    expr = rel.lhs - rel.rhs
    if isinstance(rel, (sp.StrictLessThan, sp.LessThan)):
        return -expr, FLIP[type(rel)]
    return expr, type(rel)


@checked
def positive_part(rel: sp.Basic) -> tuple[sp.Expr, bool] | None:
    """(P, strict) with rel equivalent to P > 0 (strict) or P >= 0, P expanded; None for == and !=.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> positive_part(x < y), positive_part(2*(x - 1) >= 1)
    ((-x + y, True), (2*x - 3, False))
    >>> positive_part(sp.Eq(x, 1)) is None
    True
    """
    if not isinstance(rel, _ORDER):
        return None
    return _positive_part(rel)


@lru_cache(maxsize=1024)
def _positive_part(rel: Relational) -> tuple[sp.Expr, bool]:
    # once per relation: closed forms compare the parts of large conditions pairwise, at every level
    expr, op = as_positive_relation(rel)
    return sp.expand(expr), op is sp.StrictGreaterThan


@checked(positive="Sequence[sp.Expr]")
def drop_known_factors(expr: sp.Expr, op: type, positive, factor_terms: float) -> tuple[sp.Expr, type, list]:
    """Factor ``expr`` and drop factors of known sign; returns (rest, op, nonzero conditions).

    A numerator with more than ``factor_terms`` terms is kept whole (factoring it costs
    seconds and finds nothing readable). In ``P > 0`` and ``P != 0`` an even power of a factor
    of unknown sign becomes the condition that the factor is nonzero; in ``P >= 0`` and
    ``P == 0`` it stays (the factor may vanish there).

    Examples
    --------
    >>> m = sp.Symbol("m", positive=True)
    >>> x, y = sp.symbols("x y", real=True)
    >>> drop_known_factors(-m * (x - 1) * y**2, sp.StrictGreaterThan, (), 200)
    (x - 1, <class 'sympy.core.relational.StrictLessThan'>, [Ne(y, 0)])
    """
    numerator, denominator = sp.fraction(sp.together(expr))
    if numerator == 0:  # 0 op 0 is decided, and factor_list(0) has the coefficient 0: no sign to take
        return sp.S.Zero, op, []
    sign = known_sign(denominator, positive)
    if sign is None:
        numerator, sign = sp.expand(numerator * denominator), 1
    if len(sp.Add.make_args(numerator)) > factor_terms:
        coefficient, factors = sp.S.One, [(numerator, 1)]
    else:
        coefficient, factors = factor_list(numerator)  # sympy's factor_list, skipped where irreducible is plain
    sign *= 1 if coefficient > 0 else -1
    rest, nonzero = sp.S.One, []
    for base, power in factors:
        base_sign = known_sign(base, positive)
        if base_sign is None and power % 2 == 0:
            base_sign = 1 if known_sign(base**2, positive) == 1 else None
            if base_sign is None and op in (sp.StrictGreaterThan, sp.Unequality):
                nonzero.append(sp.Ne(base, 0))
                continue
        if base_sign is None:
            rest *= base**power
        else:
            sign *= base_sign**power
    if sign < 0:
        op = FLIP[op]
    return rest, op, nonzero


@checked(positive="Sequence[sp.Expr]")
def arrange(expr: sp.Expr, op: type, positive, factor_terms: float) -> sp.Basic:
    """Write ``P > 0`` (or >=) as a reader would: terms of unknown sign on the left.

    P = known positive + known negative + rest; ``rest > -(known)`` or, when the rest
    reads negative, ``-rest < known``; with no rest, ``-negative < positive``.

    Examples
    --------
    >>> kappa = sp.Symbol("kappa", positive=True)
    >>> v1, v2 = sp.symbols("v_1 v_2", real=True)
    >>> arrange(2 * kappa**2 - v1 - v2, sp.StrictGreaterThan, (), 200)
    v_1 + v_2 < 2*kappa**2
    """
    if op in (sp.Equality, sp.Unequality) or expr.is_number:
        return op(expr, 0)
    if op in (sp.StrictLessThan, sp.LessThan):
        expr, op = -expr, FLIP[op]
    if expr.is_Mul:  # a product of factors of unknown sign reads best as it is: (1 + v1)(1 + v2) >= 0
        return FLIP[op](-expr, 0) if expr.could_extract_minus_sign() else op(expr, 0)
    terms = sp.Add.make_args(sp.expand(expr))
    signs = [known_sign(t, positive) for t in terms]
    positive_part_ = sp.Add(*[t for t, s in zip(terms, signs) if s == 1])
    negative_part = sp.Add(*[t for t, s in zip(terms, signs) if s == -1])
    rest = sp.Add(*[t for t, s in zip(terms, signs) if s is None])
    less, greater = (sp.Lt, sp.Gt) if op is sp.StrictGreaterThan else (sp.Le, sp.Ge)
    group = sp.factor_terms if len(terms) <= factor_terms else sp.Add  # gcd_terms costs seconds on big sums
    if rest == 0:
        return less(group(-negative_part), group(positive_part_))
    if rest.could_extract_minus_sign():
        return less(group(-rest), group(positive_part_ + negative_part))
    return greater(group(rest), group(-positive_part_ - negative_part))


@checked(positive="Sequence[sp.Expr]")
def solve_for(rel: sp.Basic, symbol: sp.Symbol, positive=()) -> sp.Basic:
    """Solve ``small op big`` for a positive symbol when it is a x**2 + c or a x + c.

    Examples
    --------
    >>> mu, a = sp.Symbol("mu", positive=True), sp.Symbol("alpha", positive=True)
    >>> solve_for(mu**2 * sp.sin(a) ** 2 <= sp.cos(a) ** 2, mu, positive=[sp.sin(a)])
    mu <= Abs(cot(alpha))
    """
    if not isinstance(rel, Relational) or symbol not in rel.free_symbols or not symbol.is_positive:
        return rel
    expr, op = as_positive_relation(rel)
    poly = sp.Poly(sp.expand(expr), symbol)
    if poly.degree() not in (1, 2) or (poly.degree() == 2 and poly.coeff_monomial(symbol) != 0):
        return rel
    a = poly.LC()
    c = poly.coeff_monomial(1)
    sign = known_sign(a, positive)
    if sign is None:
        return rel
    bound = -c / a
    if poly.degree() == 2:
        bound = sp.sqrt(sp.trigsimp(sp.cancel(bound))).rewrite(sp.cot)  # short: trigsimp is cheap here
    # a x^d + c op 0  <=>  x^d op' bound (op flips when a < 0)
    op = op if sign > 0 else FLIP[op]
    return {sp.StrictGreaterThan: sp.Gt, sp.GreaterThan: sp.Ge, sp.StrictLessThan: sp.Lt, sp.LessThan: sp.Le}[op](
        symbol, bound
    )


@checked(positive="Sequence[sp.Expr]")
def tidy(rel: sp.Basic, positive) -> sp.Basic:
    """``a - b < -c`` (c known positive) reads better as ``b - a > c``.

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> tidy(x - y < -2, ())
    -x + y > 2
    """
    if not isinstance(rel, _ORDER):
        return rel
    if rel.lhs.is_Add and known_sign(rel.rhs, positive) == -1:
        flipped = {sp.StrictLessThan: sp.Gt, sp.LessThan: sp.Ge, sp.StrictGreaterThan: sp.Lt, sp.GreaterThan: sp.Le}
        return flipped[type(rel)](-rel.lhs, -rel.rhs)
    return rel


@checked
def univariate(condition: sp.Basic) -> sp.Basic:
    """A Boolean in one real symbol, as the union of intervals it describes.

    Examples
    --------
    >>> x = sp.Symbol("x", real=True)
    >>> univariate(sp.And(x > 0, x < 2, x < 1))
    (0 < x) & (x < 1)
    """
    require(len(condition.free_symbols) == 1, "univariate", "condition", condition, "a condition in one symbol")
    (x,) = condition.free_symbols
    try:
        return condition.as_set().as_relational(x)
    except (NotImplementedError, TypeError, ValueError):
        return condition
