"""Friction laws (1.3): Coulomb friction, and viscous friction for comparison (3.3)."""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..arguments import checked
from ..parse import sympy_only
from ..validate import friction_coefficient

__all__ = ["Coulomb", "Viscous"]


@dataclass(frozen=True)
class Coulomb:
    """Coulomb friction of magnitude ``mu |N|`` opposing a known sliding direction.

    Parameters
    ----------
    mu : sympy expression
        The friction coefficient.
    direction : sympy.physics.vector.Vector or dict
        The unit direction of sliding. With ``Scene.from_lagrangian`` give a Vector and
        the ``point`` that slides; with ``Scene.from_accelerations`` give a dict
        ``{coordinate: coefficient}``: the friction adds ``-mu |N| * coefficient`` to
        that coordinate's acceleration.
    point : sympy.physics.vector.Point, optional
        The material point that slides (Lagrangian scenes only).

    Examples
    --------
    >>> import sympy as sp
    >>> Coulomb(sp.Symbol("mu"), {}).magnitude(sp.Symbol("N"), None)
    mu*Abs(N)
    """

    mu: sp.Expr
    direction: object
    point: object = None

    def __post_init__(self):
        object.__setattr__(self, "mu", friction_coefficient(self.mu))

    @checked
    def magnitude(self, reaction: sp.Expr, slip_speed: sp.Expr | None) -> sp.Expr:
        return self.mu * sp.Abs(sympy_only(reaction, "the reaction"))  # text is refused, never evaluated


@dataclass(frozen=True)
class Viscous:
    """Viscous friction ``c * (slip speed)`` opposing sliding; independent of N.

    With viscous friction (3.3) holds and Proposition 4 gives a unique stable reaction.

    Examples
    --------
    >>> import sympy as sp
    >>> Viscous(sp.Symbol("c"), {}).magnitude(sp.Symbol("N"), sp.Symbol("w"))
    c*w
    """

    c: sp.Expr
    direction: object
    point: object = None

    def __post_init__(self):
        object.__setattr__(self, "c", friction_coefficient(self.c, "the viscous coefficient c"))

    def magnitude(self, reaction: sp.Expr, slip_speed: sp.Expr | None) -> sp.Expr:
        return self.c * sympy_only(slip_speed, "the slip speed")
