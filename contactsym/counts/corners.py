"""Equilibrium counts for one bilateral contact (k = 1, §3): the orderings of the corners of f.

The corners c_i are the roots of the switching functions sigma_i (each oriented
increasing in u). For each ordering of the corners (a condition on the parameters, e.g.
Y*_1 + Y*_2 < 0, = 0, > 0) the pieces, from left to right, start with every sign -1 and
flip the signs of the switching functions that vanish at each corner. The signs of the
slopes f' on the pieces name the count (:func:`slope_count_name`; the rules are in
:mod:`contactsym.counts.regions`). Slopes of known sign are not enumerated, orderings and sign
combinations that a short exact argument excludes are dropped, and the regions are
written with the inequality engine (:mod:`contactsym.inequalities`).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass, field

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..arguments import checked
from ..errors import ContactsymError
from ..inequalities import Condition, Facts, boolean, closed_conjuncts, merge_or
from .conditions import count_facts, sign_choices

__all__ = ["CountCase", "corner_cases", "corner_regions", "slope_count_name", "uses_corners"]

_WORDS = ["none", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine"]


def _count_name(counts: tuple[int, ...]) -> str:
    """'two or none', 'one or three', 'none, two or four', ..."""
    if counts == (0, 2):
        return "two or none"
    words = [_WORDS[c] if c < len(_WORDS) else str(c) for c in counts]
    return ", ".join(words[:-1]) + " or " + words[-1]


@checked(scene="Scene")
def uses_corners(scene) -> bool:
    """k = 1 with bilateral contact: the corner cases (any number of corners).

    Examples
    --------
    >>> import contactsym as cs
    >>> uses_corners(cs.scene("painleve-klein-rod")), uses_corners(cs.scene("painleve-rod"))
    (True, False)
    """
    return scene.k == 1 and not scene.contacts[0].unilateral


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


@checked
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


@checked
def slope_count_name(signs: tuple[int, ...]) -> str:
    """Name of the count for slopes of these signs, left to right.

    Examples
    --------
    >>> slope_count_name((1, 1)), slope_count_name((1, -1)), slope_count_name((1, -1, 1))
    ('unique stable', 'two or none', 'one or three')
    """
    if all(s > 0 for s in signs):
        return "unique stable"
    if all(s < 0 for s in signs):
        return "unique unstable"
    changes = sum(1 for a, b in zip(signs, signs[1:]) if a != b)
    if changes >= 4:
        return "undecided"  # e.g. +-+-+: five roots need the two minima below both maxima
    start = 0 if signs[0] != signs[-1] else 1
    return _count_name(tuple(range(start, changes + 2, 2)))


@checked(scene="Scene")
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
    if not uses_corners(scene):
        raise ContactsymError(
            f"scene '{scene.name}' has a unilateral contact: its counts (lift-off included) come from "
            "count_regions (contactsym.counts.orthants), not from corner cases."
        )
    return list(scene.cached("corner cases", lambda: tuple(_corner_cases(scene))))


def _corner_cases(scene) -> list[CountCase]:
    facts = count_facts(scene)
    fast = scene.fast_subsystem()
    (u,) = fast.u
    corners = _corners(scene)
    cases = []
    for blocks in _ordered_partitions(list(range(len(corners)))):
        ordering = [facts.condition(corners[right[0]] - corners[left[0]]) for left, right in zip(blocks, blocks[1:])]
        ties = [normalize(corners[a] - corners[b]) for block in blocks for a, b in zip(block, block[1:])]
        if any(known_sign(t, facts.positive) is not None for t in ties) or facts.infeasible(ordering):
            continue  # corners of known order cannot tie or swap
        equalities = [sp.Eq(t, 0) for t in ties]
        cases.append(_corner_case(scene, facts, u, corners, blocks, ordering, equalities))
    return cases


def _corner_case(scene, facts: Facts, u, corners, blocks, ordering: list[Condition], equalities) -> CountCase:
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
        slopes.append(facts.condition(slope))
    known = [facts.sign(s) for s in slopes]
    open_ = [i for i, s in enumerate(known) if s is None]
    disjuncts: dict[str, list[frozenset]] = {}
    for slope_signs in sign_choices(known, open_):
        if 0 in slope_signs:
            continue
        conditions = [facts.condition(slope_signs[i] * slopes[i].raw) for i in open_]  # sign * slope > 0
        if facts.infeasible(conditions + ordering):
            continue
        name = slope_count_name(tuple(slope_signs))
        kept = facts.drop_implied(conditions, ordering)
        disjuncts.setdefault(name, []).append(closed_conjuncts(kept, [], facts))
    merged = {name: merge_or(ds, facts.positive) for name, ds in disjuncts.items()}
    ordering_conjuncts = closed_conjuncts(ordering, equalities, facts)
    return CountCase(
        ordering=sp.And(*ordering_conjuncts),
        corners=tuple(facts.present(corners[block[0]]) for block in blocks),
        patterns=tuple(patterns),
        slopes=tuple(s.presented for s in slopes),
        regions={name: boolean(ds) for name, ds in merged.items()},
        _disjuncts=merged,
        _ordering_conjuncts=ordering_conjuncts,
    )


@checked(scene="Scene")
def corner_regions(scene) -> dict[str, sp.Basic]:
    """The count regions of a k = 1 scene: each count's disjuncts over every ordering of the corners, merged.

    Examples
    --------
    >>> import contactsym as cs
    >>> regions = corner_regions(cs.scene("painleve-klein-rod"))
    >>> sorted(regions)
    ['one or three', 'two or none', 'unique stable']
    >>> regions["two or none"]
    Abs(mu_-) > 2
    """
    by_name: dict[str, list[frozenset]] = {}
    for case in corner_cases(scene):
        for name, disjuncts in case._disjuncts.items():
            by_name.setdefault(name, []).extend(case._ordering_conjuncts | d for d in disjuncts)
    return {name: boolean(merge_or(ds, tuple(scene.positive_expressions))) for name, ds in by_name.items()}
