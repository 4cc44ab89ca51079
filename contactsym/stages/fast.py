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
from ..algebra.fraction_free import solve_fraction_free, t
from ..arguments import checked, require
from ..errors import ContactsymError, SceneError, SingularJacobianError
from ..printing.latex_output import Formula, LatexReprMixin, Numbering, prime, tex

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


def _canonical(arg: sp.Expr, u) -> tuple[sp.Expr, int]:
    """(sigma, c) with arg = c * sigma, c a nonzero number, sigma increasing in the first u it has."""
    first = next(x for x in u if arg.has(x))
    content, sigma = sp.expand(arg).as_content_primitive()  # |2 u - 2 w| and |u - w| switch together
    return (-sigma, -content) if sp.diff(sigma, first).could_extract_minus_sign() else (sigma, content)


@checked(exprs="Sequence[sp.Expr]", u="Sequence[sp.Expr]")
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


@checked(expr="sp.Expr", switching="Sequence[sp.Expr]", signs="Sequence[sp.Expr]", u="Sequence[sp.Expr]")
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
    part of g_j'' without accelerations; see :mod:`contactsym.mechanism.contact_space`. The linearization
    needs only the reaction part, so a large load is never derived for it.
    """
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
        return scene.plain(expr).subs(positions)

    M, W = space.M.applyfunc(place), space.W.applyfunc(place)
    if load:
        second = {sp.diff(q, t, 2): 0 for q in scene.coordinates}
        h = sp.Matrix([place(sp.diff(g, t, 2).subs(second)) for g in scene.gaps])
        (b,) = solve_fraction_free(M, [space.F.applyfunc(place)], W, substitution=rates, offsets=[h])
        return b
    return reaction_part(*reaction_factors(scene, u))


def reaction_part(M, W, loads, multipliers) -> list[sp.Expr]:
    """G u + H phi(u) = W^T M^-1 L m(u) from the factors of :func:`reaction_factors`."""
    columns = solve_fraction_free(M, [loads[:, c] for c in range(loads.cols)], W)
    return [sp.Add(*[c[i] * w for c, w in zip(columns, multipliers)]) for i in range(W.cols)]


def reaction_factors(scene, u) -> tuple[sp.Matrix, sp.Matrix, sp.Matrix, list]:
    """(M, W, L, m(u)) on the contact manifold: the reaction part of f is W^T M^-1 L m(u), with the
    columns of L the gap gradients and the friction directions and m(u) = (u, phi(u)). The
    linearization keeps A = W^T M^-1 L dm/du in these factors (its minors need no division)."""
    space = scene.contact_space
    rate_symbols = {scene.frozen_symbols[sp.diff(q, t)] for q in scene.coordinates}
    positions = {k: v for k, v in scene.manifold.items() if k not in rate_symbols}

    def place(expr):
        return scene.plain(expr).subs(positions)

    frozen = [term for term in space.friction if term is not None]
    loads = sp.Matrix.hstack(*[space.W[:, j] for j in range(scene.k)], *[term[0] for term in frozen])
    to_u = dict(zip(scene.reactions, u))
    multipliers = [*u] + [scene.freeze(term[1]).subs(to_u) for term in frozen]
    return space.M.applyfunc(place), space.W.applyfunc(place), loads.applyfunc(place), multipliers


@checked
def solve_piece(f: sp.Matrix, u: tuple, signs: tuple) -> list[tuple]:
    """Roots of one smooth piece ``f`` of the fast subsystem: a linear solve when f is affine in u.

    Examples
    --------
    >>> u, a = sp.symbols("u a", real=True)
    >>> solve_piece(sp.Matrix([2*u - a]), (u,), (1,))
    [(a/2,)]
    """
    polys = [fj.as_poly(*u) for fj in f]
    if all(p is not None and p.total_degree() <= 1 for p in polys):
        A, b = sp.linear_eq_to_matrix(list(f), list(u))
        det = normalize(A.det(method="berkowitz"))
        if det == 0:
            raise SingularJacobianError(
                f"det A = 0 on the piece with signs {signs}: the equilibria are not isolated and "
                "f(u) = 0 cannot be solved for u; choose parameters with det A != 0."
            )
        adjugate = A.adjugate(method="berkowitz")
        return [tuple(sp.factor_terms(sp.cancel(normalize(x) / det)) for x in adjugate * b)]
    try:
        solutions = sp.solve(list(f), list(u), dict=True)
    except NotImplementedError:
        solutions = []
    if not solutions and _no_real_root(f, u):
        return []
    if not solutions:
        raise ContactsymError(
            f"sympy found no closed-form root of the piece {list(f)} with signs {signs}; "
            "solve f(u) = 0 numerically (contactsym.numerics)."
        )
    return [tuple(sol[x] for x in u) for sol in solutions if all(x in sol for x in u)]


def _no_real_root(f: sp.Matrix, u: tuple) -> bool:
    """True when f is polynomial in u, SymPy finds all its complex roots and none is real
    (u^2 + 1 = 0). An empty real solve alone proves nothing: it is also empty for
    u^5 + u + a, and for other functions solve may return only some roots."""
    if any(fj.as_poly(*u) is None for fj in f):
        return False
    free = [sp.Dummy() for _ in u]
    try:
        roots = sp.solve(list(f.xreplace(dict(zip(u, free)))), free, dict=True)
    except NotImplementedError:
        return False
    complete = roots and all(all(z in root for z in free) for root in roots)
    return bool(complete) and all(any(sp.im(root[z]).is_nonzero for z in free) for root in roots)


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
        names = ["f"] if self.k == 1 else [f"f_{j}" for j in range(1, self.k + 1)]
        f_of_u = [sp.Function(name)(*u) for name in names]

        def row(key, lhs, rhs):
            return NUMBERS.formula(key, lhs, rhs, k=self.k, own=self.paper_equations)

        rows = []
        for j in range(self.k):
            rows.append(row("fast", prime(u[j]), self.Phi[j] * self.v[j] + self.Psi[j] * f_of_u[j]))
            rows.append(row("fast", prime(self.v[j]), f_of_u[j]))
        rows += [row("f", tex(f_of_u[j]), self.f[j]) for j in range(self.k)]
        return tuple(rows)
