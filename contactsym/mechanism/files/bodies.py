"""Scene files, the mechanics: points, masses, bodies and loads in the plane.

:func:`read_points` and :func:`read_motion` read the tables into spec items
(:mod:`contactsym.mechanism.files.spec`); :class:`Plane` builds from those items what
``Scene.from_lagrangian`` needs (``sympy.physics.mechanics`` Points, frames, Particles,
RigidBodies), from positions written as (x(q), y(q)).
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, RigidBody, inertia

from ...algebra.basic import known_sign
from ..contact_space import t
from ..friction_geometry import vanishes
from .contacts import COMPLIANCE_LAWS  # noqa: F401  (0.1's path of the table of laws)
from .declarations import FormulaReader
from .space import printed
from .spec import BodySpec, LoadSpec, MassSpec, PointSpec, SceneSpec, removed_mixin
from .toml_source import SceneFileError

__all__ = ["Plane", "inertia_proved", "read_motion", "read_points", "turning_problem"]


def read_points(reader: FormulaReader, positive=()) -> tuple[PointSpec, ...]:
    """``[points]``: ``P = [x, y]`` or ``P = {position = [x, y], body = "C", angle = "theta"}``.

    A material point takes its velocity from the body turning counter-clockwise by ``angle`` about
    the point ``body``; its position must turn so too (:func:`turning_problem`, on the domain where
    the expressions ``positive`` are positive), or the file is refused with the fix.
    """
    points: dict[str, PointSpec] = {}
    for name, entry in reader.section("points").items():
        body = angle = None
        if isinstance(entry, dict):
            reader.checked(entry, "points", "points.entry")
            if "position" not in entry or {"frame", "offset"} & set(entry):
                reader.doc.fail(
                    "points",
                    name,
                    "a point of the plane is {position = [x, y], ...} (frame and offset: dimensions = 3)",
                )
            if "body" in entry:
                body = reader.reference(entry, "body", "points", list(points), "points declared above it")
            angle = reader.formula(entry["angle"], "points", name) if "angle" in entry else None
            if (body is None) != (angle is None):
                reader.doc.fail("points", name, "a material point needs both body = ... and angle = ...")
            entry = entry["position"]
        position = reader.pair(entry, "points", name)
        if body is not None:
            problem = turning_problem(name, position, points[body].position, angle, body, positive)
            if problem:
                reader.doc.fail("points", name, problem)
        points[name] = PointSpec(name, position, body, angle, reader.doc.line("points", name))
    return tuple(points.values())


def turning_problem(name: str, position, base, angle, body: str = "C", positive=()) -> str | None:
    """Why a point at ``position`` (x, y) does not move with the body turning counter-clockwise by
    ``angle`` about its point at ``base`` (and the fix), or None.

    The velocity a file gives the material point is that body's, v_C + angle' z x (P - C). A point
    fixed in the body moves so: d/dt (P - C) = angle' z x (P - C). A spot at a fixed offset from C
    (d/dt (P - C) = 0, as the brake's pads: the material point of the disc passing through it) is
    accepted too; any other offset is refused. Checked exactly where possible, otherwise at random
    points of the domain (:func:`contactsym.mechanism.friction_geometry.vanishes`).

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> x, theta = dynamicsymbols("x theta")
    >>> l = sp.Symbol("l", positive=True)
    >>> turning_problem("A", (x + l*sp.cos(theta), l*sp.sin(theta)), (x, 0), theta) is None
    True
    >>> print(turning_problem("A", (x + l*sp.cos(theta), -l*sp.sin(theta)), (x, 0), theta))
    ... # doctest: +ELLIPSIS
    the rate of the position of A is not the velocity of the body turning counter-clockwise by theta ...
    """
    offset = [sp.sympify(p) - b for p, b in zip(position, base)]

    def turns(rate) -> bool:
        turned = (-rate * offset[1], rate * offset[0])  # rate z x (P - C)
        return all(vanishes(sp.diff(o, t) - v, positive) for o, v in zip(offset, turned))

    rate = sp.diff(angle, t)
    if turns(rate) or turns(sp.S.Zero):  # fixed in the body, or a spot fixed relative to C
        return None
    plain = f"or give {name} as a plain position [x, y] (its velocity is then the rate of its position)"
    if rate != 0 and turns(-rate):
        fix = f'it turns clockwise as {printed(angle)} grows: write angle = "{printed(-angle)}", {plain}'
    else:
        fix = (
            f"its offset from {body} moves, but not as a point fixed in that body: give the angle the body "
            f"turns by, {plain}"
        )
    return (
        f"the rate of the position of {name} is not the velocity of the body turning counter-clockwise by "
        f"{printed(angle)} about {body} (angles in the plane count counter-clockwise); {fix}"
    )


def read_masses(reader: FormulaReader, known) -> list[MassSpec]:
    """``[[masses]]``: point masses at the named points (planar and spatial files alike)."""
    masses = []
    for index, entry in enumerate(reader.section("masses", kind=list)):
        where = f"masses.{index}"
        reader.checked(entry, where, "masses")
        point = reader.reference(entry, "point", where, known, "[points]")
        masses.append(MassSpec(point, reader.formula(entry["mass"], where, "mass")))
    return masses


def read_motion(reader: FormulaReader, points: tuple[PointSpec, ...]) -> dict:
    """``[[masses]]``, ``[[bodies]]``, ``[energy]`` and ``[[loads]]``: the SceneSpec fields of a Lagrangian."""
    known = [p.name for p in points]
    masses, bodies, loads = read_masses(reader, known), [], []
    for index, entry in enumerate(reader.section("bodies", kind=list)):
        where = f"bodies.{index}"
        reader.checked(entry, where, "bodies")
        if "angle" not in entry or "frame" in entry:
            reader.doc.fail(where, None, "a body in the plane needs angle = ... (frame = ... is for dimensions = 3)")
        angle = reader.formula(entry["angle"], where, "angle")
        point = reader.reference(entry, "point", where, known, "[points]")
        mass, moment = (reader.formula(entry[k], where, k) for k in ("mass", "inertia"))
        bodies.append(BodySpec(point, angle, mass, moment))
    energy = reader.checked(reader.section("energy"), "energy", "energy")
    kinetic, potential = (reader.formula(energy.get(k, 0), "energy", k) for k in ("kinetic", "potential"))
    for index, entry in enumerate(reader.section("loads", kind=list)):
        where = f"loads.{index}"
        reader.checked(entry, where, "loads")
        if set(entry) == {"point", "force"}:
            point = reader.reference(entry, "point", where, known, "[points]")
            loads.append(LoadSpec(point=point, force=reader.pair(entry["force"], where, "force")))
        elif set(entry) == {"angle", "moment"}:
            angle, moment = (reader.formula(entry[k], where, k) for k in ("angle", "moment"))
            loads.append(LoadSpec(angle=angle, moment=moment))
        else:
            reader.doc.fail(where, None, "a load is point = ... with force = [Fx, Fy], or angle = ... with moment")
    return dict(masses=tuple(masses), bodies=tuple(bodies), loads=tuple(loads), kinetic=kinetic, potential=potential)


class Plane:
    """The inertial frame O, the points of a spec and the frames of the angles they turn with.

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> x, theta = dynamicsymbols("x theta")
    >>> plane = Plane((PointSpec("C", (x, sp.S.Zero), None, None, 1),
    ...                PointSpec("P", (x, sp.S.One), "C", theta, 2)))
    >>> plane.points["P"].vel(plane.frame)
    (-Derivative(theta(t), t) + Derivative(x(t), t))*O.x
    """

    def __init__(self, points: tuple[PointSpec, ...]):
        self.frame, self.origin = ReferenceFrame("O"), Point("O")
        self.origin.set_vel(self.frame, 0)
        self.points: dict[str, Point] = {}
        self.frames: dict = {}
        for spec in points:
            px, py = spec.position
            if spec.body is None:
                point = self.origin.locatenew(spec.name, px * self.frame.x + py * self.frame.y)
                point.set_vel(self.frame, point.pos_from(self.origin).dt(self.frame))
            else:
                base = self.points[spec.body]
                offset = self.origin.locatenew(spec.name, px * self.frame.x + py * self.frame.y).pos_from(base)
                point = base.locatenew(spec.name, offset)
                point.v2pt_theory(base, self.frame, self.turning(spec.angle))
            self.points[spec.name] = point

    def turning(self, angle: sp.Expr) -> ReferenceFrame:
        """The frame turning with ``angle`` about the z axis (one per distinct angle, B1, B2, ...)."""
        if angle not in self.frames:
            self.frames[angle] = self.frame.orientnew(f"B{len(self.frames) + 1}", "Axis", [angle, self.frame.z])
        return self.frames[angle]

    def vector(self, pair) -> object:
        return pair[0] * self.frame.x + pair[1] * self.frame.y

    def lagrangian(self, spec: SceneSpec) -> tuple:
        """The Lagrangian of the spec's masses, bodies and energy, and its loads as (Point or frame, Vector)."""
        items = [Particle(f"m{i}", self.points[m.point], m.mass) for i, m in enumerate(spec.masses)]
        for index, body in enumerate(spec.bodies):
            frame, point = self.turning(body.angle), self.points[body.point]
            central = (inertia(frame, 0, 0, body.inertia), point)
            items.append(RigidBody(f"body{index}", point, frame, body.mass, central))
        L = Lagrangian(self.frame, *items) if items else sp.S.Zero
        L += spec.kinetic
        L -= spec.potential
        if L == 0:
            raise SceneFileError(
                f"{spec.source}:1: no motion: give [accelerations], or [energy] kinetic = ..., [[masses]], [[bodies]]."
            )
        loads = []
        for load in spec.loads:
            if load.point is not None:
                loads.append((self.points[load.point], self.vector(load.force)))
            else:
                loads.append((self.turning(load.angle), load.moment * self.frame.z))
        return L, loads


def inertia_proved(spec: SceneSpec) -> bool:
    """True when the spec's mass matrix is positive definite for every admissible value, by its structure.

    Proof. The kinetic energy is ``T = sum_p m_p |v_p|^2 / 2 + sum_b (m_b |v_b|^2 + I_b theta_b'^2) / 2``
    (no ``[energy] kinetic`` term added). With every mass proved >= 0 and every body's inertia
    proved > 0 from the declarations, ``T >= sum_b I_b theta_b'^2 / 2``; when every coordinate
    q_j is the angle theta_b of some body, this is > 0 for every q' != 0, so ``q'^T M q' = 2T > 0``.
    False means only "not proved this way" (:func:`contactsym.mechanism.admissibility.check_inertia`
    then decides).

    Examples
    --------
    >>> from contactsym.mechanism.files import read_spec
    >>> rod = ('[scene]\\ncoordinates = ["q"]\\n[parameters]\\nm = "positive"\\nl = "positive"\\n'
    ...        '[points]\\nC = ["l*sin(q)/2", "-l*cos(q)/2"]\\n'
    ...        '[[bodies]]\\npoint = "C"\\nangle = "q"\\nmass = "m"\\ninertia = "m*l^2/12"\\n'
    ...        '[[contacts]]\\ngap = "l*cos(q)"\\nreaction = "N"\\n')
    >>> inertia_proved(read_spec(rod, "rod.toml"))
    True
    >>> inertia_proved(read_spec(rod.replace('inertia = "m*l^2/12"', 'inertia = "l - m"'), "rod.toml"))
    False
    """
    if spec.kinetic != 0 or not spec.bodies:
        return False
    positive = spec.positive
    masses = [m.mass for m in spec.masses] + [b.mass for b in spec.bodies]
    if any(m != 0 and known_sign(m, positive) != 1 for m in masses):
        return False
    turning = {b.angle for b in spec.bodies if known_sign(b.inertia, positive) == 1}
    return all(c.symbol in turning for c in spec.coordinates)


#: 0.1's mixin of the reader (removed: see :class:`Plane`).
PlaneMixin = removed_mixin("PlaneMixin")
