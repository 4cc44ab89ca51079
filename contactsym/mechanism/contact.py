"""One compliant contact, and the contact manifold (1.1) its gap defines.

A contact's gap is a coordinate that must vanish (1.1), or a gap function ``g_j(q)`` for
Lagrangian scenes. In the fast subsystem the slow state is frozen in plain symbols
(q(t) -> q, q'(t) -> qdot) and put on the manifold g = 0, g' = 0.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import sympy as sp

from ..algebra.basic import PaperSymbol
from ..arguments import checked, require
from ..errors import SceneError
from ..laws import Compliance, Coulomb, Generic, Viscous
from ..parse import sympy_only
from ..validate import contact_fields, shorten
from .contact_space import t

__all__ = ["Contact", "contact_manifold", "frozen_symbol", "plain_symbol", "solve_linear"]


@dataclass(frozen=True)
class Contact:
    """One compliant contact.

    Parameters
    ----------
    coordinate : sympy expression
        The coordinate q_j of (1.1) that vanishes for rigid contact (a dynamicsymbol
        among the scene's coordinates), or, for ``Scene.from_lagrangian``, a gap
        function g_j(q) whose zero set is the contact.
    reaction : sympy.Symbol
        The normal reaction N_j, as it appears in the accelerations.
    compliance : Compliance, optional
        The law (1.5). Default: ``Generic()``, any admissible law.
    friction : Coulomb or Viscous, optional
        A friction law attached to this contact; its force is added to the equations.
    unilateral : bool
        True when the contact can only push (N >= 0) and may open; then only
        equilibria with u_j > 0 are admissible. False (default): bilateral.

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> Contact(coordinate=dynamicsymbols("y"), reaction=sp.Symbol("N"))
    Contact(y(t), N, Generic())
    """

    coordinate: sp.Expr
    reaction: sp.Symbol
    compliance: Compliance | None = None
    friction: Coulomb | Viscous | None = None
    unilateral: bool = False

    def __post_init__(self):
        contact_fields(self.coordinate, self.compliance, self.friction, self.unilateral)
        if self.compliance is None:
            object.__setattr__(self, "compliance", Generic())
        object.__setattr__(self, "coordinate", sympy_only(self.coordinate, "the gap of a contact"))
        if not isinstance(self.reaction, sp.Symbol):
            raise SceneError(f"the reaction of a contact must be a sympy Symbol, not {shorten(self.reaction)}.")

    def __repr__(self) -> str:
        side = ", unilateral" if self.unilateral else ""
        return f"Contact({self.coordinate}, {self.reaction}, {self.compliance!r}{side})"


@checked
def plain_symbol(symbol: sp.Expr, suffix: str = "") -> sp.Symbol:
    """A plain real symbol for a frozen coordinate q(t) or its rate ('qdot', 'xdot_1': printed with a dot).

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> theta, x1 = dynamicsymbols("theta x_1")
    >>> plain_symbol(theta), plain_symbol(theta, "dot"), plain_symbol(x1, "dot")
    (theta, thetadot, xdot_1)
    >>> plain_symbol(theta).is_real
    True
    """
    name = symbol.func.__name__ if isinstance(symbol, sp.core.function.AppliedUndef) else str(symbol)
    base, underscore, index = name.partition("_")
    return sp.Symbol(base + suffix + underscore + index, real=True)


def frozen_symbol(symbol: sp.Expr, suffix: str = "", taken=()) -> sp.Symbol:
    r"""The frozen coordinate or rate (see :func:`plain_symbol`); a ``PaperSymbol`` with a hat when
    ``taken`` (declared parameters' names) has its plain name, so the two never merge.

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> y = dynamicsymbols("y")
    >>> frozen_symbol(y, "dot"), frozen_symbol(y, "dot", {"ydot"}), sp.latex(frozen_symbol(y, "dot", {"ydot"}))
    (ydot, ydothat, '\\hat{\\dot{y}}')
    """
    plain = plain_symbol(symbol, suffix)
    if plain.name not in taken:
        return plain
    base, underscore, index = plain.name.partition("_")
    for mark in ("hat", "check", "tilde", "breve"):
        name = base + mark + underscore + index
        if name not in taken:
            return PaperSymbol(name, real=True)
    raise SceneError(f"rename the parameters {sorted(taken)}: they take every name of the frozen {plain}.")


@checked
def solve_linear(equations: list[sp.Expr], candidates: list[sp.Symbol]) -> dict:
    """Solve equations, linear in some of the candidates, uniquely for the fewest of them.

    Examples
    --------
    >>> a, b, c = sp.symbols("a b c")
    >>> solution = solve_linear([a + b - 1, a - b - c], [a, b, c])
    >>> solution
    {a: c/2 + 1/2, b: 1/2 - c/2}
    >>> [sp.expand(e.subs(solution)) for e in (a + b - 1, a - b - c)]
    [0, 0]
    >>> solve_linear([a**2 - 1], [a])  # not linear: no solution offered
    {}
    """
    equations = [e for e in (sp.expand(e) for e in equations) if e != 0]
    for size in range(1, len(equations) + 1):
        for chosen in itertools.combinations(candidates, size):
            polys = [e.as_poly(*chosen) for e in equations]
            if any(p is None or p.total_degree() > 1 for p in polys):
                continue
            if any(c.free_symbols & set(chosen) for p in polys for c in p.coeffs()):
                continue
            solutions = sp.linsolve(equations, list(chosen))
            if not isinstance(solutions, sp.FiniteSet) or len(solutions) != 1:
                continue
            solution = dict(zip(chosen, next(iter(solutions))))
            if any(v.has(*chosen) for v in solution.values()):
                continue
            if all(sp.expand(e.subs(solution)) == 0 for e in equations):
                return {c: sp.cancel(v) for c, v in solution.items()}
    return {}


@checked(plain="Callable", coordinates="list | tuple", gaps="Sequence[sp.Expr]")
def contact_manifold(plain, frozen_symbols: dict, coordinates, gaps, at: dict) -> dict:
    """Substitution that puts the frozen state on the contact manifold g = 0, g' = 0.

    ``plain`` freezes an expression (q(t) -> q, q' -> qdot, see ``frozen_symbols``).
    Coordinates and rates are eliminated where the gaps are linear in them; ``at``
    (coordinates or parameters at contact) fixes the rest.

    Examples
    --------
    Painleve's rod touches where its gap y - l sin(theta) and the gap's rate vanish:

    >>> import contactsym as cs
    >>> rod = cs.scene("painleve-rod")
    >>> at = contact_manifold(rod.plain, rod.frozen_symbols, rod.coordinates, rod.gaps, rod.at)
    >>> at
    {y: l*sin(theta), ydot: l*thetadot*cos(theta)}
    >>> [sp.expand(rod.plain(g).subs(at)) for g in rod.gaps]
    [0]
    """
    known = all(q in frozen_symbols for q in coordinates)
    require(known, "contact_manifold", "coordinates", coordinates, "coordinates that frozen_symbols names")
    at = {plain(key): plain(value) for key, value in at.items()}
    frozen_gaps = [plain(g) for g in gaps]
    require(
        all(isinstance(g, sp.Basic) for g in frozen_gaps), "contact_manifold", "plain", plain, "a freezing function"
    )
    frozen_gaps = [g.subs(at) for g in frozen_gaps]
    positions = [frozen_symbols[q] for q in reversed(coordinates)]
    at.update(solve_linear(frozen_gaps, [p for p in positions if p not in at]))
    residual = [g for g in (sp.expand(g.subs(at)) for g in frozen_gaps) if g != 0]
    if residual:
        raise SceneError(
            f"cannot place the state on the contact manifold: gaps {residual} do not vanish; "
            "pass at={...} giving coordinates or parameters at contact."
        )
    rates = [plain(sp.diff(g, t)).subs(at) for g in gaps]
    # eliminate first the rates of the coordinates whose positions the gaps fixed
    order = sorted(reversed(coordinates), key=lambda q: frozen_symbols[q] not in at)
    velocities = [frozen_symbols[sp.diff(q, t)] for q in order]
    at.update(solve_linear(rates, velocities))
    if any(sp.expand(r.subs(at)) != 0 for r in rates):
        raise SceneError("the contact rates g_j' cannot all vanish: the contacts are redundant or inconsistent.")
    return at
