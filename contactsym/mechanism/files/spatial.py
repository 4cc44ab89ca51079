r"""Scene files in space (``dimensions = 3`` in ``[scene]``): frames, points, bodies, loads and contacts in 3-D.

The tables of a spatial file, read here into a :class:`SpatialSpec` (built into
``sympy.physics.mechanics`` objects by :class:`contactsym.mechanism.files.space.Space`):

``[frames]``
    One entry per body frame, oriented relative to the inertial frame O (or to the frame
    named by ``relative_to``): ``rod = {body_fixed = "zyx", angles = ["psi", "theta", "phi"]}``
    (successive turns about the frame's own axes, ``ReferenceFrame.orient_body_fixed``),
    ``space_fixed = "zyx"`` (about the parent's axes) or ``euler_parameters = ["e0", "e1",
    "e2", "e3"]`` (a unit quaternion). Angles are formulas in the coordinates and parameters.
``[points]``
    ``G = ["x", "y", "z"]`` (a position in O), or ``A = {body = "G", frame = "rod", offset
    = ["l", "0", "0"]}``: the material point of the body with frame ``rod`` at ``offset``
    (components in that frame) from its point G.
``[[masses]]``, ``[[bodies]]``
    ``point`` and ``mass``; a body also has ``frame`` and ``inertia``, its inertia tensor
    about its point in its frame: three principal moments ``["I1", "I2", "I3"]`` or six
    entries ``[Ixx, Iyy, Izz, Ixy, Iyz, Izx]``.
``[[loads]]``
    ``point`` and ``force = [Fx, Fy, Fz]``, or ``frame`` and ``moment = [Mx, My, Mz]`` (a
    torque on that frame's body); components in O.
``[[contacts]]``
    ``gap = {point = "A", normal = ["0", "0", "1"], distance = "0"}``: the height of A above
    the fixed plane n . r = distance (n a unit vector), or a gap formula in the coordinates
    (a frictionless contact). ``friction = {mu = "mu", direction = ["cos(beta)",
    "sin(beta)", "0"]}``: the unit sliding direction in the tangent plane, in the coordinates
    and parameters (frozen in the fast time, as the theory needs).

Refused, with the fix: a rotation sequence in gimbal lock at the file's configuration
(``[at]``, ``[intervals]``), an inertia tensor that is not positive definite, a normal or a
direction that is not a unit vector, a friction direction not tangent to its contact.
"""

from __future__ import annotations

import sympy as sp

from ..friction_geometry import unit_vector_problem
from .bodies import read_masses
from .contacts import _law
from .declarations import _NAME, FormulaReader
from .space import FrameSpec, Space, SpaceBodySpec, SpaceLoadSpec, SpacePointSpec, SpatialSpec, is_identity, printed
from .spec import ContactSpec, FrictionSpec
from .toml_source import shown

__all__ = ["read_space"]

_SEQUENCES = ("body_fixed", "space_fixed")


def _vector(reader: FormulaReader, value, where: str, key: str) -> tuple:
    if not isinstance(value, list) or len(value) != 3:
        reader.doc.fail(where, key, f'\'{key}\' must be three formulas [x, y, z], e.g. ["0", "0", "1"]')
    return tuple(reader.formula(v, where, key) for v in value)


def _formulas(reader: FormulaReader, value, where: str, key: str, count: int) -> tuple:
    if not isinstance(value, list) or len(value) != count:
        reader.doc.fail(where, key, f"'{key}' must be a list of {count} formulas")
    return tuple(reader.formula(v, where, key) for v in value)


def _frames(reader: FormulaReader) -> tuple[FrameSpec, ...]:
    frames: dict[str, FrameSpec] = {}
    for name, entry in reader.section("frames").items():
        reader.checked(entry, "frames", "frames.entry")
        if not _NAME.match(name):
            reader.doc.fail("frames", name, f"{shown(name)} is not a name; use letters, digits and _")
        parent = None
        if "relative_to" in entry:
            parent = reader.reference(entry, "relative_to", "frames", list(frames), "frames declared above it")
        given = [k for k in (*_SEQUENCES, "euler_parameters") if k in entry]
        if len(given) != 1:
            reader.doc.fail(
                "frames",
                name,
                'give the orientation as body_fixed = "zyx" (or space_fixed) with angles = [...], '
                "or as euler_parameters = [e0, e1, e2, e3]",
            )
        kind = given[0]
        if kind == "euler_parameters":
            angles, sequence = _formulas(reader, entry[kind], "frames", name, 4), ""
            if "angles" in entry:
                reader.doc.fail("frames", name, "euler_parameters take no angles")
        else:
            sequence = entry[kind]
            if not isinstance(sequence, str) or len(sequence) != 3 or set(sequence.lower()) - set("xyz"):
                reader.doc.fail("frames", name, f'{kind} = {shown(sequence)} must be three axes, e.g. "zyx" or "zxz"')
            if any(a == b for a, b in zip(sequence.lower(), sequence.lower()[1:])):
                reader.doc.fail("frames", name, f"{kind} = {shown(sequence)} turns twice in a row about one axis")
            if "angles" not in entry:
                reader.doc.fail("frames", name, f"{kind} needs angles = [three formulas]")
            angles = _formulas(reader, entry["angles"], "frames", name, 3)
        frames[name] = FrameSpec(name, parent, kind, sequence.lower(), angles, reader.doc.line("frames", name))
    return tuple(frames.values())


def _points(reader: FormulaReader, frames) -> tuple[SpacePointSpec, ...]:
    points: dict[str, SpacePointSpec] = {}
    for name, entry in reader.section("points").items():
        line = reader.doc.line("points", name)
        if not isinstance(entry, dict):
            points[name] = SpacePointSpec(name, _vector(reader, entry, "points", name), None, None, None, line)
            continue
        reader.checked(entry, "points", "points.entry")
        if set(entry) == {"position"}:
            position = _vector(reader, entry["position"], "points", name)
            points[name] = SpacePointSpec(name, position, None, None, None, line)
            continue
        if set(entry) != {"body", "frame", "offset"}:
            reader.doc.fail(
                "points",
                name,
                'a point in space is [x, y, z], or {body = "G", frame = "F", offset = [a, b, c]} '
                "(fixed in the body of frame F, at the offset from its point G)",
            )
        base = reader.reference(entry, "body", "points", list(points), "points declared above it")
        frame = reader.reference(entry, "frame", "points", frames, "[frames]")
        offset = _vector(reader, entry["offset"], "points", name)
        points[name] = SpacePointSpec(name, None, base, frame, offset, line)
    return tuple(points.values())


def _motion(reader: FormulaReader, points, frames) -> dict:
    masses, bodies, loads = read_masses(reader, points), [], []
    for index, entry in enumerate(reader.section("bodies", kind=list)):
        where = f"bodies.{index}"
        reader.checked(entry, where, "bodies")
        if "angle" in entry or "frame" not in entry:
            reader.doc.fail(where, None, 'a body in space turns with a frame: frame = "F" (of [frames]), no angle')
        point = reader.reference(entry, "point", where, points, "[points]")
        frame = reader.reference(entry, "frame", where, frames, "[frames]")
        value = entry["inertia"]
        if not isinstance(value, list) or len(value) not in (3, 6):
            reader.doc.fail(
                where,
                "inertia",
                "inertia must be three principal moments [I1, I2, I3] or six entries "
                "[Ixx, Iyy, Izz, Ixy, Iyz, Izx] (in the body's frame, about its point)",
            )
        tensor = _formulas(reader, value, where, "inertia", len(value))
        tensor = tensor + (sp.S.Zero,) * 3 if len(tensor) == 3 else tensor
        mass = reader.formula(entry["mass"], where, "mass")
        bodies.append(SpaceBodySpec(point, frame, mass, tensor, reader.doc.line(where, "inertia")))
    energy = reader.checked(reader.section("energy"), "energy", "energy")
    kinetic, potential = (reader.formula(energy.get(k, 0), "energy", k) for k in ("kinetic", "potential"))
    for index, entry in enumerate(reader.section("loads", kind=list)):
        where = f"loads.{index}"
        reader.checked(entry, where, "loads")
        if set(entry) == {"point", "force"}:
            point = reader.reference(entry, "point", where, points, "[points]")
            loads.append(SpaceLoadSpec(point=point, force=_vector(reader, entry["force"], where, "force")))
        elif set(entry) == {"frame", "moment"}:
            frame = reader.reference(entry, "frame", where, frames, "[frames]")
            loads.append(SpaceLoadSpec(frame=frame, moment=_vector(reader, entry["moment"], where, "moment")))
        else:
            reader.doc.fail(
                where,
                None,
                "a load in space is point = ... with force = [Fx, Fy, Fz], or frame = ... with moment = [Mx, My, Mz]",
            )
    return dict(masses=tuple(masses), bodies=tuple(bodies), loads=tuple(loads), kinetic=kinetic, potential=potential)


def _shown(vector) -> str:
    """A vector as a message shows it: coordinates q(t) as q."""
    return "[" + ", ".join(str(printed(v)) for v in vector) + "]"


def _rates(reader: FormulaReader) -> list:
    return [reader.names[n] for n, kind in reader.kinds.items() if kind == "rate"]


def _contacts(reader: FormulaReader, space, coordinates, eps) -> tuple[ContactSpec, ...]:
    symbols = [c.symbol for c in coordinates]
    contacts = []
    for index, entry in enumerate(reader.section("contacts", required=True, kind=list)):
        where = f"contacts.{index}"
        reader.checked(entry, where, "contacts")
        point = normal = None
        if isinstance(entry["gap"], dict):
            table = reader.checked(entry["gap"], f"{where}.gap", "contacts.gap")
            point = reader.reference(table, "point", where, list(space.points), "[points]")
            normal = _vector(reader, table["normal"], where, "gap")
            distance = reader.formula(table.get("distance", 0), where, "gap")
            if any(e.has(*symbols, *_rates(reader)) for e in (*normal, distance)):
                reader.doc.fail(
                    where,
                    "gap",
                    "the plane of a contact is fixed: its normal and distance are "
                    "formulas in the parameters, not the coordinates",
                )
            problem = unit_vector_problem(normal, what="the normal")
            if problem:
                reader.doc.fail(where, "gap", problem)
            gap = space.height(point, normal) - distance
        else:
            gap = reader.formula(entry["gap"], where, "gap")
        if not gap.has(*symbols):
            reader.doc.fail(where, "gap", f"the gap {gap} does not depend on the coordinates; write it in them")
        name = entry["reaction"]
        reader.declare(
            name, sp.Symbol(name, real=True) if isinstance(name, str) else None, "reaction", where, "reaction"
        )
        unilateral = entry.get("unilateral", False)
        if not isinstance(unilateral, bool):
            reader.doc.fail(where, "unilateral", "unilateral must be true or false")
        friction = None
        if "friction" in entry:
            friction = _friction(reader, entry["friction"], where, point, normal)
        law = _law(reader, entry.get("law", "generic"), where, eps)
        contacts.append(ContactSpec(gap, reader.names[name], unilateral, law, friction, reader.doc.line(where, "law")))
    if not contacts:
        reader.doc.fail("", None, "no [[contacts]]; add one with gap = ... and reaction = ...")
    return tuple(contacts)


def _friction(reader: FormulaReader, entry, where: str, point, normal) -> FrictionSpec:
    if not isinstance(entry, dict):
        reader.doc.fail(where, "friction", "friction must be a table {mu = ..., direction = [dx, dy, dz]}")
    reader.checked(entry, f"{where}.friction", "contacts.friction")
    if ("mu" in entry) == ("viscous" in entry):
        reader.doc.fail(where, "friction", "give friction either mu = ... (Coulomb) or viscous = ... (viscous)")
    if point is None:
        reader.doc.fail(
            where,
            "gap",
            "friction in space acts in the tangent plane of the contact: give the gap as "
            '{point = "A", normal = [nx, ny, nz]}',
        )
    if entry.get("point", point) != point:
        reader.doc.fail(where, "friction", f"friction acts at the contact's point {point}, not {shown(entry['point'])}")
    kind, key = ("coulomb", "mu") if "mu" in entry else ("viscous", "viscous")
    coefficient = reader.formula(entry[key], where, "friction")
    direction = _vector(reader, entry["direction"], where, "friction")
    if any(d.has(*_rates(reader)) for d in direction):
        reader.doc.fail(
            where,
            "friction",
            "the sliding direction is frozen in the fast time: write it in the "
            "coordinates and parameters (e.g. an angle parameter), not the rates",
        )
    problem = unit_vector_problem(direction, what="the friction direction")
    if problem:
        reader.doc.fail(where, "friction", problem)
    if not is_identity(sum(d * n for d, n in zip(direction, normal)), 0):
        reader.doc.fail(
            where,
            "friction",
            f"the friction direction {_shown(direction)} is not tangent to the contact: its dot product "
            f"with the normal {_shown(normal)} is not zero; give a direction in the tangent plane",
        )
    return FrictionSpec(kind, coefficient, direction, point, reader.doc.line(where, "friction"))


def read_space(reader: FormulaReader, coordinates, eps) -> tuple[SpatialSpec, tuple, dict]:
    """The frames, points, bodies, loads and contacts of a spatial file: (SpatialSpec, contacts, energy).

    ``energy`` holds the ``[energy]`` formulas (``kinetic``, ``potential``).

    Examples
    --------
    >>> from contactsym.mechanism.files import read_spec
    >>> text = ('[scene]\\ncoordinates = ["z"]\\ndimensions = 3\\n[points]\\nC = ["0", "0", "z"]\\n'
    ...         '[[masses]]\\npoint = "C"\\nmass = "1"\\n'
    ...         '[[contacts]]\\ngap = {point = "C", normal = ["0", "0", "1"]}\\nreaction = "N"\\n')
    >>> spec = read_spec(text, "a.toml")
    >>> spec.contacts[0].gap, [p.name for p in spec.space.points]
    (z(t), ['C'])
    """
    frames = _frames(reader)
    names = [f.name for f in frames]
    points = _points(reader, names)
    motion = _motion(reader, [p.name for p in points], names)
    spec = SpatialSpec(frames, points, motion["masses"], motion["bodies"], motion["loads"])
    space = Space(spec, reader)
    contacts = _contacts(reader, space, coordinates, eps)
    return spec, contacts, {"kinetic": motion["kinetic"], "potential": motion["potential"]}
