"""The associated (fast) system (2.1), in the form (3.1)/(4.1):

    u_j' = Phi_j(u_j, v_j) v_j + Psi_j(u_j, v_j) f_j(u),    v_j' = f_j(u),

where ' is d/dtau, tau = t/eps, and f_j(u) is the acceleration of contact j with the
deformations and their rates set to zero, the slow state frozen and N = u.
"""

from __future__ import annotations

import itertools
import logging
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from ..algebra.basic import PaperSymbol, normalize, present
from ..arguments import checked, require
from ..errors import SceneError
from ..printing.glyphs import spelled_apart
from ..printing.latex_output import Formula, LatexReprMixin, Numbering, prime, tex
from .fast_space import (
    _monomial_denominator,
    contact_accelerations,
    reaction_factors,
    reaction_part,
    switching_of_factors,
)
from .pieces import on_piece, solve_piece, switching_functions

__all__ = ["FastSubsystem", "fast_variables", "law_coefficients", "switching_functions", "on_piece", "solve_piece"]

#: The general theory's numbers of the fast subsystem: (3.1) for k = 1, (4.1) for k = 2, (2.1) beyond.
NUMBERS = Numbering({key: (("3.1",), ("4.1",), ("2.1",)) for key in ("fast", "f", "law")})

#: Stage messages for long derivations: ``logging.basicConfig(level=logging.INFO)`` shows them.
log = logging.getLogger("contactsym")


def fast_variables(k: int, taken=()) -> tuple[tuple[sp.Symbol, ...], tuple[sp.Symbol, ...]]:
    """The fast variables (1.6) of k contacts: the reactions u_j and the scaled rates v_j (u, v for k = 1).

    They are :class:`~contactsym.algebra.reductions.PaperSymbol` objects, which no user symbol
    equals. Where a name of ``taken`` (the names the scene's own symbols print with) is one of
    theirs, they print with a hat (``uhat``, LaTeX ``\\hat{u}``), so that no printed formula
    shows two different symbols under one name.

    Examples
    --------
    >>> fast_variables(1), fast_variables(2)
    (((u,), (v,)), ((u_1, u_2), (v_1, v_2)))
    >>> fast_variables(1, taken={"u"})
    ((uhat,), (v,))
    """
    taken = set(taken)

    def names(letter: str) -> tuple[sp.Symbol, ...]:
        def spelled(base: str) -> list[str]:
            return [base] if k == 1 else [f"{base}_{j}" for j in range(1, k + 1)]

        bases = [letter + mark for mark in ("", "hat", "check", "tilde", "breve")]
        base = next((b for b in bases if not taken.intersection(spelled(b))), letter * 2)
        while taken.intersection(spelled(base)):  # every decorated name taken: lengthen the letter
            base += letter
        return tuple(PaperSymbol(name, real=True) for name in spelled(base))

    return names("u"), names("v")


def law_coefficients(compliances, u, v, taken=()) -> tuple[tuple[sp.Expr, sp.Expr], ...]:
    """(Phi_j, Psi_j) of (2.1) for each contact's compliance law at (u_j, v_j); indexed j when k > 1.

    A generic law's Phi, Psi print with a hat where a name of ``taken`` is theirs.
    """
    index = (lambda j: None) if len(compliances) == 1 else (lambda j: j + 1)
    taken = set(taken)
    laws = []
    for j, law in enumerate(compliances):
        phi_psi = law.phi_psi(u[j], v[j], index(j))
        own = [c for c in law.coefficients(index(j)) if isinstance(c, PaperSymbol) and c.name in taken]
        hats = {c: PaperSymbol(_decorated(c.name, taken), **c.assumptions0) for c in own}
        laws.append(tuple(sp.sympify(x).xreplace(hats) for x in phi_psi))
    return tuple(laws)


def _decorated(name: str, taken) -> str:
    """``name`` with a hat (Phi_1 -> Phihat_1, LaTeX \\hat{\\Phi}_{1}), or another accent, not in ``taken``."""
    base, underscore, index = name.partition("_")
    for mark in ("hat", "check", "tilde", "breve"):
        if base + mark + underscore + index not in taken:
            return base + mark + underscore + index
    return _decorated(base + base[-1] + underscore + index, taken)


@dataclass(frozen=True, eq=False)
class FastSubsystem(LatexReprMixin):
    """The fast subsystem (2.1) of a scene. All attributes are SymPy objects.

    Attributes
    ----------
    u, v : tuple of Symbol
        Fast variables (1.6): u_j = N_j (the reaction), v_j = q_j'/eps.
    f : Matrix
        f_j(u), piecewise smooth through Abs/sign of the switching functions.
    Phi, Psi : tuple
        eps^2 dN_j/dq_j and eps dN_j/dq_j' in the limit eps -> 0 (3.1).
    rhs : Matrix
        The right-hand side, in the order ``state = (u_1..u_k, v_1..v_k)``.
    switching : tuple
        Arguments of Abs/sign that depend on u; a sign pattern gives one sign each.

    Examples
    --------
    >>> import contactsym as cs
    >>> fs = cs.scene("sliding-point").fast_subsystem()
    >>> fs.rhs.T
    Matrix([[-2*b*(u/m + Y(x, xdot)/m) - v, u/m + Y(x, xdot)/m]])

    Built from the scene (its only input, as ``scene``), it carries what every later stage
    needs: the sign patterns and fixed signs, the positive expressions, the presentation,
    the paper's numbers of the scene. A Linearization, Equilibria or Stability never asks
    the scene.
    """

    scene: object

    @cached_property
    def k(self) -> int:
        return self.scene.k

    @cached_property
    def name(self) -> str:
        return self.scene.name

    @cached_property
    def paper_equations(self) -> dict:
        """The paper's own equation numbers of the scene, ``{formula key: (numbers, note)}``."""
        return self.scene.equations

    @cached_property
    def positive(self) -> tuple:
        """Expressions positive throughout the scene's domain (see ``Scene.positive_expressions``)."""
        return self.scene.positive_expressions

    @cached_property
    def presentation(self) -> dict:
        return self.scene.presentation

    @checked(expr="sp.Basic | sp.MatrixBase", signs="Sequence[sp.Expr] | None")
    def present(self, expr: sp.Expr, signs=None) -> sp.Expr:
        """``expr`` in the scene's presentation variables (see :func:`contactsym.algebra.basic.present`)."""
        return present(expr, self.presentation, signs)

    @cached_property
    def unilateral(self) -> tuple[bool, ...]:
        """For each contact: True when it only pushes and may open."""
        return tuple(c.unilateral for c in self.scene.contacts)

    @cached_property
    def compliances(self) -> tuple:
        """The compliance law (1.5) of each contact."""
        return tuple(c.compliance for c in self.scene.contacts)

    @cached_property
    def fixed_signs(self) -> dict:
        """Switching functions whose sign the scene fixes (unilateral contacts: u_j > 0)."""
        return {u: 1 for u, unilateral in zip(self.u, self.unilateral) if unilateral}

    @checked
    def sign_patterns(self) -> list[tuple[int, ...]]:
        """All admissible sign patterns of the switching functions (fixed ones kept)."""
        choices = [(self.fixed_signs[s],) if s in self.fixed_signs else (1, -1) for s in self.switching]
        return list(itertools.product(*choices))

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The symbols other than u, v: loads, geometry, frozen state."""
        exprs = list(self.f) + list(self.Phi) + list(self.Psi)
        free = set().union(*(e.free_symbols for e in exprs)) - set(self.u) - set(self.v)
        return tuple(sorted(free, key=str))

    @cached_property
    def _taken(self) -> frozenset:
        """The names the scene's own symbols print with (the paper's symbols avoid them)."""
        return frozenset(getattr(self.scene, "symbol_names", ()))

    @cached_property
    def u(self) -> tuple[sp.Symbol, ...]:
        return fast_variables(self.k, self._taken)[0]

    @cached_property
    def v(self) -> tuple[sp.Symbol, ...]:
        return fast_variables(self.k, self._taken)[1]

    @cached_property
    def state(self) -> sp.Matrix:
        return sp.Matrix(self.u + self.v)

    @cached_property
    def f(self) -> sp.Matrix:
        to_u = dict(zip(self.scene.reactions, self.u))
        if self.scene.contact_space is not None:
            # b + G u + H phi(u) with canonical coefficients: one fraction only when that stays small
            load = contact_accelerations(self.scene, self.u, load=True)
            structured = [b + r for b, r in zip(load, self._reaction_part)]
            compact = all(_monomial_denominator(c) for fj in structured for c in sp.Add.make_args(fj))
            f = sp.Matrix([normalize(fj) if compact else fj for fj in structured])
        else:
            f = sp.Matrix([normalize(self.scene.freeze(g).subs(to_u)) for g in self.scene.gap_accelerations])
        if not any(fj.has(*self.u) for fj in f):
            raise SceneError(
                "the contact accelerations f_j do not depend on any reaction; "
                "check that each reaction acts along its contact's normal."
            )
        return f

    @cached_property
    def _laws(self) -> tuple[tuple[sp.Expr, sp.Expr], ...]:
        return law_coefficients(self.compliances, self.u, self.v, self._taken)

    @cached_property
    def Phi(self) -> tuple[sp.Expr, ...]:
        return tuple(phi for phi, _ in self._laws)

    @cached_property
    def Psi(self) -> tuple[sp.Expr, ...]:
        return tuple(psi for _, psi in self._laws)

    @cached_property
    def rhs(self) -> sp.Matrix:
        du = [self.Phi[j] * self.v[j] + self.Psi[j] * self.f[j] for j in range(self.k)]
        return sp.Matrix(du + list(self.f))

    @cached_property
    def _reaction_part(self) -> list | None:
        """G u + H phi(u) of a Lagrangian scene (see :func:`contact_accelerations`), else None."""
        if self.reaction_factors is None:
            return None
        log.info("scene '%s': contact space, the %d x %d Delassus matrix", self.name, self.k, self.k)
        return reaction_part(*self.reaction_factors)

    @cached_property
    def reaction_factors(self) -> tuple | None:
        """(M, W, L, m(u)) of :func:`reaction_factors` for a scene in contact space, else None."""
        if self.scene.contact_space is None:
            return None
        return reaction_factors(self.scene, self.u)

    @cached_property
    def _depends_on_u(self) -> sp.Matrix:
        """The terms of f that depend on u: all of f, or its reaction part when that is known."""
        return self.f if self._reaction_part is None else sp.Matrix(self._reaction_part)

    @cached_property
    def switching(self) -> tuple[sp.Expr, ...]:
        if self.reaction_factors is not None:  # read from m(u): the whole reaction part is not needed
            found = switching_of_factors(*self.reaction_factors, self.u)
            if found is not None:
                return found
        return switching_functions(self._depends_on_u, self.u)

    @cached_property
    def constant_laws(self) -> bool:
        """True when every Phi_j, Psi_j is constant (Proposition 5 applies for k = 1)."""
        return all(law.constant for law in self.compliances)

    @cached_property
    def _later_stages(self) -> dict:
        return {}

    @checked(key="tuple | str", build="Callable")
    def later_stage(self, key, build):
        """A stage built from this fast subsystem alone (a Linearization or a Stability per sign
        pattern), built once: the scene and :class:`~contactsym.stages.equilibria.Equilibria` share it."""
        if key not in self._later_stages:
            self._later_stages[key] = build()
        return self._later_stages[key]

    @checked(signs="Sequence[sp.Expr]")
    def piece(self, signs) -> sp.Matrix:
        """f on the piece of a sign pattern (numbers or symbols)."""
        require(
            len(signs) == len(self.switching),
            "FastSubsystem.piece",
            "signs",
            signs,
            f"{len(self.switching)} signs, one per switching function",
        )
        return self.f.applyfunc(lambda e: on_piece(e, self.switching, signs, self.u))

    @checked(signs="Sequence[sp.Expr]")
    def jacobian(self, signs) -> sp.Matrix:
        """df/du on the piece of a sign pattern, from the terms of f that depend on u."""
        require(
            len(signs) == len(self.switching),
            "FastSubsystem.jacobian",
            "signs",
            signs,
            f"{len(self.switching)} signs, one per switching function",
        )
        piece = self._depends_on_u.applyfunc(lambda e: on_piece(e, self.switching, signs, self.u))
        return piece.jacobian(self.u)

    def jacobian_factors(self, signs) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix] | None:
        """(M, W, V) with df/du = W^T M^-1 V on the piece of a sign pattern, for a scene built in
        contact space (else None): the mass matrix and the gap gradients on the manifold, and V
        the loads times d(u, phi(u))/du."""
        if self.reaction_factors is None:
            return None
        M, W, loads, multipliers = self.reaction_factors
        piece = sp.Matrix([on_piece(m, self.switching, signs, self.u) for m in multipliers])
        return M, W, loads * piece.jacobian(self.u)

    @checked(signs="Sequence[sp.Expr]")
    def roots(self, signs) -> list[tuple]:
        """The roots u* of f on the piece of a sign pattern (see :func:`solve_piece`)."""
        require(
            len(signs) == len(self.switching),
            "FastSubsystem.roots",
            "signs",
            signs,
            f"{len(self.switching)} signs, one per switching function",
        )
        return solve_piece(self.piece(signs), self.u, signs)

    @cached_property
    def equations(self) -> list[sp.Eq]:
        """The equations (2.1) as ``Eq(Symbol("u_j'"), ...)``, for display."""
        return [sp.Eq(sp.Symbol(f"{x}'"), r) for x, r in zip(self.state, self.rhs)]

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """(2.1) in the form (3.1)/(4.1), and each f_j(u): see :func:`contactsym.printing.latex_output.formulas`."""
        u = self.u
        f = spelled_apart("f", self._taken, {n.partition("_")[0] for n in self._taken})  # fhat beside a user's f
        names = [f] if self.k == 1 else [f"{f}_{j}" for j in range(1, self.k + 1)]
        f_of_u = [sp.Function(name)(*u) for name in names]

        def row(key, lhs, rhs):
            return NUMBERS.formula(key, lhs, rhs, k=self.k, own=self.paper_equations)

        rows = []
        for j in range(self.k):
            rows.append(row("fast", prime(u[j]), self.Phi[j] * self.v[j] + self.Psi[j] * f_of_u[j]))
            rows.append(row("fast", prime(self.v[j]), f_of_u[j]))
        rows += [row("f", tex(f_of_u[j]), self.f[j]) for j in range(self.k)]
        return tuple(rows)
