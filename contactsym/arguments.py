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
import sys
import types
import typing

import numpy as np
import sympy as sp

from .boundary.hints import LARGEST, REAL_TYPES, Between, NotANumber, RealArray, between, describe, fits
from .errors import ArgumentError
from .validate import shorten

__all__ = ["LARGEST", "Between", "RealArray", "between", "checked", "describe", "fits", "require"]

_CHECKED = "__contactsym_checked__"


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
                if sympy and isinstance(value, REAL_TYPES) and not isinstance(value, sp.Basic):
                    args = (*args[:position], sp.sympify(value), *args[position + 1 :])  # a number, never text
        for name, value in kwargs.items():
            hint, sympy = by_name.get(name, (None, False))
            if hint is not None and not fits(value, hint):
                _refuse(label, name, value, hint)
            if sympy and isinstance(value, REAL_TYPES) and not isinstance(value, sp.Basic):
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
