"""The compliance laws with Phi, Psi in closed form: the base class, any admissible law, Kelvin-Voigt.

A compliance law gives the normal reaction ``N(q, q', eps)`` of a deformed contact; the
fast subsystem needs only Phi = lim eps**2 dN/dq and Psi = lim eps dN/dq' in the fast
variables (u, v) (see :mod:`contactsym.laws`). A law written as a formula is
:class:`contactsym.laws.formula.Law`.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from ..algebra.reductions import PaperSymbol
from ..arguments import checked
from ..errors import ComplianceError
from ..parse import sympy_only
from ..validate import positive_parameter, shorten

__all__ = ["Compliance", "Generic", "KelvinVoigt"]


def _fast_names(index: int | None) -> tuple[str, str]:
    suffix = "" if index is None else f"_{index}"
    return f"u{suffix}", f"v{suffix}"


class Compliance:
    """Base class of compliance laws.

    Subclasses give ``Phi`` and ``Psi`` in the fast variables and the deformation
    ``q`` in terms of ``(u, v, eps)``.

    Examples
    --------
    Every law answers the same questions; a scene's contacts take any of them:

    >>> import sympy as sp
    >>> u, v = sp.symbols("u v")
    >>> for law in (Generic(), KelvinVoigt(2, 3)):
    ...     print(type(law).__name__, isinstance(law, Compliance), law.constant, law.phi_psi(u, v, 1))
    Generic True True (Phi_1, Psi_1)
    KelvinVoigt True True (-2, -3)
    """

    #: True when Phi and Psi do not depend on the state (Proposition 5 applies).
    constant: bool = True

    def phi_psi(self, u: sp.Symbol, v: sp.Symbol, index: int | None) -> tuple[sp.Expr, sp.Expr]:
        raise NotImplementedError

    def deformation(self, u: sp.Symbol, v: sp.Symbol, eps: sp.Symbol, index: int | None) -> sp.Expr:
        """The contact deformation q as a function of the fast variables (1.6)."""
        raise NotImplementedError

    def reaction(self, q: sp.Expr, qdot: sp.Expr, eps: sp.Expr, index: int | None) -> sp.Expr:
        """The reaction N(q, q', eps) at the deformation ``q``, its rate ``qdot`` and ``eps`` (1.5).

        ``index`` numbers the contact (None for a scene's only contact); it names the
        symbols of a law that leaves Phi, Psi free (:meth:`coefficients`).
        """
        raise NotImplementedError

    def reaction_scaled(self, Q: sp.Expr, V: sp.Expr, index: int | None) -> sp.Expr:
        """The reaction in the scaled deformation Q = q/eps**2 and rate V = q'/eps, as eps -> 0 (1.8)."""
        raise NotImplementedError

    @checked
    def smooth_scaled(self, Q: sp.Expr, V: sp.Expr, index: int | None) -> sp.Expr:
        """:meth:`reaction_scaled` on the law's smooth branch, not cut to 0 outside its domain (for derivatives)."""
        return self.reaction_scaled(Q, V, index)

    @checked
    def parameters(self) -> set:
        """The symbols the law brings into a scene (its stiffness, damping, ...)."""
        return set()

    @checked
    def coefficients(self, index: int | None) -> tuple:
        """The symbols that need numbers before the law gives a numeric reaction (a generic law's Phi, Psi)."""
        return ()


@dataclass(frozen=True)
class Generic(Compliance):
    """Any admissible law: ``Phi`` and ``Psi`` are negative symbols.

    Results derived with it hold for every law that satisfies (1.5).

    Examples
    --------
    >>> import sympy as sp
    >>> Generic().phi_psi(sp.Symbol("u_1"), sp.Symbol("v_1"), 1)
    (Phi_1, Psi_1)
    """

    @checked(u="sp.Expr | None", v="sp.Expr | None", index="int | None")
    def phi_psi(self, u, v, index):
        suffix = "" if index is None else f"_{index}"
        return (PaperSymbol(f"Phi{suffix}", negative=True), PaperSymbol(f"Psi{suffix}", negative=True))

    @checked(u="sp.Expr", v="sp.Expr", eps="sp.Expr", index="int | None")
    def deformation(self, u, v, eps, index):
        suffix = "" if index is None else f"_{index}"
        return eps**2 * sp.Function(f"Q{suffix}")(u, v)

    @checked(q="sp.Expr", qdot="sp.Expr", eps="sp.Expr", index="int | None")
    def reaction(self, q, qdot, eps, index):
        """``N = Phi q/eps**2 + Psi q'/eps``: the linear law with the contact's Phi, Psi.

        Examples
        --------
        >>> import sympy as sp
        >>> q, qdot, eps = sp.symbols("q qdot epsilon")
        >>> Generic().reaction(q, qdot, eps, 2)
        Phi_2*q/epsilon**2 + Psi_2*qdot/epsilon
        """
        Phi, Psi = self.coefficients(index)
        return Phi * q / eps**2 + Psi * qdot / eps

    @checked(Q="sp.Expr", V="sp.Expr", index="int | None")
    def reaction_scaled(self, Q, V, index):
        Phi, Psi = self.coefficients(index)
        return Phi * Q + Psi * V

    @checked(index="int | None")
    def coefficients(self, index):
        return self.phi_psi(None, None, index)


def _require_positive(value: sp.Expr, what: str) -> sp.Expr:
    value = sympy_only(value, what)
    positive_parameter(value, what, "(1.5) needs a positive law", ComplianceError)
    if value.is_positive:
        return value
    if value.is_positive is False:
        raise ComplianceError(f"{what} = {shorten(value)} is not positive, so (1.5) fails; use a positive {what}.")
    raise ComplianceError(
        f"cannot show {what} = {shorten(value)} > 0 as (1.5) requires; "
        f"declare its symbols with positive=True, e.g. sympy.Symbol('{shorten(value)}', positive=True)."
    )


@dataclass(frozen=True)
class KelvinVoigt(Compliance):
    """Linear spring-damper with the scaling (1.8):

        N = -stiffness * q / eps**2 - damping * q' / eps,

    so ``Phi = -stiffness`` and ``Psi = -damping``. The paper's (1.11) is
    ``KelvinVoigt(1, 2*b)`` with ``eps = 1/c``.

    Examples
    --------
    >>> import sympy as sp
    >>> b = sp.Symbol("b", positive=True)
    >>> KelvinVoigt(1, 2*b).phi_psi(sp.Symbol("u"), sp.Symbol("v"), None)
    (-1, -2*b)
    >>> KelvinVoigt(-1, 1)
    Traceback (most recent call last):
    ...
    contactsym.errors.ComplianceError: stiffness = -1 is not positive, so (1.5) fails; use a positive stiffness.
    """

    stiffness: sp.Expr = sp.S.One
    damping: sp.Expr = sp.S.One

    def __post_init__(self):
        object.__setattr__(self, "stiffness", _require_positive(self.stiffness, "stiffness"))
        object.__setattr__(self, "damping", _require_positive(self.damping, "damping"))

    @checked(u="sp.Expr | None", v="sp.Expr | None", index="int | None")
    def phi_psi(self, u, v, index):
        return -self.stiffness, -self.damping

    @checked(u="sp.Expr", v="sp.Expr", eps="sp.Expr", index="int | None")
    def deformation(self, u, v, eps, index):
        return -(eps**2) * (u + self.damping * v) / self.stiffness

    @checked(q="sp.Expr", qdot="sp.Expr", eps="sp.Expr", index="int | None")
    def reaction(self, q, qdot, eps, index):
        """``N = -stiffness q/eps**2 - damping q'/eps``.

        Examples
        --------
        >>> import sympy as sp
        >>> KelvinVoigt(2, 3).reaction(sp.Symbol("q"), sp.Symbol("qdot"), sp.Float(0.5), None)
        -8.0*q - 6.0*qdot
        """
        return -self.stiffness * q / eps**2 - self.damping * qdot / eps

    @checked(Q="sp.Expr", V="sp.Expr", index="int | None")
    def reaction_scaled(self, Q, V, index):
        return -self.stiffness * Q - self.damping * V

    @checked
    def parameters(self):
        return self.stiffness.free_symbols | self.damping.free_symbols
