r"""Scene files: a mechanical system written in TOML as on paper, read into a :class:`Scene`.

Every formula is read by the safe parser :func:`contactsym.parse.parse_expression` with
the names the file declares; nothing in a file is evaluated as Python. The examples in
``examples/`` state the paper's four scenes this way. The tables:

``[scene]``
    ``coordinates = ["x", "y", "theta"]`` (required); ``name``, ``description``,
    ``solve_for`` (a parameter that closed-form regions are solved for).
``[parameters]``
    One entry per symbol: ``m = "positive"`` (or ``"real"``, ``"negative"``,
    ``"nonnegative"``, ``"sign"`` for a sign symbol s = +-1), ``alpha = [0, "pi"]`` (an
    open interval: a real symbol, positive when the interval is), or a table
    ``mu_p = {assume = "real", symbol = "mu_+"}`` whose ``symbol`` is the printed name.
``[intervals]``
    Open intervals of coordinates, e.g. ``phi = [0, "pi/2"]``. From every interval the
    loader derives which of sin, cos, tan are positive there.
``[functions]``
    Loads that depend on the state: ``X = ["x", "x'"]`` is X(x, x').
The motion, either ``[accelerations]`` (``x = "formula"`` per coordinate, x'' = formula)
or a Lagrangian from any of:
    ``[energy]`` (``kinetic``, ``potential``); ``[points]`` (``P = ["x", "y - r"]``, its
    position in the plane, or ``P = {position = [...], body = "C", angle = "theta"}`` for
    the material point at P of a body turning with ``theta`` about point C);
    ``[[masses]]`` (``point``, ``mass``); ``[[bodies]]`` (``point``, ``angle``, ``mass``,
    ``inertia``); ``[[loads]]`` (``point`` and ``force = [Fx, Fy]``, or ``angle`` and
    ``moment``).
``[[contacts]]``
    ``gap`` (a coordinate, or a gap function of the coordinates for a Lagrangian),
    ``reaction`` (a new name), ``unilateral`` (default false), ``law`` (see
    :data:`COMPLIANCE_LAWS`, default generic), ``friction = {mu = "mu", point = "P",
    direction = ["1", "0"]}`` (or ``direction = {x = "1"}`` with ``[accelerations]``;
    ``viscous = "c"`` instead of ``mu`` for viscous friction).
``[at]``, ``[presentation]``, ``[count_presentation]``
    As the Scene options of the same names; presentation keys are formulas in quotes.
``[figures]``
    ``x``, ``y`` (two parameters), ``x_range``, ``y_range`` and ``values`` (numbers for
    the other symbols, by their names in the file, or for symbols the pipeline adds, such
    as the laws' ``Phi_1``, ``Psi_1`` and the sign symbols ``s_1``) for the report's region
    maps and phase portrait.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

from ...algebra.basic import SignSymbol
from ...errors import ContactsymError, SceneError
from ...parse import CONSTANTS, FUNCTIONS, ParseError, parse_expression
from ...scenes import scene, scene_names
from ...validate import checked_fields, cut, path_text, shorten
from ..contact import plain_symbol
from ..contact_space import t
from ..scene import Scene
from .bodies import COMPLIANCE_LAWS, PlaneMixin
from .contacts import ContactsMixin
from .toml_source import SceneFileError, TomlSource, shown

__all__ = ["COMPLIANCE_LAWS", "FigurePlan", "SceneFileError", "load_scene", "read_scene", "scene_or_file"]

_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*\Z")
_PRINTED = re.compile(r"[A-Za-z][A-Za-z0-9_^*+\-]{0,31}\Z")  # printed in LaTeX: no backslash, no braces
_SCENE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.\-]{0,63}\Z")  # it names the report's directory
_ASSUMPTIONS = {"positive": {"positive": True}, "negative": {"negative": True}, "real": {"real": True}}
_ASSUMPTIONS["nonnegative"] = {"nonnegative": True}
_TABLES = (
    "scene parameters intervals functions accelerations energy points masses bodies loads contacts at "
    "presentation count_presentation figures"
).split()


@dataclass(frozen=True)
class FigurePlan:
    """What a scene file asks to draw: region maps over (x, y) at fixed values."""

    x: str
    y: str
    x_range: tuple[float, float]
    y_range: tuple[float, float]
    values: dict = field(default_factory=dict)

    def __post_init__(self):
        checked_fields(self, SceneError)  # then the ranges: two finite numbers, low < high
        for what, pair in (("x_range", self.x_range), ("y_range", self.y_range)):
            numbers = all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in pair)
            if len(pair) != 2 or not numbers or not pair[0] < pair[1]:
                raise SceneError(f"FigurePlan {what} = {shorten(pair)} must be two finite numbers, low < high.")


class _Reader(PlaneMixin, ContactsMixin):
    """Reads one document; ``names`` grows as declarations are read, so use follows declaration."""

    def __init__(self, doc: TomlSource, default_name: str):
        self.doc, self.data = doc, doc.data
        doc.keys(self.data, "", _TABLES, required=("scene",))
        self.head = doc.table(self.data, "scene", "", required=True)
        doc.keys(self.head, "scene", ("name", "description", "coordinates", "solve_for"), required=("coordinates",))
        self.default_name = default_name
        self.names: dict = {}
        self.eps = sp.Symbol("epsilon", positive=True)
        self.positive: list = []

    # --- names and formulas -------------------------------------------------------

    def declare(self, name, value, where: str, key: str | None = None) -> None:
        if not isinstance(name, str) or not _NAME.match(name):
            self.doc.fail(where, key, f"{shown(name)} is not a name; use letters, digits and _ (e.g. mu_1)")
        if name in FUNCTIONS or name in CONSTANTS:
            self.doc.fail(where, key, f"'{name}' is the name of a function or a constant; rename it")
        if name in self.names or name + "'" in self.names:
            self.doc.fail(where, key, f"the name '{name}' is declared twice; give each symbol one name")
        self.names[name] = value

    def formula(self, value, where: str, key: str, names: dict | None = None) -> sp.Expr:
        if isinstance(value, bool) or not isinstance(value, (str, int, float)):
            self.doc.fail(where, key, f"'{key}' must be a formula in quotes or a number, not {shown(value)}")
        if isinstance(value, int):
            return sp.Integer(value)
        if isinstance(value, float):
            if not math.isfinite(value):
                self.doc.fail(where, key, f"'{key}' = {value} is not finite")
            return sp.Rational(repr(value))
        line, column = self.doc.position(where, key, value)
        return parse_expression(
            value, self.names if names is None else names, source=self.doc.source, line=line, column=column
        )

    def name_list(self, value, where: str, key: str) -> list:
        if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
            self.doc.fail(where, key, f'\'{key}\' must be a list of names in quotes, e.g. ["x", "y"]')
        return value

    def interval(self, value, where: str, key: str) -> tuple:
        low, high = self.pair(value, where, key, {})
        if not (low.is_real and high.is_real and bool(low < high)):
            self.doc.fail(where, key, f"the interval ({low}, {high}) is empty; give [low, high] with low < high")
        return low, high

    def pair(self, value, where: str, key: str, names=None) -> tuple:
        if not isinstance(value, list) or len(value) != 2:
            self.doc.fail(where, key, f'\'{key}\' must be a pair [first, second], e.g. ["x", "y"]')
        return tuple(self.formula(v, where, key, names) for v in value)

    # --- declarations -------------------------------------------------------------

    def coordinates(self) -> list:
        coordinates = []
        for name in self.name_list(self.head["coordinates"], "scene", "coordinates"):
            q = dynamicsymbols(name) if _NAME.match(name) else None
            self.declare(name, q, "scene", "coordinates")
            self.names[name + "'"] = q.diff(t)
            coordinates.append(q)
        if not coordinates:
            self.doc.fail("scene", "coordinates", 'no coordinates; list them, e.g. coordinates = ["x", "y"]')
        return coordinates

    def parameters(self) -> None:
        for name, spec in self.doc.table(self.data, "parameters", "").items():
            symbol_name, interval = name, None
            if isinstance(spec, dict):
                self.doc.keys(spec, "parameters", ("assume", "symbol", "interval"))
                symbol_name, interval = spec.get("symbol", name), spec.get("interval")
                if not isinstance(symbol_name, str) or not _PRINTED.match(symbol_name):
                    self.doc.fail("parameters", name, f"symbol = {shown(symbol_name)} must be e.g. mu_+ or X^*_1")
                spec = spec.get("assume", "real" if interval is None else None)
            elif isinstance(spec, list):
                spec, interval = None, spec
            if interval is not None:
                low, high = self.interval(interval, "parameters", name)
                spec = spec or ("positive" if low >= 0 else "real")
            if spec == "sign":
                symbol = SignSymbol(symbol_name)
            elif spec in _ASSUMPTIONS:
                symbol = sp.Symbol(symbol_name, **_ASSUMPTIONS[spec])
            else:
                self.doc.fail(
                    "parameters",
                    name,
                    f"unknown assumption {shown(spec)}; use one of "
                    f"{', '.join(_ASSUMPTIONS)}, sign, or an interval [low, high]",
                )
            self.declare(name, symbol, "parameters", name)
            if interval is not None:
                self.positive += _positive_on(symbol, low, high)

    def intervals(self) -> None:
        for name, interval in self.doc.table(self.data, "intervals", "").items():
            if not isinstance(self.names.get(name), sp.core.function.AppliedUndef):
                self.doc.fail(
                    "intervals",
                    name,
                    f"'{name}' is not a coordinate; give parameters' intervals in "
                    '[parameters], e.g. alpha = [0, "pi"]',
                )
            self.positive += _positive_on(self.names[name], *self.interval(interval, "intervals", name))

    def functions(self) -> None:
        for name, arguments in self.doc.table(self.data, "functions", "").items():
            arguments = [self.formula(a, "functions", name) for a in self.name_list(arguments, "functions", name)]
            self.declare(name, sp.Function(name)(*arguments), "functions", name)

    # --- motion -------------------------------------------------------------------

    def accelerations(self, coordinates) -> list:
        table = self.doc.table(self.data, "accelerations", "")
        self.doc.keys(table, "accelerations", [str(q.func.__name__) for q in coordinates])
        missing = [q for q in coordinates if q.func.__name__ not in table]
        if missing:
            self.doc.fail("accelerations", None, f"no acceleration for {missing[0].func.__name__}; add it")
        return [self.formula(table[q.func.__name__], "accelerations", q.func.__name__) for q in coordinates]

    # --- options ----------------------------------------------------------------

    def substitutions(self, name: str, plain: bool) -> dict:
        names = dict(self.names)
        if plain:  # presentations act on the frozen state: coordinates as plain real symbols
            for key, value in self.names.items():
                if isinstance(value, (sp.core.function.AppliedUndef, sp.Derivative)):
                    base = key.rstrip("'")
                    names[key] = sp.Symbol(base + ("dot" if key.endswith("'") else ""), real=True)
        out = {}
        for key, value in self.doc.table(self.data, name, "").items():
            line, column = self.doc.position(name, key, key)
            lhs = parse_expression(key, names, source=self.doc.source, line=line, column=column)
            out[lhs] = self.formula(value, name, key, names)
        return out

    def figures(self) -> FigurePlan | None:
        spec = self.doc.table(self.data, "figures", "")
        if not spec:
            return None
        self.doc.keys(spec, "figures", ("x", "y", "x_range", "y_range", "values"), ("x", "y", "x_range", "y_range"))
        ranges = {}
        for key in ("x_range", "y_range"):
            low, high = (float(v) for v in self.pair(spec[key], "figures", key, {}))
            if not (math.isfinite(low) and math.isfinite(high) and low < high):
                self.doc.fail("figures", key, f"{key} must be [low, high] with low < high")
            ranges[key] = (low, high)
        values = {}
        for key, value in self.doc.table(spec, "values", "figures").items():
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
                self.doc.fail("figures.values", key, f"the value of {key} must be a finite number")
            values[self.printed(key)] = float(value)
        for key in ("x", "y"):
            if not isinstance(spec[key], str) or spec[key] not in self.names:
                self.doc.fail("figures", key, f"{key} must name a declared parameter, not {shown(spec[key])}")
        symbol_of = {key: self.printed(spec[key]) for key in ("x", "y")}
        return FigurePlan(symbol_of["x"], symbol_of["y"], ranges["x_range"], ranges["y_range"], values)

    def printed(self, name: str) -> str:
        """The name of a declared symbol as the pipeline prints it (mu_p -> mu_+; a function by its name)."""
        value = self.names.get(name)
        if isinstance(value, sp.Derivative):  # a rate x' is frozen as xdot
            return plain_symbol(value.expr, "dot").name
        if isinstance(value, sp.core.function.AppliedUndef):
            return value.func.__name__
        return str(value) if isinstance(value, sp.Symbol) else name

    def build(self) -> Scene:
        coordinates = self.coordinates()
        self.parameters()
        self.intervals()
        self.functions()
        lagrangian = "accelerations" not in self.data
        if lagrangian:
            self.plane()
        contacts = self.contacts(coordinates, lagrangian)
        head = self.head
        solve_for = self.formula(head["solve_for"], "scene", "solve_for") if "solve_for" in head else None
        name = head.get("name", self.default_name)
        if not isinstance(name, str) or not _SCENE_NAME.match(name):
            self.doc.fail("scene", "name", f"the name {shown(name)} must be letters, digits, '-', '_' or '.'")
        options = dict(
            name=name,
            description=str(head.get("description", "")),
            at=self.substitutions("at", plain=False),
            presentation=self.substitutions("presentation", plain=True),
            positive=tuple(self.positive),
            solve_for=solve_for,
        )
        try:
            if lagrangian:
                L, loads = self.lagrangian()
                scene = Scene.from_lagrangian(L, coordinates, contacts, loads=loads, frame=self.frame, **options)
            else:
                scene = Scene.from_accelerations(coordinates, self.accelerations(coordinates), contacts, **options)
        except (SceneFileError, ParseError):
            raise
        except ContactsymError as error:  # the API's own message, from the file
            raise type(error)(f"{self.doc.source}: {error}") from None
        if "count_presentation" in self.data:
            scene.count_presentation = {**scene.presentation, **self.substitutions("count_presentation", True)}
        scene.figure_plan = self.figures()
        return scene


def _positive_on(symbol, low, high) -> list:
    """sin and cos of ``symbol`` where positive throughout the open interval (low, high)."""
    positive = []
    for function, zero in ((sp.sin, sp.S.Zero), (sp.cos, sp.pi / 2)):
        # the zeros are zero + k*pi; with none strictly inside, the sign at the midpoint holds throughout
        first = zero + (sp.floor((low - zero) / sp.pi) + 1) * sp.pi
        if bool(first >= high) and bool(function((low + high) / 2) > 0):
            positive.append(function(symbol))
    return positive


def read_scene(text: str, source: str = "<scene file>", default_name: str = "user") -> Scene:
    """A Scene from the text of a scene file (see the module's documentation for the format).

    Examples
    --------
    >>> s = read_scene(\'\'\'
    ... [scene]
    ... coordinates = ["x", "y"]
    ... [parameters]
    ... mu = "positive"
    ... [accelerations]
    ... x = "0"
    ... y = "N - 1"
    ... [[contacts]]
    ... gap = "y"
    ... reaction = "N"
    ... friction = {mu = "mu", direction = {x = "1"}}
    ... \'\'\')
    >>> s.accelerations
    {x(t): -mu*Abs(N), y(t): N - 1}
    >>> read_scene(\'[scene]\\ncoordinates = ["x"]\\n[[contacts]]\\ngap = "x"\\nreaction = "N"\\nlaww = "generic"\\n\', "a.toml")
    Traceback (most recent call last):
    ...
    contactsym.mechanism.files.toml_source.SceneFileError: a.toml:6: unknown key 'laww' in [contacts.0]; did you mean 'law'? allowed: gap, reaction, unilateral, law, friction.
    """
    for what, value in (("text", text), ("source", source), ("default_name", default_name)):
        if not isinstance(value, str) or (what != "text" and len(value) > 200):
            raise SceneFileError(f"read_scene: {what} = {shorten(value)} must be text (a name up to 200 characters).")
    try:
        return _Reader(TomlSource(text, source), default_name).build()
    except RecursionError:
        raise SceneFileError(f"{source}: the file nests too deeply to read.") from None


def load_scene(path) -> Scene:
    """A Scene from a scene file (TOML). Its name defaults to the file's stem.

    Examples
    --------
    >>> from pathlib import Path
    >>> load_scene(Path(__file__).parent.parent / "examples" / "brake.toml")
    <Scene 'brake-file': 3 coordinates, k = 2 contacts>
    """
    path = Path(path_text(path, "the scene file's path", SceneFileError))
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as error:
        why = getattr(error, "strerror", None) or type(error).__name__
        raise SceneFileError(f"{cut(str(path))}: cannot read the scene file ({why}).") from None
    return read_scene(text, str(path), re.sub(r"[^A-Za-z0-9_.\-]", "-", path.stem)[:64] or "user")


def scene_or_file(argument: str) -> Scene:
    """A scene file by path (a name ending in .toml), else a built-in scene, else an existing file.

    Examples
    --------
    >>> scene_or_file("brake")
    <Scene 'brake': 3 coordinates, k = 2 contacts>
    """
    if not isinstance(argument, str):
        raise SceneError(f"{shorten(argument)} is not a scene name or a scene file's path; give text.")
    if argument.endswith(".toml") or (argument not in scene_names() and Path(argument).is_file()):
        return load_scene(argument)
    return scene(argument)
