"""The one-sided Painlevé classification: consistent, inconsistent, indeterminate.

For one unilateral contact the normal acceleration of the rigid system is affine in
the reaction, f(N) = a + b N on N > 0 (a = f(0), the acceleration with the contact
free; b = f', the slope). The equilibria of the fast subsystem with lift-off
(:mod:`contactsym.stages.equilibria`) are

- sliding: N* = -a/b, when N* > 0; stable iff the Hurwitz conditions of (4.5) hold,
  and they are a positive multiple of b (Proposition 3);
- lift-off: N = 0, when the gap accelerates open, a > 0; stable (nothing is left closed).

Each sign case of (a, b) counts them: none is *inconsistent* (b < 0, a < 0: no motion,
an impact without collision), one is *consistent* (b > 0: sliding if a < 0, lift-off if
a > 0), two is *indeterminate* (b < 0, a > 0: lift-off, and a sliding equilibrium that
is unstable). The signs of every condition are decided from the derived expressions,
not from this table; the tests compare both.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..errors import ContactsymError
from ..stages.regions import Region, closed_form, known_sign
from .orthants import scene_map

__all__ = ["OneSidedCase", "one_sided_cases"]

_NAMES = {0: "inconsistent", 1: "consistent", 2: "indeterminate"}


@dataclass(frozen=True)
class OneSidedCase:
    """One sign case of (a, b): its name, region and equilibria.

    Attributes
    ----------
    name : str
        'consistent', 'inconsistent' or 'indeterminate'.
    region : Region
        Where the case holds, in the scene's symbols.
    equilibria : tuple of (str, bool)
        ('sliding' or 'lift-off', stable) for each equilibrium that exists.

    Examples
    --------
    >>> import contactsym as cs
    >>> case = one_sided_cases(cs.scene("painleve-rod"))[-1]
    >>> isinstance(case, OneSidedCase), case.name, case.equilibria
    (True, 'indeterminate', (('sliding', False), ('lift-off', True)))
    """

    name: str
    region: Region
    equilibria: tuple


def _sign_of(expr, signs: dict, positive) -> int:
    """The sign of ``expr`` from the signs of a and b: expr is a known-sign multiple of a, b, a b or a/b."""
    (a, a_sign), (b, b_sign) = signs.items()
    for ratio, sign in ((b, b_sign), (a, a_sign), (a * b, a_sign * b_sign), (a / b, a_sign * b_sign)):
        known = known_sign(sp.cancel(expr / ratio), positive)
        if known is not None:
            return known * sign
    raise ContactsymError(f"the sign of {expr} does not follow from those of a = {a} and b = {b}.")


def _holds(condition, signs: dict, positive) -> bool:
    """A conjunction of ``e > 0``, decided from the signs of a and b."""
    return all(_sign_of(rel.lhs - rel.rhs, signs, positive) > 0 for rel in sp.And.make_args(condition))


def one_sided_cases(scene) -> list[OneSidedCase]:
    """The cases of the one-sided Painlevé problem, derived from the equilibria with lift-off.

    Parameters
    ----------
    scene : Scene
        One unilateral contact (k = 1) with f piecewise linear.

    Examples
    --------
    >>> import contactsym as cs
    >>> for case in one_sided_cases(cs.scene("painleve-rod")):
    ...     print(case.name, case.equilibria)
    consistent (('sliding', True),)
    consistent (('lift-off', True),)
    inconsistent ()
    indeterminate (('sliding', False), ('lift-off', True))
    """
    if scene.k != 1 or not scene.contacts[0].unilateral:
        raise ContactsymError(f"one_sided_cases needs one unilateral contact; scene '{scene.name}' is not one.")
    G = scene_map(scene)
    slope, a = G.plus[0], G.load[0]
    positive = tuple(scene.positive_expressions)
    equilibria = scene.equilibria()
    (sliding,) = equilibria.branches
    (lift,) = equilibria.lift_offs
    hurwitz = scene.stability(sliding.signs).hurwitz
    cases = []
    for slope_sign in (1, -1):
        for a_sign in (-1, 1):
            signs = {a: a_sign, slope: slope_sign}
            found = []
            if _holds(sliding.condition, signs, positive):
                found.append(("sliding", all(_sign_of(h, signs, positive) > 0 for h in hurwitz)))
            if _holds(lift.condition, signs, positive):
                found.append(("lift-off", lift.stable == sp.true))
            condition = sp.And(closed_form(slope_sign * slope > 0, scene), closed_form(a_sign * a > 0, scene))
            if condition == sp.false:
                continue
            name = _NAMES[len(found)]
            cases.append(OneSidedCase(name, Region(condition, name=name), tuple(found)))
    return cases
