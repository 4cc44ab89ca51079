"""Scene files, the figures: ``[figures]`` read into a :class:`FigurePlan` and checked against the scene.

The axes are parameters or coordinates of the scene (not a reaction, a rate or a load
function), two different ones; each range lies within the axis's declared sign or interval;
every value names a symbol of the scene or one the pipeline adds (the laws' ``Phi``,
``Psi``, the sign symbols ``s``) and is admissible for it (a positive parameter > 0, a sign
+-1, ``Phi`` and ``Psi`` < 0 as (1.5) asks). A misspelt name gets the nearest valid one.
"""

from __future__ import annotations

import difflib
import math

import sympy as sp

from ..contact import plain_symbol
from .declarations import FormulaReader
from .spec import FigurePlan, ParameterSpec
from .toml_source import shown

__all__ = ["pipeline_names", "read_figures"]

#: What a value must satisfy, by the declared assumption: (test, words for the message).
_ADMISSIBLE = {
    "positive": (lambda v: v > 0, "> 0"),
    "negative": (lambda v: v < 0, "< 0"),
    "nonnegative": (lambda v: v >= 0, ">= 0"),
    "sign": (lambda v: v in (1, -1), "1 or -1"),
    "law": (lambda v: v < 0, "< 0 (the sign conditions (1.5))"),
}


def pipeline_names(contacts: int, switching: int) -> dict[str, str]:
    """Names the pipeline adds that a plan may give values for: the laws' Phi, Psi (one pair per
    contact) and the sign symbols (at most ``switching`` of them), each with its assumption.

    Examples
    --------
    >>> sorted(pipeline_names(2, 1))
    ['Phi_1', 'Phi_2', 'Psi_1', 'Psi_2', 's', 's_1']
    """
    laws = ["Phi", "Psi"] if contacts == 1 else [f"{n}_{j}" for j in range(1, contacts + 1) for n in ("Phi", "Psi")]
    signs = (["s"] if switching else []) + [f"s_{j}" for j in range(1, switching + 1)]
    return {**dict.fromkeys(laws, "law"), **dict.fromkeys(signs, "sign")}


def _printed(reader: FormulaReader, name: str) -> str:
    """A declared name as the pipeline prints it (mu_p -> mu_+, x' -> xdot, a function by its name)."""
    value = reader.names.get(name)
    if isinstance(value, sp.Derivative):
        return plain_symbol(value.expr, "dot").name
    if isinstance(value, sp.core.function.AppliedUndef):
        return value.func.__name__
    return str(value) if isinstance(value, sp.Symbol) else name


def _interval_words(interval) -> str:
    return f"the interval ({interval[0]}, {interval[1]})"


def _declared(reader: FormulaReader, parameters, coordinates) -> dict[str, tuple]:
    """name -> (assumption or None, interval or None) for every parameter and coordinate."""
    out = {p.name: (p.assume, p.interval) for p in parameters}
    out.update({c.name: (None, c.interval) for c in coordinates})
    return out


def _axis(reader: FormulaReader, figures: dict, key: str, declared: dict) -> str:
    name = figures[key]
    kind = reader.kinds.get(name) if isinstance(name, str) else None
    if kind in ("parameter", "coordinate") and declared[name][0] != "sign":
        return name
    axes = [n for n, (assume, _) in declared.items() if assume != "sign"]
    close = difflib.get_close_matches(name, axes, n=1) if isinstance(name, str) else []
    what = {"reaction": "a reaction", "rate": "a rate", "function": "a load function", "parameter": "a sign"}.get(kind)
    why = f"{shown(name)} is {what}, not an axis" if what else f"{shown(name)} is not a parameter or coordinate"
    hint = f"did you mean '{close[0]}'? " if close else ""
    reader.doc.fail("figures", key, f"{why}; {hint}{key} must be one of {', '.join(axes)}")


def _range(reader: FormulaReader, figures: dict, key: str, axis: str, declared: dict) -> tuple[float, float]:
    low, high = (float(v) for v in reader.pair(figures[key], "figures", key, {}))
    if not (math.isfinite(low) and math.isfinite(high) and low < high):
        reader.doc.fail("figures", key, f"{key} must be [low, high] with low < high")
    assume, interval = declared[axis]
    if interval is not None and not (low >= float(interval[0]) and high <= float(interval[1])):
        reader.doc.fail(
            "figures", key, f"{key} = [{low:g}, {high:g}] leaves {_interval_words(interval)} declared for {axis}"
        )
    if assume in ("positive", "nonnegative") and low < 0 or assume == "negative" and high > 0:
        reader.doc.fail(
            "figures", key, f"{key} = [{low:g}, {high:g}] leaves the sign declared for {axis} ({axis} is {assume})"
        )
    return low, high


def _value(reader: FormulaReader, key: str, value, rule: tuple) -> float:
    assume, interval = rule
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        reader.doc.fail("figures.values", key, f"the value of {key} must be a finite number, not {shown(value)}")
    value = float(value)
    if assume in _ADMISSIBLE and not _ADMISSIBLE[assume][0](value):
        words = "a sign symbol" if assume == "sign" else ("a law's" if assume == "law" else assume)
        reader.doc.fail(
            "figures.values",
            key,
            f"{key} = {value:g} is not admissible: {key} is {words}, so give {key} {_ADMISSIBLE[assume][1]}",
        )
    if interval is not None and not float(interval[0]) < value < float(interval[1]):
        reader.doc.fail(
            "figures.values", key, f"{key} = {value:g} is outside {_interval_words(interval)} declared for it"
        )
    return value


def read_figures(
    reader: FormulaReader, parameters: tuple[ParameterSpec, ...], coordinates, extra: dict[str, str]
) -> FigurePlan | None:
    """``[figures]`` as a plan, checked against the declarations; ``extra`` are :func:`pipeline_names`."""
    figures = reader.section("figures")
    if not figures:
        return None
    reader.checked(figures, "figures", "figures")
    declared = _declared(reader, parameters, coordinates)
    x, y = (_axis(reader, figures, key, declared) for key in ("x", "y"))
    if x == y:
        reader.doc.fail("figures", "y", f"x and y are both {x}; give two different parameters or coordinates")
    ranges = {key: _range(reader, figures, key, axis, declared) for key, axis in (("x_range", x), ("y_range", y))}
    valid = {n: declared.get(n, (None, None)) for n, kind in reader.kinds.items() if kind != "reaction"}
    valid.update({n: (assume, None) for n, assume in extra.items() if n not in valid})
    values = {}
    for key, value in reader.doc.table(figures, "values", "figures").items():
        if key not in valid:
            close = difflib.get_close_matches(key, list(valid), n=1)
            hint = f"did you mean '{close[0]}'? " if close else ""
            what = (
                "a reaction: the figures fix parameters and the state"
                if reader.kinds.get(key)
                else "not a name of the scene"
            )
            reader.doc.fail(
                "figures.values",
                key,
                f"'{key}' is {what}; {hint}give values for parameters, coordinates, rates (x'), load functions, "
                f"or {', '.join(extra) or 'none'}",
            )
        values[_printed(reader, key)] = _value(reader, key, value, valid[key])
    return FigurePlan(_printed(reader, x), _printed(reader, y), ranges["x_range"], ranges["y_range"], values)
