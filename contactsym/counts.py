"""Equilibrium counts for piecewise-linear f: how many reactions a load can produce.

f is affine on each piece of a sign pattern; the slopes (k = 1) or the orthant
determinants (k >= 2) decide how many roots f(u) = 0 can have, for every load.

k = 1 (§3). The corners c_i are the roots of the switching functions sigma_i (each
oriented increasing in u). For each ordering of the corners (a condition on the
parameters, e.g. Y*_1 + Y*_2 < 0, = 0, > 0) the pieces, from left to right, start with
every sign -1 and flip the signs of the switching functions that vanish at each corner.
With the signs of the slopes f' on the pieces:

- all f' > 0: a unique root, stable for every contact law (Propositions 3, 4);
- c <= 3 sign changes: f has c local extrema; when the outer slopes differ in sign the count
  is even (c = 1: a fold, two roots or none, none being an impact-type catastrophe),
  when they agree it is odd (c = 2: a cusp, one root or three; c = 3: none, two or four);
- four or more sign changes: the values at the extrema, not the signs, decide which
  counts occur: undecided.

Orthant maps (k >= 2, and any unilateral contact, lift-off included): see
:mod:`contactsym.orthants` and :mod:`contactsym.plmap`. With the orthant determinants
(principal minors of A with lift-off):

- all of one sign (coherent orientation): a unique solution for every load;
- k = 2, otherwise: the degree of the map decides, and it follows from the signs and
  one cross determinant (:func:`contactsym.plmap.k2_label`): two or none, one or
  three, or none, two or four;
- k >= 3, otherwise: undecided in closed form; :func:`contactsym.count_points.decide_counts`
  decides at numeric points.

Determinants and slopes of known sign are not enumerated, and sign combinations that a
short exact argument excludes (a sum of the conditions of known non-positive sign) are
dropped; conditions implied by the others are removed. Each region is then written in the
scene's presentation variables (:func:`contactsym.regions.closed_form`), with
``x < c, -x < c`` merged into ``|x| < c`` and ``x > c or -x > c`` into ``|x| > c``. A
scene may carry ``count_presentation``, a presentation used for the counts only (the
guides use mu_j = |v_j|/kappa, as the paper does for (5.8)-(5.10)). Boundaries (a slope
or a determinant equal to 0, two corners meeting where the scene leaves that open) belong
to no region.

:func:`square_threshold` finds where the unique region stops lying inside the region
"stable for every law": for the guides, phi = arctan(sqrt(2)) (5.9);
:func:`threshold_angle` returns that angle.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from sympy.core.relational import Relational

from .algebra import normalize
from .errors import ContactsymError
from .orthants import orthant_regions
from .regions import Region, _as_positive_relation, closed_form, known_sign

__all__ = [
    "COUNT_DESCRIPTIONS",
    "CountCase",
    "Threshold",
    "corner_cases",
    "count_regions",
    "square_threshold",
    "threshold_angle",
]

#: What each count region means.
COUNT_DESCRIPTIONS = {
    "unique stable": "one root for every load, stable for every contact law (f' > 0 on every piece; Props. 3-4)",
    "unique unstable": "one root for every load, unstable for every contact law (f' < 0 on every piece)",
    "unique": "one solution for every load (coherent orientation: all orthant determinants of one sign)",
    "two or none": "degree 0: two solutions or none, by the load (a fold; none is an impact-type catastrophe)",
    "one or three": "degree +-1 with mixed orientation: one solution or three, by the load (a cusp)",
    "none, two or four": "degree 0, orthant determinant signs alternating: none, two or four, by the load",
    "undecided": (
        "orthant determinants of mixed signs: the count follows the degree of the map, which their signs "
        "do not fix; decide it at numeric points with contactsym.count_points.decide_counts"
    ),
}

_WORDS = ["none", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine"]


def _count_name(counts: tuple[int, ...]) -> str:
    """'two or none', 'one or three', 'none, two or four', ..."""
    if counts == (0, 2):
        return "two or none"
    words = [_WORDS[c] if c < len(_WORDS) else str(c) for c in counts]
    return ", ".join(words[:-1]) + " or " + words[-1]


# --- presentation for counts ------------------------------------------------------------


class _Presenter:
    """The scene's presentation, or its ``count_presentation`` when it has one.

    Offers what :func:`closed_form` needs: ``present`` and ``positive_expressions``.
    """

    def __init__(self, scene):
        self.scene = scene
        self.name = scene.name
        self.presentation = dict(getattr(scene, "count_presentation", None) or scene.presentation)
        self.positive_expressions = tuple(scene.positive_expressions)

    def present(self, expr, signs=None):
        return self.scene.present(expr, signs, self.presentation)


def _sign_choices(known: list, open_: list):
    """Every completion of the known signs: each open position takes +1 and -1."""
    for choice in itertools.product((1, -1), repeat=len(open_)):
        signs = list(known)
        for i, s in zip(open_, choice):
            signs[i] = s
        yield signs


# --- exact sign facts ------------------------------------------------------------------


@dataclass(frozen=True)
class _Condition:
    """``raw > 0`` (strict) or ``raw >= 0``; ``presented`` is the same number in other variables."""

    raw: sp.Expr
    presented: sp.Expr
    strict: bool = True


def _stand_in(expr, positive):
    return sp.sympify(expr).subs({p: sp.Dummy(positive=True) for p in positive})


def _pythagorean(expr) -> sp.Expr:
    """sin(x)**(2n) written as (1 - cos(x)**2)**n: 4 - 3 sin^2 + ... shows its sign as 1 + 3 cos^2 + ..."""
    even_sines = [p for p in expr.atoms(sp.Pow) if isinstance(p.base, sp.sin) and p.exp.is_even]
    if not even_sines:
        return expr
    return sp.expand(expr.xreplace({p: (1 - sp.cos(p.base.args[0]) ** 2) ** (p.exp // 2) for p in even_sines}))


def _half_angles(expr) -> sp.Expr:
    """cos(x) written as 1 - 2 sin(x/2)**2: m (cos 2q - 1) shows its sign as -2 m sin(q)**2."""
    cosines = expr.atoms(sp.cos)
    if not cosines:
        return expr
    return sp.expand(expr.xreplace({c: 1 - 2 * sp.sin(c.args[0] / 2) ** 2 for c in cosines}))


def _sign(condition: _Condition, positive) -> int | None:
    for form in (condition.raw, condition.presented, _pythagorean(sp.expand(condition.raw))):
        sign = known_sign(form, positive)
        if sign is not None:
            return sign
    return None


def _condition(presenter: _Presenter, expr) -> _Condition:
    return _Condition(*_forms(presenter, expr))


def _forms(presenter: _Presenter, expr) -> tuple:
    expr = normalize(expr)
    return expr, presenter.present(expr)


def _proves(slack_forms, positive, strict_premise: bool, strict_conclusion: bool) -> bool:
    """slack >= 0 (with a strict premise, or a non-strict conclusion) or slack > 0 proves it."""
    for slack in slack_forms:
        value = _stand_in(slack, positive)
        if value.is_positive:
            return True
        if value.is_nonnegative and (strict_premise or not strict_conclusion):
            return True
    return False


def _implied(premises: list[_Condition], conclusion: _Condition, presenter, max_size=None) -> bool:
    """A sum of some premises (at most ``max_size`` of them) is below the conclusion by a known
    non-negative amount."""
    for size in range(1, min(len(premises), max_size or len(premises)) + 1):
        for chosen in itertools.combinations(premises, size):
            raw = conclusion.raw - sp.Add(*[p.raw for p in chosen])
            key = ("proves", raw, any(p.strict for p in chosen), conclusion.strict)
            if _cached(presenter, key, _proves_slack, raw, presenter, *key[2:]):
                return True
    return False


def _proves_slack(raw, presenter, strict_premise: bool, strict_conclusion: bool) -> bool:
    forms = (normalize(raw), presenter.present(raw))
    return _proves(forms, presenter.positive_expressions, strict_premise, strict_conclusion)


def _cached(presenter, key, compute, *args):
    """Sums of conditions recur across sign cases: decide each once per presenter."""
    cache = presenter.__dict__.setdefault("_cache", {})
    if key not in cache:
        cache[key] = compute(*args)
    return cache[key]


def _infeasible(conditions: list[_Condition], presenter, max_size=None) -> bool:
    """Some of the conditions (at most ``max_size``) add up to a quantity known to be <= 0 (< 0 when
    none is strict). A sufficient test: False does not prove the conditions compatible."""
    for size in range(1, min(len(conditions), max_size or len(conditions)) + 1):
        for chosen in itertools.combinations(conditions, size):
            total = sp.Add(*[c.raw for c in chosen])
            key = ("nonpositive", total, any(c.strict for c in chosen))
            if _cached(presenter, key, _known_nonpositive, total, key[2], presenter):
                return True
    return False


def _known_nonpositive(total, strict: bool, presenter) -> bool:
    """total < 0 is known (total <= 0 when some condition is strict)."""
    for form in (normalize(total), presenter.present(total), _half_angles(sp.expand(total))):
        value = _stand_in(form, presenter.positive_expressions)
        if value.is_negative or (strict and value.is_nonpositive):
            return True
    return False


def _drop_implied(conditions: list[_Condition], keep: list[_Condition], presenter, max_size=None) -> list[_Condition]:
    """Remove conditions implied by the others (``keep`` conditions stay and serve as premises)."""
    kept = list(conditions)
    for condition in conditions:
        others = [c for c in kept if c is not condition] + list(keep)
        if _implied(others, condition, presenter, max_size):
            kept.remove(condition)
    return kept


# --- closed forms and merges -------------------------------------------------------------


def _positive_part(rel: Relational) -> tuple[sp.Expr, bool] | None:
    """(P, strict) with rel equivalent to P > 0 or P >= 0; None for == and !=."""
    if not isinstance(rel, (sp.StrictGreaterThan, sp.GreaterThan, sp.StrictLessThan, sp.LessThan)):
        return None
    expr, op = _as_positive_relation(rel)
    return sp.expand(expr), op is sp.StrictGreaterThan


def _tidy(rel: sp.Basic, positive) -> sp.Basic:
    """``a - b < -c`` (c known positive) reads better as ``b - a > c``."""
    if not isinstance(rel, (sp.StrictLessThan, sp.LessThan, sp.StrictGreaterThan, sp.GreaterThan)):
        return rel
    if rel.lhs.is_Add and known_sign(rel.rhs, positive) == -1:
        flipped = {sp.StrictLessThan: sp.Gt, sp.LessThan: sp.Ge, sp.StrictGreaterThan: sp.Lt, sp.GreaterThan: sp.Le}
        return flipped[type(rel)](-rel.lhs, -rel.rhs)
    return rel


def _split(p1: sp.Expr, p2: sp.Expr, positive=()) -> tuple[sp.Expr, sp.Expr] | None:
    """(x, c) with p1 = c - x and p2 = c + x, when c is known positive and shares no symbol with x."""
    c, x = sp.expand((p1 + p2) / 2), sp.expand((p2 - p1) / 2)
    if x == 0 or known_sign(c, positive) != 1 or x.free_symbols & c.free_symbols:
        return None
    return x, c


def _merge_and(conjuncts: list[sp.Basic], positive=()) -> list[sp.Basic]:
    """``c - x > 0`` and ``c + x > 0`` become ``|x| < c``."""
    out = list(conjuncts)
    changed = True
    while changed:
        changed = False
        for a, b in itertools.combinations(out, 2):
            pa, pb = _positive_part(a), _positive_part(b)
            if pa is None or pb is None or pa[1] != pb[1]:
                continue
            split = _split(pa[0], pb[0], positive)
            if split is None:
                continue
            x, c = split
            out.remove(a)
            out.remove(b)
            out.append((sp.Lt if pa[1] else sp.Le)(sp.Abs(x), c))
            changed = True
            break
    return out


def _merge_pair(a: sp.Basic, b: sp.Basic, positive=()) -> sp.Basic | None:
    """One relational equivalent to ``a or b`` when a short one exists (True when they cover all)."""
    pa = _positive_part(a) if isinstance(a, Relational) else None
    pb = _positive_part(b) if isinstance(b, Relational) else None
    if pa and pb:
        if sp.expand(pa[0] + pb[0]) == 0 and pa[1] != pb[1]:
            return sp.true  # P > 0 or P <= 0
        if pa[1] == pb[1]:
            split = _split(-pa[0], -pb[0], positive)  # p_a = x - c, p_b = -x - c
            if split is not None:
                x, c = split
                return (sp.Gt if pa[1] else sp.Ge)(sp.Abs(x), c)
        return None
    for strict, equal in ((a, b), (b, a)):
        ps = _positive_part(strict) if isinstance(strict, Relational) else None
        if ps and ps[1] and isinstance(equal, sp.Equality):
            difference = sp.expand(equal.lhs - equal.rhs)
            if sp.expand(ps[0] - difference) == 0 or sp.expand(ps[0] + difference) == 0:
                weak = {sp.StrictLessThan: sp.Le, sp.StrictGreaterThan: sp.Ge}[type(strict)]
                return weak(strict.lhs, strict.rhs)
    return None


def _merge_or(disjuncts: list[frozenset], positive=()) -> list[frozenset]:
    """Merge disjuncts (sets of conjuncts) that differ in one conjunct; drop absorbed ones."""
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
            merged = _merge_pair(next(iter(only1)), next(iter(only2)), positive)
            if merged is None:
                continue
            common = d1 & d2
            new = common if merged == sp.true else common | {merged}
            out[out.index(d1)] = frozenset(new)
            out.remove(d2)
            changed = True
            break
    return out


def _closed_conjuncts(conditions, equalities, presenter) -> frozenset:
    """Closed forms of raw conditions (``_Condition``s and ``Eq``s), merged into |x| < c."""
    positive = presenter.positive_expressions
    parts = []
    for c in conditions:
        rel = sp.Gt(c.raw, 0) if c.strict else sp.Ge(c.raw, 0)
        parts.extend(sp.And.make_args(_cached(presenter, ("closed", rel), closed_form, rel, presenter)))
    for e in equalities:
        parts.extend(sp.And.make_args(closed_form(e, presenter)))
    parts = [_tidy(p, positive) for p in parts if p != sp.true]
    return frozenset(_merge_and(parts, positive))


def _boolean(disjuncts: list[frozenset]) -> sp.Basic:
    return sp.Or(*[sp.And(*d) for d in disjuncts])


# --- k = 1: corners and slopes ------------------------------------------------------------


def _ordered_partitions(items: list) -> list[list[tuple]]:
    """All weak orderings of the items: lists of blocks, left to right (ties first, as in §3)."""

    def build(items):
        if not items:
            return [[]]
        result = []
        for size in range(1, len(items) + 1):
            for block in itertools.combinations(items, size):
                rest = [i for i in items if i not in block]
                result.extend([block, *tail] for tail in build(rest))
        return result

    def rank(blocks):
        where = {i: n for n, block in enumerate(blocks) for i in block}
        return tuple(where[i] for i in items)

    return sorted(build(items), key=rank)


@dataclass(frozen=True)
class CountCase:
    """One ordering of the corners of f (k = 1) and the counts within it.

    Attributes
    ----------
    ordering : sympy Boolean
        The condition on the parameters for this ordering, closed form (True: one corner).
    corners : tuple
        The corners u = c_i, left to right (tied corners are listed once).
    patterns : tuple
        The sign patterns of the pieces, left to right.
    slopes : tuple
        f' on each piece, presented.
    regions : dict
        Count name -> closed-form condition within this ordering.

    Examples
    --------
    >>> import contactsym as cs
    >>> [str(case.ordering) for case in corner_cases(cs.scene("painleve-klein-rod"))]
    ['Eq(Y^*_1 + Y^*_2, 0)', 'Y^*_1 + Y^*_2 < 0', 'Y^*_1 + Y^*_2 > 0']
    """

    ordering: sp.Basic
    corners: tuple
    patterns: tuple
    slopes: tuple
    regions: dict = field(default_factory=dict)
    _disjuncts: dict = field(default_factory=dict, repr=False, compare=False)
    _ordering_conjuncts: frozenset = field(default=frozenset(), repr=False, compare=False)


def _corners(scene) -> list[sp.Expr]:
    fast = scene.fast_subsystem()
    (u,) = fast.u
    corners = []
    for sigma in fast.switching:
        poly = sp.Poly(normalize(sigma), u) if normalize(sigma).is_polynomial(u) else None
        if poly is None or poly.degree() != 1:
            raise ContactsymError(
                f"the switching function {sigma} is not affine in {u}: equilibrium counts need a piecewise-linear f."
            )
        a, b = poly.all_coeffs()
        if known_sign(a, scene.positive_expressions) != 1:
            raise ContactsymError(
                f"cannot show that the switching function {sigma} increases in {u} (coefficient {a}); "
                "declare the positive expressions of the scene (positive=...)."
            )
        corners.append(sp.cancel(-b / a))
    return corners


def _slope_classes(signs: tuple[int, ...]) -> str:
    """Name of the count for slopes of these signs, left to right."""
    if all(s > 0 for s in signs):
        return "unique stable"
    if all(s < 0 for s in signs):
        return "unique unstable"
    changes = sum(1 for a, b in zip(signs, signs[1:]) if a != b)
    if changes >= 4:
        return "undecided"  # e.g. +-+-+: five roots need the two minima below both maxima
    start = 0 if signs[0] != signs[-1] else 1
    return _count_name(tuple(range(start, changes + 2, 2)))


def corner_cases(scene) -> list[CountCase]:
    """The orderings of the corners of f (k = 1) with the counts in each.

    Parameters
    ----------
    scene : Scene
        A scene with one contact whose f is piecewise linear in u.

    Returns
    -------
    list of CountCase
        One per ordering of the corners that is not excluded by a known sign.

    Examples
    --------
    >>> import contactsym as cs
    >>> cases = corner_cases(cs.scene("painleve-klein-rod"))
    >>> cases[0].slopes
    (2 - mu_-, mu_- + 2)
    >>> cases[0].regions
    {'unique stable': Abs(mu_-) < 2, 'two or none': Abs(mu_-) > 2}
    >>> cases[2].regions["unique stable"], cases[2].regions["one or three"]
    (mu_+ < 2, (mu_+ > 2) & (Abs(mu_-) < 2))
    """
    if scene.k != 1:
        raise ContactsymError(f"corner_cases is for one contact; scene '{scene.name}' has k = {scene.k}.")
    if not _uses_corners(scene):
        raise ContactsymError(
            f"scene '{scene.name}' has a unilateral contact: its counts (lift-off included) come from "
            "count_regions (contactsym.orthants), not from corner cases."
        )
    return list(scene._stage("corner cases", lambda: tuple(_corner_cases(scene))))


def _corner_cases(scene) -> list[CountCase]:
    presenter = _Presenter(scene)
    positive = presenter.positive_expressions
    fast = scene.fast_subsystem()
    (u,) = fast.u
    corners = _corners(scene)
    cases = []
    for blocks in _ordered_partitions(list(range(len(corners)))):
        ordering = [
            _Condition(*_forms(presenter, corners[right[0]] - corners[left[0]]))
            for left, right in zip(blocks, blocks[1:])
        ]
        ties = [normalize(corners[a] - corners[b]) for block in blocks for a, b in zip(block, block[1:])]
        if any(known_sign(t, positive) is not None for t in ties) or _infeasible(ordering, presenter):
            continue  # corners of known order cannot tie or swap
        equalities = [sp.Eq(t, 0) for t in ties]
        cases.append(_corner_case(scene, presenter, u, corners, blocks, ordering, equalities))
    return cases


def _corner_case(scene, presenter, u, corners, blocks, ordering, equalities) -> CountCase:
    positive = presenter.positive_expressions
    signs = [-1] * len(corners)
    patterns = [tuple(signs)]
    for block in blocks:
        for i in block:
            signs[i] = 1
        patterns.append(tuple(signs))
    slopes = []
    for pattern in patterns:
        slope = normalize(scene.linearization(signs=pattern).A[0])
        if slope.has(u):
            raise ContactsymError(f"f' = {slope} depends on {u}: equilibrium counts need a piecewise-linear f.")
        slopes.append(_Condition(*_forms(presenter, slope)))
    known = [_sign(s, positive) for s in slopes]
    open_ = [i for i, s in enumerate(known) if s is None]
    disjuncts: dict[str, list[frozenset]] = {}
    for slope_signs in _sign_choices(known, open_):
        if 0 in slope_signs:
            continue
        conditions = [_Condition(*_forms(presenter, slope_signs[i] * slopes[i].raw)) for i in open_]  # sign * slope > 0
        if _infeasible(conditions + ordering, presenter):
            continue
        name = _slope_classes(tuple(slope_signs))
        kept = _drop_implied(conditions, ordering, presenter)
        disjuncts.setdefault(name, []).append(_closed_conjuncts(kept, [], presenter))
    merged = {name: _merge_or(ds, positive) for name, ds in disjuncts.items()}
    ordering_conjuncts = _closed_conjuncts(ordering, equalities, presenter)
    return CountCase(
        ordering=sp.And(*ordering_conjuncts),
        corners=tuple(presenter.present(corners[block[0]]) for block in blocks),
        patterns=tuple(patterns),
        slopes=tuple(s.presented for s in slopes),
        regions={name: _boolean(ds) for name, ds in merged.items()},
        _disjuncts=merged,
        _ordering_conjuncts=ordering_conjuncts,
    )


def _k1_regions(scene) -> dict[str, sp.Basic]:
    by_name: dict[str, list[frozenset]] = {}
    for case in corner_cases(scene):
        for name, disjuncts in case._disjuncts.items():
            by_name.setdefault(name, []).extend(case._ordering_conjuncts | d for d in disjuncts)
    return {name: _boolean(_merge_or(ds, tuple(scene.positive_expressions))) for name, ds in by_name.items()}


# --- orthant maps (k >= 2, unilateral contacts): see contactsym.orthants ---------------------

#: Sums of at most this many conditions are tried when pruning orthant determinants (display only:
#: a sign case kept by mistake is empty, never mislabelled).
_QUICK = 2


class _Tools:
    """The exact condition tools above, bound to a scene's count presentation."""

    def __init__(self, scene):
        self.presenter = _Presenter(scene)
        self.positive = self.presenter.positive_expressions

    def condition(self, expr) -> _Condition:
        return _cached(self.presenter, ("condition", expr), _condition, self.presenter, expr)

    def sign(self, condition: _Condition) -> int | None:
        return _sign(condition, self.positive)

    sign_choices = staticmethod(_sign_choices)
    boolean = staticmethod(_boolean)

    def infeasible(self, conditions, quick: bool = False) -> bool:
        return _infeasible(conditions, self.presenter, _QUICK if quick else None)

    def drop_implied(self, conditions, quick: bool = False):
        return _drop_implied(conditions, [], self.presenter, _QUICK if quick else None)

    def closed(self, conditions) -> frozenset:
        return _closed_conjuncts(conditions, [], self.presenter)

    def merge(self, disjuncts):
        return _merge_or(disjuncts, self.positive)


def _uses_corners(scene) -> bool:
    """k = 1 with bilateral contact: the corner cases (any number of corners)."""
    return scene.k == 1 and not scene.contacts[0].unilateral


def count_regions(scene) -> dict[str, Region]:
    """Named closed-form regions by the number of equilibria, for piecewise-linear f.

    Parameters
    ----------
    scene : Scene
        A built-in or user scene with k = 1 (corners and slopes) or k >= 2 (orthant
        determinants; for k >= 3 only "unique" is decided).

    Returns
    -------
    dict of str to Region
        Keys among :data:`COUNT_DESCRIPTIONS`; regions that are empty are left out.

    Examples
    --------
    >>> import contactsym as cs
    >>> for name, region in count_regions(cs.scene("painleve-klein-guides")).items():
    ...     print(f"{name}: {region.condition}")
    unique: Abs(v_1) + Abs(v_2) < 2*kappa**2
    one or three: (Abs(v_1) + Abs(v_2) > 2*kappa**2) & (Abs(Abs(v_1) - Abs(v_2)) < 2*kappa**2)
    two or none: Abs(Abs(v_1) - Abs(v_2)) > 2*kappa**2
    >>> count_regions(cs.scene("painleve-klein-rod"))["two or none"]
    Region(two or none: Abs(mu_-) > 2)
    >>> count_regions(cs.scene("brake"))
    {'unique': Region(unique: True)}
    """
    raw = _k1_regions(scene) if _uses_corners(scene) else orthant_regions(scene, _Tools(scene))
    regions = {}
    for name, condition in raw.items():
        if condition == sp.false:
            continue
        description = COUNT_DESCRIPTIONS.get(name, f"{name} solutions, by the load")
        regions[name] = Region(condition, name=name, description=f"{scene.name}: {description}")
    return regions


# --- the threshold (5.9) ---------------------------------------------------------------------


@dataclass(frozen=True)
class Threshold:
    """Where the unique region stops lying inside the region stable for every law.

    Attributes
    ----------
    parameter : Symbol
        The parameter that moves the regions (kappa for the guides).
    value : sympy expression
        Its critical value, exact.
    inside : sympy Boolean
        Where the unique region lies inside the stable region, in the parameter, or in
        the angle when the scene presents one (phi >= atan(sqrt(2)) for the guides).
    angle : sympy expression or None
        The critical angle, when the parameter is a cotangent of a scene angle.
    vertex : tuple
        The vertex of the unique region that meets the boundary there.
    """

    parameter: sp.Symbol
    value: sp.Expr
    inside: sp.Basic
    angle: sp.Expr | None = None
    vertex: tuple = ()


def _atoms(condition) -> list[Relational]:
    return [a for a in sp.sympify(condition).atoms(Relational)]


def _abs_lines(condition, plane) -> list[sp.Expr]:
    """The lines (expressions = 0) along which the atoms of a condition with |.| change."""
    lines = []
    for atom in _atoms(condition):
        expr = atom.lhs - atom.rhs
        absolutes = sorted(expr.atoms(sp.Abs), key=sp.default_sort_key)
        for choice in itertools.product((1, -1), repeat=len(absolutes)):
            # innermost first: replace an Abs whose argument has no Abs left
            line = expr
            for a, s in sorted(zip(absolutes, choice), key=lambda pair: sp.count_ops(pair[0])):
                line = line.xreplace({a: s * a.args[0]})
            line = sp.expand(line)
            if line.free_symbols & set(plane) and line not in lines and -line not in lines:
                lines.append(line)
    return lines


def _closure(condition):
    weak = {sp.StrictLessThan: sp.Le, sp.StrictGreaterThan: sp.Ge}
    return sp.sympify(condition).replace(lambda e: type(e) in weak, lambda e: weak[type(e)](e.lhs, e.rhs))


def _vertices(condition, plane) -> list[dict]:
    lines = _abs_lines(condition, plane)
    closed = _closure(condition)
    vertices = []
    for a, b in itertools.combinations(lines, 2):
        solution = sp.solve([a, b], list(plane), dict=True)
        if len(solution) != 1 or set(solution[0]) != set(plane):
            continue
        point = solution[0]
        if closed.xreplace(point) == sp.true and point not in vertices:
            vertices.append(point)
    return vertices


def _inside_on_grid(unique: Region, stable: Region, plane, parameter, value: float, vertices, size=161) -> bool:
    """Every grid point of the unique region lies in the stable region (decides a side only)."""
    corners = np.array([[float(v[x].subs(parameter, value)) for x in plane] for v in vertices])
    low, high = corners.min(axis=0), corners.max(axis=0)
    axes = [np.linspace(lo, hi, size) for lo, hi in zip(low, high)]
    grid = np.meshgrid(*axes, indexing="ij")
    arrays = {str(x): g for x, g in zip(plane, grid)}
    arrays[str(parameter)] = np.full(grid[0].shape, value)
    chosen = unique.evaluate(**{k: v for k, v in arrays.items() if k in unique._by_name})
    chosen = np.broadcast_to(chosen, grid[0].shape)
    good = stable.evaluate(**{k: v for k, v in arrays.items() if k in stable._by_name})
    return bool(np.all(np.broadcast_to(good, grid[0].shape)[chosen]))


def square_threshold(scene, unique: str = "unique", stable: str = "stable for every law") -> Threshold:
    """The parameter value at which the unique region leaves the region stable for every law.

    A vertex of the unique region (intersections of the lines of its |.| pieces) meets
    the boundary of the stable region (a factor of one of its inequalities vanishes):
    the candidates are solved exactly; a grid test on each side of every candidate picks
    the one where containment changes.

    Parameters
    ----------
    scene : Scene
        A scene whose count regions and stability regions live in one plane and one parameter.
    unique, stable : str
        Names of the two regions.

    Returns
    -------
    Threshold

    Examples
    --------
    >>> import contactsym as cs
    >>> th = square_threshold(cs.scene("painleve-klein-guides"))
    >>> th.value, th.angle, th.inside
    (sqrt(2)/2, atan(sqrt(2)), phi >= atan(sqrt(2)))
    """
    return scene._stage(("square threshold", unique, stable), lambda: _square_threshold(scene, unique, stable))


def threshold_angle(scene, unique: str = "unique", stable: str = "stable for every law") -> sp.Expr:
    """The angle at which the unique region leaves the region stable for every law (5.9).

    Examples
    --------
    >>> import contactsym as cs
    >>> threshold_angle(cs.scene("painleve-klein-guides"))
    atan(sqrt(2))
    """
    angle = square_threshold(scene, unique, stable).angle
    if angle is None:
        raise ContactsymError(f"scene '{scene.name}' presents no angle; use square_threshold(...).value.")
    return angle


def _square_threshold(scene, unique: str, stable: str) -> Threshold:
    inner = scene.equilibrium_counts()[unique]
    outer = scene.regions()[stable]
    plane = sorted({s for a in inner.condition.atoms(sp.Abs) for s in a.free_symbols}, key=str)
    rest = (inner.condition.free_symbols | outer.condition.free_symbols) - set(plane)
    if len(plane) != 2 or len(rest) != 1:
        raise ContactsymError(
            f"square_threshold needs a plane of two variables and one parameter; found plane {plane}, "
            f"parameters {sorted(map(str, rest))}."
        )
    (parameter,) = rest
    vertices = _vertices(inner.condition, plane)
    factors = []
    for atom in _atoms(outer.condition):
        for base, _ in sp.factor_list(sp.expand(atom.lhs - atom.rhs))[1]:
            if base.free_symbols & set(plane) and base not in factors:
                factors.append(base)
    candidates = {}
    for vertex in vertices:
        for factor in factors:
            meeting = sp.expand(factor.xreplace(vertex))
            if meeting == 0 or parameter not in meeting.free_symbols:
                continue
            for root in sp.solve(meeting, parameter):
                if root.is_real and (root.is_positive or not parameter.is_positive):
                    candidates.setdefault(root, tuple(vertex[x] for x in plane))
    if not candidates:
        raise ContactsymError(f"no vertex of '{unique}' meets the boundary of '{stable}'.")
    values = sorted(candidates, key=float)
    floats = [float(v) for v in values]
    samples = [floats[0] / 2, *[(a + b) / 2 for a, b in zip(floats, floats[1:])], floats[-1] * 2]
    inside = [_inside_on_grid(inner, outer, plane, parameter, s, vertices) for s in samples]
    flips = [i for i in range(len(values)) if inside[i] != inside[i + 1]]
    if len(flips) != 1:
        raise ContactsymError(f"containment changes at {len(flips)} candidates {values}; expected one.")
    (i,) = flips
    value = values[i]
    at_value = _inside_on_grid(inner, outer, plane, parameter, floats[i], vertices)
    below = inside[i]  # containment for parameters just below the value
    if below:
        condition = (sp.Le if at_value else sp.Lt)(parameter, value)
    else:
        condition = (sp.Ge if at_value else sp.Gt)(parameter, value)
    angle, in_angle = _as_angle(scene, parameter, value, condition, samples[i] if below else samples[i + 1])
    return Threshold(parameter, value, in_angle if in_angle is not None else condition, angle, candidates[value])


def _as_angle(scene, parameter, value, condition, inside_sample):
    """The angle theta with the parameter a function of it through sin(theta), cos(theta)."""
    presentation = {**scene.presentation, **getattr(scene, "count_presentation", {})}
    for key in presentation:
        if not isinstance(key, sp.sin):
            continue
        theta = key.args[0]
        tangent = sp.cancel(presentation[key] / presentation.get(sp.cos(theta), sp.nan))
        if tangent.has(sp.nan) or parameter not in tangent.free_symbols:
            continue
        angle = sp.atan(tangent.subs(parameter, value))
        sample = float(sp.atan(tangent.subs(parameter, inside_sample)))
        above = sample > float(angle)
        weak = isinstance(condition, (sp.LessThan, sp.GreaterThan))
        op = (sp.Ge if weak else sp.Gt) if above else (sp.Le if weak else sp.Lt)
        return angle, op(theta, angle)
    return None, None
