"""Where each robustness statement is proved: Propositions 3-8 as regions in the parameters.

- k = 1: Proposition 3 (a > 0 stable, a < 0 unstable, for every law);
- k = 2: Proposition 6 with its boundary: stable for every law where a_11, a_22, det A > 0 and
  a_12 a_21 >= 0; unstable for every law where det A < 0 or a_11, a_22 <= 0; law-dependent
  on the rest of det A > 0;
- k >= 3: Propositions 7 (A symmetric with positive leading principal minors) and 8 (det A < 0
  or all a_ss < 0), widened by the closed forms of :func:`contactsym.robustness.classify.regions`.

The sign of a product. Proposition 6 asks the sign of a_12 a_21. For a mechanism each entry is
a fraction of large polynomials in the angles' sines and cosines, and their product brought to
the canonical form (one fraction, cancelled by a gcd) costs minutes (the four-link, two-contact
arm of ``examples/four-link-arm.toml``: 440 s), though its sign is read off the factors:

    for real x_1, ..., x_r with x_i = P_i / Q_i and Q_i != 0,
    sign(x_1 ... x_r) = sign(P_1) sign(Q_1) ... sign(P_r) sign(Q_r) = sign(P_1 Q_1 ... P_r Q_r),

because the sign of a product of nonzero reals is the product of their signs (and both sides
are 0 exactly when some P_i is). Where sign(Q_i) = sigma_i is proved (:func:`known_sign`: a
monomial in positive parameters, det M of a Lagrangian scene), Q_i is replaced by sigma_i. So
:func:`sign_equivalent` returns a product of factors, never expanded, with the sign of
x_1 ... x_r wherever every x_i is defined; ``x_1 ... x_r >= 0`` is the relation on it. A small
product (its expansion bounded by :data:`contactsym.algebra.hurwitz.EXPAND_TERMS` terms) is
still brought to the canonical form, as before: the built-in scenes print what they printed.
"""

from __future__ import annotations

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..algebra.hurwitz import EXPAND_TERMS, expansion_bound
from ..arguments import checked
from .minors import entry_numerators, equality_matrix, polynomial_factors, positive_multiple

__all__ = ["classification_matrix", "proved_regions", "sign_equivalent"]


@checked(factors="Sequence[sp.Expr]", positive="Sequence[sp.Expr]")
def sign_equivalent(factors, positive=()) -> sp.Expr:
    """An expression with the sign of the product of ``factors`` wherever each factor is defined:
    the canonical form of the product when it is small, else a product of their numerators (and of
    the denominators whose sign is not proved), never expanded. See the module docstring.

    ``positive`` lists expressions known to be positive (as :func:`contactsym.algebra.basic.known_sign` takes them).

    Examples
    --------
    >>> a, b = sp.symbols("a b", real=True)
    >>> m = sp.Symbol("m", positive=True)
    >>> sign_equivalent([a / m, (a + b) / m])  # small: the product in the canonical form
    a**2/m**2 + a*b/m**2
    >>> P = sp.Add(*sp.symbols("x0:30", real=True))  # 30 terms: the product may have 465
    >>> sign_equivalent([P / (m * (1 + b**2)), (P - 1) / (a - 1)]) == P * (P - 1) * (a - 1)  # sign(1/(a-1)) = sign(a-1)
    True
    """
    product = sp.Mul(*factors)
    if expansion_bound(product) <= EXPAND_TERMS:
        return normalize(product)
    sign, kept = 1, []
    for factor in factors:
        numerator, denominator = sp.fraction(factor)
        known = known_sign(denominator, positive) if denominator.free_symbols else (1 if denominator > 0 else -1)
        if known is None:
            kept += [numerator, denominator]  # sign(P / Q) = sign(P Q) where Q != 0
        else:
            sign *= known
            kept.append(numerator)
    if sign < 0:  # -P distributes over one factor's terms, not over the product
        kept[0] = -kept[0]
    return sp.Mul(*kept)


def _relation(op, expr: sp.Expr) -> sp.Basic:
    """``op(expr, 0)``; unevaluated when ``expr`` is large: asking the sign of a long product of
    sums (SymPy's assumptions on each term) decides nothing a parameter value would not."""
    if expansion_bound(expr) > EXPAND_TERMS:
        return op(expr, 0, evaluate=False)
    return op(expr, 0)


@checked(A="sp.Matrix", det="sp.Expr", positive="Sequence[sp.Expr]")
def proved_regions(A, det, closed=None, positive=(), leading=None) -> tuple[sp.Basic, sp.Basic, sp.Basic]:
    """(stable for every law, unstable for every law, law-dependent): where each is proved.

    ``det`` is det A in the canonical form; ``closed`` the closed-form regions of
    :func:`contactsym.robustness.classify.regions` (k >= 3 only); ``positive`` the expressions known
    to be positive; ``leading`` (k >= 3) the leading principal minors det A[:m, :m], m = 1..k, when
    the caller has them (else they are computed here).

    Examples
    --------
    >>> a, b, c = sp.symbols("a b c", real=True)
    >>> A = sp.Matrix([[a, b], [c, 1]])
    >>> proved_regions(A, a - b * c)[0]
    (a > 0) & (b*c >= 0) & (a - b*c > 0)
    >>> proved_regions(sp.Matrix([[a]]), a)
    (a > 0, a < 0, False)
    """
    k = A.rows
    diagonal = [A[i, i] for i in range(k)]
    if k == 1:
        return sp.Gt(A[0], 0), sp.Lt(A[0], 0), sp.false
    if k == 2:
        # Prop. 6, with its boundary: a11, a22 <= 0 (not both 0 when det A > 0) makes p_3 <= 0
        unstable = sp.Or(_relation(sp.Lt, det), sp.And(*[_relation(sp.Le, a) for a in diagonal]))
        coupling = sign_equivalent([A[0, 1], A[1, 0]], positive)
        stable = sp.And(*[_relation(sp.Gt, a) for a in diagonal], _relation(sp.Gt, det), _relation(sp.Ge, coupling))
        not_unstable = sp.Or(*[_relation(sp.Gt, a) for a in diagonal])
        not_stable = sp.Or(*[_relation(sp.Le, a) for a in diagonal], _relation(sp.Lt, coupling))
        return stable, unstable, sp.And(_relation(sp.Gt, det), not_unstable, not_stable)
    unstable = sp.Or(sp.Lt(det, 0), sp.And(*[sp.Lt(a, 0) for a in diagonal]), closed["unstable for every law"])
    symmetric = [sp.Eq(A[i, j], A[j, i]) for i in range(k) for j in range(i) if sp.expand(A[i, j] - A[j, i])]
    if leading is None:
        leading = [normalize(A[:m, :m].det(method="berkowitz")) for m in range(1, k + 1)]
    return sp.And(*symmetric, *[sp.Gt(minor, 0) for minor in leading]), unstable, closed["law-dependent"]


def classification_matrix(linearization) -> tuple[sp.Matrix, bool]:
    """(a matrix that gives what :func:`proved_regions` reads of A, whether A has free symbols) for a
    :class:`~contactsym.stages.linear.Linearization`, with no division where A's entries would each
    need a gcd over det M:

    - k = 2 with polynomial factors whose entries' product may pass :data:`EXPAND_TERMS` terms: the
      positive multiple |det M| A (:func:`~contactsym.stages.minors.positive_multiple`). The regions of
      Proposition 6 are those of any positive multiple c A: the signs of a_ii, of det(c A) = c^2 det A
      (det A itself is given) and of c^2 a_12 a_21 are A's. Where the sign of det M is not proved, the
      matrix of the next case: a_12 a_21 = N_12 N_21 / (det M)^2 has the sign of N_12 N_21.
    - k >= 3 with polynomial factors and a det M that is not a number: a_ii (the principal minors of
      size 1) on the diagonal and N_ij = a_ij det M off it (:func:`~contactsym.stages.minors.equality_matrix`):
      Propositions 7 and 8 read the signs of a_ii and the equalities a_ij = a_ji only.
    - otherwise A.

    Examples
    --------
    >>> import contactsym as cs
    >>> lin = cs.scene("brake").linearization()
    >>> classification_matrix(lin) == (lin.A, True)
    True
    """
    factors = linearization.factors
    k = linearization.fast.k
    if k >= 2 and polynomial_factors(factors):
        if k == 2:
            numerators, minors = entry_numerators(factors, linearization.minors)
            if max(len(x) for row in numerators for x in row) ** 2 <= EXPAND_TERMS:  # A's entries are small
                return linearization.A, bool(linearization.A.free_symbols)
            found = positive_multiple(factors, linearization.fast.positive, minors)
            if found is not None:
                return found[0], not found[2]
        # k >= 3, or k = 2 with det M of unproved sign (N_12 N_21 has the sign of a_12 a_21)
        principal = linearization.principal_minors
        found = equality_matrix(factors, [principal[(i,)] for i in range(k)], linearization.minors)
        if found is not None:
            return found[0], not found[1]
    return linearization.A, bool(linearization.A.free_symbols)
