"""Closed-form robustness regions for a symbolic A, from its principal minors, and the nested
sequences of positive minors (proofs P2, P3 and P6 of :mod:`contactsym.robustness.classify`).

Examples
--------
>>> import sympy as sp
>>> a = sp.Symbol("a", real=True)
>>> regions(sp.Matrix([[a, 0], [0, 1]]))["stable law exists"]
a > 0
"""

from __future__ import annotations

import itertools

import sympy as sp

from ..algebra.basic import normalize
from ..arguments import checked, require
from .witnesses import generic_vertex_coefficients

__all__ = ["nested_sequences", "regions"]


# --- nested sequences (P6) ----------------------------------------------------------------


@checked
def nested_sequences(minors: dict) -> list[tuple[int, ...]]:
    """Orderings i1..ik along which every leading principal minor is positive.

    Examples
    --------
    ``minors`` maps index tuples (from 0) to det A_S, as :attr:`LawPolynomials.minors` gives them:

    >>> nested_sequences({(0,): 1, (1,): -1, (0, 1): 2})  # a_11 > 0, det A > 0; a_22 < 0
    [(0, 1)]
    >>> nested_sequences({(0,): -1, (1,): -1, (0, 1): 2})
    []
    """
    k = max((len(S) for S in minors if isinstance(S, tuple)), default=0)
    every = all(S in minors for r in range(1, k + 1) for S in itertools.combinations(range(k), r))
    require(k > 0 and every, "nested_sequences", "minors", minors, "the principal minors {(0,): det A_0, ...}")
    found = []
    for order in itertools.permutations(range(k)):
        if all(minors[tuple(sorted(order[: r + 1]))] > 0 for r in range(k)):
            found.append(order)
    return found


# --- closed-form regions for a symbolic A -------------------------------------------------


def _principal_minors(A: sp.Matrix) -> dict:
    k = A.rows
    subsets = [S for r in range(1, k + 1) for S in itertools.combinations(range(k), r)]
    return {S: normalize(A.extract(list(S), list(S)).det(method="berkowitz")) for S in subsets}


@checked
def regions(A: sp.Matrix, vertices: bool = False, minors: dict | None = None) -> dict[str, sp.Basic]:
    """Closed-form regions, any k, in the entries of A (all sufficient for what they name).

    ``minors`` gives A's principal minors {S: det A_S} in the canonical form when they are known (a
    scene's :attr:`~contactsym.stages.linear.Linearization.principal_minors`, one polynomial over
    det M each), so that they are not expanded again from A's entries.

    - ``"unstable for every law"``: some p_s has all coefficients <= 0 (P2): for the weight
      w = 2k - s, every principal minor of a size in [w/2, min(w, k)] is <= 0;
    - ``"stable law exists"``: a nested sequence of positive principal minors (P6);
    - ``"unstable law exists"``: some principal minor is negative (P3); with ``vertices``
      (k <= 3), or some vertex coefficient of a Hurwitz minor is negative (P3);
    - ``"law-dependent"``: both of the last two;
    - ``"stable for every law needs"``: the negation of ``"unstable law exists"``, a necessary
      condition. For k = 2 with ``vertices`` it is Proposition 6's stable region exactly.

    Examples
    --------
    >>> a, b = sp.symbols("a b", real=True)
    >>> regions(sp.Matrix([[a, 1], [-1, b]]))["unstable law exists"]
    (a < 0) | (b < 0) | (a*b + 1 < 0)
    """
    k = A.rows
    if minors is None:
        minors = _principal_minors(A)
    else:
        subsets = {S for r in range(1, k + 1) for S in itertools.combinations(range(k), r)}
        require(subsets <= set(minors), "regions", "minors", minors, "every principal minor {(0,): det A_0, ...}")
        minors = {S: minors[S] for S in sorted(subsets, key=lambda S: (len(S), S))}  # the order _principal_minors has
    unstable = []
    for weight in range(1, 2 * k + 1):
        sizes = range((weight + 1) // 2, min(weight, k) + 1)
        unstable.append(sp.And(*[sp.Le(m, 0) for S, m in minors.items() if len(S) in sizes]))
    nested = []
    for order in itertools.permutations(range(k)):
        nested.append(sp.And(*[sp.Gt(minors[tuple(sorted(order[: r + 1]))], 0) for r in range(k)]))
    stable_law = sp.Or(*nested)
    unstable_law = sp.Or(*[sp.Lt(m, 0) for m in minors.values()])
    if vertices and k <= 3:
        symbols = {sp.Symbol("m_" + "_".join(str(j + 1) for j in S)): m for S, m in minors.items()}
        coefficients = {c.xreplace(symbols) for _, c in generic_vertex_coefficients(k)}
        unstable_law = sp.Or(unstable_law, *[sp.Lt(c, 0) for c in coefficients])
    return {
        "unstable for every law": sp.Or(*unstable),
        "stable law exists": stable_law,
        "unstable law exists": unstable_law,
        "law-dependent": sp.And(stable_law, unstable_law),
        "stable for every law needs": sp.Not(unstable_law),
    }
