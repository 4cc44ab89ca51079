"""A canonical rational form for expressions in several angles, with no ``simplify``.

Every expression the pipeline derives is a rational function of the parameters, of sign
symbols ``s_j`` (values +-1), and of ``sin q`` and ``cos q`` of a few angles. In such an
expression the angles' sines and cosines are algebraically tied by ``sin^2 q + cos^2 q = 1``
and the signs by ``s^2 = 1``; nothing else ties them. :func:`canonical` uses exactly that:

1.-4. (:mod:`contactsym.algebra.trig_field`) Angles expanded, the expression as P/Q of two
   polynomials reduced modulo the ideal ``(cos^2 q + sin^2 q - 1, ..., s^2 - 1, ...)`` (a normal
   form: the generators are a Groebner basis), signs moved up, P/Q cancelled by its polynomial gcd.
5. (:mod:`contactsym.algebra.half_angle`) The common factors that only the circle sees are
   cancelled: with t = tan(q/2) per angle of Q, P/Q is an element of a field of rational
   functions in independent variables, whose cancelled form is unique; it is mapped back with the
   least powers of 1 + t^2, so equal fractions become the same (P', Q') up to a constant.
6. The trigonometric units of Q are put in one place: Q becomes sin^m q cos^n q Q'' with no
   factor sin q, cos q, 1 +- cos q, 1 +- sin q of Q'' modulo the ideal (1 +- cos q becomes
   sin^2 q, 1 +- sin q cos^2 q, P times the conjugate), and sin q, cos q are cancelled from P
   where they divide P modulo the ideal (``_settled``); constants are fixed (integer, coprime
   contents, Q's leading coefficient > 0). Where step 5 was skipped, a result presented in
   multiple angles is read once more, until it reads the same.

What is guaranteed, and why. Step 5 makes (P', Q') a function of the value of the fraction (as a
rational function of the parameters, the signs and the angles, with sin^2 + cos^2 = 1 and
s^2 = 1), and steps 6 and the presentation are functions of (P', Q'). So two inputs with the same
value give the same output, and :func:`canonical` is idempotent (its output has the input's
value, so it reads back to itself: no second reading is needed where step 5 ran). Both are
tested as properties on random fractions: equal inputs written differently (multiple angles
expanded, the identities applied, a common factor multiplied in and rewritten, partial
fractions), and the output read again. Where no output is
guaranteed: when P or Q has more than :data:`contactsym.algebra.half_angle.MAX_TERMS` terms step
5 is skipped (to bound its cost), and a sign symbol left in Q (Q vanishes for one sign) keeps the
polynomial gcd alone. A polynomial (a denominator of monomials in sin q and the parameters) takes
a shorter path, expanded and reduced term by term: the same normal form. The form is always
*correct*: each step is an identity.

For presentation, P and the non-monomial part of Q are written either as polynomials in
``sin q_i``, ``cos q_i`` or as Fourier sums ``sum a_k cos(k.q) + b_k sin(k.q)`` (multiple
angles, e.g. ``cos(2 q1 - 2 q2)``), each exactly converted, whichever has fewer operations.
A monomial denominator is distributed over the terms, so a polynomial in the parameters
keeps the expanded form of earlier versions.

Examples
--------
>>> import sympy as sp
>>> a, b, m = sp.symbols("a b m", positive=True)
>>> canonical(sp.sin(a)**2/m + sp.cos(a)**2/m)
1/m
>>> canonical(1/(1 - sp.cos(a - b)**2)) == canonical(1/sp.sin(a - b)**2)
True
>>> canonical((sp.cos(2*a) + 1)/(m*sp.cos(a)))
2*cos(a)/m
"""

from __future__ import annotations

import sympy as sp

from ..arguments import checked
from ..deprecation import deprecated_names
from ..parse import sympy_only
from .coprime import cofactors
from .half_angle import cancelled_on_the_circle, circle_form
from .reductions import reduce_signs, reduce_trig
from .trig_field import (
    TrigField,
    TrigFraction,
    _integer_combination,
    _integral,
    _is_angle,
    _reduce,
    present_factor,
    to_fraction,
)

__all__ = ["canonical", "TrigField", "TrigFraction", "present_factor", "to_fraction"]


#: Re-readings of a fraction's presented form before it is returned (see :func:`canonical`).
_PASSES = 4


@checked
def canonical(expr: sp.Expr) -> sp.Expr:
    """``expr`` in the canonical rational form (see the module docstring).

    Examples
    --------
    >>> x, m = sp.symbols("x m", positive=True)
    >>> canonical(1/(1 - sp.cos(x)**2))
    sin(x)**(-2)
    >>> canonical(sp.sin(x)**2/m + sp.cos(x)**2/m)
    1/m
    """
    expr = sympy_only(expr, "the expression")
    if expr.is_Number or expr.is_Symbol:
        return expr
    if _laurent_in_plain_angles(expr):
        # a polynomial over monomial denominators in sin q, cos q of plain angles: expanding and
        # reducing term by term gives the same normal form, without building a fraction field
        return reduce_signs(reduce_trig(sp.expand(expr)))
    cancelled, unique = circle_form(to_fraction(expr))
    result = _settled(cancelled).as_expr()
    if unique or not any(_integer_combination(f.args[0]) for f in result.atoms(sp.sin, sp.cos)):
        # unique: step 5 made (P', Q') a function of the value, so a re-read (same value) gives the
        # same P', Q' and the same presentation; reduced polynomials re-read as the same P and Q
        return result
    # step 5 skipped (a sign symbol in Q, or too many terms) and a Fourier presentation (cos(2 q),
    # cos(q1 - q2)): re-read, it expands to other polynomials, whose gcd can see a factor that
    # cancels only modulo sin^2 + cos^2 = 1: read it again until nothing changes
    seen = [result]
    for _ in range(_PASSES):
        again = _settled(cancelled_on_the_circle(to_fraction(result))).as_expr()
        if again == result:
            return result
        if again in seen:  # a cycle: its first member in a fixed order, whichever one we entered it by
            cycle = seen[seen.index(again) :]
            return min(cycle, key=lambda e: (sp.count_ops(e), sp.default_sort_key(e)))
        seen.append(again)
        result = again
    return result


def _laurent_in_plain_angles(expr: sp.Expr) -> bool:
    """No denominator but powers of generators other than cosines, and sin/cos only of plain angles."""
    for node in sp.preorder_traversal(expr):
        if (
            node.is_Pow
            and node.exp.is_negative
            and (node.base.is_Add or node.base.is_Mul or isinstance(node.base, sp.cos))
        ):
            return False  # a power of cos q below: cos^2 q = 1 - sin^2 q may cancel with it (see _settled)
        if isinstance(node, (sp.sin, sp.cos)) and not _is_angle(node.args[0]):
            return False
        if node.is_Pow and not node.exp.is_Integer:
            return False
    return True


def _settled(fraction: TrigFraction) -> TrigFraction:
    """P/Q with the trigonometric units of Q in one place, so that equal fractions read the same.

    The polynomial gcd of step 4 does not see factors that cancel only modulo
    sin^2 q + cos^2 q = 1: cos q / (1 - sin^2 q) and 1 / cos q, or 1 / (1 + cos q) and
    (1 - cos q) / sin^2 q, are reduced and coprime as polynomials. For each angle, in order,
    Q becomes sin^m q cos^n q Q'' with no factor sin q, cos q, 1 +- cos q or 1 +- sin q left in
    Q'' modulo the ideal: cos q and 1 +- sin q (P times 1 -+ sin q) go to the power of cos q,
    1 +- cos q (P times 1 -+ cos q) to the power of sin q; then sin q and cos q are cancelled
    from P where they divide it modulo the ideal. The power of cos q is the one place where Q
    is not reduced. Each step multiplies P and Q by one factor or divides both by one.
    """
    numer, denom, pairs, signs = fraction.numer, fraction.denom, fraction.pairs, fraction.signs
    ring = numer.ring
    one = ring.one
    if denom.is_ground or not pairs:
        return fraction
    powers = [0] * ring.ngens

    for c, s in pairs:
        C, S = ring.gens[c], ring.gens[s]

        def by_unit(poly, conjugate, square, C=C, S=S):  # poly / unit = poly * conjugate / square, or None
            # the unit vanishes at one point of the circle (1 + cos q at cos q = -1, sin q = 0): poly must too
            zero = [(C, conjugate.coeff(C)), (S, 0)] if square == "sin" else [(S, conjugate.coeff(S)), (C, 0)]
            if poly.evaluate(zero):
                return None
            return _by_square(_reduce(poly * conjugate, pairs, signs), square, C, S)

        changed = True
        while changed:
            changed = False
            while (quotient := _exact(denom, S)) is not None:
                denom, powers[s], changed = quotient, powers[s] + 1, True
            while (quotient := _by_cos(denom, C, S)) is not None:
                denom, powers[c], changed = quotient, powers[c] + 1, True
            for conjugate, square in ((one - C, "sin"), (one + C, "sin"), (one - S, "cos"), (one + S, "cos")):
                quotient = by_unit(denom, conjugate, square)  # a unit 1 +- cos q, 1 +- sin q of Q
                if quotient is not None:
                    numer, denom, changed = _reduce(numer * conjugate, pairs, signs), quotient, True
                    powers[s if square == "sin" else c] += 2
        while powers[s] > 0 and (quotient := _exact(numer, S)) is not None:
            numer, powers[s] = quotient, powers[s] - 1
        while powers[c] > 0 and numer and (quotient := _by_cos(numer, C, S)) is not None:
            numer, powers[c] = quotient, powers[c] - 1
    _, numer, denom = cofactors(numer, denom)
    denom = denom * ring({tuple(powers): ring.domain.one})
    numer, denom = _integral(numer, denom)
    return TrigFraction(numer, denom, pairs, signs)


def _exact(poly, factor):
    """poly / factor when it divides exactly (as polynomials), else None."""
    quotient, remainder = poly.div(factor)
    return None if remainder else quotient


def _by_cos(poly, C, S):
    """poly / cos q modulo the ideal, or None: (X0 + X1 C) / C = X1 + C X0 / (1 - S^2)."""
    low = _exact(poly.coeff_wrt(C, 0), poly.ring.one - S**2)
    return None if low is None else poly.coeff_wrt(C, 1) + C * low


def _by_square(poly, square: str, C, S):
    """poly / cos^2 q (``square == "cos"``) or / sin^2 q modulo the ideal, or None."""
    if square == "cos":
        once = _by_cos(poly, C, S)
        return None if once is None else _by_cos(once, C, S)
    return _exact(poly, S**2)


# 0.1's name, kept (it warns): it shadowed the standard fractions.TrigFraction
__getattr__ = deprecated_names(__name__, {"Fraction": "TrigFraction"}, globals())
