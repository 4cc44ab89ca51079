"""Parameter values for numerics: finite numbers and functions, checked, and their substitution.

Every numeric entry point first turns the user's ``values`` into :class:`NumericValues`
(Symbol -> number, undefined function -> Lambda) with :func:`numeric_values`, which
refuses text, non-finite numbers and values that break a symbol's declared sign.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import sympy as sp

from .. import validate
from ..arguments import checked
from ..errors import NumericsError
from ..parse import sympy_only

_UNIT = 2.0**-53  # unit roundoff of IEEE double precision


_UNIT = 2.0**-53  # unit roundoff of IEEE double precision


def _number(value, name: str) -> sp.Expr:
    """A finite real number as a SymPy number; never parses text."""
    if isinstance(value, (str, bytes)):
        raise NumericsError(
            f"{name} = {validate.shorten(value)} is text; pass a number (contactsym never parses text)."
        )
    if isinstance(value, (bool, np.bool_)):
        raise NumericsError(f"{name} = {validate.shorten(value)} is a truth value; pass a number.")
    if isinstance(value, (int, np.integer)):
        return sp.Integer(int(value))
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if not math.isfinite(x):
            raise NumericsError(f"{name} = {x} is not finite; pass a finite number.")
        return sp.Float(x)
    if isinstance(value, sp.Basic):
        if value.free_symbols:
            raise NumericsError(
                f"{name} = {validate.shorten(value)} still contains the symbols {sorted(map(str, value.free_symbols))}; pass a number."
            )
        if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or value.is_finite is False:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not finite; pass a finite number.")
        if value.is_real is False:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not real; pass a real number.")
        if not value.is_number:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not a number.")
        if not math.isfinite(float(value)):
            raise NumericsError(f"{name} = {validate.shorten(value)} is not finite; pass a finite number.")
        return value
    raise NumericsError(f"{name} = {validate.shorten(value)} of type {type(value).__name__} is not a number.")


def _positive(value, name: str, why: str) -> float:
    x = float(_number(value, name))
    if not x > 0:
        raise NumericsError(f"{name} = {x} must be > 0: {why}.")
    return x


def _plain_expr(scene, expr) -> sp.Expr:
    return scene.plain(expr)


@checked
@dataclass(frozen=True)
class NumericValues:
    """Numeric parameter values (Symbol -> number) and function substitutions.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = numeric_values(cs.scene("brake"), {"m": 1, "mu": 0.5, "alpha": 1.0})
    >>> type(values).__name__, sorted(str(s) for s in values.numbers)
    ('NumericValues', ['alpha', 'm', 'mu'])
    """

    numbers: dict
    functions: dict  # UndefinedFunction -> Lambda

    def key(self) -> tuple:
        return (frozenset(self.numbers.items()), frozenset(self.functions.items()))


def _scene_symbols(scene) -> dict[str, sp.Basic]:
    """Names of the symbols and undefined functions a scene uses, for string keys."""
    exprs = [_plain_expr(scene, g) for g in scene.accelerations.values()]
    exprs += [_plain_expr(scene, c.coordinate) for c in scene.contacts]
    fast = scene.fast_subsystem()
    exprs += list(fast.Phi) + list(fast.Psi)
    for contact in scene.contacts:
        exprs.append(sp.Tuple(*contact.compliance.parameters()))
    names: dict[str, sp.Basic] = {}
    for expr in exprs:
        expr = sp.sympify(expr)
        for symbol in expr.free_symbols:
            names.setdefault(str(symbol), symbol)
        for applied in expr.atoms(sp.core.function.AppliedUndef):
            names.setdefault(str(applied.func), applied.func)
    return names


@checked(scene="Scene")
def numeric_values(scene, values: Mapping | None) -> NumericValues:
    """Validate parameter values for a scene: finite numbers, and functions for X(x, xdot).

    Keys are the scene's SymPy symbols or their names (strings are looked up among the
    scene's symbols, never parsed). An undefined function such as the sliding point's
    ``X(x, xdot)`` is given either applied, ``{X(x, xdot): expression in x, xdot}``, or as
    the function with a ``sympy.Lambda``.

    Examples
    --------
    >>> import contactsym as cs
    >>> v = numeric_values(cs.scene("brake"), {"m": 2, "mu": 0.5})
    >>> sorted(map(str, v.numbers))
    ['m', 'mu']
    >>> numeric_values(cs.scene("brake"), {"m": float("nan")})
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: m = nan is not finite; pass a finite number.
    >>> numeric_values(cs.scene("brake"), {"m": "2"})
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: m = '2' is text; pass a number (contactsym never parses text).
    """
    numbers: dict = {}
    functions: dict = {}
    if values is None:
        return NumericValues(numbers, functions)
    if isinstance(values, NumericValues):
        return values
    if not isinstance(values, Mapping):
        raise NumericsError(f"values must be a mapping {{symbol: number}}, not {type(values).__name__}.")
    known = None
    for key, value in values.items():
        if isinstance(key, str):
            known = known if known is not None else _scene_symbols(scene)
            if key not in known:
                raise NumericsError(f"unknown parameter name {key!r}; the scene's names are {sorted(known)}.")
            key = known[key]
        if isinstance(key, sp.core.function.UndefinedFunction):
            if isinstance(value, sp.Lambda):
                functions[key] = value
                continue
            raise NumericsError(f"give the function {key} as sympy.Lambda((x, xdot), expression) or applied.")
        if not isinstance(key, sp.Basic):
            raise NumericsError(f"parameter key {key!r} is neither a SymPy symbol nor a name.")
        if isinstance(key, sp.core.function.AppliedUndef):
            key = _plain_expr(scene, key)
            arguments = key.args
            if not all(isinstance(a, sp.Symbol) for a in arguments):
                raise NumericsError(f"the function {key} must be applied to plain symbols, e.g. X(x, xdot).")
            body = _number(value, str(key)) if not isinstance(value, sp.Basic) else sp.sympify(value)
            if isinstance(body, sp.Basic) and body.free_symbols - set(arguments):
                extra = sorted(map(str, body.free_symbols - set(arguments)))
                raise NumericsError(f"the value of {key} uses {extra}, which are not its arguments {list(arguments)}.")
            functions[key.func] = sp.Lambda(arguments, body)
            continue
        if not isinstance(key, sp.Symbol):
            raise NumericsError(f"parameter key {key} is not a symbol.")
        number = _number(value, str(key))
        _check_assumptions(key, number)
        numbers[key] = number
    return NumericValues(numbers, functions)


def _merge(scene, values, state) -> NumericValues:
    """Parameter values with a (frozen) state merged in."""
    vals = numeric_values(scene, values)
    extra = numeric_values(scene, state)
    return NumericValues({**vals.numbers, **extra.numbers}, {**vals.functions, **extra.functions})


def _check_assumptions(symbol: sp.Symbol, number: sp.Expr) -> None:
    x = float(number)
    if symbol.is_positive and not x > 0:
        raise NumericsError(f"{symbol} = {x} must be > 0 (the symbol is declared positive).")
    if symbol.is_negative and not x < 0:
        raise NumericsError(f"{symbol} = {x} must be < 0 (the symbol is declared negative, as (1.5) requires).")
    if symbol.is_nonnegative and not x >= 0:
        raise NumericsError(f"{symbol} = {x} must be >= 0.")


@checked(expr="sp.Basic | sp.MatrixBase")
def substitute(expr, values: NumericValues) -> sp.Expr:
    """Plain numeric substitution: functions first, then numbers (``xreplace``).

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> s = cs.scene("sliding-point")
    >>> x, xdot = sp.symbols("x xdot", real=True)
    >>> v = numeric_values(s, {"m": 2, sp.Function("X")(x, xdot): 3*x})
    >>> substitute(s.reduced_system().accelerations[x], v)
    -mu*Abs(Y(x, xdot))/2 + 3*x/2
    """
    expr = sympy_only(expr, "the expression")
    for function, body in values.functions.items():
        expr = expr.replace(function, body)
    if isinstance(expr, sp.MatrixBase):
        return expr.xreplace(values.numbers)
    return expr.xreplace(values.numbers)


def _check_free(expr_list, allowed: set, what: str) -> None:
    free = set()
    for e in expr_list:
        free |= sp.sympify(e).free_symbols
    missing = free - allowed
    if missing:
        raise NumericsError(f"{what} needs values for {sorted(map(str, missing))}; add them to values.")
    functions = set()
    for e in expr_list:
        functions |= {a.func for a in sp.sympify(e).atoms(sp.core.function.AppliedUndef)}
    if functions:
        raise NumericsError(
            f"{what} still contains the undefined functions {sorted(map(str, functions))}; "
            "give them in values, e.g. {X(x, xdot): expression}."
        )


def _check_span(span, name: str) -> tuple[float, float]:
    if not isinstance(span, (tuple, list)) or len(span) != 2:
        raise NumericsError(f"{name} = {validate.shorten(span)} must be a pair (start, end).")
    start, end = (float(_number(v, name)) for v in span)
    if not end > start:
        raise NumericsError(f"{name} = ({start}, {end}): the end must come after the start.")
    return start, end


def _state_values(names: Sequence[str], symbols: Sequence[sp.Symbol], initial, what: str) -> dict:
    """Initial values keyed by symbol, from a mapping keyed by symbols or names."""
    if initial is None:
        return {}
    if not isinstance(initial, Mapping):
        raise NumericsError(f"the initial state of the {what} must be a mapping {{symbol or name: number}}.")
    by_name = dict(zip(names, symbols))
    out = {}
    for key, value in initial.items():
        name = key if isinstance(key, str) else str(key)
        if name not in by_name:
            raise NumericsError(f"{name!r} is not a state variable of the {what}; its state is {list(names)}.")
        out[by_name[name]] = float(_number(value, name))
    return out


def _with(vals: NumericValues, extra: Mapping) -> NumericValues:
    numbers = dict(vals.numbers)
    numbers.update({k: sp.Float(v) if isinstance(v, float) else v for k, v in extra.items()})
    return NumericValues(numbers, vals.functions)


def _evaluate(expr, vals: NumericValues, what: str) -> float:
    value = substitute(expr, vals)
    if value.free_symbols:
        raise NumericsError(f"{what} needs values for {sorted(map(str, value.free_symbols))}.")
    return float(value)
