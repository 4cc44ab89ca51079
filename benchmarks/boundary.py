"""The public boundary, generated: every public callable, every parameter, wrong values.

:func:`targets` enumerates the callables: ``contactsym.__all__`` and each subpackage's
``__all__`` (functions and class constructors; exception classes are left out), the
public methods of the public classes (on instances found by walking the attributes of a
few built objects), and the command line's subcommands and options, read from its argparse
parser. :func:`make_call` builds one call of a target from a seed: every parameter gets a
plausible value (its default, or one chosen by its name and type hint), then one or two
parameters get a wrong value (None, text, nan, inf, negative, empty, huge, a list of the
wrong length, a Scene where a law is expected, ...). Whether a value is of the wrong
*type* is judged against the parameter's type hint (:func:`matches`); a parameter
without a hint is never judged.

``benchmarks/fuzz.py`` runs the calls in worker processes with a time limit and sorts
their outcomes.
"""

from __future__ import annotations

import argparse
import collections.abc as abc
import importlib
import inspect
import random
import types
import typing
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs

#: Subpackages whose ``__all__`` is part of the public boundary.
PACKAGES = (
    "contactsym",
    "contactsym.algebra",
    "contactsym.atlas",
    "contactsym.counts",
    "contactsym.hopf",
    "contactsym.inequalities",
    "contactsym.laws",
    "contactsym.mechanism",
    "contactsym.mechanism.files",
    "contactsym.numerics",
    "contactsym.plotting",
    "contactsym.printing",
    "contactsym.report",
    "contactsym.robustness",
    "contactsym.scenes",
    "contactsym.stages",
)

#: Set by the sentinel text when an entry point executes it as Python.
FLAG = "CONTACTSYM_FUZZ_EVALUATED"
SENTINEL = f"__import__('os').environ.__setitem__('{FLAG}', '1') or 1"

x, y = dynamicsymbols("x y")
N = sp.Symbol("N", real=True)
MU = sp.Symbol("mu", positive=True)


@dataclass
class Target:
    """A public callable: ``label`` names it in the table; ``function`` is called (a bound method for methods)."""

    label: str
    function: object
    parameters: tuple  # inspect.Parameter, self excluded
    hints: dict  # parameter name -> resolved type hint or its text


@dataclass
class Call:
    target: str
    function: object
    args: list
    kwargs: dict
    wrong: list  # names of the parameters given a value of the wrong type (by their hints)
    mutated: list  # names of the parameters given a wrong value of any kind


# --- wrong values ---------------------------------------------------------------------------------


def wrong_values() -> list:
    """The values fed where something else is expected."""
    brake = cs.scene("brake")
    return [
        None,
        "",
        "x" * 20_000,
        SENTINEL,
        "nope",
        b"bytes",
        float("nan"),
        float("inf"),
        -float("inf"),
        -1,
        0,
        -0.5,
        10**30,
        1e308,
        1j,
        True,
        [],
        [1, 2, 3],
        {},
        {"nope": 1},
        (),
        object(),
        np.array([[1.0, 2.0]]),
        np.array([np.nan]),
        sp.nan,
        sp.oo,
        sp.zoo,
        sp.Symbol("u"),
        brake,  # a Scene where a law, a number or a name is expected
        cs.Generic(),  # a law where a scene is expected
        print,  # a callable where data are expected
    ]


# --- plausible values -----------------------------------------------------------------------------


#: Parameters never left at their default: a figure at its full resolution takes longer than the time limit
#: (``paper_figures`` draws four scenes), and that would be counted as a hang of a valid call.
QUICK = {"resolution": 8, "dpi": 20}


def plausible(name: str, hint) -> object:
    """A value that could be right for a parameter called ``name`` with this hint."""
    text = str(hint).lower() if hint is not inspect.Parameter.empty else ""
    lowered = name.lower()
    if lowered in ("scene", "s") or "scene" in text and "name" not in lowered:
        return cs.scene("brake")
    if lowered in ("values", "point", "numbers", "at"):
        return {"alpha": 1.0, "m": 1.0, "mu": 0.7, "Phi_1": -2.0, "Phi_2": -3.0, "Psi_1": -1.0, "Psi_2": -0.5}
    if lowered in ("signs", "pattern"):
        return (1, 1)
    if lowered in ("name", "scene_name"):
        return "brake"
    if lowered in QUICK:
        return QUICK[lowered]
    if lowered in ("compliance", "law"):
        return cs.Generic()
    if lowered == "friction":
        return cs.Coulomb(MU, {x: 1})
    if "bool" in text:
        return False
    if "int" in text and "point" not in text:
        return 2
    if "float" in text:
        return 0.5
    if "str" in text or "path" in text:
        return "out"
    if "mapping" in text or "dict" in text:
        return {}
    if "sequence" in text or "list" in text or "tuple" in text or "iterable" in text:
        return ()
    if "callable" in text:
        return lambda *args, **kwargs: None
    if "expr" in text or "basic" in text or lowered in ("expr", "expression", "condition"):
        return MU - 1
    return MU


# --- type hints ---------------------------------------------------------------------------------------

_BUILTIN = {"int": int, "float": float, "str": str, "bool": bool, "dict": dict, "list": list, "tuple": tuple}
_BUILTIN |= {"bytes": bytes, "complex": complex, "None": type(None)}
_NUMBER = (int, float, np.integer, np.floating)


def _is(value, kind) -> bool | None:
    """Whether ``value`` is of ``kind`` (None: cannot tell)."""
    if kind is typing.Any or isinstance(kind, typing.TypeVar):
        return None
    if kind is type(None):
        return value is None
    if kind is bool:
        return isinstance(value, (bool, np.bool_))
    if kind in (int, float, complex):
        allowed = {int: (int, np.integer), float: _NUMBER, complex: (*_NUMBER, complex)}[kind]
        return isinstance(value, allowed) and not isinstance(value, (bool, np.bool_))
    if kind in (sp.Basic, sp.Expr, sp.Symbol):
        numeric = isinstance(value, (*_NUMBER, bool))  # SymPy takes numbers and True/False exactly
        return isinstance(value, kind) or (kind is not sp.Symbol and numeric)
    if isinstance(kind, type):
        if kind in (abc.Sequence, list, tuple) and isinstance(value, (str, bytes)):
            return False
        if kind is Path and isinstance(value, str):
            return True
        if kind in (abc.Sequence, abc.Iterable, abc.Collection) and isinstance(value, np.ndarray):
            return True  # the package's rule (contactsym.arguments): an array is a sequence of its entries
        return isinstance(value, kind)
    return None


def matches(value, hint) -> bool:
    """Whether ``value`` fits the type hint (True where the hint cannot be judged)."""
    if hint is inspect.Parameter.empty or hint is None:
        return True
    if isinstance(hint, str):
        return _matches_text(value, hint)
    origin = typing.get_origin(hint)
    if origin in (typing.Union, types.UnionType):
        return any(matches(value, h) for h in typing.get_args(hint))
    if origin is typing.Literal:
        return any(type(value) is type(a) and value == a for a in typing.get_args(hint))  # no array ==
    if origin is not None:
        return _is(value, origin) is not False
    return _is(value, hint) is not False


_PLAIN = (type(None), str, bytes, int, float, complex, list, dict, tuple, np.ndarray, np.number)


def _matches_text(value, text: str) -> bool:
    """A hint that could not be resolved: judged by the names of plain types, else not at all."""
    parts = [p.strip() for p in text.split("|")]
    if any("[" in p or "." in p for p in parts):
        return True
    names = {cls.__name__ for cls in type(value).__mro__}
    for part in parts:
        if part in _BUILTIN:
            if _is(value, _BUILTIN[part]):
                return True
        elif part in ("Any", "object") or part in names:
            return True
        elif part in ("Expr", "Basic") and _is(value, float):
            return True
        elif part in ("Path", "PathLike") and isinstance(value, str):
            return True
        elif part in ("Sequence", "Iterable") and isinstance(value, (list, tuple, np.ndarray)):
            return True
        elif part == "Mapping" and isinstance(value, dict):
            return True
        elif part == "Callable" and callable(value):
            return True
        elif not isinstance(value, _PLAIN):  # an object of some class: the hint's class is not known here
            return True
    return False


# --- the callables -------------------------------------------------------------------------------


def _hints(function) -> dict:
    try:
        return typing.get_type_hints(function)
    except Exception:  # noqa: BLE001 - names only imported for type checking: fall back to the text
        return dict(getattr(function, "__annotations__", {}) or {})


def _target(label: str, function, drop_first: bool = False) -> Target | None:
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        return None
    parameters = tuple(signature.parameters.values())[1 if drop_first else 0 :]
    hints = _hints(function.__init__ if isinstance(function, type) else function)
    return Target(label, function, parameters, hints)


def _instances() -> list:
    """Objects of the public classes, found by walking the attributes of a few built objects."""
    brake = cs.scene("brake")
    seeds = [brake, cs.scene("sliding-point"), cs.Generic(), cs.KelvinVoigt(2, 1), cs.Coulomb(MU, {x: 1})]
    seeds += [cs.Contact(y, N), brake.fast_subsystem(), brake.linearization(), brake.stability()]
    seeds += [brake.equilibria(), brake.regions(), cs.closed_form(brake.stability().robustly_stable, brake)]
    found, queue = [], list(seeds)
    seen: set = set()
    while queue and len(found) < 400:
        obj = queue.pop(0)
        if id(obj) in seen or isinstance(obj, (str, bytes, int, float, sp.Basic, np.ndarray, type)):
            continue
        seen.add(id(obj))
        found.append(obj)
        items = obj if isinstance(obj, (list, tuple)) else []
        if isinstance(obj, dict):
            items = list(obj.values())
        for name in [] if isinstance(obj, (list, tuple, dict)) else dir(obj):
            if name.startswith("_") or not str(type(obj).__module__).startswith("contactsym"):
                continue
            try:
                attribute = getattr(obj, name)
            except Exception:  # noqa: BLE001 - a property that fails here is not a seed
                continue
            if not callable(attribute) and str(type(attribute).__module__).startswith("contactsym"):
                items = [*items, attribute]
        queue.extend(items)
    return found


def targets() -> list[Target]:
    """Every public callable and public method, each once (by identity)."""
    found, seen = [], set()
    classes = []
    for package in PACKAGES:
        module = importlib.import_module(package)
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name, None)
            if obj is None or id(obj) in seen or not callable(obj):
                continue
            seen.add(id(obj))
            if isinstance(obj, type) and issubclass(obj, BaseException):
                continue
            if isinstance(obj, type):
                classes.append(obj)
            target = _target(f"{package}.{name}", obj)
            if target is not None:
                found.append(target)
    instances = _instances()
    for cls in classes:
        instance = next((i for i in instances if type(i) is cls), None)
        if instance is None:
            continue
        for name, member in inspect.getmembers(cls):
            if name.startswith("_") or not inspect.isfunction(member) or id(member) in seen:
                continue
            if not getattr(member, "__module__", "").startswith("contactsym"):
                continue
            seen.add(id(member))
            target = _target(f"{cls.__name__}.{name}", getattr(instance, name), drop_first=False)
            if target is not None:
                target.hints = _hints(member)
                found.append(target)
    return found


def make_call(target: Target, rng: random.Random, wrong: list) -> Call:
    """One call of ``target``: plausible values everywhere, then wrong values in one or two parameters."""
    args, kwargs = [], {}
    slots = []
    for p in target.parameters:
        if p.kind in (p.VAR_POSITIONAL, p.VAR_KEYWORD):
            continue
        hint = target.hints.get(p.name, p.annotation)
        default = p.default is not p.empty and p.name.lower() not in QUICK
        value = p.default if default and rng.random() < 0.7 else plausible(p.name, hint)
        slots.append([p, hint, value])
    mutated, bad = [], []
    if slots:
        for slot in rng.sample(slots, k=min(len(slots), 1 if rng.random() < 0.8 else 2)):
            slot[2] = wrong[rng.randrange(len(wrong))]
            mutated.append(slot[0].name)
    for p, hint, value in slots:
        if not matches(value, hint) and p.name in mutated:
            bad.append(p.name)
        if p.kind is p.POSITIONAL_ONLY:
            args.append(value)
        else:
            kwargs[p.name] = value
    return Call(target.label, target.function, args, kwargs, bad, mutated)


# --- the command line -----------------------------------------------------------------------------


def cli_options() -> dict:
    """Subcommand -> (positional names, {option: (takes a value, choices)}), read from the parser."""
    from contactsym.cli import _parser

    parser = _parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    out = {}
    for command, subparser in sub.choices.items():
        positionals, options = [], {}
        for action in subparser._actions:
            if isinstance(action, argparse._HelpAction):
                continue
            if not action.option_strings:
                positionals.append(action.dest)
            else:
                takes = action.nargs != 0
                options[action.option_strings[-1]] = (takes, tuple(action.choices or ()))
        out[command] = (positionals, options)
    return out


_CLI_JUNK = ["", "x" * 5000, SENTINEL, "-", "nope", "nan", "inf", "-1", "0", "1e400", "+1,x", "\x00", "mu=", "=1"]
_CLI_JUNK += ["mu=0:1:0", "mu=1:0:-3", "mu=0:1:1e12", "mu=a,b", "../x", "--force"]


def cli_argv(rng: random.Random, options: dict, command: str) -> tuple[str, list[str]]:
    """A command line for ``command`` with wrong arguments (never a run of the benchmarks, at most one report)."""
    positionals, flags = options[command]
    argv = [command]
    for name in positionals:
        valid = ["sliding-point"] if command == "report" else ["brake", "sliding-point"]  # one quick report at most
        argv.append(rng.choice([*valid, *_CLI_JUNK]) if name != "quantity" else "classification")
    for option, (takes, choices) in flags.items():
        if rng.random() < 0.5:
            continue
        argv.append(option)
        if takes:
            argv.append(rng.choice([*choices, *_CLI_JUNK] if choices else _CLI_JUNK))
    if command == "bench":  # a valid bench would run the benchmarks: make it fail fast (the last --json counts)
        argv += ["--json", "/nonexistent/folder/x.json"]
    if command == "report":  # one scene at most, no pdflatex: a valid report must fit the time limit
        argv[1:1] = ["sliding-point"] if argv[1].startswith("-") else []
        argv.append("--no-pdf")
    if command == "atlas" and "--grid" not in argv:
        argv += ["--grid", rng.choice(_CLI_JUNK)]
    return command, argv
