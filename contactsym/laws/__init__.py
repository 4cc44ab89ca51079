"""Compliance laws (1.5) and friction laws (1.3): the names, from the modules that define them.

A compliance law gives the normal reaction ``N(q, q', eps)`` of a deformed contact.
After the scaling (1.8), ``q = eps**2 Q`` and ``q' = eps V``, the fast subsystem only
needs the two limits

    Phi = lim eps**2 dN/dq,    Psi = lim eps dN/dq'            (3.1)

as functions of the fast variables ``(u, v)`` with ``u = N`` and ``v = V``.
The sign conditions (1.5) say ``Phi < 0``, ``Psi < 0`` and ``Phi(0, 0) != 0``.

:mod:`contactsym.laws.compliance` has the base class, :class:`Generic` and :class:`KelvinVoigt`;
:mod:`contactsym.laws.formula` the law written as a formula (:class:`Law`);
:mod:`contactsym.laws.friction` Coulomb and viscous friction.
"""

from .compliance import Compliance, Generic, KelvinVoigt
from .formula import ImplicitDeformation, Law
from .friction import Coulomb, Viscous

__all__ = ["Compliance", "Generic", "ImplicitDeformation", "KelvinVoigt", "Law", "Coulomb", "Viscous"]
