"""Scene files, the contacts: gaps, reactions, compliance laws and friction.

:class:`ContactsMixin` gives the reader of :mod:`contactsym.mechanism.files.reader` the methods that
read the ``[[contacts]]`` tables into :class:`contactsym.mechanism.contact.Contact` objects, each
error placed at its table and key.
"""

from __future__ import annotations

import sympy as sp

from ...errors import ContactsymError
from ...laws import Coulomb, Viscous
from ...parse import ParseError
from ..contact import Contact
from .bodies import COMPLIANCE_LAWS
from .toml_source import SceneFileError, shown

__all__ = ["ContactsMixin"]


class ContactsMixin:
    """Reading ``[[contacts]]``; the reader supplies ``doc``, ``data``, ``names``, ``formula``,
    ``declare``, ``pair`` and, for a Lagrangian, ``points`` and ``frame``."""

    def compliance(self, spec, where: str):
        spec = {"name": spec} if isinstance(spec, str) else spec
        if not isinstance(spec, dict) or spec.get("name") not in COMPLIANCE_LAWS:
            self.doc.fail(
                where,
                "law",
                f"unknown law {shown(spec.get('name') if isinstance(spec, dict) else spec)}; use one of {', '.join(COMPLIANCE_LAWS)} "
                "(a table {name = ..., ...} for laws with parameters)",
            )
        return COMPLIANCE_LAWS[spec["name"]](self, spec, where)

    def check_gap(self, gap, coordinates, lagrangian: bool, where: str) -> None:
        listed = ", ".join(q.func.__name__ for q in coordinates)
        if lagrangian and not gap.has(*coordinates):
            self.doc.fail(where, "gap", f"the gap {gap} does not depend on the coordinates {listed}; write it in them")
        if not lagrangian and gap not in coordinates:
            self.doc.fail(
                where,
                "gap",
                f"with [accelerations] the gap must be one of the coordinates {listed}, not {gap}; "
                "for a gap function give the motion by a Lagrangian ([energy], [[masses]], [[bodies]])",
            )

    def contacts(self, coordinates, lagrangian: bool) -> list:
        contacts = []
        for index, spec in enumerate(self.doc.table(self.data, "contacts", "", required=True, kind=list)):
            where = f"contacts.{index}"
            self.doc.keys(spec, where, ("gap", "reaction", "unilateral", "law", "friction"), ("gap", "reaction"))
            gap = self.formula(spec["gap"], where, "gap")
            self.check_gap(gap, coordinates, lagrangian, where)
            reaction = sp.Symbol(str(spec["reaction"]), real=True)
            self.declare(spec["reaction"], reaction, where, "reaction")
            unilateral = spec.get("unilateral", False)
            if not isinstance(unilateral, bool):
                self.doc.fail(where, "unilateral", "unilateral must be true or false")
            friction = self.friction(spec["friction"], where, lagrangian) if "friction" in spec else None
            try:
                law = self.compliance(spec.get("law", "generic"), where)
                contacts.append(Contact(gap, reaction, law, friction, unilateral))
            except (SceneFileError, ParseError):
                raise
            except ContactsymError as error:  # the API's own message, placed at the contact's law
                self.doc.fail(where, "law", str(error).rstrip("."))
        if not contacts:
            self.doc.fail("", None, "no [[contacts]]; add one with gap = ... and reaction = ...")
        return contacts

    def friction(self, spec, where: str, lagrangian: bool):
        if not isinstance(spec, dict):
            self.doc.fail(where, "friction", "friction must be a table {mu = ..., direction = ...}")
        self.doc.keys(spec, where, ("mu", "viscous", "point", "direction"), ("direction",))
        if ("mu" in spec) == ("viscous" in spec):
            self.doc.fail(where, "friction", "give friction either mu = ... (Coulomb) or viscous = ... (viscous)")
        law, key = (Coulomb, "mu") if "mu" in spec else (Viscous, "viscous")
        coefficient = self.formula(spec[key], where, "friction")
        direction = spec["direction"]
        if not lagrangian:
            if not isinstance(direction, dict):
                self.doc.fail(where, "friction", "with [accelerations], give direction = {coordinate = coefficient}")
            coordinates = {n: self.names.get(n) for n in direction}
            if not all(isinstance(q, sp.core.function.AppliedUndef) for q in coordinates.values()):
                self.doc.fail(where, "friction", f"direction names {list(direction)} must be coordinates")
            return law(coefficient, {coordinates[n]: self.formula(v, where, "friction") for n, v in direction.items()})
        if spec.get("point") not in self.points:
            self.doc.fail(where, "friction", f"friction needs point = one of the [points] {sorted(self.points)}")
        dx, dy = self.pair(direction, where, "friction")
        return law(coefficient, dx * self.frame.x + dy * self.frame.y, self.points[spec["point"]])
