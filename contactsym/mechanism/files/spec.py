"""Scene files as data: the typed, frozen record of what a file says (:class:`SceneSpec` and its items).

The schema a file is read by and the caps on its size are in :mod:`contactsym.mechanism.files.schema`
(their names are imported here too).

Reading a file has two steps. :func:`contactsym.mechanism.files.reader.read_spec` checks the
TOML against :data:`SCHEMA`, resolves every name and parses every formula into a
:class:`SceneSpec`; :func:`contactsym.mechanism.files.reader.build_scene` then builds the
mechanics (``sympy.physics.mechanics`` points and bodies, contacts, laws) and the Scene from
the spec alone. Every spec item keeps the line it was read from, for messages.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from types import MappingProxyType

import sympy as sp

from ...arguments import checked
from ...errors import SceneError
from ...validate import checked_fields, shorten
from .schema import SCHEMA, Limits, TableSchema, file_limits, limits_in_force

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
    gap_line: int = 0  # of the gap, where a gap that is not the distance is reported (0: the law's line)


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
