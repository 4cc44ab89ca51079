"""The associated (fast) system (2.1), in the form (3.1)/(4.1):

    u_j' = Phi_j(u_j, v_j) v_j + Psi_j(u_j, v_j) f_j(u),    v_j' = f_j(u),

where ' is d/dtau, tau = t/eps, and f_j(u) is the acceleration of contact j with the
deformations and their rates set to zero, the slow state frozen and N = u.
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from .algebra import normalize
from .errors import SceneError
from .scene import t

__all__ = ["FastSubsystem", "switching_functions", "on_piece"]

#: Stage messages for long derivations: ``logging.basicConfig(level=logging.INFO)`` shows them.
log = logging.getLogger("contactsym")


def _canonical(arg: sp.Expr, u) -> tuple[sp.Expr, int]:
    """(sigma, c) with arg = c * sigma, c a nonzero number, sigma increasing in the first u it has."""
    first = next(x for x in u if arg.has(x))
    content, sigma = sp.expand(arg).as_content_primitive()  # |2 u - 2 w| and |u - w| switch together
    return (-sigma, -content) if sp.diff(sigma, first).could_extract_minus_sign() else (sigma, content)


def switching_functions(exprs, u) -> tuple[sp.Expr, ...]:
    """The distinct arguments of Abs and sign in ``exprs`` that depend on ``u``.

    Examples
    --------
    >>> import sympy as sp
    >>> u1, u2, y = sp.symbols("u_1 u_2 y", real=True)
    >>> switching_functions([sp.Abs(u1) + sp.sign(-u1) + sp.Abs(u2 + y) + sp.Abs(y)], [u1, u2])
    (u_1, u_2 + y)
    """
    found = set()
    for expr in exprs:
        for atom in sp.sympify(expr).atoms(sp.Abs, sp.sign):
            if atom.args[0].has(*u):
                found.add(_canonical(atom.args[0], u)[0])
    order = {symbol: i for i, symbol in enumerate(u)}
    return tuple(sorted(found, key=lambda s: (min(order[x] for x in s.free_symbols if x in order), str(s))))


def on_piece(expr, switching, signs, u) -> sp.Expr:
    """``expr`` on the piece where sign(switching[i]) = signs[i]; signs may be symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> u, s = sp.symbols("u s", real=True)
    >>> on_piece(2*u + sp.Abs(-u) - sp.sign(u), [u], [s], [u])
    s*u - s + 2*u
    """
    by_sigma = dict(zip(switching, signs))
    replacements = {}
    for atom in sp.sympify(expr).atoms(sp.Abs, sp.sign):
        if not atom.args[0].has(*u):
            continue
        sigma, c = _canonical(atom.args[0], u)
        if sigma in by_sigma:
            s = by_sigma[sigma]
            replacements[atom] = abs(c) * s * sigma if atom.func is sp.Abs else sp.sign(c) * s
    return sp.sympify(expr).xreplace(replacements)


def _monomial_denominator(expr: sp.Expr) -> bool:
    """True when the denominator is a product of powers of symbols (a paper-style form)."""
    return all(base.is_Symbol or base.is_Number for base in sp.fraction(expr)[1].as_powers_dict())


def contact_accelerations(scene, u, *, load: bool) -> list[sp.Expr]:
    """The parts of f(u) = b + G u + H phi(u) from the scene's contact space, on the manifold:
    the load b (``load=True``) or the reaction part G u + H phi(u).

    G = W^T M^-1 W (Delassus), H = W^T M^-1 D (friction), b = W^T M^-1 F + h with h_j the
    part of g_j'' without accelerations; see :mod:`contactsym.mechanics`. The linearization
    needs only the reaction part, so a large load is never derived for it.
    """
    from .mechanics import solve_fraction_free

    space = scene.contact_space
    log.info(
        "scene '%s': contact space (%s), adj(M) of the %d x %d mass matrix",
        scene.name,
        "load b" if load else f"{scene.k} x {scene.k} Delassus matrix",
        space.M.rows,
        space.M.rows,
    )
    # positions are put on the manifold by substitution, rates inside the field (they are rational)
    rate_symbols = {scene.frozen_symbols[sp.diff(q, t)] for q in scene.coordinates}
    rates = {k: v for k, v in scene.manifold.items() if k in rate_symbols}
    positions = {k: v for k, v in scene.manifold.items() if k not in rate_symbols}

    def place(expr):
        return scene._plain(expr).subs(positions)

    M, W = space.M.applyfunc(place), space.W.applyfunc(place)
    if load:
        second = {sp.diff(q, t, 2): 0 for q in scene.coordinates}
        h = sp.Matrix([place(sp.diff(g, t, 2).subs(second)) for g in scene.gaps])
        (b,) = solve_fraction_free(M, [space.F.applyfunc(place)], W, substitution=rates, offsets=[h])
        return b
    frozen = [term for term in space.friction if term is not None]
    loads = [space.W[:, j] for j in range(scene.k)] + [term[0] for term in frozen]
    columns = solve_fraction_free(M, [x.applyfunc(place) for x in loads], W)
    to_u = dict(zip(scene.reactions, u))
    multipliers = [*u] + [scene.freeze(term[1]).subs(to_u) for term in frozen]
    return [sp.Add(*[c[i] * w for c, w in zip(columns, multipliers)]) for i in range(scene.k)]


@dataclass(frozen=True, eq=False)
class FastSubsystem:
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
    """

    scene: object

    @property
    def k(self) -> int:
        return self.scene.k

    def _names(self, letter: str) -> tuple[sp.Symbol, ...]:
        if self.k == 1:
            return (sp.Symbol(letter, real=True),)
        return tuple(sp.Symbol(f"{letter}_{j}", real=True) for j in range(1, self.k + 1))

    @cached_property
    def u(self) -> tuple[sp.Symbol, ...]:
        return self._names("u")

    @cached_property
    def v(self) -> tuple[sp.Symbol, ...]:
        return self._names("v")

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
        index = (lambda j: None) if self.k == 1 else (lambda j: j + 1)
        return tuple(c.compliance.phi_psi(self.u[j], self.v[j], index(j)) for j, c in enumerate(self.scene.contacts))

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
        if self.scene.contact_space is None:
            return None
        return contact_accelerations(self.scene, self.u, load=False)

    @cached_property
    def _depends_on_u(self) -> sp.Matrix:
        """The terms of f that depend on u: all of f, or its reaction part when that is known."""
        return self.f if self._reaction_part is None else sp.Matrix(self._reaction_part)

    @cached_property
    def switching(self) -> tuple[sp.Expr, ...]:
        return switching_functions(self._depends_on_u, self.u)

    @cached_property
    def constant_laws(self) -> bool:
        """True when every Phi_j, Psi_j is constant (Proposition 5 applies for k = 1)."""
        return all(c.compliance.constant for c in self.scene.contacts)

    def piece(self, signs) -> sp.Matrix:
        """f on the piece of a sign pattern (numbers or symbols)."""
        return self.f.applyfunc(lambda e: on_piece(e, self.switching, signs, self.u))

    def jacobian(self, signs) -> sp.Matrix:
        """df/du on the piece of a sign pattern, from the terms of f that depend on u."""
        piece = self._depends_on_u.applyfunc(lambda e: on_piece(e, self.switching, signs, self.u))
        return piece.jacobian(self.u)

    @cached_property
    def equations(self) -> list[sp.Eq]:
        """The equations (2.1) as ``Eq(Symbol("u_j'"), ...)``, for display."""
        return [sp.Eq(sp.Symbol(f"{x}'"), r) for x, r in zip(self.state, self.rhs)]

    def _repr_latex_(self) -> str:
        from .latex import _repr_latex

        return _repr_latex(self)
