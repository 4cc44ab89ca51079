"""Scene files, the mechanics: points, bodies and loads in the plane, and the table of laws.

:class:`PlaneMixin` gives the reader of :mod:`contactsym.mechanism.files.reader` the methods that build
what ``Scene.from_lagrangian`` needs (``sympy.physics.mechanics`` Points, frames,
Particles, RigidBodies) from positions written as (x(q), y(q)).
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, RigidBody, inertia

from ...laws import Generic, KelvinVoigt, Law
from .toml_source import shown

__all__ = ["COMPLIANCE_LAWS", "PlaneMixin"]


def _generic(reader, table, where):
    reader.doc.keys(table, where, ("name",))
    return Generic()


def _kelvin_voigt(reader, table, where):
    reader.doc.keys(table, where, ("name", "stiffness", "damping"))
    return KelvinVoigt(*(reader.formula(table.get(k, 1), where, k) for k in ("stiffness", "damping")))


def _user_law(reader, table, where):
    """``N = "-k*q/eps^2 - d*q'/eps"``: q the deformation, q' its rate, eps the small parameter.

    Inside the law these three names mean only that, whatever else the file calls q or eps.
    """
    reader.doc.keys(table, where, ("name", "N", "check"), required=("N",))
    q, qdot = sp.symbols("q qdot", real=True)
    local = {"q": q, "q'": qdot, "eps": reader.eps}
    expr = reader.formula(table["N"], where, "N", {**reader.names, **local})
    return Law(expr, q, qdot, reader.eps, check=bool(table.get("check", True)))


#: Compliance laws by their name in a file; each reads its table into a Compliance.
#: Add an entry to make a new law available to scene files.
COMPLIANCE_LAWS = {"generic": _generic, "kelvin-voigt": _kelvin_voigt, "law": _user_law}


class PlaneMixin:
    """Planar mechanics for the scene-file reader (which supplies ``doc``, ``data`` and ``formula``)."""

    def plane(self) -> None:
        """The inertial frame O, the [points] and the frames of the angles they turn with."""
        self.frame, self.origin, self.points, self.frames = ReferenceFrame("O"), Point("O"), {}, {}
        self.origin.set_vel(self.frame, 0)
        for name, spec in self.doc.table(self.data, "points", "").items():
            body = angle = None
            if isinstance(spec, dict):
                self.doc.keys(spec, "points", ("position", "body", "angle"), ("position",))
                body, angle, spec = spec.get("body"), spec.get("angle"), spec["position"]
            px, py = self.pair(spec, "points", name)
            if body is None:
                point = self.origin.locatenew(name, px * self.frame.x + py * self.frame.y)
                point.set_vel(self.frame, point.pos_from(self.origin).dt(self.frame))
            else:
                if body not in self.points:
                    self.doc.fail("points", name, f"body = {shown(body)} must name a point declared above it")
                base = self.points[body]
                offset = self.origin.locatenew(name, px * self.frame.x + py * self.frame.y).pos_from(base)
                point = base.locatenew(name, offset)
                point.v2pt_theory(base, self.frame, self.turning(angle, "points", name))
            self.points[name] = point

    def turning(self, angle, where: str, key: str) -> ReferenceFrame:
        expr = self.formula(angle, where, key)
        if expr not in self.frames:
            self.frames[expr] = self.frame.orientnew(f"B{len(self.frames) + 1}", "Axis", [expr, self.frame.z])
        return self.frames[expr]

    def lagrangian(self) -> tuple:
        items = []
        for index, spec in enumerate(self.doc.table(self.data, "masses", "", kind=list)):
            where = f"masses.{index}"
            self.doc.keys(spec, where, ("point", "mass"), ("point", "mass"))
            items.append(Particle(f"m{index}", self.point(spec, where), self.formula(spec["mass"], where, "mass")))
        for index, spec in enumerate(self.doc.table(self.data, "bodies", "", kind=list)):
            where = f"bodies.{index}"
            self.doc.keys(spec, where, ("point", "angle", "mass", "inertia"), ("point", "angle", "mass", "inertia"))
            frame = self.turning(spec["angle"], where, "angle")
            point, mass = self.point(spec, where), self.formula(spec["mass"], where, "mass")
            central = (inertia(frame, 0, 0, self.formula(spec["inertia"], where, "inertia")), point)
            items.append(RigidBody(f"body{index}", point, frame, mass, central))
        energy = self.doc.table(self.data, "energy", "")
        self.doc.keys(energy, "energy", ("kinetic", "potential"))
        L = Lagrangian(self.frame, *items) if items else sp.S.Zero
        L += self.formula(energy.get("kinetic", 0), "energy", "kinetic")
        L -= self.formula(energy.get("potential", 0), "energy", "potential")
        if L == 0:
            self.doc.fail(
                "", None, "no motion: give [accelerations], or [energy] kinetic = ..., [[masses]], [[bodies]]"
            )
        return L, self.loads()

    def point(self, spec, where: str):
        if spec["point"] not in self.points:
            self.doc.fail(where, "point", f"point = {shown(spec['point'])} is not among the [points]")
        return self.points[spec["point"]]

    def loads(self) -> list:
        loads = []
        for index, spec in enumerate(self.doc.table(self.data, "loads", "", kind=list)):
            where = f"loads.{index}"
            self.doc.keys(spec, where, ("point", "force", "angle", "moment"))
            if set(spec) == {"point", "force"}:
                fx, fy = self.pair(spec["force"], where, "force")
                loads.append((self.point(spec, where), fx * self.frame.x + fy * self.frame.y))
            elif set(spec) == {"angle", "moment"}:
                moment = self.formula(spec["moment"], where, "moment")
                loads.append((self.turning(spec["angle"], where, "angle"), moment * self.frame.z))
            else:
                self.doc.fail(where, None, "a load is point = ... with force = [Fx, Fy], or angle = ... with moment")
        return loads
