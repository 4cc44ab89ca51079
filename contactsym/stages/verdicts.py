"""Three-valued robustness verdicts: where each statement is proved, where it is disproved, and neither.

A statement about every admissible law ("stable for every law", "unstable for every law",
"law-dependent") follows SymPy's logic: true where it is proved, false where it is disproved,
unknown (None) otherwise; "not proved" is never answered False. A :class:`Verdict` holds the
two regions; :func:`classification_verdicts` derives them from the propositions:

- k <= 2: Propositions 3 and 6 classify every A with det A != 0 (each point is in exactly one
  region). With det A = 0, p_0 = 0 for every law, so no law is asymptotically stable:
  "stable for every law" and "law-dependent" are disproved there, "unstable for every law"
  is left undecided (the zero eigenvalue: the propositions need det A != 0).
- k >= 3: the closed-form regions of :func:`contactsym.robustness.classify.regions` are
  sufficient, each for what it names. A negative principal minor gives an unstable law
  (disproves "stable for every law"), a nested sequence of positive principal minors a
  stable law (disproves "unstable for every law"); each proved statement disproves the
  other two.

For a numeric A, :func:`with_point_decision` adds the point decision of
:func:`contactsym.robustness.classify.decide`: its certificate proves one statement and
disproves the others; a witness law alone disproves one.

Examples
--------
>>> import sympy as sp
>>> a = sp.Symbol("a", real=True)
>>> v = Verdict(sp.Gt(a, 1), sp.Lt(a, 0))
>>> v.at({a: 2}), v.at({a: -1}), v.at({a: sp.Rational(1, 2)})
(True, False, None)
>>> v.undecided
(a >= 0) & (a <= 1)
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..errors import ContactsymError

__all__ = ["NAMES", "Verdict", "classification_verdicts", "with_point_decision"]

#: The three statements, by the attribute of :class:`contactsym.stages.stability.Stability` that holds each.
NAMES = ("robustly_stable", "robustly_unstable", "law_dependent")

#: The statement that each verdict of :func:`contactsym.robustness.classify.decide` proves.
_DECIDED = {"stable": "robustly_stable", "unstable": "robustly_unstable", "law-dependent": "law_dependent"}


@dataclass(frozen=True)
class Verdict:
    """Where a statement is proved and where it is disproved (SymPy Booleans in the parameters).

    Attributes
    ----------
    proved, disproved : sympy Boolean
        Sufficient regions; a point in neither is undecided.
    """

    proved: sp.Basic
    disproved: sp.Basic

    @property
    def undecided(self) -> sp.Basic:
        """Where the statement is neither proved nor disproved."""
        return sp.And(sp.Not(self.proved), sp.Not(self.disproved))

    def at(self, values: dict | None = None):
        """``sympy.true`` where proved, ``sympy.false`` where disproved, None where undecided (or not evaluable)."""
        proved = sp.sympify(self.proved).xreplace(values or {})
        disproved = sp.sympify(self.disproved).xreplace(values or {})
        if proved == sp.true and disproved == sp.true:
            raise ContactsymError(
                f"a robustness statement is both proved and disproved at {values}: proved by {self.proved}, "
                f"disproved by {self.disproved}. Please report this scene."
            )
        if proved == sp.true:
            return sp.true
        if disproved == sp.true:
            return sp.false
        return None


def classification_verdicts(k: int, proved: dict, closed: dict | None = None) -> dict[str, Verdict]:
    """The three verdicts from the proved regions ``proved`` (by :data:`NAMES`) and, for k >= 3,
    the closed-form regions ``closed`` of :func:`contactsym.robustness.classify.regions`.

    Examples
    --------
    >>> a = sp.Symbol("a", real=True)
    >>> v = classification_verdicts(1, {"robustly_stable": a > 0, "robustly_unstable": a < 0, "law_dependent": sp.false})
    >>> v["robustly_unstable"].at({a: 0}), v["robustly_stable"].at({a: 0}), v["law_dependent"].at({a: 3})
    (None, False, False)
    """
    stable, unstable, dependent = (proved[name] for name in NAMES)
    if k <= 2:
        disproved = (sp.Not(stable), sp.Or(stable, dependent), sp.Not(dependent))
    else:
        disproved = (
            sp.Or(closed["unstable law exists"], unstable),
            sp.Or(closed["stable law exists"], stable),
            sp.Or(stable, unstable),
        )
    return {name: Verdict(proved[name], no) for name, no in zip(NAMES, disproved)}


def with_point_decision(verdicts: dict[str, Verdict], robustness) -> dict[str, Verdict]:
    """The verdicts at a numeric A with the point decision ``robustness`` (a
    :class:`contactsym.robustness.classify.Robustness`, or None) added as evidence."""
    if robustness is None:
        return verdicts
    decided = _DECIDED.get(robustness.verdict)
    out = {}
    for name, verdict in verdicts.items():
        proved, disproved = verdict.proved, verdict.disproved
        if name == decided:
            proved = sp.true
        elif decided is not None:
            disproved = sp.true  # the three statements exclude each other
        if (name, robustness.stable_law is not None) == ("robustly_unstable", True):
            disproved = sp.true  # an exactly stable law
        if (name, robustness.unstable_law is not None) == ("robustly_stable", True):
            disproved = sp.true  # an exactly unstable law
        out[name] = Verdict(proved, disproved)
    return out
