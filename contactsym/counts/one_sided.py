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

A sign that does not follow from those of a and b (nor from the mechanics: det M > 0, bounds
on sin and cos, see :func:`contactsym.algebra.reductions.known_sign`) splits its case in two,
as the paper does: one with the expression positive, one with it negative, each with its own
region and equilibria, and the case records which sign it assumed.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..algebra.reductions import known_sign, quotient_sign
from ..arguments import checked
from ..errors import ContactsymError
from ..stages.regions import Region, closed_form
from .orthants import scene_map

__all__ = ["OneSidedCase", "one_sided_cases"]

_NAMES = {0: "inconsistent", 1: "consistent", 2: "indeterminate"}

#: Splits on undecided Hurwitz signs per case beyond which a stability is left undecided (None).
STABILITY_SPLITS = 3


@checked
@dataclass(frozen=True)
class OneSidedCase:
    """One sign case of (a, b): its name, region and equilibria.

    Attributes
    ----------
    name : str
        'consistent', 'inconsistent' or 'indeterminate'.
    region : Region
        Where the case holds, in the scene's symbols.
    equilibria : tuple of (str, bool or None)
        ('sliding' or 'lift-off', stable) for each equilibrium that exists; stable is None
        when its sign could not be decided even after splitting.
    assumed : tuple of (Expr, int)
        Expressions whose sign does not follow from those of a and b, with the sign this
        case assumes (the case split); empty when the signs of a and b decide everything.

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
    assumed: tuple = ()


class _Undecided(Exception):
    """The sign of ``expr`` does not follow from the signs known so far."""

    def __init__(self, expr):
        super().__init__()
        self.expr = expr


def _sign_of(expr, known: tuple, positive) -> int | None:
    """The sign of ``expr`` as a known-sign multiple of 1, of a known expression, of a b or of a/b."""
    (a, a_sign), (b, b_sign) = known[:2]
    candidates = ((1, 1),) + known + ((a * b, a_sign * b_sign), (a / b, a_sign * b_sign))
    for ratio, sign in candidates:
        if expr == ratio:
            return sign
        found = quotient_sign(expr, ratio, positive)
        if found is None:  # not a polynomial multiple: what cancelling the fraction shows
            found = known_sign(sp.cancel(expr / ratio), positive)
        if found is not None:
            return found * sign
    return None


def _holds(condition, known: tuple, positive) -> bool:
    """A conjunction of strict inequalities, decided from the known signs; _Undecided names the first gap."""
    if condition in (sp.true, sp.false):
        return bool(condition)
    for rel in sp.And.make_args(condition):
        if not isinstance(rel, (sp.StrictGreaterThan, sp.StrictLessThan)):
            raise ContactsymError(f"one_sided_cases expects strict inequalities, not {type(rel).__name__}.")
        difference = rel.gts - rel.lts
        sign = _sign_of(difference, known, positive)
        if sign is None:
            raise _Undecided(difference)
        if sign < 0:
            return False
    return True


def _split(evaluate, known: tuple, splits: int = 0) -> list:
    """[(known signs, result)] of ``evaluate(known, splits)``, split on every sign it cannot decide."""
    try:
        return [(known, evaluate(known, splits))]
    except _Undecided as gap:
        if any(gap.expr == expr for expr, _ in known):  # cannot happen (a known sign decides itself): no loop
            raise ContactsymError("one_sided_cases: a case split did not decide its own sign.") from None
        return [case for sign in (1, -1) for case in _split(evaluate, known + ((gap.expr, sign),), splits + 1)]


@checked(scene="Scene")
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
    ...     print(case.name, case.equilibria, case.assumed)
    consistent (('sliding', True),) ()
    consistent (('lift-off', True),) ()
    inconsistent () ()
    indeterminate (('sliding', False), ('lift-off', True)) ()
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
    pushing = sp.And(sliding.condition, sp.Gt(sliding.u_star[0], 0))  # the contact pushes: N* > 0

    def stable(known, splits) -> bool | None:
        try:
            return all(_holds(h > 0, known, positive) for h in hurwitz)
        except _Undecided:
            if splits >= STABILITY_SPLITS:
                return None
            raise

    def evaluate(known, splits) -> tuple:
        found = []
        if _holds(pushing, known, positive):
            found.append(("sliding", stable(known, splits)))
        if _holds(lift.condition, known, positive):
            found.append(("lift-off", lift.stable == sp.true or _holds(lift.stable, known, positive)))
        return tuple(found)

    cases = []
    for slope_sign in (1, -1):
        for a_sign in (-1, 1):
            for known, found in _split(evaluate, ((a, a_sign), (slope, slope_sign))):
                assumed = known[2:]
                condition = sp.And(*(closed_form(sign * expr > 0, scene) for expr, sign in known))
                if condition == sp.false:
                    continue
                name = _NAMES[len(found)]
                cases.append(OneSidedCase(name, Region(condition, name=name), found, assumed))
    return cases
