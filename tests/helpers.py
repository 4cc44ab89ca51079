"""Shared numerical witnesses for the tests: eigenvalues of (4.5), random samples."""

from __future__ import annotations

import functools
import math
from fractions import Fraction

import mpmath
import numpy as np
import sympy as sp
from hypothesis import strategies as st


def fast_matrix(A, Phi, Psi) -> np.ndarray:
    """The linearization (4.5) [[Psi A, Phi], [A, 0]] as a float array."""
    A = np.asarray(A, dtype=float)
    k = A.shape[0]
    Psi, Phi = np.diag(np.atleast_1d(Psi).astype(float)), np.diag(np.atleast_1d(Phi).astype(float))
    return np.block([[Psi @ A, Phi], [A, np.zeros((k, k))]])


def max_real_part(A, Phi, Psi) -> float:
    """Largest real part of the eigenvalues of (4.5)."""
    return float(np.max(np.linalg.eigvals(fast_matrix(A, Phi, Psi)).real))


def max_real_parts(A, Phi, Psi) -> np.ndarray:
    """:func:`max_real_part` for many laws at once: ``Phi``, ``Psi`` of shape (laws, k); one batched
    eigenvalue call."""
    A = np.asarray(A, dtype=float)
    Phi, Psi = np.atleast_2d(np.asarray(Phi, dtype=float)), np.atleast_2d(np.asarray(Psi, dtype=float))
    laws, k = Phi.shape
    J = np.zeros((laws, 2 * k, 2 * k))
    J[:, :k, :k] = Psi[:, :, None] * A  # diag(Psi) A
    J[:, np.arange(k), k + np.arange(k)] = Phi
    J[:, k:, :k] = A
    return np.linalg.eigvals(J).real.max(axis=1)


def numeric(expr, values: dict) -> float:
    """Float value of a SymPy expression at a substitution."""
    return float(sp.N(sp.sympify(expr).subs(values)))


def truth(boolean, values: dict) -> bool:
    """Truth value of a SymPy Boolean/Relational at numeric values."""
    value = sp.sympify(boolean).subs(values)
    if value in (sp.true, sp.false):
        return bool(value)
    return bool(sp.simplify(value))


@functools.cache
def _compiled(expr):
    symbols = tuple(sorted(expr.free_symbols, key=str))
    return symbols, sp.lambdify(symbols, expr, modules="math")


def fast_numeric(expr, values: dict) -> float:
    """:func:`numeric` by a compiled function, for tests that evaluate the same expression at many points
    (every free symbol needs a value: a KeyError names the one missing)."""
    symbols, function = _compiled(sp.sympify(expr))
    return float(function(*(values[s] for s in symbols)))


def fast_truth(boolean, values: dict) -> bool:
    """:func:`truth` by a compiled function (the same caveat as :func:`fast_numeric`)."""
    if boolean in (sp.true, sp.false):
        return bool(boolean)
    symbols, function = _compiled(sp.sympify(boolean))
    return bool(function(*(values[s] for s in symbols)))


_EXACT_NODES = (sp.Symbol, sp.Integer, sp.Add, sp.Mul, sp.core.relational.Relational, sp.And, sp.Or, sp.Not)


@functools.cache
def _compiled_exact(expr):
    """A pure-Python function of ``expr`` (sorted free symbols) when it is built from integers, symbols,
    +, *, integer powers, relations and And/Or/Not only: at Fractions it computes exactly what substitution
    does. None otherwise (a rational constant would be printed as a float division)."""
    for node in sp.preorder_traversal(expr):
        if not (isinstance(node, _EXACT_NODES) or (node.is_Pow and node.exp.is_Integer)):
            return None
    symbols = tuple(sorted(expr.free_symbols, key=str))
    return symbols, sp.lambdify(symbols, expr, modules=[{}])


def exact(expr, values: dict):
    """``expr.xreplace(values)`` for rational values, by exact Fraction arithmetic in a function compiled
    once per expression: a Rational for an expression, sp.true/sp.false for a Boolean (substitution
    itself where the expression has other parts)."""
    expr = sp.sympify(expr)
    compiled = _compiled_exact(expr) if expr not in (sp.true, sp.false) else None
    if compiled is None or not all(isinstance(values.get(s), sp.Rational) for s in compiled[0]):
        return expr.xreplace(values)
    symbols, function = compiled
    value = function(*(Fraction(int(values[s].p), int(values[s].q)) for s in symbols))
    if isinstance(value, bool):
        return sp.true if value else sp.false
    value = Fraction(value)
    return sp.Rational(value.numerator, value.denominator)


def fast_complex(expr, digits: int = 30) -> complex:
    """``complex(expr)`` of an expression without free symbols, by one pass over its tree in mpmath at
    ``digits`` digits (each shared subexpression once): evalf's adaptive re-evaluation of a tree of
    thousands of operations takes seconds. Parts other than numbers, +, * and powers go through evalf."""
    expr = sp.sympify(expr)
    assert not expr.free_symbols, expr.free_symbols
    memo: dict = {}

    def value(e):
        if e not in memo:
            if e.is_Add:
                memo[e] = mpmath.fsum(value(a) for a in e.args)
            elif e.is_Mul:
                memo[e] = mpmath.fprod(value(a) for a in e.args)
            elif e.is_Pow:
                memo[e] = value(e.base) ** value(e.exp)
            elif e.is_Rational:
                memo[e] = mpmath.mpf(e.p) / e.q
            elif e.is_Float:
                memo[e] = mpmath.mpf(e._mpf_)
            else:  # I, pi, functions of numbers
                memo[e] = mpmath.mpmathify(complex(sp.N(e, digits)))
        return memo[e]

    with mpmath.workdps(digits):
        return complex(value(expr))


def same(a, b) -> bool:
    """Exact identity of two expressions (or matrices)."""
    difference = sp.expand(sp.sympify(a) - sp.sympify(b))
    if isinstance(difference, sp.MatrixBase):
        return difference.is_zero_matrix
    return difference == 0


_VARIANTS: dict = {}


def variant(name: str):
    """A built-in scene, or a variant that a scene module builds by keyword (built once)."""
    import contactsym as cs
    from contactsym.scenes import painleve_rod, two_leg_block

    builders = {
        "painleve-rod-bilateral": lambda: painleve_rod.build(unilateral=False),
        "two-leg-block-unilateral": lambda: two_leg_block.build(unilateral=True),
    }
    if name not in builders:
        return cs.scene(name)
    if name not in _VARIANTS:
        _VARIANTS[name] = builders[name]()
    return _VARIANTS[name]


@functools.cache
def _fraction_values(min_value: Fraction, max_value: Fraction, max_denominator: int) -> tuple:
    values = {
        Fraction(p, q)
        for q in range(1, max_denominator + 1)
        for p in range(math.ceil(min_value * q), math.floor(max_value * q) + 1)
    }
    return tuple(sorted(values, key=lambda v: (v.denominator, abs(v), v)))  # simplest first: shrinks there


def small_fractions(min_value, max_value, max_denominator: int):
    """The values of ``st.fractions(min_value, max_value, max_denominator=...)`` (a small set), drawn by
    ``sampled_from``: that strategy takes ~5 ms a draw. Integers in the range, where there are any, are
    drawn half the time (st.fractions draws them ~40% of the time): the boundaries of random relations."""
    values = _fraction_values(Fraction(min_value), Fraction(max_value), max_denominator)
    integers = [v for v in values if v.denominator == 1]
    return st.one_of(st.sampled_from(integers), st.sampled_from(values)) if integers else st.sampled_from(values)
