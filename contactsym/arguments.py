"""Arguments checked against type hints, at the public boundary: ``@checked``.

A function, method or class decorated with :func:`checked` checks each argument a caller
passed against the parameter's type hint before its body runs, and raises
:class:`~contactsym.errors.ArgumentError` (a ``ContactsymError`` and a ``TypeError``) whose
message names the callable, the parameter, what it got and what to pass. Defaults are
trusted, so a call that passes nothing pays nothing. Hints are read once, at the first
call (names imported only for type checking, such as ``Scene`` in a stage, are looked up
among contactsym's public classes then), and the per-call cost is one ``isinstance`` chain
per argument (``python -m benchmarks.arguments`` measures it).

What a hint asks for, beyond its type:

- numbers (``int``, ``float``) are finite, and ``bool`` is not a number; an ``int`` is at
  most :data:`LARGEST` in size (a count of 10**30 would run for ever);
- a SymPy hint takes numbers as SymPy does, never text (no user text reaches ``sympify``),
  and nothing holding nan, zoo or oo;
- a container hint (``Sequence[sp.Expr]``, ``tuple[int, ...]``, ``Mapping[str, float]``) is
  checked element by element; text is not a sequence.

Parameters without a hint can be given one in the decorator: ``@checked(scene="Scene")``
(kept by the check alone: the function's own annotations stay as written, so
``typing.get_type_hints`` still resolves them in the function's module).

Examples
--------
>>> @checked
... def square(n: int) -> int:
...     return n * n
>>> square(3)
9
>>> square("3")
Traceback (most recent call last):
...
contactsym.errors.ArgumentError: square: n = '3' (str) is not accepted; pass a whole number.
"""

from __future__ import annotations

import collections.abc as abc
import functools
import importlib
import inspect
import math
import os
import sys
import types
import typing
from fractions import Fraction

import numpy as np
import sympy as sp

from .errors import ArgumentError
from .validate import shorten

__all__ = ["LARGEST", "Between", "RealArray", "between", "checked", "describe", "fits", "require"]

#: The largest whole number a parameter hinted ``int`` takes (a size, a count, a degree, a seed).
LARGEST = 2**63 - 1

_INTEGERS = (int, np.integer, sp.Integer)
_REALS = (int, float, Fraction, np.integer, np.floating, sp.Rational, sp.Float)
_NOT_FINITE = (sp.nan, sp.zoo, sp.oo, sp.S.NegativeInfinity)
_CHECKED = "__contactsym_checked__"
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
    if isinstance(value, _REALS) and not isinstance(value, sp.Basic):
        return kind in (sp.Basic, sp.Expr) and _finite_number(value)
    if not isinstance(value, _LOOSE.get(kind, kind)):
        return False
    if isinstance(value, sp.Poly):  # its args would rebuild the whole expression; read the coefficients
        exact = (
            value.domain.is_ZZ or value.domain.is_QQ or value.domain.is_PolynomialRing or value.domain.is_FractionField
        )
        return exact or not any(c.has(*_NOT_FINITE) for c in value.coeffs())
    return not value.has(*_NOT_FINITE)


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
        number = isinstance(value, _REALS) and not isinstance(value, (bool, np.bool_))
        small = not isinstance(value, _INTEGERS) or abs(int(value)) <= LARGEST
        return number and small and _finite_number(value)
    if kind is complex:
        return isinstance(value, (*_REALS, complex, np.complexfloating)) and not isinstance(value, (bool, np.bool_))
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


# --- the decorator ---------------------------------------------------------------------------------


def _namespace(module: str) -> dict:
    """Names a hint may use: the defining module's, then every public class of the loaded contactsym packages."""
    names: dict = {}
    for name, loaded in list(sys.modules.items()):
        if name.startswith("contactsym") and loaded is not None:
            names.update({k: v for k, v in vars(loaded).items() if isinstance(v, type) and not k.startswith("_")})
    names.update(
        {k: getattr(abc, k) for k in ("Callable", "Collection", "Hashable", "Iterable", "Mapping", "Sequence")}
    )
    names["RealArray"] = RealArray
    names.update(sp=sp, np=np, typing=typing, PolyElement=sp.polys.rings.PolyElement)
    if "matplotlib.axes" in sys.modules:
        names["Axes"] = sys.modules["matplotlib.axes"].Axes
    names.update(vars(sys.modules[module]) if module in sys.modules else {})
    return names


def _resolve(hint, namespace: dict):
    """A hint written as text, evaluated among ``namespace`` (a hint that cannot be is not checked)."""
    if not isinstance(hint, str):
        return hint
    if "Axes" in hint:  # an ax= of a plotting function: matplotlib is loaded by then
        namespace["Axes"] = importlib.import_module("matplotlib.axes").Axes
    try:
        return eval(hint, dict(namespace))  # noqa: S307 - the source's own annotation text, never user input
    except Exception:  # noqa: BLE001 - e.g. a name defined nowhere at run time: the hint is left unchecked
        return inspect.Parameter.empty


def _with_nan(hint):
    """The hint, with nan allowed where it takes a float."""
    options = typing.get_args(hint) if typing.get_origin(hint) in (typing.Union, types.UnionType) else (hint,)
    return typing.Union[hint, NotANumber] if float in options else hint  # noqa: UP007 - built at run time


def _plan(function, extra: dict, skip_first: bool, nan: bool = False) -> tuple[dict, dict]:
    """Position -> (name, hint) and name -> hint, for the parameters that have a hint worth checking."""
    signature = inspect.signature(function)
    namespace = _namespace(function.__module__)
    by_position, by_name = {}, {}
    for position, parameter in enumerate(signature.parameters.values()):
        if skip_first and position == 0:
            continue
        if parameter.kind in (parameter.VAR_POSITIONAL, parameter.VAR_KEYWORD):
            continue
        hint = _resolve(extra.get(parameter.name, parameter.annotation), namespace)
        hint = _with_nan(hint) if nan else hint
        if hint in (inspect.Parameter.empty, typing.Any, object):
            continue
        by_name[parameter.name] = (hint, _to_sympy(hint))
        if parameter.kind is not parameter.KEYWORD_ONLY:
            by_position[position] = (parameter.name, hint, _to_sympy(hint))
    return by_position, by_name


def _to_sympy(hint) -> bool:
    """Whether a plain number passed for this hint becomes a SymPy number (the body calls SymPy methods on it)."""
    options = typing.get_args(hint) if typing.get_origin(hint) in (typing.Union, types.UnionType) else (hint,)
    sympy = [h for h in options if isinstance(h, type) and issubclass(h, sp.Basic)]
    return bool(sympy) and not any(h in (int, float, complex) for h in options)


def require(ok: bool, label: str, name: str, value, what: str) -> None:
    """Refuse ``value`` of parameter ``name`` unless ``ok``: a value check a type hint cannot state.

    Examples
    --------
    >>> require(True, "f", "n", 3, "a whole number >= 1")
    >>> require(False, "f", "n", 0, "a whole number >= 1")
    Traceback (most recent call last):
    ...
    contactsym.errors.ArgumentError: f: n = 0 (int) is not accepted; pass a whole number >= 1.
    """
    if not ok:
        _refuse(label, name, value, what)


def _refuse(label: str, name: str, value, hint):
    wanted = hint if isinstance(hint, str) else describe(hint)
    # text where SymPy objects are wanted: say why it is not parsed, and what to write instead
    why = (
        " (contactsym never evaluates text: build it with sympy, or read it with contactsym.parse.parse_expression)"
        if isinstance(value, str) and ("a SymPy" in wanted or wanted.startswith("a finite SymPy"))
        else ""
    )
    raise ArgumentError(
        f"{label}: {name} = {shorten(value)} ({type(value).__name__}) is not accepted; pass {wanted}{why}."
    )


def _wrap(function, extra: dict, label: str, skip_first: bool, nan: bool = False):
    plan: list = []

    @functools.wraps(function)
    def wrapper(*args, **kwargs):
        if not plan:
            plan.append(_plan(function, extra, skip_first, nan))
        by_position, by_name = plan[0]
        for position, value in enumerate(args):
            if position in by_position:
                name, hint, sympy = by_position[position]
                if not fits(value, hint):
                    _refuse(label, name, value, hint)
                if sympy and isinstance(value, _REALS) and not isinstance(value, sp.Basic):
                    args = (*args[:position], sp.sympify(value), *args[position + 1 :])  # a number, never text
        for name, value in kwargs.items():
            hint, sympy = by_name.get(name, (None, False))
            if hint is not None and not fits(value, hint):
                _refuse(label, name, value, hint)
            if sympy and isinstance(value, _REALS) and not isinstance(value, sp.Basic):
                kwargs[name] = sp.sympify(value)
        return function(*args, **kwargs)

    setattr(wrapper, _CHECKED, True)
    for name in ("cache_clear", "cache_info"):  # a checked lru_cache still clears and reports its cache
        if hasattr(function, name):
            setattr(wrapper, name, getattr(function, name))
    return wrapper


def checked(target=None, /, *, nan: bool = False, **hints):
    """Check the arguments of a function, a method or a class's constructor against their type hints.

    ``hints`` give (or replace) the hint of a parameter by name, as a type or as text (names are
    looked up among contactsym's public classes). A class is checked at construction, by the hints of its
    ``__init__`` (a dataclass: of its fields); ``nan=True`` lets its float fields hold nan for "no value".

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @checked
    ... @dataclass(frozen=True)
    ... class Pair:
    ...     left: int
    ...     right: str = "x"
    >>> Pair(1).right
    'x'
    >>> Pair(1, right=2)
    Traceback (most recent call last):
    ...
    contactsym.errors.ArgumentError: Pair: right = 2 (int) is not accepted; pass text.
    """
    if target is None:
        return lambda decorated: checked(decorated, nan=nan, **hints)
    if isinstance(target, type):
        init = target.__init__
        target.__init__ = _wrap(init, hints, target.__name__, skip_first=True, nan=nan)
        return target
    function = target.__func__ if isinstance(target, (classmethod, staticmethod)) else target
    qualname = function.__qualname__
    is_method = "." in qualname and "<locals>" not in qualname.rsplit(".", 1)[0]
    first = next(iter(inspect.signature(function).parameters), "")
    skip_first = is_method and not isinstance(target, staticmethod) and first in ("self", "cls")
    wrapper = _wrap(
        function, hints, qualname, skip_first
    )  # hints also here: a cache wrapper's signature is its inner function's
    if isinstance(target, classmethod):
        return classmethod(wrapper)
    if isinstance(target, staticmethod):
        return staticmethod(wrapper)
    return wrapper
