"""Scene files in space, the mechanics: the spec items of a spatial file (:class:`SpatialSpec`), built
as ``sympy.physics.mechanics`` objects, and the checks that need them.

:class:`Space` builds what ``Scene.from_lagrangian`` needs (``ReferenceFrame.orient_body_fixed``,
``orient_space_fixed``, ``orient_quaternion``; Points with ``v2pt_theory``; Particles and
RigidBodies). :func:`check_orientations` refuses a rotation sequence in gimbal lock at the file's
configuration; the inertia tensors are checked to be positive definite as they are built.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from ...algebra.canonical_form import TrigField
from ...algebra.reductions import known_sign
from .spec import MassSpec
from .toml_source import SceneFileError

__all__ = [
    "FrameSpec",
    "Space",
    "SpaceBodySpec",
    "SpaceLoadSpec",
    "SpacePointSpec",
    "SpatialSpec",
    "check_orientations",
    "is_identity",
    "printed",
    "singular_set",
]


@dataclass(frozen=True)
class FrameSpec:
    """A body frame: its parent (None: the inertial frame O) and its orientation.

    ``kind`` is ``body_fixed``, ``space_fixed`` (``sequence`` such as ``"zyx"``, three
    ``angles``) or ``euler_parameters`` (four ``angles``: a unit quaternion).

    Examples
    --------
    >>> FrameSpec("rod", None, "body_fixed", "zyx", dynamicsymbols("psi theta phi"), 3).angles
    [psi(t), theta(t), phi(t)]
    """

    name: str
    parent: str | None
    kind: str
    sequence: str
    angles: tuple
    line: int


@dataclass(frozen=True)
class SpacePointSpec:
    """A point at ``position`` in O, or fixed in ``frame`` at ``offset`` (in that frame) from point ``base``.

    Examples
    --------
    >>> SpacePointSpec("A", None, "C", "rod", (1, 0, 0), 7).frame
    'rod'
    """

    name: str
    position: tuple | None
    base: str | None
    frame: str | None
    offset: tuple | None
    line: int


@dataclass(frozen=True)
class SpaceBodySpec:
    """A rigid body at a point, turning with a frame; ``inertia`` = (xx, yy, zz, xy, yz, zx) in that frame.

    Examples
    --------
    >>> SpaceBodySpec("C", "rod", 1, (1, 2, 2, 0, 0, 0), 9).inertia[:3]
    (1, 2, 2)
    """

    point: str
    frame: str
    mass: sp.Expr
    inertia: tuple
    line: int


@dataclass(frozen=True)
class SpaceLoadSpec:
    """A force (components in O) at a point, or a moment (in O) on the body of a frame.

    Examples
    --------
    >>> SpaceLoadSpec(frame="rod", moment=(0, 0, 1)).point is None
    True
    """

    point: str | None = None
    force: tuple | None = None
    frame: str | None = None
    moment: tuple | None = None


@dataclass(frozen=True)
class SpatialSpec:
    """The mechanics of a spatial scene file, as read (:func:`contactsym.mechanism.files.spatial.read_space`).

    Examples
    --------
    >>> SpatialSpec((), (), (), (), ()).frames
    ()
    """

    frames: tuple[FrameSpec, ...]
    points: tuple[SpacePointSpec, ...]
    masses: tuple[MassSpec, ...]
    bodies: tuple[SpaceBodySpec, ...]
    loads: tuple[SpaceLoadSpec, ...]


def is_identity(expr: sp.Expr, value) -> bool:
    """``expr == value`` identically, modulo sin^2 + cos^2 = 1 of every angle (exact).

    Examples
    --------
    >>> b = sp.Symbol("beta", real=True)
    >>> is_identity(sp.cos(b)**2 + sp.sin(b)**2, 1), is_identity(sp.cos(b/2)**2 + sp.sin(b/2)**2, 1)
    (True, True)
    >>> is_identity(sp.cos(b), 0)
    False
    """
    difference = sp.sympify(expr) - value
    field = TrigField([difference])
    if not field.element(difference):
        return True
    # half angles and other compound arguments: trigsimp, on the few terms of a norm or a dot product
    return sp.count_ops(difference) <= 200 and sp.trigsimp(sp.expand(difference)) == 0


@lru_cache(maxsize=32)
def singular_set(kind: str, sequence: str) -> sp.Expr:
    """The factor that vanishes where the rotation sequence ``sequence`` is in gimbal lock,
    in its angles ``a1, a2, a3`` (Dummy-free symbols): det of the map from the angles' rates to
    the angular velocity, e.g. ``cos(a2)`` for ``zyx`` and ``sin(a2)`` for ``zxz``.

    Examples
    --------
    >>> singular_set("body_fixed", "zyx"), singular_set("body_fixed", "zxz")
    (cos(a2), sin(a2))
    """
    angles = dynamicsymbols("a1:4")
    parent, frame = ReferenceFrame("P"), ReferenceFrame("F")
    getattr(frame, f"orient_{kind}")(parent, angles, sequence)
    omega = frame.ang_vel_in(parent)
    rates = [a.diff() for a in angles]
    E = sp.Matrix([[sp.diff(omega.dot(axis), r) for r in rates] for axis in (frame.x, frame.y, frame.z)])
    determinant = sp.trigsimp(E.det())  # 3 x 3 of sines and cosines of the three angles
    plain = dict(zip(angles, sp.symbols("a1:4", real=True)))
    factors = [f for f in sp.Mul.make_args(sp.factor(determinant.xreplace(plain))) if not f.is_number]
    return sp.Mul(*factors)


def check_orientations(reader, spec: SpatialSpec, coordinates, at: dict) -> None:
    """Refuse a rotation sequence that is singular (gimbal lock) everywhere, at the ``[at]``
    configuration, or somewhere in the ``[intervals]`` of its angles.

    Examples
    --------
    >>> from contactsym.mechanism.files import read_spec
    >>> text = ('[scene]\\ncoordinates = ["z", "a"]\\ndimensions = 3\\n[frames]\\n'
    ...         'F = {body_fixed = "zyx", angles = ["0", "a", "0"]}\\n[points]\\nC = ["0", "0", "z"]\\n'
    ...         '[[bodies]]\\npoint = "C"\\nframe = "F"\\nmass = "1"\\ninertia = ["1", "1", "1"]\\n'
    ...         '[[contacts]]\\ngap = "z"\\nreaction = "N"\\n[at]\\na = "pi/2"\\n')
    >>> try:
    ...     read_spec(text, "a.toml")
    ... except SceneFileError as error:
    ...     print(str(error).split(";")[0])
    a.toml:5: the rotation zyx of frame 'F' (angles 0, a, 0) is in gimbal lock at the configuration [at] (cos(a) = 0)
    """
    for frame in spec.frames:
        if frame.kind == "euler_parameters":
            if not is_identity(sum(e**2 for e in frame.angles), 1):
                reader.doc.fail(
                    "frames",
                    frame.name,
                    f"the Euler parameters {list(frame.angles)} do not have "
                    "e0^2 + e1^2 + e2^2 + e3^2 = 1; give a unit quaternion",
                )
            continue
        generic = singular_set(frame.kind, frame.sequence)
        factor = generic.xreplace(dict(zip(sp.symbols("a1:4", real=True), frame.angles)))
        named = ", ".join(map(str, printed(frame.angles)))
        where = f"the rotation {frame.sequence} of frame '{frame.name}' (angles {named}) is in gimbal lock"
        fix = "choose another sequence (e.g. zxz for a body near level, zyx for one near upright) or other angles"
        if is_identity(factor, 0):
            reader.doc.fail(
                "frames",
                frame.name,
                f"{where} for every configuration ({generic} = 0 at (a1, a2, a3) = ({named})); {fix}",
            )
        fixed = factor.xreplace(at)
        if at and is_identity(fixed, 0):
            reader.doc.fail("frames", frame.name, f"{where} at the configuration [at] ({printed(factor)} = 0); {fix}")
        for coordinate in coordinates:
            if coordinate.interval is None or not fixed.has(coordinate.symbol):
                continue
            low, high = coordinate.interval
            plain = sp.Symbol(coordinate.name, real=True)
            local = fixed.xreplace({coordinate.symbol: plain})
            if local.free_symbols != {plain}:
                continue
            zeros = sp.solveset(local, plain, sp.Interval.open(low, high))
            if zeros != sp.S.EmptySet:
                reader.doc.fail(
                    "frames",
                    frame.name,
                    f"{where} where {printed(factor)} = 0, at {coordinate.name} in "
                    f"{printed(zeros)}, inside the interval ({low}, {high}) of {coordinate.name}; {fix}, or narrow "
                    "the interval",
                )


def printed(expr):
    """Coordinates q(t) shown as q in a message.

    Examples
    --------
    >>> printed(sp.cos(dynamicsymbols("theta")))
    cos(theta)
    """
    if isinstance(expr, tuple):
        return tuple(printed(e) for e in expr)
    functions = {f: sp.Symbol(f.func.__name__) for f in sp.sympify(expr).atoms(sp.core.function.AppliedUndef)}
    return sp.sympify(expr).xreplace(functions)


def _positive_definite(tensor: sp.Matrix) -> bool | None:
    """Sylvester's criterion, three-valued: False when a leading minor is proved <= 0."""
    answers = []
    for size in (1, 2, 3):
        minor = sp.expand(tensor[:size, :size].det())
        sign = 0 if minor == 0 else known_sign(minor)
        if sign is not None and sign <= 0:
            return False
        answers.append(sign == 1)
    return True if all(answers) else None


class Space:
    """The inertial frame O, the frames and points of a spatial spec, its bodies and loads.

    ``reader`` (a :class:`~contactsym.mechanism.files.declarations.FormulaReader`) places the
    refusal of an inertia tensor that is not positive definite at its line of the file.

    Examples
    --------
    >>> x, th = dynamicsymbols("x theta")
    >>> frames = (FrameSpec("B", None, "body_fixed", "zyx", (0, th, 0), 1),)
    >>> points = (SpacePointSpec("G", (x, 0, 0), None, None, None, 2),
    ...           SpacePointSpec("A", None, "G", "B", (1, 0, 0), 3))
    >>> space = Space(SpatialSpec(frames, points, (), (), ()))
    >>> space.height("A", (0, 0, 1))
    -sin(theta(t))
    """

    def __init__(self, spec: SpatialSpec, reader=None):
        self.spec = spec
        self.frame, self.origin = ReferenceFrame("O"), Point("O")
        self.origin.set_vel(self.frame, 0)
        self.frames: dict[str, ReferenceFrame] = {}
        for item in spec.frames:
            frame = ReferenceFrame(item.name)
            parent = self.frame if item.parent is None else self.frames[item.parent]
            if item.kind == "euler_parameters":
                frame.orient_quaternion(parent, item.angles)
            else:
                getattr(frame, f"orient_{item.kind}")(parent, item.angles, item.sequence)
            self.frames[item.name] = frame
        self.points: dict[str, Point] = {}
        for item in spec.points:
            if item.position is not None:
                point = self.origin.locatenew(item.name, self.vector(item.position))
                point.set_vel(self.frame, point.pos_from(self.origin).dt(self.frame))
            else:
                base, frame = self.points[item.base], self.frames[item.frame]
                point = base.locatenew(item.name, sum((c * a for c, a in zip(item.offset, _axes(frame))), sp.S.Zero))
                point.v2pt_theory(base, self.frame, frame)
            self.points[item.name] = point
        for body in spec.bodies:
            tensor = _tensor(body.inertia)
            if _positive_definite(tensor) is False and reader is not None:
                where = f"bodies.{spec.bodies.index(body)}"
                reader.doc.fail(
                    where,
                    "inertia",
                    f"the inertia tensor {tensor.tolist()} is not positive definite "
                    "(a leading minor is <= 0); every body needs positive principal moments",
                )

    def vector(self, components) -> object:
        """The Vector with these components in O."""
        return sum((c * a for c, a in zip(components, _axes(self.frame))), sp.S.Zero * self.frame.x)

    def height(self, point: str, normal) -> sp.Expr:
        """n . r of a point (its position from the origin of O)."""
        return sp.expand(self.points[point].pos_from(self.origin).dot(self.vector(normal)))

    def lagrangian(self, spec) -> tuple:
        """The Lagrangian of the masses, bodies and energy of a SceneSpec, and its loads."""
        space = self.spec
        items = [Particle(f"m{i}", self.points[m.point], m.mass) for i, m in enumerate(space.masses)]
        for index, body in enumerate(space.bodies):
            frame, point = self.frames[body.frame], self.points[body.point]
            central = (inertia(frame, *body.inertia), point)
            items.append(RigidBody(f"body{index}", point, frame, body.mass, central))
        L = (Lagrangian(self.frame, *items) if items else sp.S.Zero) + spec.kinetic - spec.potential
        if L == 0:
            raise SceneFileError(f"{spec.source}:1: no motion: give [[masses]], [[bodies]] or [energy] kinetic = ....")
        loads = []
        for load in space.loads:
            if load.point is not None:
                loads.append((self.points[load.point], self.vector(load.force)))
            else:
                loads.append((self.frames[load.frame], self.vector(load.moment)))
        return L, loads


def _axes(frame: ReferenceFrame) -> tuple:
    return frame.x, frame.y, frame.z


def _tensor(entries) -> sp.Matrix:
    xx, yy, zz, xy, yz, zx = entries
    return sp.Matrix([[xx, xy, zx], [xy, yy, yz], [zx, yz, zz]])
