"""Closed-form regions: the raw Hurwitz/proposition conditions as inequalities a reader writes.

``closed_form`` reduces each relational ``P op 0`` exactly:

1. present it in the scene's variables (kappa, v_j, mu_pm, ...);
2. clear the denominator (its sign must be known) and factor the numerator;
3. drop constant factors, factors of known sign (masses, squares of nonzero symbols,
   Phi < 0, Psi < 0, sines the scene declares positive) flipping the relation for
   negative ones; an even power of an unknown factor f becomes the condition f != 0;
4. write what is left as ``small < big`` with the terms of known positive sign on the
   right (``v1 + v2 < 2 kappa**2``, ``-m mu**2 Phi < Psi**2 (mu**2 + 1)``);
5. solve for a parameter the scene names when the condition is ``a x**2 + c`` or
   ``a x + c`` in it (``mu <= |cot(alpha)|``);
6. merge ``x < c`` and ``-x < c`` into ``|x| < c``.

Size limits. A fully symbolic scene with k >= 3 has Hurwitz minors no reader can use in
closed form: for q_i'' = sum_j a_ij N_j + b_i with k = 3, Delta_5 of the Hopf line is 2665
operations unexpanded and 19390 terms expanded, and ``factor_list`` of its 306-term
Delta_3 alone takes seconds (it is irreducible). Past :data:`RAW_OPS` operations a relation
is kept exactly as derived (step 1 only: no expansion, no factoring); past
:data:`FACTOR_TERMS` terms a numerator is kept unfactored and its sides are not regrouped by
common factors (steps 3-6 still apply to it as a whole). Both only skip rewriting: the
relation kept is the derived one or an equivalent multiple of it, so the region means the
same; only its presentation is less reduced. The built-in scenes stay far below both limits
(at most 986 operations, 130 terms).

A :class:`Region` wraps such a Boolean: ``&``, ``|``, ``~``, ``latex()``, vectorised
``evaluate``, exact ``contains`` and ``plot``.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
import sympy as sp
from sympy.core.relational import Relational
from sympy.logic.boolalg import BooleanFunction

from .algebra import known_sign, normalize
from .latex import tex
from .parse import sympy_only

__all__ = ["Region", "closed_form", "known_sign"]

#: Relations with more operations (unexpanded) are kept as derived: see the module docstring.
RAW_OPS = 1500
#: Numerators with more terms are not factored: see the module docstring.
FACTOR_TERMS = 200

_FLIP = {
    sp.StrictGreaterThan: sp.StrictLessThan,
    sp.GreaterThan: sp.LessThan,
    sp.StrictLessThan: sp.StrictGreaterThan,
    sp.LessThan: sp.GreaterThan,
    sp.Equality: sp.Equality,
    sp.Unequality: sp.Unequality,
}


def _as_positive_relation(rel: Relational) -> tuple[sp.Expr, type]:
    """``P op 0`` with op in {>, >=, ==, !=}."""
    expr = rel.lhs - rel.rhs
    if isinstance(rel, (sp.StrictLessThan, sp.LessThan)):
        return -expr, _FLIP[type(rel)]
    return expr, type(rel)


def _drop_known_factors(expr: sp.Expr, op: type, positive) -> tuple[sp.Expr, type, list]:
    """Factor ``expr`` and drop factors of known sign; returns (rest, op, nonzero conditions)."""
    numerator, denominator = sp.fraction(sp.together(expr))
    sign = known_sign(denominator, positive)
    if sign is None:
        numerator, sign = sp.expand(numerator * denominator), 1
    if len(sp.Add.make_args(numerator)) > FACTOR_TERMS:  # factoring costs seconds and finds nothing readable
        coefficient, factors = sp.S.One, [(numerator, 1)]
    else:
        coefficient, factors = sp.factor_list(numerator)
    sign *= 1 if coefficient > 0 else -1
    rest, nonzero = sp.S.One, []
    for base, power in factors:
        base_sign = known_sign(base, positive)
        if base_sign is None and power % 2 == 0:
            base_sign = 1 if known_sign(base**2, positive) == 1 else None
            if base_sign is None:
                nonzero.append(sp.Ne(base, 0))
                continue
        if base_sign is None:
            rest *= base**power
        else:
            sign *= base_sign**power
    if sign < 0:
        op = _FLIP[op]
    return rest, op, nonzero


def _arrange(expr: sp.Expr, op: type, positive) -> sp.Basic:
    """Write ``P > 0`` (or >=) as a reader would: terms of unknown sign on the left.

    P = known positive + known negative + rest; ``rest > -(known)`` or, when the rest
    reads negative, ``-rest < known``; with no rest, ``-negative < positive``.
    """
    if op in (sp.Equality, sp.Unequality) or expr.is_number:
        return op(expr, 0)
    if op in (sp.StrictLessThan, sp.LessThan):
        expr, op = -expr, _FLIP[op]
    if expr.is_Mul:  # a product of factors of unknown sign reads best as it is: (1 + v1)(1 + v2) >= 0
        return _FLIP[op](-expr, 0) if expr.could_extract_minus_sign() else op(expr, 0)
    terms = sp.Add.make_args(sp.expand(expr))
    signs = [known_sign(t, positive) for t in terms]
    positive_part = sp.Add(*[t for t, s in zip(terms, signs) if s == 1])
    negative_part = sp.Add(*[t for t, s in zip(terms, signs) if s == -1])
    rest = sp.Add(*[t for t, s in zip(terms, signs) if s is None])
    strict = op is sp.StrictGreaterThan
    less, greater = (sp.Lt, sp.Gt) if strict else (sp.Le, sp.Ge)
    tidy = sp.factor_terms if len(terms) <= FACTOR_TERMS else sp.Add  # gcd_terms costs seconds on big sums
    if rest == 0:
        return less(tidy(-negative_part), tidy(positive_part))
    if rest.could_extract_minus_sign():
        return less(tidy(-rest), tidy(positive_part + negative_part))
    return greater(tidy(rest), tidy(-positive_part - negative_part))


def _difference(rel: sp.Basic) -> tuple[sp.Expr, bool] | None:
    """(P, strict) with rel equivalent to P > 0 (strict) or P >= 0."""
    if not isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan, sp.StrictLessThan, sp.LessThan)):
        return None
    expr, op = _as_positive_relation(rel)
    return sp.expand(expr), op is sp.StrictGreaterThan


def _implies(premises: list[sp.Basic], conclusion: sp.Basic, positive) -> bool:
    """True when P_c - (a sum of some premises' P) is known positive: a cheap exact proof."""
    target = _difference(conclusion)
    parts = [_difference(p) for p in premises]
    if target is None or any(p is None for p in parts):
        return False
    for size in range(1, len(parts) + 1):
        for chosen in itertools.combinations(parts, size):
            slack = target[0] - sp.Add(*[p for p, _ in chosen])
            if known_sign(slack, positive) == 1:
                return True
    return False


def _infeasible(relations: list[sp.Basic], positive) -> bool:
    """True when some of the relations (each P > 0 or P >= 0) sum to a known negative number."""
    parts = [_difference(r) for r in relations]
    if any(p is None for p in parts):
        return False
    for size in range(2, len(parts) + 1):
        for chosen in itertools.combinations(parts, size):
            if known_sign(sp.Add(*[p for p, _ in chosen]), positive) == -1:
                return True
    return False


def _drop_implied_conjuncts(conjuncts: list[sp.Basic], positive) -> list[sp.Basic]:
    """Remove an Or of relationals that the relational conjuncts imply (premises and its negation clash)."""
    premises = [c for c in conjuncts if isinstance(c, Relational)]
    kept = []
    for c in conjuncts:
        if isinstance(c, sp.Or) and all(isinstance(d, Relational) for d in c.args):
            if _infeasible(premises + [sp.Not(d) for d in c.args], positive):
                continue
        kept.append(c)
    return kept


def _drop_implied_disjuncts(disjuncts: list[sp.Basic], positive) -> list[sp.Basic]:
    """Remove a disjunct that implies another one (it adds nothing to the Or)."""
    kept = list(disjuncts)
    for d in disjuncts:
        others = [o for o in kept if o is not d]
        if any(_implies(list(sp.And.make_args(d)), o, positive) for o in others if isinstance(o, Relational)):
            kept.remove(d)
    return kept


def _solve_for(rel: sp.Basic, symbol: sp.Symbol, positive=()) -> sp.Basic:
    """Solve ``small op big`` for a positive symbol when it is a x**2 + c or a x + c."""
    if not isinstance(rel, Relational) or symbol not in rel.free_symbols or not symbol.is_positive:
        return rel
    expr, op = _as_positive_relation(rel)
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
    op = op if sign > 0 else _FLIP[op]
    flipped = {sp.StrictGreaterThan: sp.Gt, sp.GreaterThan: sp.Ge, sp.StrictLessThan: sp.Lt, sp.LessThan: sp.Le}
    return flipped[op](symbol, bound)


def _merge_abs(conditions: list[sp.Basic]) -> list[sp.Basic]:
    """Replace the pair x < c, -x < c (c free of x) by |x| < c."""
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


def _univariate(condition: sp.Basic) -> sp.Basic:
    """A Boolean in one real symbol, as the union of intervals it describes."""
    (x,) = condition.free_symbols
    try:
        return condition.as_set().as_relational(x)
    except (NotImplementedError, TypeError, ValueError):
        return condition


def closed_form(condition, scene=None, solve_for: sp.Symbol | None = None, signs=None) -> sp.Basic:
    """The simplest equivalent form of a condition, in the scene's presentation variables.

    Examples
    --------
    >>> import contactsym as cs
    >>> s = cs.scene("painleve-klein-guides")
    >>> closed_form(s.stability().robustly_unstable, s)
    v_1 + v_2 > 2*kappa**2
    >>> b = cs.scene("brake")
    >>> closed_form(b.stability().robustly_stable, b, solve_for=sp.Symbol("mu", positive=True))
    mu <= Abs(cot(alpha))
    >>> closed_form(s.stability().robustly_stable, s)
    ((v_1 + 1)*(v_2 + 1) >= 0) & (v_1 < 2*kappa**2 + 1) & (v_2 < 2*kappa**2 + 1) & (v_1 + v_2 < 2*kappa**2)
    """
    positive = tuple(getattr(scene, "positive_expressions", ()))
    condition = scene.present(condition, signs) if scene is not None else sympy_only(condition, "the condition")
    reduced = _reduce(condition, positive, solve_for)
    if len(reduced.free_symbols) == 1 and isinstance(reduced, BooleanFunction):
        return _univariate(reduced)
    return reduced


#: The regions every scene offers, from its stability object.
REGION_NAMES = {
    "stable for every law": "robustly_stable",
    "unstable for every law": "robustly_unstable",
    "law-dependent": "law_dependent",
    "Hopf line": "hopf",
}


def scene_regions(scene, signs=None) -> dict[str, Region]:
    """The named closed-form regions of a scene (one sign pattern, or all with symbols s_i).

    Examples
    --------
    >>> import contactsym as cs
    >>> scene_regions(cs.scene("brake"))["stable for every law"]
    Region(stable for every law: mu <= Abs(cot(alpha)))
    """
    stability = scene.stability(signs)
    regions = {}
    for name, attribute in REGION_NAMES.items():
        raw = getattr(stability, attribute)
        if raw is None:
            continue
        condition = closed_form(raw, scene, solve_for=getattr(scene, "solve_for", None), signs=signs)
        regions[name] = Region(condition, name=name, description=f"{scene.name}: {attribute}")
    return regions


def _reduce(condition, positive, solve_for):
    if condition in (sp.true, sp.false):
        return condition
    if isinstance(condition, Relational):
        expr, op = _as_positive_relation(condition)
        if sp.count_ops(expr) > RAW_OPS:  # too large to expand: kept as derived (module docstring)
            return condition
        rest, op, nonzero = _drop_known_factors(normalize(expr), op, positive)
        arranged = _arrange(rest, op, positive)
        if solve_for is not None:
            arranged = _solve_for(arranged, solve_for, positive)
        return sp.And(arranged, *nonzero)
    if isinstance(condition, BooleanFunction):
        args = [_reduce(arg, positive, solve_for) for arg in condition.args]
        if isinstance(condition, sp.And):
            flat = [c for arg in args for c in sp.And.make_args(arg)]
            return sp.And(*_drop_implied_conjuncts(_merge_abs(flat), positive))
        if isinstance(condition, sp.Or):
            return sp.Or(*_drop_implied_disjuncts(args, positive))
        return condition.func(*args)
    return condition


@dataclass(frozen=True, eq=False)
class Region:
    """A closed-form Boolean region in a scene's symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y", real=True)
    >>> r = Region(x + y < 2, name="below") & Region(x > 0)
    >>> r.contains(x=1, y="1/2"), r.contains(x=1, y=1)
    (True, False)
    >>> r.evaluate(x=np.array([0.5, 1.5]), y=np.array([0.0, 1.0])).tolist()
    [True, False]
    >>> print(r.latex())
    x > 0 \\wedge x + y < 2
    """

    condition: sp.Basic
    name: str = ""
    description: str = ""
    symbols: tuple = field(default=())

    def __post_init__(self):
        object.__setattr__(self, "condition", sympy_only(self.condition, "a region's condition"))
        if not self.symbols:
            object.__setattr__(self, "symbols", tuple(sorted(self.condition.free_symbols, key=str)))

    def _combine(self, other: Region, op, word: str) -> Region:
        name = f"({self.name} {word} {other.name})" if self.name and other.name else ""
        return Region(op(self.condition, other.condition), name)

    def __and__(self, other: Region) -> Region:
        return self._combine(other, sp.And, "and")

    def __or__(self, other: Region) -> Region:
        return self._combine(other, sp.Or, "or")

    def __invert__(self) -> Region:
        return Region(sp.Not(self.condition), f"not {self.name}" if self.name else "")

    def latex(self) -> str:
        return tex(self.condition)

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"

    def __repr__(self) -> str:
        label = f"{self.name}: " if self.name else ""
        return f"Region({label}{self.condition})"

    @cached_property
    def _by_name(self) -> dict:
        return {str(s): s for s in self.condition.free_symbols}

    def _symbols_for(self, values: dict) -> dict:
        unknown = set(values) - set(self._by_name)
        missing = set(self._by_name) - set(values)
        if missing:
            raise ValueError(f"give values for {sorted(missing)}; the region depends on them.")
        if unknown:
            raise ValueError(f"the region does not depend on {sorted(unknown)}; known: {sorted(self._by_name)}.")
        return {self._by_name[name]: value for name, value in values.items()}

    @cached_property
    def _compiled(self):
        symbols = sorted(self.condition.free_symbols, key=str)
        return symbols, sp.lambdify(symbols, self.condition, modules="numpy")

    def evaluate(self, **arrays) -> np.ndarray:
        """Membership for arrays of parameter values (broadcast with numpy), by symbol name."""
        self._symbols_for(arrays)
        symbols, function = self._compiled
        arguments = [np.asarray(arrays[str(s)], dtype=float) for s in symbols]
        shape = np.broadcast_shapes(*(a.shape for a in arguments)) if arguments else ()
        return np.broadcast_to(np.asarray(function(*arguments), dtype=bool), shape)

    def contains(self, **exact_values) -> bool:
        """Exact membership: values are converted to rationals (floats exactly, strings parsed as numbers)."""
        values = {s: _exact(v) for s, v in self._symbols_for(exact_values).items()}
        result = self.condition.xreplace(values)
        if result not in (sp.true, sp.false):
            result = result.simplify() if not result.free_symbols else result
        if result not in (sp.true, sp.false):
            raise ValueError(f"cannot decide {result} exactly.")
        return bool(result)

    def plot(self, ax=None, *, x, y, fixed=None, **style):
        """Hatch the region in the (x, y) plane; see :func:`contactsym.plotting.region_plot`."""
        from .plotting.regionplot import region_plot  # the leaf module: no import cycle

        return region_plot(self, ax=ax, x=x, y=y, fixed=fixed or {}, **style)


def _exact(value) -> sp.Expr:
    """A rational (or exact SymPy number) from an int, float, Fraction, or numeric string."""
    if isinstance(value, sp.Basic):
        if not value.is_number:
            raise ValueError(f"{value} is not a number.")
        return value
    if isinstance(value, str):
        try:
            return sp.Rational(value)
        except (TypeError, ValueError) as error:
            raise ValueError(f"'{value}' is not a number; give e.g. '3/4' or '0.75'.") from error
    if isinstance(value, float):
        if not np.isfinite(value):
            raise ValueError(f"{value} is not finite.")
        return sp.Rational(value)
    return sp.Rational(value)
