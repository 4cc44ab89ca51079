"""Lagrangian scenes in contact space, built on ``sympy.physics.mechanics``.

Lagrange's equations with the reactions as unknown loads read

    M(q) q'' = F(q, q') + W N + sum_j phi_j(N_j) D_j,                       (1.4)

where the columns w_j = grad g_j of W carry the normal reactions (virtual work N_j dg_j,
the normal n_j of (1.1) in the metric of the kinetic energy) and D_j is the generalized
direction of contact j's friction force, of magnitude -phi_j(N_j) (``mu |N_j|`` for Coulomb).

The fast subsystem needs only the contact accelerations g'' = W^T q'' + h(q, q'):

    f(u) = b + G u + H phi(u),   G = W^T M^-1 W,   H = W^T M^-1 D,   b = W^T M^-1 F + h,

a k x k Delassus matrix G, its friction partner H and the load b (:class:`ContactSpace`).
They are computed fraction-free: adj(M) and det(M) by the Faddeev–LeVerrier recurrence,
which divides only by integers, so every product is reduced at once modulo
sin^2 + cos^2 = 1 (:mod:`contactsym.canonical`) and nothing swells; one common denominator
det(M) > 0 (M is positive definite) is kept for every entry. The full accelerations are
built only when a stage asks for them (:attr:`ContactSpace.accelerations`).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp
from sympy.physics.mechanics import LagrangesMethod
from sympy.physics.vector import Point, Vector
from sympy.polys.matrices import DomainMatrix

from ..algebra.canonical_form import TrigField
from ..algebra.fraction_free import (
    adjugate_and_det,
    adjugate_and_det_in_field,
    polynomial_det,
    rational_point,
    solve_fraction_free,
    t,
    value_at,
)
from ..arguments import checked
from ..errors import SceneError
from ..validate import lagrangian_parts, scene_parts

__all__ = [
    "ContactSpace",
    "contact_space",
    "lagrangian_accelerations",
    "mass_determinant",
    "mass_determinant_is_zero",
    "t",
]


def _friction_terms(contacts, frame, coordinates) -> list[tuple[sp.Matrix, sp.Expr] | None]:
    """(D_j, phi_j(N_j)) per contact: friction's generalized direction and signed magnitude."""
    terms = []
    for contact in contacts:
        law = contact.friction
        if law is None:
            terms.append(None)
            continue
        if not isinstance(law.point, Point) or not isinstance(law.direction, Vector):
            raise SceneError(
                "with from_lagrangian, a friction law needs point=<the sliding Point> and "
                "direction=<unit Vector of its sliding velocity>."
            )
        if frame is None:
            raise SceneError("friction laws on points need frame=<the inertial ReferenceFrame>.")
        slip = law.point.vel(frame).dot(law.direction)
        # the generalized force of -m d is -m * d(slip)/dq' (the partial velocity along d)
        direction = sp.Matrix([sp.diff(slip, sp.diff(q, t)) for q in coordinates])
        terms.append((direction, -law.magnitude(contact.reaction, slip)))
    return terms


def slip_speeds(contacts, coordinates, space=None) -> tuple:
    """Per contact, the sliding speed its friction law takes to be positive, or None.

    Coulomb friction, mu |N| against a given sliding direction d, holds while the contact point
    slides along d: its speed v . d (with ``Scene.from_lagrangian``; ``space`` gives D = d(v . d)/dq',
    so v . d = D . q') or sum(c_i q_i') for a direction {q_i: c_i} (``Scene.from_accelerations``)
    must stay positive. Where it reaches zero the contact sticks or slides back, which the scene
    does not describe. None for a contact without friction, with a law whose force follows the
    speed itself (viscous friction), or with friction written out in the accelerations.

    Examples
    --------
    >>> import contactsym as cs
    >>> cs.scene("sliding-point").slip_speeds
    (xdot,)
    """
    rates = [sp.diff(q, t) for q in coordinates]
    speeds = []
    for j, contact in enumerate(contacts):
        law, speed = contact.friction, sp.Dummy("speed")
        if law is None or law.magnitude(contact.reaction, speed).has(speed):
            speeds.append(None)
        elif space is not None and space.friction[j] is not None:
            speeds.append(sum(d * r for d, r in zip(space.friction[j][0], rates)))
        elif isinstance(law.direction, dict):
            speeds.append(sum(c * sp.diff(q, t) for q, c in law.direction.items()))
        else:
            speeds.append(None)
    return tuple(speeds)


@checked
@dataclass(frozen=True, eq=False)
class ContactSpace:
    """Lagrange's equations (1.4) split as M q'' = F + W N + D phi(N) (see the module docstring).

    Attributes
    ----------
    coordinates : tuple of dynamicsymbols
    M : Matrix
        The mass matrix.
    F : Matrix
        Generalized forces without the contact forces.
    W : Matrix
        n x k, the gap gradients w_j = grad g_j.
    friction : tuple
        Per contact ``(D_j, phi_j(N_j))`` or None.
    reactions : tuple of Symbol

    Examples
    --------
    Painleve's rod (x, y, theta), touching the floor with its end, y - l sin(theta) = 0:

    >>> import contactsym as cs
    >>> space = cs.scene("painleve-rod").contact_space
    >>> isinstance(space, ContactSpace), space.coordinates
    (True, (x(t), y(t), theta(t)))
    >>> space.M, space.W.T, space.reactions
    (Matrix([
    [m, 0,        0],
    [0, m,        0],
    [0, 0, l**2*m/3]]), Matrix([[0, 1, -l*cos(theta(t))]]), (N,))
    """

    coordinates: tuple
    M: sp.Matrix
    F: sp.Matrix
    W: sp.Matrix
    friction: tuple
    reactions: tuple

    @cached_property
    def forcing(self) -> sp.Matrix:
        """F + W N + sum_j phi_j(N_j) D_j."""
        total = self.F + self.W * sp.Matrix(self.reactions)
        for term in self.friction:
            if term is not None:
                total += term[1] * term[0]
        return total

    @cached_property
    def accelerations(self) -> list[sp.Expr]:
        """q'' = adj(M) (F + W N + D phi) / det M, each entry in canonical form per load term."""
        loads = [self.F] + [self.W[:, j] for j in range(self.W.cols)]
        loads += [term[0] for term in self.friction if term is not None]
        multipliers = [sp.S.One, *self.reactions] + [term[1] for term in self.friction if term is not None]
        columns = solve_fraction_free(self.M, loads)
        return [sp.Add(*[c[i] * w for c, w in zip(columns, multipliers)]) for i in range(self.M.rows)]


@checked
def mass_determinant(M: sp.Matrix):
    """1/det M as a :class:`~contactsym.algebra.canonical_form.TrigFraction`: det M is its denominator over
    its (constant) numerator.

    Examples
    --------
    >>> q, m = sp.symbols("q m", positive=True)
    >>> monomial, rest = mass_determinant(sp.Matrix([[2*m, m*sp.cos(q)], [m*sp.cos(q), m]])).denominator_split()
    >>> monomial, rest.as_expr()
    (m**2, sin(q)**2 + 1)
    """
    field = TrigField(list(M))
    det = polynomial_det(sp.ImmutableMatrix(M))  # det alone: the adjugate is A's, which may not be needed
    if det is None:
        return field.fraction(1 / adjugate_and_det_in_field(field, M)[1])
    return field.fraction(1 / field.field.new(det.set_ring(field.ring)))


def _check_mass_matrix(M: sp.Matrix, coordinates) -> None:
    """A clear error for a singular mass matrix, naming the coordinates involved."""

    def name(q):
        return getattr(q.func, "__name__", str(q)) if q.args == (t,) else str(q)

    zero = [name(q) for i, q in enumerate(coordinates) if M[i, i] == 0]
    if zero:
        raise SceneError(
            f"the mass matrix is singular: no kinetic energy in the coordinates {zero}; "
            "every coordinate needs inertia (give its body a mass or moment of inertia)."
        )
    if mass_determinant_is_zero(M):
        involved = [name(q) for i, q in enumerate(coordinates) if any(M[i, j] != 0 for j in range(M.cols) if j != i)]
        raise SceneError(
            f"the mass matrix is singular (det M = 0): the coordinates {involved} are not independent; "
            "drop one of them or add the inertia that tells them apart."
        )


@checked
def mass_determinant_is_zero(M: sp.Matrix) -> bool:
    """det M = 0 identically.

    A nonzero value at one exact point proves det M != 0: the point puts rationals
    (2t/(1 + t^2), (1 - t^2)/(1 + t^2)) for each angle's sine and cosine, 1 for each sign
    symbol and a rational for every other generator, so it respects the only relations of
    the field (sin^2 + cos^2 = 1, s^2 = 1) and evaluating there is a ring homomorphism: a
    nonzero value means det M != 0 in the same field in which the symbolic determinant is
    computed. The test is exact and costs one rational determinant; only a zero there (or a
    pole of an entry) needs the symbolic det. Coordinates q(t), their rates and t are
    generators like symbols (q is independent of sin q and cos q: e^(iq) is transcendental
    over the rational functions of q), so det M != 0 in the field means not identically zero.

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> q, m = dynamicsymbols("q"), sp.Symbol("m", positive=True)
    >>> mass_determinant_is_zero(sp.Matrix([[m, m*sp.cos(q)], [m*sp.cos(q), m]]))
    False
    >>> mass_determinant_is_zero(sp.Matrix([[m*sp.cos(q)**2, m*sp.cos(q)], [m*sp.cos(q), m]]))
    True
    """
    field = TrigField(list(M))
    entries = [[field.element(x) for x in row] for row in M.tolist()]
    value = _value_at_a_point(field, entries)
    if value:
        return False
    return not adjugate_and_det(entries, field.reduce)[1]


def _value_at_a_point(field, entries):
    """det of the entries at one exact point of the field's generators (:func:`rational_point`), or None
    at a pole of an entry or where no such point exists (a root among the generators)."""
    point = rational_point(field)
    if point is None:
        return None
    try:
        values = [[value_at(x, point) for x in row] for row in entries]
    except ZeroDivisionError:  # the point hit a pole of an entry: decide symbolically
        return None
    return DomainMatrix(values, (len(values), len(values)), sp.QQ).det()


def contact_space(lagrangian, coordinates, contacts, loads=(), frame=None) -> ContactSpace:
    """Lagrange's equations of a scene split into contact-space parts (no solve, no expand).

    Parameters
    ----------
    lagrangian : sympy expression
        T - V in the coordinates (dynamicsymbols) and their rates.
    coordinates : list of dynamicsymbols
    contacts : list of Contact
        Each ``coordinate`` is a gap function g_j(q) (or a coordinate).
    loads : list of (Point, Vector) or (ReferenceFrame, Vector)
        Applied forces and torques, as in ``LagrangesMethod``'s forcelist.
    frame : ReferenceFrame
        The inertial frame; needed when there are loads or friction laws.
    """
    coordinates = list(coordinates)
    friction = _friction_terms(contacts, frame, coordinates)
    # sympy.physics.mechanics forms Lagrange's equations (a plain-symbol rewrite halved this step's ~1-2 s
    # on the four-link arm, not worth a second implementation of the mechanics)
    method = LagrangesMethod(lagrangian, coordinates, forcelist=list(loads) or None, frame=frame)
    method.form_lagranges_equations()
    M, forcing = method.mass_matrix, method.forcing
    _check_mass_matrix(M, coordinates)
    columns = []
    for contact in contacts:
        gradient = sp.Matrix([sp.diff(contact.coordinate, q) for q in coordinates])
        if gradient.is_zero_matrix:
            raise SceneError(f"the gap {contact.coordinate} does not depend on the coordinates {coordinates}.")
        columns.append(gradient)
    W = sp.Matrix.hstack(*columns)
    reactions = tuple(c.reaction for c in contacts)
    return ContactSpace(tuple(coordinates), M, forcing, W, tuple(friction), reactions)


@checked(
    lagrangian="sp.Expr",
    coordinates="Sequence",
    contacts="Sequence[Contact]",
    loads="Sequence",
    frame="ReferenceFrame | None",
)
def lagrangian_accelerations(lagrangian, coordinates, contacts, loads=(), frame=None) -> list[sp.Expr]:
    """Solve Lagrange's equations for the accelerations, with the reactions as unknown loads.

    See :func:`contact_space` for the parameters; returns the accelerations of ``coordinates``.

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> y = dynamicsymbols("y")
    >>> m, g = sp.symbols("m g", positive=True)
    >>> N = sp.Symbol("N", real=True)
    >>> L = m*y.diff()**2/2 - m*g*y
    >>> lagrangian_accelerations(L, [y], [cs.Contact(coordinate=y, reaction=N)])
    [N/m - g]
    """
    scene_parts(coordinates, None, contacts, derived=True)  # dynamicsymbols and Contacts, one each at least
    lagrangian_parts(lagrangian, loads, frame)
    return contact_space(lagrangian, coordinates, contacts, loads, frame).accelerations
