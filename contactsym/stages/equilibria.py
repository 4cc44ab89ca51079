"""Equilibria (u*, 0) of the fast subsystem: f(u*) = 0 (3.1), (4.2).

f is smooth on each piece of a sign pattern; a root of that piece is an equilibrium
when it lies in the piece: s_i sigma_i(u*) > 0 for every switching function sigma_i, and
every unilateral contact pushes, u_j* > 0. The sign patterns fix sigma = u_j to +1 where
u_j is a switching function (friction mu_j |u_j| in f); where it is not (no friction, or
friction at right angles to the gap, so that f does not switch with the sign of u_j), the
branch's condition carries u_j* > 0 itself, decided where the scene's declared signs decide
it (:func:`pushing`): a load that pulls a one-sided contact open leaves the branch False,
and the equilibrium that exists is a lift-off.

Lift-off (:class:`LiftOff`). A unilateral contact j only pushes; with its gap open the
law gives N_j = 0 identically, so (2.1) reads u_j = 0, v_j' = f_j(u). The reactions rest
(u_j = 0 and the closed contacts' f_i = 0) while the gap accelerates open, f_j(u*) > 0:
v_j grows, q_j = eps^2 Q_j becomes positive and the contact leaves the fast scale, which
is the rigid motion with the contact released. That state persists (is stable) when
the opening is strict and the closed contacts' fast subsystem, with the open u_j frozen
at 0, is asymptotically stable: its linearization is (4.5) with the principal submatrix
A_S of the closed contacts S, so its Hurwitz conditions are those of charpoly(A_S).
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from ..algebra.basic import known_sign, normalize
from ..algebra.hurwitz import Hurwitz
from ..arguments import checked
from ..printing.latex_output import Formula, LatexReprMixin, Numbering, signs_latex, tex
from .fast import solve_piece
from .linear import charpoly
from .stability import Stability, stability_of

__all__ = ["Branch", "Equilibria", "LiftOff", "pushing"]

#: The general theory's number of an equilibrium: (3.2) for k = 1, (4.2) beyond.
NUMBERS = Numbering({"equilibrium": (("3.2",), ("4.2",), ("4.2",))})


@checked
@dataclass(frozen=True)
class Branch(LatexReprMixin):
    """One equilibrium: its sign pattern, the reactions u* and where it exists.

    Examples
    --------
    >>> import contactsym as cs
    >>> cs.scene("sliding-point").equilibria().branches[0].u_star
    (-Y(x, xdot),)
    """

    signs: tuple
    u_star: tuple
    condition: sp.Basic

    def formulas(self, present: bool = False, own: dict | None = None) -> tuple[Formula, ...]:
        """u* (3.2)/(4.2) and, on a sign pattern, where it exists; ``own``: the scene's paper numbers."""
        k = len(self.u_star)
        rows = []
        for j, value in enumerate(self.u_star, 1):
            lhs = "u^{*}" if k == 1 else f"u_{{{j}}}^{{*}}"
            rows.append(NUMBERS.formula("equilibrium", lhs, value, k=k, own=own))
        if self.signs or self.condition != sp.true:  # a one-sided contact's u* > 0 also without a pattern
            where = r"\text{where } " + (r"s = " + signs_latex(self.signs) + r":\ " if self.signs else "")
            rows.append(Formula("existence", "", where + tex(self.condition), ""))
        return tuple(rows)


@checked
@dataclass(frozen=True)
class LiftOff:
    """An equilibrium at which the unilateral contacts ``open`` lift off (u_j = 0, f_j > 0).

    Attributes
    ----------
    open : tuple of int
        Indices (from 0) of the contacts that lift off.
    signs : tuple
        The sign pattern of the piece (the open contacts' switching functions are 0 there).
    u_star : tuple
        The reactions, 0 at the open contacts.
    condition : sympy Boolean
        Where it exists: inside its piece, the closed unilateral contacts pushing, and
        every open gap accelerating open.
    stable : sympy Boolean
        The Hurwitz conditions of the closed contacts' (4.5), all positive (True when all open).

    Examples
    --------
    >>> import contactsym as cs
    >>> (lift,) = cs.scene("painleve-rod").equilibria().lift_offs
    >>> lift.u_star, lift.stable
    ((0,), True)
    >>> lift.condition
    -g + l*thetadot**2*sin(theta) > 0
    """

    open: tuple
    signs: tuple
    u_star: tuple
    condition: sp.Basic
    stable: sp.Basic


def pushing(fast, at: dict) -> list:
    """``u_j* > 0`` for each unilateral contact j whose sign no switching function fixes, at the root ``at``.

    Each relation is decided where the scene's declared signs and positive expressions
    (``fast.positive``) decide it: ``True`` or ``False``, else kept as ``u_j* > 0``.

    Parameters
    ----------
    fast : FastSubsystem
        The fast subsystem (2.1) of the scene.
    at : dict
        The root, ``{u_j: u_j*}``.

    Returns
    -------
    list of sympy Boolean
        One relation per such contact (empty when every unilateral u_j is a switching function).

    Examples
    --------
    A block pressed by a load t onto a frictionless one-sided floor: f = u/m - t/m, u* = t.

    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> y = dynamicsymbols("y")
    >>> N, t = sp.symbols("N t", real=True)
    >>> m = sp.Symbol("m", positive=True)
    >>> s = cs.Scene.from_accelerations([y], [N/m - t/m], [cs.Contact(coordinate=y, reaction=N, unilateral=True)])
    >>> fast = s.fast_subsystem()
    >>> pushing(fast, {fast.u[0]: t}), pushing(fast, {fast.u[0]: -m})
    ([t > 0], [False])
    """
    fixed = set(fast.switching)
    found = []
    for u_j, one_sided in zip(fast.u, fast.unilateral):
        if not one_sided or u_j in fixed:
            continue
        value = at[u_j]
        relation = sp.Gt(value, 0)
        if isinstance(relation, sp.Gt):  # SymPy's assumptions left it open: the scene's positive expressions
            sign = known_sign(value, fast.positive)
            relation = relation if sign is None else sp.true if sign > 0 else sp.false
        found.append(relation)
    return found


def _lift_offs(fast, patterns, stability_of) -> list[LiftOff]:
    u = fast.u
    unilateral = [j for j, pushes_only in enumerate(fast.unilateral) if pushes_only]
    found = []
    for size in range(1, len(unilateral) + 1):
        for opened in itertools.combinations(unilateral, size):
            closed = [i for i in range(fast.k) if i not in opened]
            at_zero = {u[j]: 0 for j in opened}
            for pattern in patterns:
                f = fast.piece(pattern).subs(at_zero)
                rest = sp.Matrix([f[i] for i in closed])
                roots = solve_piece(rest, tuple(u[i] for i in closed), pattern) if closed else [()]
                for root in roots:
                    at = {**at_zero, **dict(zip((u[i] for i in closed), root))}
                    inside = [sp.Gt(sp.cancel(s * sw.subs(at)), 0) for s, sw in zip(pattern, fast.switching)]
                    inside = [c for c, sw in zip(inside, fast.switching) if not sw.has(*at_zero)]
                    pushing = [sp.Gt(at[u[i]], 0) for i in closed if i in unilateral]
                    opening = [sp.Gt(normalize(f[j].subs(at)), 0) for j in opened]
                    lin = stability_of(pattern).linearization
                    A = lin.A.extract(closed, closed)
                    poly = charpoly(A, [lin.Phi[i] for i in closed], [lin.Psi[i] for i in closed])
                    stable = sp.And(*[sp.Gt(c, 0) for c in Hurwitz(poly).conditions]) if closed else sp.true
                    u_star = tuple(at[x] for x in u)
                    found.append(LiftOff(opened, pattern, u_star, sp.And(*inside, *pushing, *opening), stable))
    return found


@checked(fast="FastSubsystem")
@dataclass(frozen=True, eq=False)
class Equilibria(LatexReprMixin):
    """All equilibrium branches, one or more per admissible sign pattern.

    Examples
    --------
    >>> import contactsym as cs
    >>> eq = cs.scene("painleve-klein-rod").equilibria()
    >>> len(eq.branches)
    4

    Built from the fast subsystem alone; the Stability of each sign pattern is the one the fast
    subsystem keeps (:func:`~contactsym.stages.stability.stability_of`), shared with the scene.
    """

    fast: object
    signs: tuple | None = None

    def _stability(self, signs) -> Stability:
        return stability_of(self.fast, signs)

    @cached_property
    def patterns(self) -> list[tuple]:
        return [self.signs] if self.signs is not None else self.fast.sign_patterns()

    @cached_property
    def branches(self) -> tuple[Branch, ...]:
        fast = self.fast
        branches = []
        for pattern in self.patterns:
            for root in fast.roots(pattern):
                at = dict(zip(fast.u, root))
                inside = [sp.Gt(sp.cancel(s * sw.subs(at)), 0) for s, sw in zip(pattern, fast.switching)]
                branches.append(Branch(pattern, root, sp.And(*inside, *pushing(fast, at))))
        return tuple(branches)

    @cached_property
    def exists(self) -> bool | None:
        """Whether some branch exists where the scene is declared (three-valued).

        True when some branch's condition is True throughout, False when every branch's
        condition is False (then no equilibrium with every contact closed exists, and nothing
        is stable or unstable: the regions say so), None when it depends on the parameters or
        is not proved.

        Examples
        --------
        >>> import contactsym as cs
        >>> cs.scene("sliding-point").equilibria().exists, cs.scene("brake").equilibria().exists
        (True, None)
        """
        conditions = [branch.condition for branch in self.branches]
        if any(condition == sp.true for condition in conditions):
            return True
        if all(condition == sp.false for condition in conditions):
            return False
        return None

    @cached_property
    def lift_offs(self) -> tuple[LiftOff, ...]:
        """Equilibria with some unilateral contacts open (see the module docstring)."""
        return tuple(_lift_offs(self.fast, self.patterns, self._stability))

    @checked(equilibrium="Branch | LiftOff")
    def stable(self, equilibrium) -> sp.Basic:
        """Where an equilibrium (a Branch or a LiftOff) is asymptotically stable for the scene's laws.

        For a Branch these are the Hurwitz conditions of its piece, a claim where the branch
        exists (its ``condition``); a branch that exists nowhere (condition False) is stable
        nowhere: False.

        Examples
        --------
        >>> import contactsym as cs
        >>> eq = cs.scene("painleve-rod").equilibria()
        >>> len(sp.And.make_args(eq.stable(eq.branches[0])))  # the two Hurwitz conditions of k = 1
        2
        >>> eq.stable(eq.lift_offs[0])
        True
        """
        if isinstance(equilibrium, LiftOff):
            return equilibrium.stable
        if equilibrium.condition == sp.false:
            return sp.false
        return sp.And(*[sp.Gt(h, 0) for h in self._stability(equilibrium.signs).hurwitz])

    def __iter__(self):
        return iter(self.branches)

    def __len__(self) -> int:
        return len(self.branches)

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """Every branch's u* and where it exists: see :func:`contactsym.printing.latex_output.formulas`."""
        return tuple(row for branch in self.branches for row in branch.formulas(own=self.fast.paper_equations))
