r"""Scene files: a mechanical system written in TOML as on paper, read into a :class:`Scene`.

Every formula is read by the safe parser :func:`contactsym.parse.parse_expression` with
the names the file declares; nothing in a file is evaluated as Python. The examples in
``examples/`` state the paper's four scenes this way. Reading has two steps:
:func:`read_spec` checks the file against its schema
(:data:`contactsym.mechanism.files.spec.SCHEMA`) into a frozen
:class:`~contactsym.mechanism.files.spec.SceneSpec`, and :func:`build_scene`
(:mod:`contactsym.mechanism.files.builder`) builds the Scene from that spec alone. The tables:

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
The motion
    Either ``[accelerations]`` (``x = "formula"`` per coordinate, x'' = formula), or a
    Lagrangian from any of ``[energy]`` (``kinetic``, ``potential``); ``[points]`` (``P = ["x", "y - r"]``, its
    position in the plane, or ``P = {position = [...], body = "C", angle = "theta"}`` for
    the material point at P of a body turning counter-clockwise by ``theta`` about point C);
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
    ``x``, ``y`` (two parameters or coordinates), ``x_range``, ``y_range`` (within the
    axes' declared signs and intervals) and ``values`` (numbers for the other symbols, by
    their names in the file, or for symbols the pipeline adds, such as the laws' ``Phi_1``,
    ``Psi_1`` and the sign symbols ``s_1``; each admissible for its symbol) for the
    report's region maps and phase portrait. See :mod:`contactsym.mechanism.files.figures`.
``[values]``
    Parameters fixed at numbers before the derivation (``m1 = 1``, ``l2 = "1/3"``): a partly
    numeric scene, :meth:`contactsym.Scene.with_values`; its stages are smaller.

Bodies in space: ``dimensions = 3`` in ``[scene]`` with ``[frames]``, points, bodies, loads
and contacts in 3-D (see :mod:`contactsym.mechanism.files.spatial`).

A file is refused, with the cap named, beyond the sizes of :class:`Limits` (bytes,
coordinates, contacts, points, ...; pass ``limits=Limits(...)`` to read a larger one) and
the caps on formulas of :mod:`contactsym.parse`. Only regular files are read.
"""

from __future__ import annotations

import os
import re
import stat
from pathlib import Path

import sympy as sp

from ...arguments import checked
from ...scenes import scene, scene_names
from ...validate import shorten
from ..scene import Scene
from .bodies import read_motion, read_points
from .builder import build_scene
from .contacts import COMPLIANCE_LAWS, read_contacts
from .declarations import FormulaReader, read_declarations
from .figures import pipeline_names, read_figures
from .space import check_orientations
from .spatial import read_space
from .spec import FigurePlan, Limits, SceneSpec, limits_in_force
from .toml_source import SceneFileError, TomlSource, shown

__all__ = [
    "COMPLIANCE_LAWS",
    "LIMITS",
    "FigurePlan",
    "Limits",
    "SceneFileError",
    "build_scene",
    "load_scene",
    "read_scene",
    "read_spec",
    "scene_or_file",
]

#: The default caps on a scene file's size.
#:
#: >>> from contactsym.mechanism.files import LIMITS
#: >>> LIMITS.max_contacts
#: 6
LIMITS = Limits()

_SCENE_NAME = re.compile(r"[A-Za-z0-9_][A-Za-z0-9_.\-]{0,63}\Z")  # it names the report's directory
_LAGRANGIAN_TABLES = ("energy", "points", "masses", "bodies", "loads")


def _beyond(source: str, line: int, count: int, what: str, cap: str, limits: Limits):
    raise SceneFileError(
        f"{source}:{line}: {count} {what}, more than the cap of {getattr(limits, cap)} (Limits.{cap}); "
        f"to read it anyway, pass limits=Limits({cap}={count}) (contactsym.mechanism.files.Limits) to load_scene, "
        f"or on the command line: contactsym --limit {cap}={count} ..."
    )


def _sized(doc: TomlSource, limits: Limits) -> None:
    """Refuse a scene beyond the caps before any formula is read (a table of the wrong kind counts 0 here)."""

    def count(*path) -> int:
        value = doc.data
        for step in path:
            value = value.get(step) if isinstance(value, dict) else None
        return len(value) if isinstance(value, (list, dict)) else 0

    sizes = (
        ("coordinates", "scene", "coordinates", "max_coordinates", count("scene", "coordinates")),
        ("contacts", "contacts", None, "max_contacts", count("contacts")),
        ("points", "points", None, "max_points", count("points")),
        ("frames", "frames", None, "max_points", count("frames")),
        ("masses, bodies and loads", "", None, "max_items", count("masses") + count("bodies") + count("loads")),
        (
            "parameters, functions and intervals",
            "parameters",
            None,
            "max_names",
            count("parameters") + count("functions") + count("intervals"),
        ),
    )
    for what, table, key, cap, size in sizes:
        if size > getattr(limits, cap):
            _beyond(doc.source, doc.line(table, key), size, what, cap, limits)


def _switching(contacts, formulas) -> int:
    """At most how many switching functions (Abs, sign) the pipeline finds: one per frictional
    contact, one per distinct Abs or sign written in the motion."""
    written = {a.args[0] for f in formulas for a in f.atoms(sp.Abs, sp.sign)}
    return len(written) + sum(c.friction is not None for c in contacts)


def _dimensions(doc: TomlSource, head: dict, lagrangian: bool) -> int:
    """2 (the plane, by default) or 3 (space: :mod:`contactsym.mechanism.files.spatial`)."""
    dimensions = head.get("dimensions", 2)
    if isinstance(dimensions, bool) or dimensions not in (2, 3):
        doc.fail("scene", "dimensions", f"dimensions = {shown(dimensions)} must be 2 (the plane) or 3 (space)")
    if dimensions == 3 and not lagrangian:
        doc.fail(
            "scene",
            "dimensions",
            "dimensions = 3 is for a Lagrangian in space ([frames], [points], "
            "[[bodies]]); with [accelerations] leave it out",
        )
    if dimensions == 2 and "frames" in doc.data:
        doc.fail("frames", None, "[frames] are for a scene in space; add dimensions = 3 to [scene]")
    return dimensions


@checked
def read_spec(
    text: str, source: str = "<scene file>", default_name: str = "user", *, limits: Limits = LIMITS
) -> SceneSpec:
    """The checked, frozen content of a scene file (see the module's documentation for the format).

    Examples
    --------
    >>> spec = read_spec('[scene]\\ncoordinates = ["y"]\\n[accelerations]\\ny = "N - 1"\\n'
    ...                  '[[contacts]]\\ngap = "y"\\nreaction = "N"\\n', "a.toml")
    >>> spec.accelerations, spec.contacts[0].reaction, spec.contacts[0].law.name
    ((N - 1,), N, 'generic')
    """
    if not isinstance(source, str) or not isinstance(default_name, str):
        raise SceneFileError(f"source and default_name must be text, not {shown(source)} and {shown(default_name)}.")
    if not isinstance(text, str):
        raise SceneFileError(f"{source}: a scene file's text must be a str, not {type(text).__name__}.")
    if not isinstance(limits, Limits):
        raise SceneFileError(f"{source}: limits must be a contactsym.mechanism.files.Limits, not {shown(limits)}.")
    limits = limits_in_force(limits)
    if len(text) > limits.max_bytes:  # the characters of a text; load_scene counts bytes before it decodes
        _beyond(source, 1, len(text), "characters", "max_bytes", limits)
    doc = TomlSource(text, source)
    _sized(doc, limits)
    reader = FormulaReader(doc)
    reader.checked(doc.data, "", "")
    head = reader.checked(reader.section("scene", required=True), "scene", "scene")
    coordinates, parameters, positive = read_declarations(reader, head)
    lagrangian = "accelerations" not in doc.data
    if not lagrangian and any(t in doc.data for t in _LAGRANGIAN_TABLES):
        used = next(t for t in _LAGRANGIAN_TABLES if t in doc.data)
        doc.fail(used, None, f"[{used}] is for a Lagrangian, but the file gives [accelerations]; remove one of them")
    spatial = _dimensions(doc, head, lagrangian) == 3
    points = read_points(reader, positive) if lagrangian and not spatial else ()
    eps = SceneSpec.eps
    if spatial:
        space, contacts, energy = read_space(reader, coordinates, eps)
    else:
        contacts = read_contacts(reader, coordinates, lagrangian, [p.name for p in points], eps, positive)
    solve_for = reader.formula(head["solve_for"], "scene", "solve_for") if "solve_for" in head else None
    if solve_for is not None and not isinstance(solve_for, sp.Symbol):
        doc.fail("scene", "solve_for", f"solve_for = {shown(head['solve_for'])} must name a parameter")
    name = head.get("name", default_name)
    if not isinstance(name, str) or not _SCENE_NAME.match(name):
        doc.fail("scene", "name", f"the name {shown(name)} must be letters, digits, '-', '_' or '.'")
    options = dict(
        source=source,
        name=name,
        description=reader.text(head, "description", "scene"),
        coordinates=coordinates,
        parameters=parameters,
        contacts=contacts,
        at=reader.substitutions("at", plain=False),
        presentation=reader.substitutions("presentation", plain=True),
        positive=positive,
        solve_for=solve_for,
        eps=eps,
    )
    if spatial:
        check_orientations(reader, space, coordinates, dict(options["at"]))
        options.update(space=space, **energy)
        forces = [c for load in space.loads for c in (load.force or load.moment)]
        written = [energy["kinetic"], energy["potential"], *forces]
    elif lagrangian:
        options.update(points=points, **read_motion(reader, points))
        written = [
            options["kinetic"],
            options["potential"],
            *(m for load in options["loads"] for m in (load.force or ())),
        ]
    else:
        table = reader.checked(reader.section("accelerations"), "accelerations", "accelerations")
        doc.keys(table, "accelerations", [c.name for c in coordinates])
        missing = [c.name for c in coordinates if c.name not in table]
        if missing:
            doc.fail("accelerations", None, f"no acceleration for {missing[0]}; add it")
        options["accelerations"] = written = tuple(
            reader.formula(table[c.name], "accelerations", c.name) for c in coordinates
        )
    if "count_presentation" in doc.data:
        options["count_presentation"] = reader.substitutions("count_presentation", plain=True)
    extra = pipeline_names(len(contacts), _switching(contacts, written))
    options["figures"] = read_figures(reader, parameters, coordinates, extra)
    options["values"] = _read_values(reader)
    return SceneSpec(**options)


def _read_values(reader: FormulaReader) -> tuple:
    """``[values]``: a declared parameter = a number (or a formula of numbers, "1/3")."""
    table = reader.checked(reader.section("values"), "values", "values")
    values = []
    for key, value in table.items():
        if reader.kinds.get(key) != "parameter":
            reader.doc.fail("values", key, f"'{key}' is not a declared parameter; [values] fixes parameters at numbers")
        number = reader.formula(value, "values", key, names={})
        if not (number.is_real and number.is_finite):
            reader.doc.fail("values", key, f"the value of {key} must be a finite real number, not {shown(value)}")
        values.append((reader.names[key], number))
    return tuple(values)


def read_scene(
    text: str, source: str = "<scene file>", default_name: str = "user", *, limits: Limits = LIMITS
) -> Scene:
    """A Scene from the text of a scene file: :func:`build_scene` of :func:`read_spec`.

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
    contactsym.errors.SceneFileError: a.toml:6: unknown key 'laww' in [contacts.0]; did you mean 'law'? allowed: gap, reaction, unilateral, law, friction.
    """
    for what, value in (("text", text), ("source", source), ("default_name", default_name)):
        if not isinstance(value, str) or (what != "text" and len(value) > 200):
            raise SceneFileError(f"read_scene: {what} = {shorten(value)} must be text (a name up to 200 characters).")
    try:
        return build_scene(read_spec(text, source, default_name, limits=limits))
    except RecursionError:
        raise SceneFileError(f"{source}: the file nests too deeply to read.") from None


def _read_regular_file(path: Path, limits: Limits) -> str:
    """The text of a regular file of at most ``limits.max_bytes`` bytes; a FIFO or a device is never opened for a read that waits."""
    try:
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as error:
        raise SceneFileError(f"{path}: cannot read the scene file ({error.strerror or error}).") from None
    mode = os.fstat(descriptor).st_mode
    if not stat.S_ISREG(mode):
        os.close(descriptor)
        kind = "a directory" if stat.S_ISDIR(mode) else "a pipe" if stat.S_ISFIFO(mode) else "not a regular file"
        raise SceneFileError(f"{path}: {kind}; a scene file must be a regular file (a .toml text).")
    with os.fdopen(descriptor, "rb") as file:
        data = file.read(limits.max_bytes + 1)
    if len(data) > limits.max_bytes:
        size = path.stat().st_size
        _beyond(str(path), 1, size, "bytes", "max_bytes", limits)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as error:
        raise SceneFileError(f"{path}: cannot read the scene file (not UTF-8 text: {error.reason}).") from None


def load_scene(path, *, limits: Limits = LIMITS) -> Scene:
    """A Scene from a scene file (TOML). Its name defaults to the file's stem.

    Examples
    --------
    >>> from pathlib import Path
    >>> load_scene(Path(__file__).parents[3] / "examples" / "brake.toml")
    <Scene 'brake-file': 3 coordinates, k = 2 contacts>
    """
    if not isinstance(path, (str, os.PathLike)):
        raise SceneFileError(f"load_scene takes a path (str or pathlib.Path), not {shown(path)}.")
    if not isinstance(limits, Limits):
        raise SceneFileError(f"limits must be a contactsym.mechanism.files.Limits, not {shown(limits)}.")
    limits = limits_in_force(limits)
    path = Path(path)
    text = _read_regular_file(path, limits)
    default = re.sub(r"[^A-Za-z0-9_.\-]", "-", path.stem)[:64] or "user"
    return read_scene(text, str(path), default, limits=limits)


def _is_file(name: str) -> bool:
    """Whether ``name`` is a file; a name the system cannot hold (too long, say) is none."""
    try:
        return Path(name).is_file()
    except OSError:
        return False


def scene_or_file(argument: str) -> Scene:
    """A scene file by path (a name ending in .toml), else a built-in scene, else an existing file.

    Examples
    --------
    >>> scene_or_file("brake")
    <Scene 'brake': 3 coordinates, k = 2 contacts>
    """
    if not isinstance(argument, (str, os.PathLike)):
        raise SceneFileError(f"give a scene's name or a scene file's path, not {shown(argument)}.")
    argument = os.fspath(argument)
    if argument.endswith(".toml") or (argument not in scene_names() and _is_file(argument)):
        return load_scene(argument)
    return scene(argument)
