"""Scene files, the names: what a file declares (coordinates, parameters, intervals, functions)
and the formulas read with those names.

:class:`FormulaReader` is the one object every part of the reader shares: the document
(:class:`~contactsym.mechanism.files.toml_source.TomlSource`, for positions), the names
declared so far and what each is (a coordinate, a rate, a parameter, a function, a
reaction). A name is usable once declared, so use follows declaration as in the file.
"""

from __future__ import annotations

import math
import re

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

from ...algebra.basic import SignSymbol
from ...parse import CONSTANTS, FUNCTIONS, parse_expression
from ..contact_space import t
from .spec import SCHEMA, CoordinateSpec, ParameterSpec
from .toml_source import TomlSource, shown

__all__ = ["ASSUMPTIONS", "FormulaReader", "positive_on", "read_declarations"]

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_PRINTED = re.compile(r"[A-Za-z][A-Za-z0-9_^*+\-]{0,31}\Z")  # printed in LaTeX: no backslash, no braces

#: A parameter's assumption in a file, as SymPy assumptions ("sign" is a sign symbol s = +-1).
ASSUMPTIONS = {
    "positive": {"positive": True},
    "negative": {"negative": True},
    "real": {"real": True},
    "nonnegative": {"nonnegative": True},
}


class FormulaReader:
    """The declared names of one scene file, and its formulas read with them.

    Examples
    --------
    >>> reader = FormulaReader(TomlSource('[parameters]\\nm = "positive"\\n', "a.toml"))
    >>> reader.declare("m", sp.Symbol("m", positive=True), "parameter", "parameters", "m")
    >>> reader.formula("m*g", "parameters", "m")
    Traceback (most recent call last):
    ...
    contactsym.errors.ParseError: a.toml:2:3: unknown name 'g'; declared names: m.
    """

    def __init__(self, doc: TomlSource):
        self.doc = doc
        #: name in the file -> SymPy object (a coordinate's rate is declared as ``x'``).
        self.names: dict = {}
        #: name in the file -> coordinate, rate, parameter, function or reaction.
        self.kinds: dict[str, str] = {}

    def declare(self, name, value, kind: str, where: str, key: str | None = None) -> None:
        if not isinstance(name, str) or not _NAME.match(name):
            self.doc.fail(where, key, f"{shown(name)} is not a name; use letters, digits and _ (e.g. mu_1)")
        if name in FUNCTIONS or name in CONSTANTS:
            self.doc.fail(where, key, f"'{name}' is the name of a function or a constant; rename it")
        if name in self.names or name + "'" in self.names:
            self.doc.fail(where, key, f"the name '{name}' is declared twice; give each symbol one name")
        self.names[name], self.kinds[name] = value, kind

    def checked(self, table: dict, where: str, schema: str) -> dict:
        """``table`` with its keys checked against ``SCHEMA[schema]`` (unknown keys get the nearest valid one)."""
        rules = SCHEMA[schema]
        if not isinstance(table, dict):
            self.doc.fail(where, None, f"[{where}] must be a table of key = value, not {shown(table)}")
        if rules.keys is not None:
            self.doc.keys(table, where, rules.allowed, rules.required)
        return table

    def section(self, name: str, required: bool = False, kind=dict):
        """The document's table ``[name]`` (or array of tables), checked to be one."""
        return self.doc.table(self.doc.data, name, "", required=required, kind=kind)

    def formula(self, value, where: str, key: str, names: dict | None = None) -> sp.Expr:
        """A formula in quotes or a number, read with the declared names (or ``names``)."""
        if isinstance(value, bool) or not isinstance(value, (str, int, float)):
            self.doc.fail(where, key, f"'{key}' must be a formula in quotes or a number, not {shown(value)}")
        if isinstance(value, float) and not math.isfinite(value):
            self.doc.fail(where, key, f"'{key}' = {value} is not finite")
        line, column = (
            self.doc.position(where, key, value) if isinstance(value, str) else (self.doc.line(where, key), 0)
        )
        text = value if isinstance(value, str) else repr(value)  # numbers meet the same caps as formulas
        return parse_expression(
            text, self.names if names is None else names, source=self.doc.source, line=line, column=column
        )

    def name_list(self, value, where: str, key: str) -> list:
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self.doc.fail(where, key, f'\'{key}\' must be a list of names in quotes, e.g. ["x", "y"]')
        return value

    def pair(self, value, where: str, key: str, names=None) -> tuple:
        if not isinstance(value, list) or len(value) != 2:
            self.doc.fail(where, key, f'\'{key}\' must be a pair [first, second], e.g. ["x", "y"]')
        return tuple(self.formula(v, where, key, names) for v in value)

    def interval(self, value, where: str, key: str) -> tuple:
        low, high = self.pair(value, where, key, {})
        if not (low.is_real and high.is_real and bool(low < high)):
            self.doc.fail(where, key, f"the interval ({low}, {high}) is empty; give [low, high] with low < high")
        return low, high

    def text(self, table: dict, key: str, where: str, default: str = "") -> str:
        value = table.get(key, default)
        if not isinstance(value, str):
            self.doc.fail(where, key, f"'{key}' must be text in quotes, not {shown(value)}")
        return value

    def reference(self, table: dict, key: str, where: str, known, what: str) -> str:
        """A name in ``table[key]`` that must be one of ``known`` (e.g. a point)."""
        value = table.get(key)
        if not isinstance(value, str) or value not in known:
            self.doc.fail(
                where, key, f"{key} = {shown(value)} must name one of the {what}: {', '.join(known) or 'none'}"
            )
        return value

    def substitutions(self, name: str, plain: bool) -> tuple:
        """``[at]``, ``[presentation]``: pairs (formula, formula); ``plain`` reads coordinates as the frozen state."""
        names = dict(self.names)
        if plain:  # presentations act on the frozen state: coordinates as plain real symbols
            for key in self.names:
                if self.kinds[key] in ("coordinate", "rate"):
                    base = key.rstrip("'")
                    names[key] = sp.Symbol(base + ("dot" if key.endswith("'") else ""), real=True)
        pairs = []
        for key, value in self.section(name).items():
            line, column = self.doc.position(name, key, key)
            lhs = parse_expression(key, names, source=self.doc.source, line=line, column=column)
            pairs.append((lhs, self.formula(value, name, key, names)))
        return tuple(pairs)


def positive_on(symbol, low, high) -> list:
    """sin and cos of ``symbol`` where positive throughout the open interval (low, high).

    Examples
    --------
    >>> phi = sp.Symbol("phi", real=True)
    >>> positive_on(phi, 0, sp.pi / 2), positive_on(phi, 0, sp.pi), positive_on(phi, -1, 1)
    ([sin(phi), cos(phi)], [sin(phi)], [cos(phi)])
    """
    positive = []
    for function, zero in ((sp.sin, sp.S.Zero), (sp.cos, sp.pi / 2)):
        # the zeros are zero + k*pi; with none strictly inside, the sign at the midpoint holds throughout
        first = zero + (sp.floor((low - zero) / sp.pi) + 1) * sp.pi
        if bool(first >= high) and bool(function((low + high) / 2) > 0):
            positive.append(function(symbol))
    return positive


def _coordinates(reader: FormulaReader, head: dict) -> list[str]:
    names = reader.name_list(head["coordinates"], "scene", "coordinates")
    if not names:
        reader.doc.fail("scene", "coordinates", 'no coordinates; list them, e.g. coordinates = ["x", "y"]')
    for name in names:
        q = dynamicsymbols(name) if _NAME.match(name) else None
        reader.declare(name, q, "coordinate", "scene", "coordinates")
        reader.names[name + "'"], reader.kinds[name + "'"] = q.diff(t), "rate"
    return names


def _parameter(reader: FormulaReader, name: str, entry) -> ParameterSpec:
    printed, interval, assume = name, None, entry
    if isinstance(entry, dict):
        reader.checked(entry, "parameters", "parameters.entry")
        printed, interval = entry.get("symbol", name), entry.get("interval")
        if not isinstance(printed, str) or not _PRINTED.match(printed):
            reader.doc.fail("parameters", name, f"symbol = {shown(printed)} must be e.g. mu_+ or X^*_1")
        assume = entry.get("assume", "real" if interval is None else None)
    elif isinstance(entry, list):
        assume, interval = None, entry
    if interval is not None:
        interval = reader.interval(interval, "parameters", name)
        assume = assume or ("positive" if interval[0] >= 0 else "real")
    if assume == "sign":
        symbol = SignSymbol(printed)
    elif isinstance(assume, str) and assume in ASSUMPTIONS:
        symbol = sp.Symbol(printed, **ASSUMPTIONS[assume])
    else:
        reader.doc.fail(
            "parameters",
            name,
            f"unknown assumption {shown(assume)}; use one of {', '.join(ASSUMPTIONS)}, sign, or an interval [low, high]",
        )
    if interval is not None:
        low, high = interval
        if (
            (symbol.is_positive and high <= 0)
            or (symbol.is_nonnegative and high < 0)
            or (symbol.is_negative and low >= 0)
        ):
            reader.doc.fail(
                "parameters",
                name,
                f"the interval [{low}, {high}] has no {assume} value; change the interval or the assumption",
            )
    reader.declare(name, symbol, "parameter", "parameters", name)
    return ParameterSpec(name, symbol, assume, interval, reader.doc.line("parameters", name))


def read_declarations(reader: FormulaReader, head: dict) -> tuple[tuple, tuple, tuple]:
    """The coordinates (with their intervals), the parameters, and the expressions positive on the intervals."""
    names = _coordinates(reader, head)
    parameters = tuple(_parameter(reader, name, entry) for name, entry in reader.section("parameters").items())
    positive = [e for p in parameters if p.interval is not None for e in positive_on(p.symbol, *p.interval)]
    intervals = {}
    for name, value in reader.section("intervals").items():
        if reader.kinds.get(name) != "coordinate":
            reader.doc.fail(
                "intervals",
                name,
                f"'{name}' is not a coordinate; give parameters' intervals in [parameters], e.g. alpha = [0, \"pi\"]",
            )
        intervals[name] = reader.interval(value, "intervals", name)
        positive += positive_on(reader.names[name], *intervals[name])
    for name, arguments in reader.section("functions").items():
        arguments = [reader.formula(a, "functions", name) for a in reader.name_list(arguments, "functions", name)]
        reader.declare(name, sp.Function(name)(*arguments), "function", "functions", name)
    coordinates = tuple(CoordinateSpec(n, reader.names[n], intervals.get(n)) for n in names)
    return coordinates, parameters, tuple(positive)
