"""Regularization (1.6)-(1.9) and the comparison (reduced) system (2.2).

New fast variables u_j = N_j(q_j, q_j'), v_j = q_j'/eps (1.6) and the stretched time
tau = t/eps turn the equations into the singularly perturbed system (1.9)

    x' = eps X(x, y, eps),   y' = Y(x, y, eps),   x = (t, q_i, q_i'),  y = (u_j, v_j).

Setting eps = 0 in Y gives the fast subsystem (2.1); solving its equilibrium f(u*) = 0
for the reactions gives the comparison system (2.2), the classical rigid-contact motion.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from ..algebra.basic import PaperSymbol, normalize
from ..algebra.fraction_free import t
from ..arguments import checked
from ..errors import ContactsymError
from ..printing.glyphs import spelled_apart
from ..printing.latex_output import Formula, LatexReprMixin, Numbering, prime, tex
from .fast import fast_variables, law_coefficients, on_piece

__all__ = ["Regularized", "ReducedSystem"]

#: The system (1.9) and the comparison system (2.2), for any number of contacts.
NUMBERS = Numbering({"regularized": (("1.9",),) * 3, "reduced": (("2.2",),) * 3})


@dataclass(frozen=True, eq=False)
class Regularized(LatexReprMixin):
    """The system (1.9) of a scene, in stretched time.

    Attributes
    ----------
    tau : Symbol
        Stretched time t/eps.
    x, y : Matrix
        Slow variables (t, q_i, q_i') and fast variables (u_j, v_j).
    X, Y : Matrix
        Right-hand sides; ``x' = eps X``, ``y' = Y``. The compliance law enters
        through its scaled form (exact for Kelvin–Voigt and other laws homogeneous in
        the scaling (1.8)). For contacts given by gap functions the coordinates that
        the gaps fix are put on the contact manifold, which holds to O(eps).

    Examples
    --------
    >>> import contactsym as cs
    >>> reg = cs.scene("sliding-point").regularized()
    >>> reg.Y.T
    Matrix([[-2*b*(u/m + Y(x, xdot)/m) - v, u/m + Y(x, xdot)/m]])
    >>> reg.Y.subs(reg.eps, 0) == reg.scene.fast_subsystem().rhs
    True
    """

    scene: object

    @property
    def eps(self) -> sp.Symbol:
        return self.scene.eps

    @cached_property
    def tau(self) -> sp.Symbol:
        taken = set(getattr(self.scene, "symbol_names", ()))
        return PaperSymbol(next((n for n in ("tau", "tauhat", "taucheck") if n not in taken), "tau_0"), positive=True)

    @cached_property
    def slow_coordinates(self) -> tuple:
        """Coordinates that rigid contact leaves free; the others are fixed by (u, v) to O(eps)."""
        return self.scene.free_coordinates

    @cached_property
    def _taken(self) -> frozenset:
        """The names the scene's own symbols print with (the fast variables avoid them, as in the fast subsystem)."""
        return frozenset(getattr(self.scene, "symbol_names", ()))

    @cached_property
    def u(self) -> tuple[sp.Symbol, ...]:
        """The fast variables u_j = N_j (1.6), one per contact."""
        return fast_variables(self.scene.k, self._taken)[0]

    @cached_property
    def v(self) -> tuple[sp.Symbol, ...]:
        """The fast variables v_j = q_j'/eps (1.6), one per contact."""
        return fast_variables(self.scene.k, self._taken)[1]

    @cached_property
    def _deformed(self) -> dict:
        """Contact coordinates and rates in terms of (u, v, eps), (1.6)."""
        index = (lambda j: None) if self.scene.k == 1 else (lambda j: j + 1)
        subs = {}
        for j, contact in enumerate(self.scene.contacts):
            q = contact.coordinate
            if q in self.scene.coordinates:
                subs[sp.diff(q, t)] = self.eps * self.v[j]
                subs[q] = contact.compliance.deformation(self.u[j], self.v[j], self.eps, index(j))
        return subs

    def _on_fast(self, expr: sp.Expr) -> sp.Expr:
        replace = {**self._deformed, **dict(zip(self.scene.reactions, self.u))}
        if all(_is_rate(d) for d in expr.atoms(sp.Derivative)):
            # one pass, rates before their coordinates (xreplace matches q' whole): subs took 1.4 s on the stool's Y
            expr = expr.xreplace(replace)
        else:  # a derivative of a compound expression: subs knows how to enter it
            rates = {d: v for d, v in self._deformed.items() if isinstance(d, sp.Derivative)}
            positions = {d: v for d, v in self._deformed.items() if not isinstance(d, sp.Derivative)}
            expr = expr.subs(rates).subs(positions).subs(dict(zip(self.scene.reactions, self.u)))
        # coordinates eliminated by gap functions sit on the contact manifold up to O(eps)
        return self.scene.freeze(expr)

    @cached_property
    def x(self) -> sp.Matrix:
        plain = [self.scene.plain(q) for q in self.slow_coordinates]
        rates = [self.scene.plain(sp.diff(q, t)) for q in self.slow_coordinates]
        time = PaperSymbol(spelled_apart("t", self._taken), real=True)  # never a user's t; "that" beside one
        return sp.Matrix([time, *plain, *rates])

    @cached_property
    def X(self) -> sp.Matrix:
        rates = [self.scene.plain(sp.diff(q, t)) for q in self.slow_coordinates]
        accelerations = [self._on_fast(self.scene.accelerations[q]) for q in self.slow_coordinates]
        return sp.Matrix([1, *rates, *accelerations])

    @cached_property
    def y(self) -> sp.Matrix:
        return sp.Matrix(self.u + self.v)

    @cached_property
    def Y(self) -> sp.Matrix:
        laws = law_coefficients(tuple(c.compliance for c in self.scene.contacts), self.u, self.v, self._taken)
        G = [self._on_fast(g) for g in self.scene.gap_accelerations]
        du = [phi * self.v[j] + psi * G[j] for j, (phi, psi) in enumerate(laws)]
        return sp.Matrix(du + G)

    def _row(self, lhs: sp.Basic, rhs: sp.Expr) -> Formula:
        return NUMBERS.formula("regularized", prime(lhs), rhs, k=self.scene.k, own=self.scene.equations)

    def slow_formulas(self) -> tuple[Formula, ...]:
        """x' = eps X row by row (1.9), without deriving Y (the report shows only these).

        Examples
        --------
        >>> import contactsym as cs
        >>> rows = cs.scene("sliding-point").regularized().slow_formulas()
        >>> [f.lhs for f in rows][:2], [f.key for f in rows] == ["regularized"] * 3
        (["t'", "x'"], True)
        """
        return tuple(self._row(x, self.eps * X) for x, X in zip(self.x, self.X))

    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """x' = eps X and y' = Y, row by row (1.9): see :func:`contactsym.printing.latex_output.formulas`."""
        return self.slow_formulas() + tuple(self._row(y, Y) for y, Y in zip(self.y, self.Y))


@checked(scene="Scene")
@dataclass(frozen=True, eq=False)
class ReducedSystem(LatexReprMixin):
    """The comparison system (2.2): slow coordinates with the reactions N = u*.

    Attributes
    ----------
    reactions : dict
        N_j -> u_j* (in the frozen-state symbols of the fast subsystem).
    accelerations : dict
        Each remaining slow coordinate -> its acceleration with N = u*.
    condition : sympy Boolean
        Where this branch exists (the sign pattern is consistent).

    Examples
    --------
    >>> import contactsym as cs
    >>> red = cs.scene("sliding-point").reduced_system()
    >>> red.accelerations
    {x: (-mu*Abs(Y(x, xdot)) + X(x, xdot))/m}
    """

    scene: object
    signs: tuple | None

    @cached_property
    def branch(self):
        branches = self.scene.equilibria(self.signs).branches
        if len(branches) != 1:
            raise ContactsymError(
                f"scene '{self.scene.name}' has {len(branches)} equilibrium branches; "
                "choose one with reduced_system(signs=...)."
            )
        return branches[0]

    @cached_property
    def reactions(self) -> dict:
        return dict(zip(self.scene.reactions, self.branch.u_star))

    @cached_property
    def condition(self) -> sp.Basic:
        return self.branch.condition

    @cached_property
    def coordinates(self) -> tuple:
        """Plain symbols of the coordinates that the contacts leave free to move."""
        return tuple(self.scene.plain(q) for q in self.scene.free_coordinates)

    @cached_property
    def accelerations(self) -> dict:
        """Accelerations on the branch's piece (|N_j| = s N_j there) with N = u*."""
        scene, fast = self.scene, self.scene.fast_subsystem()
        to_u = dict(zip(scene.reactions, fast.u))
        u_star = dict(zip(fast.u, self.branch.u_star))
        accelerations = {}
        for q, g in scene.accelerations.items():
            if scene.plain(q) in self.coordinates:
                on_piece_g = on_piece(scene.freeze(g).subs(to_u), fast.switching, self.branch.signs, fast.u)
                accelerations[scene.plain(q)] = sp.cancel(normalize(on_piece_g.subs(u_star)))
        return accelerations

    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """N = u* and the accelerations (2.2), and where the branch exists."""

        def row(lhs, rhs):
            return NUMBERS.formula("reduced", lhs, rhs, k=self.scene.k, own=self.scene.equations)

        rows = [row(tex(n), value) for n, value in self.reactions.items()]
        rows += [row(r"\ddot{" + tex(q) + "}", value) for q, value in self.accelerations.items()]
        if self.branch.signs:
            rows.append(Formula("existence", "", r"\text{where } " + tex(self.condition), ""))
        return tuple(rows)


def _is_rate(derivative: sp.Derivative) -> bool:
    """A first time derivative of a coordinate q(t): what the scenes' accelerations hold."""
    return derivative.derivative_count == 1 and isinstance(derivative.expr, sp.core.function.AppliedUndef)
