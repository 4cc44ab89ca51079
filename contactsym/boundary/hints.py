"""One value against one type hint: :func:`fits` (does the value fit the hint?) and :func:`describe`
(what the hint asks for, in words), for the decorator :func:`contactsym.arguments.checked`.

What a hint asks for, beyond its type, is listed in :mod:`contactsym.arguments`.

Examples
--------
>>> fits(3, int), fits(3.5, int), describe(list[int])
(True, False, 'a list, each item a whole number')
"""

from __future__ import annotations

import collections.abc as abc
import inspect
import math
import os
import types
import typing
from fractions import Fraction

import numpy as np
import sympy as sp

__all__ = ["LARGEST", "REAL_TYPES", "Between", "NotANumber", "RealArray", "between", "describe", "fits"]

#: The largest whole number a parameter hinted ``int`` takes (a size, a count, a degree, a seed).
LARGEST = 2**63 - 1

_INTEGERS = (int, np.integer, sp.Integer)
#: The types of a real number, as a value passed for a number (SymPy numbers among them).
REAL_TYPES = (int, float, Fraction, np.integer, np.floating, sp.Rational, sp.Float)
_NOT_FINITE = (sp.nan, sp.zoo, sp.oo, sp.S.NegativeInfinity)
#: ``sp.Expr`` in a hint also takes a relation or a Boolean combination (what the conditions are made of),
#: never a container such as a Tuple or a Matrix.
_LOOSE = {sp.Expr: (sp.Expr, sp.logic.boolalg.Boolean)}


class Between:
    """A range a number must lie in: the metadata of ``between(low, high)``."""

    def __init__(self, low, high):
        self.low, self.high = low, high

    def admits(self, value) -> bool:
        return self.low <= value <= self.high

    def __repr__(self) -> str:
        return f"Between({self.low!r}, {self.high!r})"


class RealArray:
    """The hint of finite real numbers in an array's shape: a numpy array, or (nested) lists of numbers."""


class NotANumber:
    """nan, where a record (``@checked(nan=True)``) uses it for "no value" (a cycle that did not converge)."""


def _real_array(value) -> bool:
    if isinstance(value, (str, bytes, dict)) or value is None:
        return False
    try:
        array = np.asarray(value)
    except (ValueError, TypeError):  # ragged lists
        return False
    return array.dtype.kind in "iuf" and bool(np.all(np.isfinite(array)))


def between(low, high, kind: type = int):
    """The hint of a number from ``low`` to ``high`` (a count that would otherwise run for ever).

    Examples
    --------
    >>> fits(3, between(1, 8)), fits(10**30, between(1, 8)), describe(between(1, 8))
    (True, False, 'a whole number from 1 to 8')
    """
    return typing.Annotated[kind, Between(low, high)]


# --- one value against one hint --------------------------------------------------------------------


def _finite_number(value) -> bool:
    try:
        return math.isfinite(float(value))
    except (TypeError, ValueError, OverflowError):
        return False


def _sympy_fits(value, kind) -> bool:
    if isinstance(value, (bool, np.bool_)):
        return kind is sp.Basic  # True and False are Boolean SymPy objects, not expressions
    if isinstance(value, REAL_TYPES) and not isinstance(value, sp.Basic):
        return kind in (sp.Basic, sp.Expr) and _finite_number(value)
    if not isinstance(value, _LOOSE.get(kind, kind)):
        return False
    if isinstance(value, sp.Poly):  # its args would rebuild the whole expression; read the coefficients
        exact = (
            value.domain.is_ZZ or value.domain.is_QQ or value.domain.is_PolynomialRing or value.domain.is_FractionField
        )
        # the dense representation, not coeffs(): that asks bool() of each coefficient, which over an
        # expression domain is an assumptions query on a possibly huge expression
        return exact or not any(value.domain.to_sympy(c).has(*_NOT_FINITE) for c in _entries(value.rep.to_list()))
    return not value.has(*_NOT_FINITE)


def _entries(nested):
    """The coefficients of a dense polynomial representation (nested lists), zeros included."""
    for item in nested:
        if isinstance(item, list):
            yield from _entries(item)
        else:
            yield item


def _class_fits(value, kind: type) -> bool:
    if kind is bool:
        return isinstance(value, (bool, np.bool_))
    if kind is RealArray:
        return _real_array(value)
    if kind is NotANumber:
        return isinstance(value, (float, np.floating)) and math.isnan(value)
    if kind is int:
        plain = isinstance(value, _INTEGERS) and not isinstance(value, (bool, np.bool_))
        return plain and abs(int(value)) <= LARGEST
    if kind is float:  # a whole number beyond int64 would turn numpy arrays into arrays of objects
        number = isinstance(value, REAL_TYPES) and not isinstance(value, (bool, np.bool_))
        small = not isinstance(value, _INTEGERS) or abs(int(value)) <= LARGEST
        return number and small and _finite_number(value)
    if kind is complex:
        return isinstance(value, (*REAL_TYPES, complex, np.complexfloating)) and not isinstance(value, (bool, np.bool_))
    if isinstance(kind, type) and issubclass(kind, sp.MatrixBase):
        return isinstance(value, sp.MatrixBase) and not any(e.has(*_NOT_FINITE) for e in value)
    if kind in (sp.Basic, sp.Expr, sp.Symbol, sp.Poly) or (isinstance(kind, type) and issubclass(kind, sp.Basic)):
        return _sympy_fits(value, kind)
    if kind in (os.PathLike,) or (isinstance(kind, type) and issubclass(kind, os.PathLike)):
        return isinstance(value, (str, os.PathLike)) and bool(str(value).strip()) and "\x00" not in str(value)
    if kind in (abc.Sequence, abc.Iterable, abc.Collection, abc.Set, list, tuple, frozenset, set):
        if isinstance(value, (str, bytes)):
            return False
        if kind in (abc.Sequence, abc.Iterable, abc.Collection) and isinstance(value, (np.ndarray, sp.MatrixBase)):
            return True  # an array or a SymPy column of entries
    if kind is abc.Callable:
        return callable(value) and not isinstance(value, type)
    if kind in (abc.Mapping, dict) and type(value).__name__ == "NumericValues":
        return kind is abc.Mapping  # numeric values already checked by numerics.numeric_values stand for a mapping
    return isinstance(value, kind)


def _items_fit(value, arguments: tuple, origin) -> bool:
    """The elements (or keys and values) of a container against the hint's arguments."""
    if not arguments:
        return True
    if origin in (abc.Mapping, dict, abc.MutableMapping):
        return all(fits(k, arguments[0]) and fits(v, arguments[-1]) for k, v in value.items())
    if origin is tuple and not (len(arguments) == 2 and arguments[1] is Ellipsis):
        return len(value) == len(arguments) and all(fits(v, a) for v, a in zip(value, arguments))
    if isinstance(value, np.ndarray) and value.ndim == 1 and value.dtype.kind in "iuf":  # numbers: by the dtype
        kinds = {int: "iu", float: "iuf", complex: "iuf", sp.Expr: "iuf", sp.Basic: "iuf"}.get(arguments[0])
        return kinds is not None and value.dtype.kind in kinds and bool(np.all(np.isfinite(value)))
    return all(fits(v, arguments[0]) for v in value)


def fits(value, hint) -> bool:
    """Whether ``value`` is acceptable for a parameter with this (resolved) type hint.

    Examples
    --------
    >>> import sympy as sp
    >>> fits([sp.Symbol("a"), 2], list[sp.Expr]), fits(["a"], list[sp.Expr])
    (True, False)
    >>> fits(float("nan"), float), fits(True, int), fits(None, int | None)
    (False, False, True)
    """
    if hint in (typing.Any, object, inspect.Parameter.empty) or isinstance(hint, (typing.TypeVar, str)):
        return True
    if hint is None or hint is type(None):
        return value is None
    origin = typing.get_origin(hint)
    if origin is typing.Annotated:
        base, *limits = typing.get_args(hint)
        return fits(value, base) and all(limit.admits(value) for limit in limits if isinstance(limit, Between))
    if origin in (typing.Union, types.UnionType):
        return any(fits(value, h) for h in typing.get_args(hint))
    if origin is typing.Literal:
        return any(type(value) is type(a) and value == a for a in typing.get_args(hint))  # type first: no array ==
    if origin is type:
        return isinstance(value, type)
    if origin is not None:
        if origin is abc.Callable:
            return callable(value) and not isinstance(value, type)
        if not _class_fits(value, origin):
            return False
        try:
            return _items_fit(value, typing.get_args(hint), origin)
        except TypeError:  # a container that cannot be walked is not the container hinted
            return False
    if isinstance(hint, type):
        return _class_fits(value, hint)
    return True


# --- what to pass -------------------------------------------------------------------------------------

_WORDS = {
    bool: "True or False",
    int: "a whole number",
    float: "a finite real number",
    complex: "a number",
    str: "text",
    bytes: "bytes",
    dict: "a dict",
    list: "a list",
    tuple: "a tuple",
    frozenset: "a frozenset",
    sp.Basic: "a SymPy object or a finite number",
    sp.Expr: "a finite SymPy expression (or relation) or a number",
    sp.Symbol: "a SymPy Symbol",
    sp.Poly: "a SymPy Poly",
    np.ndarray: "a numpy array",
    abc.Mapping: "a mapping (a dict)",
    abc.Sequence: "a list or tuple",
    abc.Iterable: "a list or tuple",
    abc.Callable: "a function",
    abc.Hashable: "a hashable value (e.g. a tuple or text)",
    abc.Collection: "a list, tuple or set",
    RealArray: "finite real numbers (a numpy array or lists of numbers)",
}


def describe(hint) -> str:
    """What a value of this hint is, in words.

    Examples
    --------
    >>> import sympy as sp
    >>> describe(tuple[int, ...] | None)
    'a tuple, each item a whole number, or None'
    >>> describe(sp.Matrix)
    'a SymPy Matrix'
    """
    if hint is None or hint is type(None):
        return "None"
    origin = typing.get_origin(hint)
    if origin is typing.Annotated:
        base, *limits = typing.get_args(hint)
        ranges = [f" from {r.low} to {r.high}" for r in limits if isinstance(r, Between)]
        return describe(base) + "".join(ranges)
    if origin in (typing.Union, types.UnionType):
        parts = [describe(h) for h in typing.get_args(hint) if h is not type(None)]
        return " or ".join(parts) + (", or None" if type(None) in typing.get_args(hint) else "")
    if origin is typing.Literal:
        return "one of " + ", ".join(repr(a) for a in typing.get_args(hint))
    if origin is not None:
        arguments = [a for a in typing.get_args(hint) if a is not Ellipsis]
        head = _WORDS.get(origin, f"a {getattr(origin, '__name__', origin)}")
        if origin in (abc.Mapping, dict) and len(arguments) == 2:
            return f"{head} from {describe(arguments[0])} to {describe(arguments[1])}"
        return f"{head}, each item {' or '.join(describe(a) for a in arguments)}" if arguments else head
    if hint in _WORDS:
        return _WORDS[hint]
    if isinstance(hint, type) and issubclass(hint, sp.MatrixBase):
        return "a SymPy Matrix"
    if isinstance(hint, type) and issubclass(hint, os.PathLike):
        return "a path (text or pathlib.Path)"
    return f"a {getattr(hint, '__name__', hint)}"
