"""The options of the atlas's quantities, checked before any work, and the identity of a sweep's content.

:func:`check_options` refuses an unknown option or a value of the wrong type or range for
each built-in quantity (the simulated ones take the keyword options of
:func:`contactsym.numerics.fast_cycle` and :func:`contactsym.numerics.simulate_full`).
:func:`content_token` turns what a sweep computes (the scene's equations and derived fast
subsystem, a quantity's options, a user function's code, constants, closure and the
globals it reads) into text whose hash identifies a checkpoint: two scenes with one name,
or two lambdas, never share one.
"""

from __future__ import annotations

import inspect
import math
import types
from collections.abc import Mapping, Sequence

import numpy as np
import sympy as sp

from ..validate import shorten, sign_pattern
from .grid import AtlasError

__all__ = ["check_options", "content_token"]

_SOLVERS = ("Radau", "BDF", "LSODA", "RK45", "RK23", "DOP853")


def _whole(value, what: str, low: int = 1, high: int = 10**9) -> None:
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or not low <= value <= high:
        raise AtlasError(f"{what} = {shorten(value)} must be a whole number from {low} to {high}.")


def _positive(value, what: str, optional: bool = False) -> None:
    if optional and value is None:
        return
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, (bool, np.bool_))
    if not ok or not math.isfinite(float(value)) or value <= 0:
        raise AtlasError(f"{what} = {shorten(value)} must be a finite number > 0.")


def _flag(value, what: str, optional: bool = False) -> None:
    if not (optional and value is None) and not isinstance(value, (bool, np.bool_)):
        raise AtlasError(f"{what} = {shorten(value)} must be True or False.")


def _mapping(value, what: str, optional: bool = True) -> None:
    if not (optional and value is None) and not isinstance(value, Mapping):
        raise AtlasError(f"{what} = {shorten(value)} must be a mapping {{name: number}}.")


def _signs(value, what: str = "signs") -> None:
    if value is not None:
        try:
            sign_pattern(value)
        except ValueError as error:
            raise AtlasError(f"{what}: {error}") from None


def _method(value, what: str) -> None:
    if value not in _SOLVERS:
        raise AtlasError(f"{what} = {shorten(value)} is not a solver; use one of {', '.join(_SOLVERS)}.")


#: Keyword options of the simulations and how each is checked.
_SIMULATION = {
    "laws": _mapping,
    "unilateral": lambda v, w: _flag(v, w, optional=True),
    "form": lambda v, w: None if v in (None, "paper", "physical") else _text_choice(v, w),
    "initial": _mapping,
    "periods": _whole,
    "tol": _positive,
    "rtol": _positive,
    "atol": lambda v, w: _positive(v, w, optional=True),
    "samples": lambda v, w: _whole(v, w, 2, 10**7),
    "method": _method,
    "start": lambda v, w: None if v in ("rigid", "slow") else _text_choice(v, w, ("rigid", "slow")),
    "signs": lambda v, w: _signs(v, w),
    "jacobian": _flag,
    "dense_output": _flag,
    "reaction_bound": lambda v, w: _positive(v, w, optional=True),
    "bound_factor": _positive,
    "max_rhs": _whole,
    "max_seconds": lambda v, w: _positive(v, w, optional=True),
}


def _text_choice(value, what: str, allowed: Sequence[str] = ("paper", "physical")) -> None:
    raise AtlasError(f"{what} = {shorten(value)}; use one of {', '.join(map(repr, allowed))}.")


def _simulation_options(options: Mapping, function, what: str, skip=()) -> None:
    known = [p.name for p in inspect.signature(function).parameters.values() if p.kind is p.KEYWORD_ONLY]
    for name, value in options.items():
        if name in skip:
            continue
        if name not in known or name == "progress":
            listed = ", ".join(k for k in known if k != "progress")
            raise AtlasError(f"{what} has no option {shorten(name)}; its options are {listed}.")
        _SIMULATION.get(name, lambda v, w: None)(value, f"{what} option {name}")


def check_options(name: str, options: Mapping) -> None:
    """Refuse unknown options and wrong values of the quantity ``name`` (an AtlasError that names them).

    Examples
    --------
    >>> check_options("stable_fraction", {"laws": 0, "magnitudes": (0.1, 10.0), "seed": 0, "signs": None})
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: stable_fraction option laws = 0 must be a whole number from 1 to 1000000.
    >>> check_options("cycle", {"sampels": 256})
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: cycle has no option 'sampels'; its options are laws, unilateral, form, initial, periods, tol, rtol, samples, method.
    """
    from .. import numerics  # the simulations' signatures name the options

    if name in ("leading_eigenvalue", "classification"):
        _signs(options.get("signs"), f"{name} option signs")
    elif name == "stable_fraction":
        _whole(options.get("laws"), f"{name} option laws", 1, 10**6)
        magnitudes = options.get("magnitudes")
        if not (isinstance(magnitudes, (tuple, list)) and len(magnitudes) == 2):
            raise AtlasError(f"{name} option magnitudes = {shorten(magnitudes)} must be two numbers (low, high).")
        for bound in magnitudes:
            _positive(bound, f"{name} option magnitudes")
        if not magnitudes[0] < magnitudes[1]:
            raise AtlasError(f"{name} option magnitudes = {shorten(magnitudes)}: low must be below high.")
        _whole(options.get("seed"), f"{name} option seed", 0, 2**63 - 1)
        _signs(options.get("signs"), f"{name} option signs")
    elif name == "cycle":
        _simulation_options(options, numerics.fast_cycle, name)
    elif name == "catastrophe":
        _positive(options.get("eps"), f"{name} option eps")
        span = options.get("span")
        ok = isinstance(span, (tuple, list)) and len(span) == 2
        if not ok or not all(
            isinstance(t, (int, float)) and not isinstance(t, bool) and math.isfinite(t) for t in span
        ):
            raise AtlasError(f"{name} option span = {shorten(span)} must be two finite times (start, end).")
        if not span[0] < span[1]:
            raise AtlasError(f"{name} option span = {shorten(span)}: the start must come before the end.")
        _mapping(options.get("initial"), f"{name} option initial", optional=False)
        _simulation_options(options, numerics.simulate_full, name, skip=("eps", "span", "initial"))
    elif name.startswith("function"):
        if not callable(options.get("fn")):
            raise AtlasError(f"{shorten(options.get('fn'))} is not callable; give a function of a mapping of values.")
        outputs = options.get("outputs")
        if isinstance(outputs, (str, bytes)) or not isinstance(outputs, Sequence) or not outputs:
            raise AtlasError(f"outputs = {shorten(outputs)} must be a non-empty list of names.")
        if not all(isinstance(o, str) and o.strip() for o in outputs) or len(set(outputs)) != len(outputs):
            raise AtlasError(f"outputs = {shorten(list(outputs))} must be distinct, non-empty names.")


# --- content ----------------------------------------------------------------------------------


def _code(code: types.CodeType, seen: set) -> str:
    consts = [(_code(c, seen) if isinstance(c, types.CodeType) else repr(c)) for c in code.co_consts]
    return repr((code.co_code.hex(), consts, code.co_names, code.co_varnames))


def _function(fn, seen: set) -> str:
    """A function's code, defaults, closure and the globals it reads, recursively (each function once)."""
    if id(fn) in seen:
        return f"<{getattr(fn, '__qualname__', '?')}>"
    seen.add(id(fn))
    if isinstance(fn, (types.BuiltinFunctionType, type)):
        return f"{getattr(fn, '__module__', '')}.{fn.__qualname__}"
    if isinstance(fn, types.MethodType):
        return _function(fn.__func__, seen) + content_token(fn.__self__, seen)
    code = getattr(fn, "__code__", None)
    if code is None:  # a callable object: its class and its state
        state = getattr(fn, "__dict__", None)
        return f"{type(fn).__module__}.{type(fn).__qualname__}" + (content_token(state, seen) if state else repr(fn))
    cells = [content_token(c.cell_contents, seen) if _filled(c) else "<empty>" for c in (fn.__closure__ or ())]
    names = [n for n in code.co_names if n in getattr(fn, "__globals__", {})]
    read = [(n, content_token(fn.__globals__[n], seen)) for n in names]
    defaults = content_token((fn.__defaults__, fn.__kwdefaults__), seen)
    return repr((fn.__module__, fn.__qualname__, _code(code, seen), cells, read, defaults))


def _filled(cell) -> bool:
    try:
        _ = cell.cell_contents
    except ValueError:
        return False
    return True


def content_token(value, seen: set | None = None) -> str:
    """Text that changes when what ``value`` computes changes: SymPy objects by ``srepr``, functions by
    their code and closure, containers item by item, modules by name, arrays by their bytes."""
    seen = set() if seen is None else seen
    if isinstance(value, types.ModuleType):
        return f"<module {value.__name__}>"
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return sp.srepr(value)
    if isinstance(value, np.ndarray):
        return f"array{value.dtype}{value.shape}{value.tobytes().hex()}"
    if isinstance(value, Mapping):
        items = sorted((content_token(k, seen), content_token(v, seen)) for k, v in value.items())
        return "{" + ",".join(f"{k}:{v}" for k, v in items) + "}"
    if isinstance(value, (list, tuple)):
        return type(value).__name__ + "(" + ",".join(content_token(v, seen) for v in value) + ")"
    if callable(value):
        return _function(value, seen)
    return repr(value)
