"""Scene files, the contacts: gaps, reactions, compliance laws and friction.

:func:`read_contacts` reads the ``[[contacts]]`` tables into
:class:`~contactsym.mechanism.files.spec.ContactSpec` items, each error placed at its table
and key; :func:`build_contact` makes a :class:`contactsym.mechanism.contact.Contact` of one,
with its law from :data:`COMPLIANCE_LAWS`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

import sympy as sp

from ...arguments import checked
from ...errors import ContactsymError
from ...laws import Coulomb, Generic, KelvinVoigt, Law, Viscous
from ...parse import ParseError
from ..contact import Contact
from ..friction_geometry import unit_vector_problem
from .declarations import FormulaReader
from .spec import ContactSpec, FrictionSpec, LawSpec, removed_mixin
from .toml_source import SceneFileError, shown

__all__ = ["COMPLIANCE_LAWS", "LawKind", "build_contact", "read_contacts"]

#: The deformation q and its rate q' inside a law written as a formula.
_Q, _QDOT = sp.symbols("q qdot", real=True)


@checked
@dataclass(frozen=True)
class LawKind:
    """How a law is written in a file and built: its formulas (with defaults, None for
    required), its true/false flags, and ``build(formulas, flags, eps)``.

    With ``local``, its formulas may use ``q`` (the deformation), ``q'`` (its rate) and
    ``eps`` (the small parameter), which inside the law mean only that.

    Examples
    --------
    The laws a file may name, and what the Kelvin-Voigt entry takes and builds:

    >>> sorted(COMPLIANCE_LAWS)
    ['generic', 'kelvin-voigt', 'law']
    >>> kind = COMPLIANCE_LAWS["kelvin-voigt"]
    >>> isinstance(kind, LawKind), kind.keys
    (True, ('name', 'stiffness', 'damping'))
    >>> kind.build({"stiffness": 2, "damping": 3}, {}, None)
    KelvinVoigt(stiffness=2, damping=3)
    """

    build: Callable
    formulas: Mapping = field(default_factory=dict)
    flags: Mapping = field(default_factory=dict)
    local: bool = False

    @property
    def keys(self) -> tuple[str, ...]:
        return ("name", *self.formulas, *self.flags)


#: Compliance laws by their name in a file. Add an entry to make a new law available to scene files.
#:
#: >>> from contactsym.mechanism import COMPLIANCE_LAWS
#: >>> sorted(COMPLIANCE_LAWS)
#: ['generic', 'kelvin-voigt', 'law']
COMPLIANCE_LAWS = {
    "generic": LawKind(lambda formulas, flags, eps: Generic()),
    "kelvin-voigt": LawKind(
        lambda formulas, flags, eps: KelvinVoigt(formulas["stiffness"], formulas["damping"]),
        {"stiffness": 1, "damping": 1},
    ),
    # N = "-k*q/eps^2 - d*q'/eps": q the deformation, q' its rate, eps the small parameter
    "law": LawKind(
        lambda formulas, flags, eps: Law(formulas["N"], _Q, _QDOT, eps, check=flags["check"]),
        {"N": None},
        {"check": True},
        local=True,
    ),
}


def _law(reader: FormulaReader, entry, where: str, eps: sp.Symbol) -> LawSpec:
    table = {"name": entry} if isinstance(entry, str) else entry
    contact, where = where, f"{where}.law"  # the law's keys are found on the line of law = {...}
    name = table.get("name") if isinstance(table, dict) else None
    if not isinstance(name, str) or name not in COMPLIANCE_LAWS:
        reader.doc.fail(
            contact,
            "law",
            f"unknown law {shown(name if isinstance(table, dict) else entry)}; use one of {', '.join(COMPLIANCE_LAWS)} "
            "(a table {name = ..., ...} for laws with parameters)",
        )
    kind = COMPLIANCE_LAWS[name]
    required = tuple(k for k, default in kind.formulas.items() if default is None)
    reader.doc.keys(table, where, kind.keys, required)
    names = {**reader.names, "q": _Q, "q'": _QDOT, "eps": eps} if kind.local else None
    formulas = {k: reader.formula(table.get(k, d), where, k, names) for k, d in kind.formulas.items()}
    flags = {}
    for key, default in kind.flags.items():
        flags[key] = table.get(key, default)
        if not isinstance(flags[key], bool):
            reader.doc.fail(where, key, f"{key} must be true or false, not {shown(flags[key])}")
    return LawSpec(name, MappingProxyType(formulas), MappingProxyType(flags))


def _gap(reader: FormulaReader, entry: dict, where: str, coordinates, lagrangian: bool) -> sp.Expr:
    gap = reader.formula(entry["gap"], where, "gap")
    symbols = [c.symbol for c in coordinates]
    listed = ", ".join(c.name for c in coordinates)
    if lagrangian and not gap.has(*symbols):
        reader.doc.fail(where, "gap", f"the gap {gap} does not depend on the coordinates {listed}; write it in them")
    if not lagrangian and gap not in symbols:
        reader.doc.fail(
            where,
            "gap",
            f"with [accelerations] the gap must be one of the coordinates {listed}, not {gap}; "
            "for a gap function give the motion by a Lagrangian ([energy], [[masses]], [[bodies]])",
        )
    return gap


def _friction(reader: FormulaReader, entry, where: str, lagrangian: bool, points, positive) -> FrictionSpec:
    if not isinstance(entry, dict):
        reader.doc.fail(where, "friction", "friction must be a table {mu = ..., direction = ...}")
    reader.checked(entry, f"{where}.friction", "contacts.friction")
    if ("mu" in entry) == ("viscous" in entry):
        reader.doc.fail(where, "friction", "give friction either mu = ... (Coulomb) or viscous = ... (viscous)")
    kind, key = ("coulomb", "mu") if "mu" in entry else ("viscous", "viscous")
    coefficient = reader.formula(entry[key], where, "friction")
    direction = entry["direction"]
    line = reader.doc.line(where, "friction")
    if not lagrangian:
        if not isinstance(direction, dict):
            reader.doc.fail(where, "friction", "with [accelerations], give direction = {coordinate = coefficient}")
        if not all(reader.kinds.get(n) == "coordinate" for n in direction):
            reader.doc.fail(where, "friction", f"direction names {list(direction)} must be coordinates")
        pairs = tuple((reader.names[n], reader.formula(v, where, "friction")) for n, v in direction.items())
        return FrictionSpec(kind, coefficient, pairs, None, line)
    if entry.get("point") not in points:
        reader.doc.fail(where, "friction", f"friction needs point = one of the [points] {sorted(points)}")
    direction = reader.pair(direction, where, "friction")
    problem = unit_vector_problem(direction, positive, "the friction direction")
    if problem:
        reader.doc.fail(where, "friction", problem)
    return FrictionSpec(kind, coefficient, direction, entry["point"], line)


def read_contacts(
    reader: FormulaReader, coordinates, lagrangian: bool, points, eps, positive=()
) -> tuple[ContactSpec, ...]:
    """The ``[[contacts]]``: each declares its reaction's name; ``points`` are the names of [points].

    A friction direction in the plane must be a unit vector (``positive``: the expressions declared
    positive, the domain where that is checked); whether the gap is the distance of the friction's
    point from its surface is checked when the scene is built
    (:func:`contactsym.mechanism.friction_geometry.check_friction_geometry`).
    """
    contacts = []
    for index, entry in enumerate(reader.section("contacts", required=True, kind=list)):
        where = f"contacts.{index}"
        reader.checked(entry, where, "contacts")
        gap = _gap(reader, entry, where, coordinates, lagrangian)
        name = entry["reaction"]
        reader.declare(
            name, sp.Symbol(name, real=True) if isinstance(name, str) else None, "reaction", where, "reaction"
        )
        unilateral = entry.get("unilateral", False)
        if not isinstance(unilateral, bool):
            reader.doc.fail(where, "unilateral", "unilateral must be true or false")
        friction = None
        if "friction" in entry:
            friction = _friction(reader, entry["friction"], where, lagrangian, points, positive)
        law = _law(reader, entry.get("law", "generic"), where, eps)
        line, gap_line = reader.doc.line(where, "law"), reader.doc.line(where, "gap")
        contacts.append(ContactSpec(gap, reader.names[name], unilateral, law, friction, line, gap_line))
    if not contacts:
        reader.doc.fail("", None, "no [[contacts]]; add one with gap = ... and reaction = ...")
    return tuple(contacts)


def build_contact(spec: ContactSpec, plane, source: str, eps: sp.Symbol) -> Contact:
    """The Contact of a spec; ``plane`` (a :class:`~contactsym.mechanism.files.bodies.Plane`) for a Lagrangian."""
    friction, line = spec.friction, spec.line
    try:
        if friction is not None:
            line = friction.line
            law = Coulomb if friction.kind == "coulomb" else Viscous
            if plane is None:
                friction = law(friction.coefficient, dict(friction.direction))
            else:
                friction = law(friction.coefficient, plane.vector(friction.direction), plane.points[friction.point])
        line = spec.line
        kind = COMPLIANCE_LAWS[spec.law.name]
        compliance = kind.build(spec.law.formulas, spec.law.flags, eps)
        return Contact(spec.gap, spec.reaction, compliance, friction, spec.unilateral)
    except (SceneFileError, ParseError):
        raise
    except ContactsymError as error:  # the API's own message, placed at the contact's law or friction
        raise SceneFileError(f"{source}:{line}: {str(error).rstrip('.')}.") from None


#: 0.1's mixin of the reader (removed: see :func:`read_contacts` and :func:`build_contact`).
ContactsMixin = removed_mixin("ContactsMixin")
