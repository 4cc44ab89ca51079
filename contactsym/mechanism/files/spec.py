"""Scene files as data: the typed, frozen record of what a file says, and the schema it is read by.

Reading a file has two steps. :func:`contactsym.mechanism.files.reader.read_spec` checks the
TOML against :data:`SCHEMA`, resolves every name and parses every formula into a
:class:`SceneSpec`; :func:`contactsym.mechanism.files.reader.build_scene` then builds the
mechanics (``sympy.physics.mechanics`` points and bodies, contacts, laws) and the Scene from
the spec alone. Every spec item keeps the line it was read from, for messages.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from contextlib import AbstractContextManager, contextmanager
from contextvars import ContextVar
from dataclasses import dataclass, field, fields
from types import MappingProxyType

import sympy as sp

from ...arguments import checked
from ...errors import SceneError
from ...validate import checked_fields, shorten

__all__ = [
    "SCHEMA",
    "BodySpec",
    "ContactSpec",
    "CoordinateSpec",
    "FigurePlan",
    "FrictionSpec",
    "LawSpec",
    "Limits",
    "LoadSpec",
    "MassSpec",
    "ParameterSpec",
    "PointSpec",
    "SceneSpec",
    "TableSchema",
    "file_limits",
    "limits_in_force",
]


def removed_mixin(name: str) -> type:
    """A class that 0.1 had, whose use now says what replaced it (the reader's mixins became
    :func:`~contactsym.mechanism.files.reader.read_spec` and
    :func:`~contactsym.mechanism.files.reader.build_scene`)."""

    def refuse(*args, **kwargs):
        raise SceneError(
            f"{name} was removed in 0.2: a scene file is read into a SceneSpec by read_spec() and built "
            "by build_scene() (contactsym.mechanism.files)."
        )

    return type(
        name,
        (),
        {
            "__doc__": f"Removed in 0.2; see :func:`{__name__}.removed_mixin`.",
            "__init__": refuse,
            "__init_subclass__": classmethod(refuse),
        },
    )


@dataclass(frozen=True)
class TableSchema:
    """The keys of one table and the kind of each value.

    ``keys`` maps a fixed key to its kind; a table of free names (``[parameters]``) has
    ``keys = None`` and gives the kind of every entry as ``entries``. Kinds: ``formula``
    (text in quotes or a number), ``names`` (a list of names), ``pair`` (two formulas),
    ``formulas`` (a list of formulas), ``bool``, ``text``, ``label`` (the scene's name), ``name`` (a name declared elsewhere in
    the file), ``new name`` (a name this key declares), ``table`` and ``tables`` (a table, an
    array of tables), ``law``, ``number``, ``numbers`` (a pair of numbers), ``entry`` (read
    by the table's own rules). In a spatial file (``dimensions = 3``, see
    :mod:`contactsym.mechanism.files.spatial`) a ``pair`` is three formulas (x, y, z), a body's
    ``inertia`` is its tensor in its frame (three principal moments or six entries xx, yy, zz,
    xy, yz, zx), and a gap may be a table ``{point, normal, distance}``.
    """

    keys: MappingProxyType | None
    required: tuple[str, ...] = ()
    entries: str = "entry"

    @property
    def allowed(self) -> tuple[str, ...]:
        return tuple(self.keys or ())


def _table(required=(), **keys) -> TableSchema:
    return TableSchema(MappingProxyType(keys), tuple(required))


def _free(entries: str) -> TableSchema:
    return TableSchema(None, (), entries)


#: The schema of a scene file: every table (``""`` is the document), its keys and their kinds.
#:
#: >>> from contactsym.mechanism.files import SCHEMA
#: >>> SCHEMA[''].required
#: ('scene',)
SCHEMA = MappingProxyType(
    {
        "": _table(
            ("scene",),
            scene="table",
            parameters="table",
            intervals="table",
            functions="table",
            accelerations="table",
            energy="table",
            points="table",
            masses="tables",
            bodies="tables",
            loads="tables",
            contacts="tables",
            at="table",
            presentation="table",
            count_presentation="table",
            figures="table",
            frames="table",
            values="table",
        ),
        "scene": _table(
            ("coordinates",),
            name="label",
            description="text",
            coordinates="names",
            solve_for="formula",
            dimensions="number",
        ),
        "parameters": _free("entry"),
        "parameters.entry": _table((), assume="text", symbol="text", interval="pair"),
        "intervals": _free("pair"),
        "functions": _free("names"),
        "accelerations": _free("formula"),
        "energy": _table((), kinetic="formula", potential="formula"),
        "points": _free("entry"),
        "points.entry": _table((), position="pair", body="name", angle="formula", frame="name", offset="pair"),
        "masses": _table(("point", "mass"), point="name", mass="formula"),
        "bodies": _table(
            ("point", "mass", "inertia"), point="name", angle="formula", frame="name", mass="formula", inertia="formula"
        ),
        "loads": _table((), point="name", force="pair", angle="formula", frame="name", moment="formula"),
        "contacts": _table(
            ("gap", "reaction"), gap="formula", reaction="new name", unilateral="bool", law="law", friction="table"
        ),
        "contacts.gap": _table(("point", "normal"), point="name", normal="pair", distance="formula"),
        "contacts.friction": _table(("direction",), mu="formula", viscous="formula", point="name", direction="entry"),
        "at": _free("formula"),
        "presentation": _free("formula"),
        "count_presentation": _free("formula"),
        "figures": _table(
            ("x", "y", "x_range", "y_range"), x="name", y="name", x_range="numbers", y_range="numbers", values="table"
        ),
        "figures.values": _free("number"),
        "frames": _free("entry"),
        "frames.entry": _table(
            (),
            body_fixed="text",
            space_fixed="text",
            angles="formulas",
            euler_parameters="formulas",
            relative_to="name",
        ),
        "values": _free("formula"),
    }
)


@dataclass(frozen=True)
class Limits:
    """Caps on the size of a scene file, so that a file beyond them is refused in a moment.

    Pass ``limits=Limits(max_contacts=8)`` to :func:`~contactsym.mechanism.files.reader.load_scene`
    or :func:`~contactsym.mechanism.files.reader.read_scene` to read a larger scene, or raise caps
    for every read inside a block with :func:`file_limits`; on the command line,
    ``contactsym --limit max_contacts=8 ...`` (each field by its name). The formulas have their own
    caps, in :mod:`contactsym.parse` (``--limit max_degree=64`` raises one of those). A file cannot
    raise its own caps: they guard against the file.

    Examples
    --------
    >>> from contactsym.mechanism.files import SceneFileError, read_scene
    >>> text = ('[scene]\\ncoordinates = ["x", "y"]\\n[accelerations]\\nx = "N_1"\\ny = "N_2"\\n'
    ...         '[[contacts]]\\ngap = "x"\\nreaction = "N_1"\\n[[contacts]]\\ngap = "y"\\nreaction = "N_2"\\n')
    >>> read_scene(text, "two.toml").k
    2
    >>> try:
    ...     read_scene(text, "two.toml", limits=Limits(max_contacts=1))
    ... except SceneFileError as error:
    ...     print(str(error).split(";")[0])
    two.toml:1: 2 contacts, more than the cap of 1 (Limits.max_contacts)
    """

    #: Largest file, in bytes.
    max_bytes: int = 1_000_000
    #: Most generalized coordinates.
    max_coordinates: int = 12
    #: Most ``[[contacts]]``.
    max_contacts: int = 6
    #: Most ``[points]``.
    max_points: int = 64
    #: Most ``[[masses]]``, ``[[bodies]]`` and ``[[loads]]`` together.
    max_items: int = 64
    #: Most declared names (parameters, functions, intervals).
    max_names: int = 200

    def __post_init__(self):
        for cap in fields(self):
            value = getattr(self, cap.name)
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise SceneError(f"Limits({cap.name}={shorten(value)}): a cap is a whole number >= 1.")


#: The caps :func:`file_limits` put in force, or None for the defaults (or what the caller passes).
_IN_FORCE: ContextVar = ContextVar("contactsym_file_limits", default=None)


def file_limits(limits: Limits) -> AbstractContextManager[None]:
    """``limits`` in force for every scene file read inside the block that is not given its own
    (``load_scene(path)`` without ``limits=``): what ``contactsym --limit max_contacts=8`` does.

    Examples
    --------
    >>> from contactsym.mechanism.files import read_scene
    >>> text = ('[scene]\\ncoordinates = ["x", "y"]\\n[accelerations]\\nx = "N_1"\\ny = "N_2"\\n'
    ...         '[[contacts]]\\ngap = "x"\\nreaction = "N_1"\\n[[contacts]]\\ngap = "y"\\nreaction = "N_2"\\n')
    >>> with file_limits(Limits(max_contacts=1)):
    ...     try:
    ...         read_scene(text, "two.toml")
    ...     except SceneError as error:
    ...         print(str(error).split(";")[0])
    two.toml:1: 2 contacts, more than the cap of 1 (Limits.max_contacts)
    """
    if not isinstance(limits, Limits):
        raise SceneError(f"file_limits takes a contactsym.mechanism.files.Limits, not {shorten(limits)}.")
    return _in_force(limits)  # checked now, in force when the block is entered


@contextmanager
def _in_force(limits: Limits) -> Iterator[None]:
    token = _IN_FORCE.set(limits)
    try:
        yield
    finally:
        _IN_FORCE.reset(token)


def limits_in_force(limits: Limits) -> Limits:
    """``limits``, or those of an enclosing :func:`file_limits` where ``limits`` are the defaults."""
    raised = _IN_FORCE.get()
    return raised if raised is not None and limits == Limits() else limits


@dataclass(frozen=True)
class FigurePlan:
    """What a scene file asks to draw: region maps over (x, y) at fixed values.

    ``x``, ``y`` and the keys of ``values`` are the names the pipeline prints (``mu_+`` for a
    parameter ``mu_p = {symbol = "mu_+"}``, ``thetadot`` for a rate ``theta'``).

    Examples
    --------
    The ``[figures]`` table of a scene file, as read:

    >>> from contactsym.mechanism.files import read_spec
    >>> spec = read_spec('[scene]\\ncoordinates = ["y"]\\n[parameters]\\nm = "positive"\\nk = "positive"\\n'
    ...                  '[accelerations]\\ny = "N/m - k"\\n[[contacts]]\\ngap = "y"\\nreaction = "N"\\n'
    ...                  '[figures]\\nx = "m"\\ny = "k"\\nx_range = [0.5, 2]\\ny_range = [0, 1]\\n', "a.toml")
    >>> spec.figures
    FigurePlan(x='m', y='k', x_range=(0.5, 2.0), y_range=(0.0, 1.0), values={})
    """

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


@dataclass(frozen=True)
class ParameterSpec:
    """A declared parameter: its name in the file, its symbol, its assumption and interval."""

    name: str
    symbol: sp.Symbol
    assume: str  # positive, negative, nonnegative, real or sign
    interval: tuple[sp.Expr, sp.Expr] | None
    line: int


@dataclass(frozen=True)
class CoordinateSpec:
    """A generalized coordinate q(t), with its open interval from ``[intervals]`` if any."""

    name: str
    symbol: sp.Expr
    interval: tuple[sp.Expr, sp.Expr] | None = None


@dataclass(frozen=True)
class PointSpec:
    """A point of the plane at ``position``; with ``body``, the material point of a body turning with ``angle``."""

    name: str
    position: tuple[sp.Expr, sp.Expr]
    body: str | None
    angle: sp.Expr | None
    line: int


@dataclass(frozen=True)
class MassSpec:
    """A point mass at a declared point."""

    point: str
    mass: sp.Expr


@dataclass(frozen=True)
class BodySpec:
    """A rigid body with its centre at a declared point, turning with ``angle``."""

    point: str
    angle: sp.Expr
    mass: sp.Expr
    inertia: sp.Expr


@dataclass(frozen=True)
class LoadSpec:
    """A force ``(Fx, Fy)`` at a point, or a moment on the bodies turning with ``angle``."""

    point: str | None = None
    force: tuple[sp.Expr, sp.Expr] | None = None
    angle: sp.Expr | None = None
    moment: sp.Expr | None = None


@dataclass(frozen=True)
class LawSpec:
    """A compliance law by its name in :data:`~contactsym.mechanism.files.contacts.COMPLIANCE_LAWS`,
    with its formulas and flags."""

    name: str
    formulas: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))
    flags: MappingProxyType = field(default_factory=lambda: MappingProxyType({}))


@dataclass(frozen=True)
class FrictionSpec:
    """Coulomb (``mu``) or viscous friction; ``direction`` is a planar vector (with ``point``) for a
    Lagrangian, else ``((coordinate, coefficient), ...)``."""

    kind: str  # "coulomb" or "viscous"
    coefficient: sp.Expr
    direction: tuple
    point: str | None = None
    line: int = 1


@dataclass(frozen=True)
class ContactSpec:
    """One ``[[contacts]]`` table."""

    gap: sp.Expr
    reaction: sp.Symbol
    unilateral: bool
    law: LawSpec
    friction: FrictionSpec | None
    line: int  # of the law, where the law's own checks are reported


@checked
@dataclass(frozen=True)
class SceneSpec:
    """Everything a scene file says, read and checked; :func:`build_scene` makes the Scene of it.

    Examples
    --------
    >>> from contactsym.mechanism.files import read_spec
    >>> spec = read_spec('[scene]\\ncoordinates = ["y"]\\n[accelerations]\\ny = "N - 1"\\n'
    ...                  '[[contacts]]\\ngap = "y"\\nreaction = "N"\\n', "a.toml", "drop")
    >>> isinstance(spec, SceneSpec), spec.name, spec.source, spec.accelerations
    (True, 'drop', 'a.toml', (N - 1,))
    >>> [c.name for c in spec.coordinates], spec.contacts[0].law.name
    (['y'], 'generic')
    """

    source: str
    name: str
    description: str
    coordinates: tuple[CoordinateSpec, ...]
    parameters: tuple[ParameterSpec, ...]
    contacts: tuple[ContactSpec, ...]
    accelerations: tuple[sp.Expr, ...] | None = None  # None: the motion is a Lagrangian
    kinetic: sp.Expr = sp.S.Zero
    potential: sp.Expr = sp.S.Zero
    points: tuple[PointSpec, ...] = ()
    masses: tuple[MassSpec, ...] = ()
    bodies: tuple[BodySpec, ...] = ()
    loads: tuple[LoadSpec, ...] = ()
    at: tuple[tuple[sp.Expr, sp.Expr], ...] = ()
    presentation: tuple[tuple[sp.Expr, sp.Expr], ...] = ()
    count_presentation: tuple[tuple[sp.Expr, sp.Expr], ...] | None = None
    positive: tuple[sp.Expr, ...] = ()
    solve_for: sp.Symbol | None = None
    figures: FigurePlan | None = None
    eps: sp.Symbol = sp.Symbol("epsilon", positive=True)
    #: The frames, points, bodies and loads of a spatial file (``dimensions = 3``), else None.
    space: object = None
    #: ``[values]``: parameters fixed at numbers before the derivation (``Scene.with_values``).
    values: tuple[tuple[sp.Symbol, sp.Expr], ...] = ()

    @property
    def lagrangian(self) -> bool:
        """True when the motion is given by a Lagrangian (no ``[accelerations]``)."""
        return self.accelerations is None
