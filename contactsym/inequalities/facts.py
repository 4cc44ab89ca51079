"""Short exact proofs about conditions ``P > 0`` / ``P >= 0``: known signs, implication, infeasibility.

A :class:`Facts` holds what is known about the symbols: the expressions that are positive in
the scene's domain and, optionally, a presentation (other variables, in which a sign may be
plain to see). Every answer is a sufficient test: True is a proof (a sum of conditions whose
sign follows from the assumptions), False proves nothing.
"""

from __future__ import annotations

import itertools
import random
from collections.abc import Callable, Iterator
from functools import lru_cache
from typing import Literal

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..arguments import checked
from .relations import Condition

__all__ = ["Facts", "POINTS", "pythagorean", "half_angles", "refuted"]


@checked
def pythagorean(expr: sp.Expr) -> sp.Expr:
    """sin(x)**(2n) written as (1 - cos(x)**2)**n: 4 - 3 sin^2 + ... shows its sign as 1 + 3 cos^2 + ...

    Examples
    --------
    >>> a = sp.Symbol("alpha", real=True)
    >>> pythagorean(4 - 3 * sp.sin(a) ** 2)
    3*cos(alpha)**2 + 1
    """
    even_sines = [p for p in expr.atoms(sp.Pow) if isinstance(p.base, sp.sin) and p.exp.is_even]
    if not even_sines:
        return expr
    return sp.expand(expr.xreplace({p: (1 - sp.cos(p.base.args[0]) ** 2) ** (p.exp // 2) for p in even_sines}))


@checked
def half_angles(expr: sp.Expr) -> sp.Expr:
    """cos(x) written as 1 - 2 sin(x/2)**2: m (cos 2q - 1) shows its sign as -2 m sin(q)**2.

    Examples
    --------
    >>> m, q = sp.Symbol("m", positive=True), sp.Symbol("q", real=True)
    >>> half_angles(m * sp.cos(2 * q) - m)
    -2*m*sin(q)**2
    """
    cosines = expr.atoms(sp.cos)
    if not cosines:
        return expr
    return sp.expand(expr.xreplace({c: 1 - 2 * sp.sin(c.args[0] / 2) ** 2 for c in cosines}))


#: Numbers tried for a symbol, in turn; each is used only where it has every property the symbol has.
_CANDIDATES = tuple(sp.Rational(c) for c in ("1", "-1", "2", "-2", "1/2", "-1/3", "3", "-5/2", "0", "7", "-7", "1/7"))
#: Points tried before a sign is asked of SymPy's assumptions (see :func:`refuted`).
#:
#: >>> from contactsym.inequalities import POINTS
#: >>> POINTS > 0
#: True
POINTS = 6


@lru_cache(maxsize=4096)
def _values_for(symbol: sp.Symbol) -> tuple[sp.Rational, ...]:
    """The candidate numbers with every assumption of ``symbol`` (positive, integer, nonzero, ...)."""
    facts = {k: v for k, v in symbol.assumptions0.items() if v is not None}
    return tuple(c for c in _CANDIDATES if all(getattr(c, f"is_{k}") == v for k, v in facts.items()))


@checked(sign=Literal[1, -1])
def refuted(value: sp.Expr, sign: int, strict: bool, points: int = POINTS) -> bool:
    """True when ``sign * value`` is exactly < 0 (or = 0, when ``strict``) at some point tried.

    Then no proof that ``sign * value > 0`` (``>= 0`` when not ``strict``) exists: SymPy's assumptions
    (``is_positive``, ``is_nonnegative``, ...) decide from the symbols' assumptions alone, and the
    points tried are exact rationals with every assumption of each symbol (a SignSymbol is an
    integer != 0, so +-1, +-2, ...). Only polynomials in symbols are tried; False proves nothing.

    Examples
    --------
    >>> x, m = sp.Symbol("x", real=True), sp.Symbol("m", positive=True)
    >>> refuted(m**2 + x, 1, True), refuted(m**2 + 1, 1, True), refuted(-m, -1, True)
    (True, False, False)
    """
    symbols = sorted(value.free_symbols, key=str)
    if not symbols or not all(isinstance(s, sp.Symbol) for s in symbols) or not value.is_polynomial(*symbols):
        return False
    choices = [_values_for(s) for s in symbols]
    if not all(choices):
        return False
    rng = random.Random(len(symbols))  # reproducible: the same points for the same symbols
    for _ in range(points):
        number = sign * value.xreplace({s: rng.choice(c) for s, c in zip(symbols, choices)})
        if not number.is_Rational:
            return False
        if number < 0 or (strict and number == 0):
            return True
    return False


@checked(positive="Sequence[sp.Expr]")
class Facts:
    """What is known: positive expressions and an optional presentation; decisions are cached.

    Parameters
    ----------
    positive : iterable of expressions
        Expressions known to be positive (e.g. ``sin(phi)`` for 0 < phi < pi/2).
    present : callable, optional
        The same number in the presentation variables. With it, a condition is tried in its
        canonical form and presented; without it, as it is.
    nonnegative_slack : bool
        Whether an implication may rest on a slack known only to be >= 0 (sound when a
        premise is strict or the conclusion is not); otherwise the slack must be known > 0.
    refute : bool
        Whether a sign is first tried at a few exact points (:func:`refuted`): where the sum
        has the wrong sign at one, SymPy's assumptions are not asked (they could not prove it).
        The answers are the same either way; only their cost differs.

    Examples
    --------
    >>> x, y = sp.symbols("x y", real=True)
    >>> m = sp.Symbol("m", positive=True)
    >>> facts = Facts()
    >>> x_pos, y_pos, sum_neg = Condition.of(x > 0), Condition.of(y > 0), Condition.of(x + y < -m)
    >>> facts.infeasible([x_pos, y_pos, sum_neg]), facts.infeasible([x_pos, y_pos])
    (True, False)
    >>> facts.implied([x_pos, y_pos], Condition.of(x + y + m > 0))
    True
    """

    def __init__(
        self, positive=(), present: Callable | None = None, nonnegative_slack: bool = True, refute: bool = True
    ):
        self.positive = tuple(positive)
        self.present = present
        self.nonnegative_slack = nonnegative_slack
        self.refute = refute
        self._cache: dict = {}

    def cached(self, key, compute: Callable, *args):
        """Sums of conditions recur across sign cases: decide each once."""
        if key not in self._cache:
            self._cache[key] = compute(*args)
        return self._cache[key]

    def condition(self, expr) -> Condition:
        """``expr > 0`` in canonical form with its presentation (cached)."""
        return self.cached(("condition", expr), self._condition, expr)

    def _condition(self, expr) -> Condition:
        raw = normalize(expr)
        return Condition(raw, self.present(raw) if self.present else raw)

    def _views(self, expr: sp.Expr) -> Iterator[sp.Expr]:
        """The forms of one number that are tried in turn, without their positive expressions."""
        # lazily: the presentation is computed only when the canonical form proved nothing
        forms = (lambda: normalize(expr), lambda: self.present(expr)) if self.present else (lambda: expr,)
        for form in forms:
            yield sp.sympify(form()).subs({p: sp.Dummy(positive=True) for p in self.positive})

    def sign(self, condition: Condition) -> int | None:
        """+1 or -1 when the sign of the condition's number is known."""
        for form in (condition.raw, condition.presented, pythagorean(sp.expand(condition.raw))):
            sign = known_sign(form, self.positive)
            if sign is not None:
                return sign
        return None

    def _proves(self, slack, strict_premise: bool, strict_conclusion: bool) -> bool:
        """slack > 0, or slack >= 0 with a strict premise or a non-strict conclusion."""
        weak_enough = self.nonnegative_slack and (strict_premise or not strict_conclusion)
        for value in self._views(slack):
            if self.refute and refuted(value, 1, not weak_enough):
                continue  # a point where the slack is < 0 (<= 0): no assumption proves it (cheaper than asking)
            if value.is_positive or (weak_enough and value.is_nonnegative):
                return True
        return False

    def _nonpositive(self, total, strict: bool) -> bool:
        """total < 0 is known (total <= 0 when some condition is strict)."""
        for value in itertools.chain(self._views(total), self._rewritten(total)):
            if self.refute and refuted(value, -1, not strict):
                continue
            if value.is_negative or (strict and value.is_nonpositive):
                return True
        return False

    def _rewritten(self, total) -> Iterator[sp.Expr]:
        if self.present:  # a scene's raw variables: cos(2 q) - 1 shows its sign in half angles
            yield sp.sympify(half_angles(sp.expand(total))).subs({p: sp.Dummy(positive=True) for p in self.positive})

    def implied(self, premises: list[Condition], conclusion: Condition, max_size: int | None = None) -> bool:
        """A sum of some premises (at most ``max_size``) is below the conclusion by a known non-negative amount."""
        for size in range(1, min(len(premises), max_size or len(premises)) + 1):
            for chosen in itertools.combinations(premises, size):
                raw = conclusion.raw - sp.Add(*[p.raw for p in chosen])
                key = ("proves", raw, any(p.strict for p in chosen), conclusion.strict)
                if self.cached(key, self._proves, raw, *key[2:]):
                    return True
        return False

    def infeasible(self, conditions: list[Condition], max_size: int | None = None) -> bool:
        """Some conditions (at most ``max_size``) add up to a number known to be < 0 (<= 0 when one is strict)."""
        for size in range(1, min(len(conditions), max_size or len(conditions)) + 1):
            for chosen in itertools.combinations(conditions, size):
                total = sp.Add(*[c.raw for c in chosen])
                key = ("nonpositive", total, any(c.strict for c in chosen))
                if self.cached(key, self._nonpositive, total, key[2]):
                    return True
        return False

    def drop_implied(self, conditions: list[Condition], keep=(), max_size: int | None = None) -> list[Condition]:
        """Remove conditions implied by the others (``keep`` conditions stay and serve as premises)."""
        kept = list(conditions)
        for condition in conditions:
            others = [c for c in kept if c is not condition] + list(keep)
            if self.implied(others, condition, max_size):
                kept.remove(condition)
        return kept
