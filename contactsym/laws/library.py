"""A library of compliance laws used in contact mechanics, each scaled as (1.8).

Every law is a :class:`~contactsym.laws.Law` in the deformation ``q`` (negative in
compression) and its rate, with the stiffness of order ``1/eps**2`` and the damping of
order ``1/eps`` so that the fast subsystem (2.1) has a finite limit. In the scaled
variables ``Q = q/eps**2``, ``V = q'/eps``:

===================  ==========================================  =====================
law                  N(Q, V)                                     used where
===================  ==========================================  =====================
Kelvin–Voigt         ``-k Q - d V``                              everywhere
Hertz (+ damping)    ``k (-Q)**n - d V``  (n = 3/2: Hertz)       compression, Q < 0
Hunt–Crossley        ``k (-Q)**n (1 - c V)``                     Q < 0, c V < 1
cubic stiffening     ``-k Q - k3 Q**3 - d V``                    everywhere (k3 >= 0)
===================  ==========================================  =====================

Hertz's law ``n = 3/2`` is the elastic contact of smooth bodies; Hunt–Crossley's
damping grows with the indentation, so the reaction is continuous at first touch;
Lankarani–Nikravesh is Hunt–Crossley with ``c`` fitted to a restitution coefficient.
The sign conditions (1.5) are checked on each law's domain.
"""

from __future__ import annotations

from dataclasses import replace

import sympy as sp

from ..arguments import checked
from ..errors import ComplianceError
from .compliance import KelvinVoigt, _require_positive
from .formula import Law

__all__ = ["CubicStiffening", "Hertz", "HuntCrossley", "KelvinVoigt", "with_laws"]

_q, _qd = sp.symbols("q qdot", real=True)
_eps = sp.Symbol("epsilon", positive=True)
_HERTZ = sp.Rational(3, 2)  # the exponent of Hertz contact between smooth bodies


def _positive(value, name: str) -> sp.Expr:
    """A positive parameter; a float is taken as the exact rational it is, so sign checks stay exact."""
    return _require_positive(sp.Rational(value) if isinstance(value, float) else value, name)


def _exponent(n) -> sp.Expr:
    n = sp.nsimplify(n)
    if not (n.is_number and n >= 1):
        raise _error(f"exponent n = {n} must be a number >= 1 (n = 3/2 for Hertz contact).")
    return n


def _error(message: str) -> ComplianceError:
    return ComplianceError(message)


@checked(stiffness="sp.Expr", damping="sp.Expr", exponent="sp.Expr")
class Hertz(Law):
    """Hertz contact with linear damping: ``N = k (-q)**n / eps**(2 n) - d q' / eps``.

    Defined in compression (``q < 0``, i.e. ``u + d v > 0``), where
    ``Phi = -n k**(1/n) (u + d v)**(1 - 1/n)`` and ``Psi = -d``. ``damping=0`` gives
    the undamped law (then (1.5) fails: Psi = 0).

    Examples
    --------
    >>> import sympy as sp
    >>> k, d = sp.symbols("k d", positive=True)
    >>> Hertz(k, d).phi_psi(sp.Symbol("u"), sp.Symbol("v"), None)
    (-3*k**(2/3)*(d*v + u)**(1/3)/2, -d)
    """

    def __init__(self, stiffness=1, damping=1, exponent=_HERTZ):
        self.stiffness = _positive(stiffness, "stiffness")
        self.damping = _positive(damping, "damping")
        self.exponent = _exponent(exponent)
        n = self.exponent
        expr = self.stiffness * (-_q) ** n / _eps ** (2 * n) - self.damping * _qd / _eps
        super().__init__(expr, _q, _qd, _eps, where=[-_q])

    def __repr__(self) -> str:
        return f"Hertz(stiffness={self.stiffness}, damping={self.damping}, exponent={self.exponent})"


@checked(stiffness="sp.Expr", damping="sp.Expr", exponent="sp.Expr")
class HuntCrossley(Law):
    """Hunt–Crossley contact: ``N = k (-q)**n (1 - c q'/eps) / eps**(2 n)``.

    The damping ``-k c (-Q)**n V`` vanishes at first touch. Defined for ``q < 0`` and
    ``c q'/eps < 1`` (where N > 0); there ``Phi = -n k**(1/n) u**(1 - 1/n) (1 - c v)**(1/n)``
    and ``Psi = -c u/(1 - c v)``.

    Examples
    --------
    >>> import sympy as sp
    >>> k, c = sp.symbols("k c", positive=True)
    >>> u = sp.Symbol("u")
    >>> [sp.simplify(e.subs(sp.Symbol("v"), 0)) for e in HuntCrossley(k, c).phi_psi(u, sp.Symbol("v"), None)]
    [-3*k**(2/3)*u**(1/3)/2, -c*u]
    """

    def __init__(self, stiffness=1, damping=1, exponent=_HERTZ):
        self.stiffness = _positive(stiffness, "stiffness")
        self.damping = _positive(damping, "damping")
        self.exponent = _exponent(exponent)
        k, c, n = self.stiffness, self.damping, self.exponent
        expr = k * (-_q) ** n * (1 - c * _qd / _eps) / _eps ** (2 * n)
        super().__init__(expr, _q, _qd, _eps, where=[-_q, 1 - c * _qd / _eps])

    def __repr__(self) -> str:
        return f"HuntCrossley(stiffness={self.stiffness}, damping={self.damping}, exponent={self.exponent})"


class CubicStiffening(Law):
    """A hardening spring with linear damping: ``N = -k Q - k3 Q**3 - d V`` (scaled).

    Monotone everywhere for ``k3 >= 0``; its inverse Q(u, v) is kept implicit
    (:class:`~contactsym.laws.ImplicitDeformation`).

    Examples
    --------
    >>> import sympy as sp
    >>> k, k3, d = sp.symbols("k k_3 d", positive=True)
    >>> CubicStiffening(k, k3, d).phi_psi(sp.Symbol("u"), sp.Symbol("v"), 2)
    (-k - 3*k_3*Q_2(u, v)**2, -d)
    """

    def __init__(self, stiffness=1, cubic=1, damping=1):
        self.stiffness = _positive(stiffness, "stiffness")
        self.cubic = _positive(cubic, "cubic stiffness")
        self.damping = _positive(damping, "damping")
        Q = _q / _eps**2
        expr = -self.stiffness * Q - self.cubic * Q**3 - self.damping * _qd / _eps
        super().__init__(expr, _q, _qd, _eps)

    def __repr__(self) -> str:
        return f"CubicStiffening(stiffness={self.stiffness}, cubic={self.cubic}, damping={self.damping})"


def with_laws(scene, laws):
    """A copy of ``scene`` whose contacts have the given compliance laws.

    ``laws`` is one law for every contact or a sequence with one law per contact.

    Examples
    --------
    >>> import contactsym as cs
    >>> brake = with_laws(cs.scene("brake"), Hertz(2, 1))
    >>> brake.fast_subsystem().Phi[0]
    -3*2**(2/3)*(u_1 + v_1)**(1/3)/2
    """
    if not all(hasattr(scene, a) for a in ("k", "contacts", "coordinates", "accelerations")):
        raise _error(f"with_laws takes a Scene (e.g. contactsym.scene('brake')), not {type(scene).__name__}.")
    laws = list(laws) if isinstance(laws, (list, tuple)) else [laws] * scene.k
    if len(laws) != scene.k:
        raise _error(f"got {len(laws)} laws for the {scene.k} contacts of '{scene.name}'; give one per contact.")
    contacts = [replace(c, compliance=law) for c, law in zip(scene.contacts, laws)]
    # the scene's own class: laws sit below scenes, so this module imports no Scene
    return type(scene)(
        scene.coordinates,
        list(scene.accelerations.values()),
        contacts,
        name=scene.name,
        at=scene.at,
        presentation=scene.presentation,
        positive=scene.positive_expressions,
        solve_for=scene.solve_for,
        description=scene.description,
        eps=scene.eps,
    )
