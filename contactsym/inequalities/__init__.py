"""The inequality engine shared by closed-form regions and equilibrium counts.

A condition on the parameters is a Boolean of relations ``P op 0``. The engine

- reduces one relation exactly (:mod:`~contactsym.inequalities.relations`): factors of known
  sign dropped, the sides arranged as a reader writes them, a named parameter solved for;
- factors a numerator as ``sympy.factor_list`` does, by a cheaper proof where one applies
  (:mod:`~contactsym.inequalities.factors`);
- proves short facts about conditions ``P > 0`` / ``P >= 0``
  (:mod:`~contactsym.inequalities.facts`): a known sign, an implication or an infeasible
  combination, by a sum of conditions whose sign follows from the assumptions (tried first
  at a few exact points, where a wrong sign shows no proof exists);
- shortens Booleans (:mod:`~contactsym.inequalities.merges`): ``|x| < c``, ``|x| > c`` and
  disjunctions that differ in one conjunct;
- puts these together (:mod:`~contactsym.inequalities.closed`): the closed form of a Boolean.

It knows nothing of scenes: a caller gives the expressions known to be positive and, where it
wants conditions tried in other variables too, a presentation function.

Examples
--------
>>> import sympy as sp
>>> x, y = sp.symbols("x y", real=True)
>>> m = sp.Symbol("m", positive=True)
>>> closed_form(sp.And(m * (x + y) < 2 * m, x > 0))
(x > 0) & (x + y < 2)
"""

from .closed import FACTOR_TERMS, RAW_OPS, closed_conjuncts, closed_form
from .factors import factor_list, split_by_degree_one
from .facts import POINTS, Facts, half_angles, pythagorean, refuted
from .merges import boolean, merge_abs, merge_and, merge_or, merge_pair, split
from .relations import (
    FLIP,
    Condition,
    arrange,
    as_positive_relation,
    drop_known_factors,
    positive_part,
    solve_for,
    tidy,
    univariate,
)

__all__ = [
    "FACTOR_TERMS",
    "FLIP",
    "POINTS",
    "RAW_OPS",
    "Condition",
    "Facts",
    "arrange",
    "as_positive_relation",
    "boolean",
    "closed_conjuncts",
    "closed_form",
    "drop_known_factors",
    "factor_list",
    "half_angles",
    "merge_abs",
    "merge_and",
    "merge_or",
    "merge_pair",
    "positive_part",
    "pythagorean",
    "refuted",
    "solve_for",
    "split",
    "split_by_degree_one",
    "tidy",
    "univariate",
]
