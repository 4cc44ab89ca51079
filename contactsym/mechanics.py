"""Accelerations (1.4) from a Lagrangian, built on ``sympy.physics.mechanics``.

The normal reaction of contact j does virtual work ``N_j dg_j``, so its generalized
force is ``N_j grad g_j``: its direction is the normal n_j of (1.1) in the metric of
the kinetic energy. Friction laws attached to contacts become point forces.
"""

from __future__ import annotations

import sympy as sp
from sympy.physics.mechanics import LagrangesMethod
from sympy.physics.vector import Point, Vector

from .algebra import normalize
from .errors import SceneError
from .validate import mass_matrix

__all__ = ["lagrangian_accelerations"]


def _friction_loads(contacts, frame) -> list:
    loads = []
    for contact in contacts:
        law = contact.friction
        if law is None:
            continue
        if not isinstance(law.point, Point) or not isinstance(law.direction, Vector):
            raise SceneError(
                "with from_lagrangian, a friction law needs point=<the sliding Point> and "
                "direction=<unit Vector of its sliding velocity>."
            )
        if frame is None:
            raise SceneError("friction laws on points need frame=<the inertial ReferenceFrame>.")
        slip = law.point.vel(frame).dot(law.direction)
        loads.append((law.point, -law.magnitude(contact.reaction, slip) * law.direction))
    return loads


def lagrangian_accelerations(lagrangian, coordinates, contacts, loads=(), frame=None) -> list[sp.Expr]:
    """Solve Lagrange's equations for the accelerations, with the reactions as unknown loads.

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

    Returns
    -------
    list of sympy expressions, the accelerations of ``coordinates``.

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
    forcelist = list(loads) + _friction_loads(contacts, frame)
    method = LagrangesMethod(lagrangian, list(coordinates), forcelist=forcelist or None, frame=frame)
    method.form_lagranges_equations()
    forcing = method.forcing
    for contact in contacts:
        gradient = sp.Matrix([sp.diff(contact.coordinate, q) for q in coordinates])
        if gradient.is_zero_matrix:
            raise SceneError(f"the gap {contact.coordinate} does not depend on the coordinates {list(coordinates)}.")
        forcing = forcing + contact.reaction * gradient
    mass_matrix(method.mass_matrix, coordinates)
    accelerations = method.mass_matrix.LUsolve(forcing)
    return [normalize(a) for a in accelerations]
