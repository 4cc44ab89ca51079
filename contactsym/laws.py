"""Compliance laws (1.5) and friction laws (1.3).

A compliance law gives the normal reaction ``N(q, q', eps)`` of a deformed contact.
After the scaling (1.8), ``q = eps**2 Q`` and ``q' = eps V``, the fast subsystem only
needs the two limits

    Phi = lim eps**2 dN/dq,    Psi = lim eps dN/dq'            (3.1)

as functions of the fast variables ``(u, v)`` with ``u = N`` and ``v = V``.
The sign conditions (1.5) say ``Phi < 0``, ``Psi < 0`` and ``Phi(0, 0) != 0``.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .errors import ComplianceError
from .parse import sympy_only
from .validate import friction_coefficient, positive_parameter, shorten

__all__ = ["Compliance", "Generic", "KelvinVoigt", "Law", "Coulomb", "Viscous"]


def _fast_names(index: int | None) -> tuple[str, str]:
    suffix = "" if index is None else f"_{index}"
    return f"u{suffix}", f"v{suffix}"


class Compliance:
    """Base class of compliance laws.

    Subclasses give ``Phi`` and ``Psi`` in the fast variables and the deformation
    ``q`` in terms of ``(u, v, eps)``.
    """

    #: True when Phi and Psi do not depend on the state (Proposition 5 applies).
    constant: bool = True

    def phi_psi(self, u: sp.Symbol, v: sp.Symbol, index: int | None) -> tuple[sp.Expr, sp.Expr]:
        raise NotImplementedError

    def deformation(self, u: sp.Symbol, v: sp.Symbol, eps: sp.Symbol, index: int | None) -> sp.Expr:
        """The contact deformation q as a function of the fast variables (1.6)."""
        raise NotImplementedError


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

    def phi_psi(self, u, v, index):
        suffix = "" if index is None else f"_{index}"
        return (sp.Symbol(f"Phi{suffix}", negative=True), sp.Symbol(f"Psi{suffix}", negative=True))

    def deformation(self, u, v, eps, index):
        suffix = "" if index is None else f"_{index}"
        return eps**2 * sp.Function(f"Q{suffix}")(u, v)


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

    def phi_psi(self, u, v, index):
        return -self.stiffness, -self.damping

    def deformation(self, u, v, eps, index):
        return -(eps**2) * (u + self.damping * v) / self.stiffness


class Law(Compliance):
    """A user law ``N(q, q', eps)``, checked against (1.5) and (1.8).

    Parameters
    ----------
    expr : sympy expression
        The reaction as a function of the deformation ``q``, its rate ``qdot`` and ``eps``
        (a SymPy object: text is refused, see :func:`contactsym.parse_expression`).
    q, qdot, eps : sympy.Symbol
        The symbols that ``expr`` uses for them.
    check : bool
        Check the sign conditions (1.5). Turn it off only for a law that you know is
        admissible where it is used (e.g. Hertz contact, whose stiffness vanishes at q = 0).

    Examples
    --------
    >>> import sympy as sp
    >>> q, qd = sp.symbols("q qdot", real=True)
    >>> eps, k, d, c = sp.symbols("epsilon k d c", positive=True)
    >>> law = Law(-k*q/eps**2 - d*qd/eps - c*(qd/eps)**3, q, qd, eps)
    >>> law.phi_psi(sp.Symbol("u"), sp.Symbol("v"), None)
    (-k, -3*c*v**2 - d)
    >>> Law(k*q/eps**2 - d*qd/eps, q, qd, eps)
    Traceback (most recent call last):
    ...
    contactsym.errors.ComplianceError: (1.5) requires dN/dq < 0, but Phi = eps**2 dN/dq = k is not negative; the reaction must grow with the penetration -q.
    """

    def __init__(self, expr, q: sp.Symbol, qdot: sp.Symbol, eps: sp.Symbol, *, check: bool = True):
        self.expr, self.q, self.qdot, self.eps = sympy_only(expr, "the law's expression"), q, qdot, eps
        self.Q = sp.Dummy("Q", real=True)
        self.V = sp.Dummy("V", real=True)
        self.scaled = self._scaled()
        self.Phi_QV = sp.diff(self.scaled, self.Q)
        self.Psi_QV = sp.diff(self.scaled, self.V)
        self.constant = not (self.Phi_QV.free_symbols | self.Psi_QV.free_symbols) & {self.Q, self.V}
        if check:
            self._check_signs()

    def __repr__(self) -> str:
        return f"Law({self.expr})"

    def _scaled(self) -> sp.Expr:
        """N at q = eps^2 Q, q' = eps V in the limit eps -> 0 (the scaling (1.8))."""
        scaled = self.expr.subs({self.q: self.eps**2 * self.Q, self.qdot: self.eps * self.V})
        scaled = sp.expand(scaled)  # eps > 0: positive powers of eps leave the bases by themselves
        if self.eps in scaled.free_symbols:
            scaled = sp.limit(scaled, self.eps, 0, "+")
        infinite = scaled.has(sp.oo, sp.S.NegativeInfinity, sp.zoo, sp.nan, sp.DiracDelta)
        if infinite or self.eps in scaled.free_symbols:
            raise ComplianceError(
                f"the law N = {self.expr} is not scaled as (1.8): N(eps^2 Q, eps V) must have a finite "
                "limit as eps -> 0; write stiffness/eps**2 and damping/eps."
            )
        return scaled

    def _check_signs(self) -> None:
        checks = [
            (self.Phi_QV, "dN/dq < 0", "Phi = eps**2 dN/dq", "the reaction must grow with the penetration -q"),
            (self.Psi_QV, "dN/dq' < 0", "Psi = eps dN/dq'", "the contact must dissipate"),
        ]
        for value, condition, name, why in checks:
            if value.is_negative:
                continue
            verdict = "is not negative" if value.is_negative is False else "cannot be shown negative"
            hint = (
                ""
                if value.is_negative is False
                else (
                    "; declare the law's parameters positive=True, or pass check=False if it is admissible where used"
                )
            )
            raise ComplianceError(f"(1.5) requires {condition}, but {name} = {value} {verdict}; {why}{hint}.")

    def _Q_of(self, u: sp.Symbol, v: sp.Symbol) -> sp.Expr:
        solutions = sp.solve(sp.Eq(self.scaled.subs(self.V, v), u), self.Q)
        if len(solutions) > 1:  # keep the real branch for a compressive load u > 0 (e.g. Hertz contact)
            load = sp.Dummy(positive=True)
            solutions = [s for s in solutions if s.subs(u, load).is_real]
        if len(solutions) != 1:
            raise ComplianceError(
                f"cannot invert u = N(Q, v) = {self.scaled} for the deformation (found {len(solutions)} "
                "solutions); (1.6) needs an invertible law."
            )
        return solutions[0]

    def phi_psi(self, u, v, index):
        if not ({self.Q} & (self.Phi_QV.free_symbols | self.Psi_QV.free_symbols)):
            return tuple(sp.cancel(e.subs(self.V, v)) for e in (self.Phi_QV, self.Psi_QV))
        Q = self._Q_of(u, v)
        return tuple(sp.cancel(e.subs({self.Q: Q, self.V: v})) for e in (self.Phi_QV, self.Psi_QV))

    def deformation(self, u, v, eps, index):
        return eps**2 * self._Q_of(u, v)


# --- friction laws (1.3) -----------------------------------------------------------


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

    def magnitude(self, reaction: sp.Expr, slip_speed: sp.Expr | None) -> sp.Expr:
        return self.mu * sp.Abs(reaction)


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
        return self.c * slip_speed
