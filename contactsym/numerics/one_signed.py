"""Forms of a sum of terms of one sign that floating point evaluates with a relative error bound,
and the count of roundings that gives the bound (used by :class:`~contactsym.numerics.classifier.PointClassifier`).

A sum whose terms all have one sign, evaluated in floating point, is within gamma_r relative of its
exact value, r the roundings along the longest path (Higham, *Accuracy and Stability of Numerical
Algorithms*, 3.1). ``_one_signed_form`` finds a cheaper form in which every sum still has terms of
one sign; ``_roundings`` counts r on it.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import sympy as sp

from ..errors import NumericsError
from .certified import _exact_float

__all__: list[str] = []  # helpers of the classifier


def _one_signed_form(total: sp.Expr) -> sp.Expr:
    """A cheap form of ``total``, a sum of terms of one sign, in which every sum still has
    terms of one sign (so floating point keeps a relative error bound): the sum or its
    factored form, with shared powers pulled out of sums."""
    if total.is_Number or len(sp.Add.make_args(total)) < 2:
        return total
    # the sum itself last: it wins only where strictly cheaper (a**4*q**2 + a**2 over a**2*(a**2*q**2 + 1))
    candidates = [_pulled_out(total), sp.Mul(*[_pulled_out(f) for f in sp.Mul.make_args(sp.factor(total))]), total]
    valid = [c for c in candidates if _one_signed_sums(c)]
    return min(valid, key=sp.count_ops) if valid else total


def _pulled_out(expr: sp.Expr) -> sp.Expr:
    """``expr`` with, recursively, the power shared by most terms pulled out of each sum:
    a + b x + c x y becomes a + x (b + c y), and a + b + x (a + b) becomes (x + 1)(a + b)."""
    if expr.is_Pow and expr.exp.is_Integer:
        return _pulled_out(expr.base) ** expr.exp
    terms = sp.Add.make_args(expr)
    if len(terms) < 2:
        return expr
    counts: dict = {}
    for term in terms:
        for base, exponent in term.as_powers_dict().items():
            if not base.is_Number and exponent.is_Integer and exponent > 0:
                counts.setdefault(base, []).append(int(exponent))
    shared = [(len(e), b) for b, e in counts.items() if len(e) > 1]
    if not shared:
        return expr
    _, base = max(shared, key=lambda item: (item[0], sp.default_sort_key(item[1])))
    power = base ** min(counts[base])
    inside = [t for t in terms if base in t.as_powers_dict()]
    outside = [t for t in terms if base not in t.as_powers_dict()]
    inner, rest = _pulled_out(sp.Add(*[t / power for t in inside])), _pulled_out(sp.Add(*outside))
    return (power + 1) * inner if inner == rest else power * inner + rest


def _one_signed_sums(expr: sp.Expr) -> bool:
    for node in sp.preorder_traversal(expr):
        if node.is_Add and not (all(a.is_nonnegative for a in node.args) or all(a.is_nonpositive for a in node.args)):
            return False
    return True


def _roundings(expr: sp.Expr, function: int = 4, leaves: dict | None = None) -> int:
    """Roundings along the longest path of the evaluation of ``expr`` in floating point:
    its computed value is within gamma_r relative of the exact one when every sum of
    ``expr`` has terms of one sign. ``function``: the roundings a function of an exact argument counts for
    (4: NumPy's float64 ones; a value with relative error at most k u counts for k, as gamma_k >= k u).
    ``leaves``: in float32 (u the float32 unit), per symbol the roundings its value counts for (1 if not
    given: a float64 input rounded to float32); a number not exact in float32 then counts for 2 (a float64
    literal, rounded again), and a function must be an argument (a symbol), not an operation."""
    if expr.is_Symbol:
        return 0 if leaves is None else leaves.get(expr, 1)
    if expr.is_Number or expr.is_NumberSymbol:
        if expr.is_Rational and _exact_float(float(expr), Fraction(int(expr.p), int(expr.q))):
            return 0 if leaves is None or float(np.float32(float(expr))) == float(expr) else 2
        return 1 if leaves is None else 2
    if expr.is_Add:
        return max(_roundings(a, function, leaves) for a in expr.args) + len(expr.args) - 1
    if expr.is_Mul:  # a product of k factors: k - 1 roundings, none for a power of two
        exact = sum(1 for f in expr.args if f.is_Integer and f != 0 and abs(int(f)).bit_count() == 1)
        return sum(_roundings(f, function, leaves) for f in expr.args) + len(expr.args) - 1 - exact
    if expr.is_Pow:
        base, exponent = expr.args
        if exponent.is_Integer:
            n = abs(int(exponent))
            return n * _roundings(base, function, leaves) + n + (1 if exponent < 0 else 0)
        if exponent.is_Rational and leaves is None:  # NumPy's float32 powers promise no bound
            return _roundings(base, function, leaves) + 2
    if isinstance(expr, sp.Abs):
        return _roundings(expr.args[0], function, leaves)
    if isinstance(expr, sp.Function) and len(expr.args) == 1 and leaves is None:
        if _roundings(expr.args[0], function) == 0:
            return function  # NumPy's elementary functions: at most 4 units in the last place (its SIMD ones)
        raise NumericsError(
            f"cannot bound the rounding of {expr}: its argument is rounded; introduce a parameter for the argument."
        )
    raise NumericsError(f"cannot bound the rounding of {expr}; rewrite it with +, *, powers and functions.")
