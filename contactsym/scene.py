"""Scenes: a mechanical system with compliant frictional contacts, written once.

A scene holds the accelerations (1.4) ``q'' = G(t, q, q', N)`` of its coordinates and
its contacts. Each contact has a gap: a coordinate that must vanish (1.1), or a gap
function ``g_j(q)`` for Lagrangian scenes. Every later stage of the pipeline is computed
lazily from the scene and cached on it.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from functools import cached_property

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

from .algebra import known_sign
from .errors import SceneError, SignPatternError
from .laws import Compliance, Coulomb, Generic, Viscous

__all__ = ["Contact", "Scene", "t"]

t = dynamicsymbols._t


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
        if self.compliance is None:
            object.__setattr__(self, "compliance", Generic())
        if not isinstance(self.reaction, sp.Symbol):
            raise SceneError(f"the reaction of a contact must be a sympy Symbol, not {self.reaction!r}.")

    def __repr__(self) -> str:
        side = ", unilateral" if self.unilateral else ""
        return f"Contact({self.coordinate}, {self.reaction}, {self.compliance!r}{side})"


def _plain(symbol: sp.Expr, suffix: str = "") -> sp.Symbol:
    """A plain real symbol for a frozen coordinate q(t) or its rate ('qdot', 'xdot_1': printed with a dot)."""
    name = symbol.func.__name__ if isinstance(symbol, sp.core.function.AppliedUndef) else str(symbol)
    base, underscore, index = name.partition("_")
    return sp.Symbol(base + suffix + underscore + index, real=True)


def _solve_linear(equations: list[sp.Expr], candidates: list[sp.Symbol]) -> dict:
    """Solve equations, linear in some of the candidates, uniquely for the fewest of them."""
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


def _check_eps(eps) -> sp.Expr:
    """eps is the small positive parameter of (1.6): a positive symbol or number."""
    if eps is None:
        return sp.Symbol("epsilon", positive=True)
    eps = sp.sympify(eps)
    if eps.is_positive:
        return eps
    if eps.is_positive is False:
        raise SceneError(f"eps = {eps} must be > 0: it is the small time scale of the deformations (1.6).")
    raise SceneError(f"cannot show eps = {eps} > 0; use sympy.Symbol('{eps}', positive=True) or a positive number.")


class Scene:
    """A mechanical system with k compliant contacts.

    Build one with :meth:`from_accelerations` or :meth:`from_lagrangian`, or take a
    built-in one with :func:`contactsym.scene`. Treat a scene as immutable: each stage
    (``fast_subsystem()``, ``linearization()``, ...) is computed on first request and cached.

    Parameters
    ----------
    coordinates : sequence of dynamicsymbols
        The generalized coordinates q.
    accelerations : sequence of sympy expressions
        q'' for each coordinate (1.4), in q, q', the reactions and parameters.
    contacts : sequence of Contact
    name, description : str
        For listings and reports.
    parameters : sequence of Symbol, optional
        If given, every free symbol of the accelerations must be among them (catches typos).
    at : dict, optional
        Coordinates or parameters at rigid contact that the gaps do not fix by themselves
        (e.g. ``{h: l*sin(phi)}`` for the guides of §5).
    presentation : dict, optional
        Substitutions into the variables a reader uses (kappa, v_j, mu_pm, ...).
    positive : tuple, optional
        Expressions positive in the scene's domain (e.g. ``sin(alpha)`` for 0 < alpha < pi).
    solve_for : Symbol, optional
        The parameter that closed-form regions are solved for where possible.
    eps : Symbol or number, optional
        The small parameter of (1.6); a positive symbol ``epsilon`` by default.

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> x, y = dynamicsymbols("x y")
    >>> N, mu, X, Y = sp.symbols("N mu X Y", real=True)
    >>> s = cs.Scene.from_accelerations([x, y], [X - mu*sp.Abs(N), N + Y],
    ...                                  [cs.Contact(coordinate=y, reaction=N)])
    >>> s.fast_subsystem().f
    Matrix([[Y + u]])
    """

    def __init__(
        self,
        coordinates,
        accelerations,
        contacts,
        *,
        name: str = "user",
        parameters=None,
        at: dict | None = None,
        presentation: dict | None = None,
        positive: tuple = (),
        solve_for: sp.Symbol | None = None,
        description: str = "",
        eps: sp.Symbol | None = None,
        contact_space=None,
    ):
        self.name = name
        self.description = description
        self.coordinates = tuple(coordinates)
        self.contacts = tuple(contacts)
        #: Lagrange's equations in contact-space parts (``mechanics.ContactSpace``), or None.
        self.contact_space = contact_space
        if accelerations is not None:
            self.accelerations = dict(zip(self.coordinates, (sp.sympify(g) for g in accelerations)))
        self.eps = _check_eps(eps)
        self.at = dict(at or {})
        self.presentation = dict(presentation or {})
        self._declared_positive = tuple(self._plain(e) for e in positive)
        #: The parameter that closed-form regions are solved for, where possible.
        self.solve_for = solve_for
        self._stage_cache: dict = {}
        self._check(accelerations, parameters)

    # --- construction ------------------------------------------------------------

    @classmethod
    def from_accelerations(cls, coordinates, accelerations, contacts, **options) -> Scene:
        """A scene from its accelerations (1.4): ``coordinates[i]'' = accelerations[i]``.

        Friction may be written out with ``Abs(N)``/``sign(N)``, or attached to a
        contact as ``Coulomb(mu, direction={coordinate: coefficient})``.

        Examples
        --------
        >>> import sympy as sp
        >>> from sympy.physics.mechanics import dynamicsymbols
        >>> import contactsym as cs
        >>> x, y = dynamicsymbols("x y")
        >>> N, mu = sp.symbols("N mu", real=True)
        >>> c = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1}))
        >>> cs.Scene.from_accelerations([x, y], [0, N - 1], [c]).accelerations[x]
        -mu*Abs(N)
        """
        accelerations = [sp.sympify(g) for g in accelerations]
        if len(accelerations) != len(coordinates):
            raise SceneError(
                f"got {len(accelerations)} accelerations for {len(coordinates)} coordinates; give one per coordinate."
            )
        for contact in contacts:
            if contact.coordinate not in coordinates:
                raise SceneError(
                    f"contact coordinate {contact.coordinate} is not among the coordinates "
                    f"{list(coordinates)}; add it, or use Scene.from_lagrangian for a gap function."
                )
            law = contact.friction
            if law is None:
                continue
            if not isinstance(law.direction, dict):
                raise SceneError("with from_accelerations, give a friction direction as {coordinate: coefficient}.")
            for coordinate, coefficient in law.direction.items():
                if coordinate not in coordinates:
                    raise SceneError(
                        f"the friction direction names {coordinate}, which is not among the coordinates "
                        f"{list(coordinates)}; use one of them."
                    )
                index = list(coordinates).index(coordinate)
                slip = sp.diff(coordinate, t)
                accelerations[index] -= law.magnitude(contact.reaction, slip) * coefficient
        return cls(coordinates, accelerations, contacts, **options)

    @classmethod
    def from_lagrangian(cls, lagrangian, coordinates, contacts, loads=(), frame=None, **options) -> Scene:
        """A scene from a Lagrangian, via ``sympy.physics.mechanics.LagrangesMethod``.

        See :func:`contactsym.mechanics.lagrangian_accelerations`.
        """
        from .mechanics import contact_space

        space = contact_space(lagrangian, coordinates, contacts, loads, frame)
        return cls(coordinates, None, contacts, contact_space=space, **options)

    @cached_property
    def positive_expressions(self) -> tuple:
        """Expressions positive throughout the scene's domain: the declared ones (e.g.
        sin(alpha), 0 < alpha < pi) and, for a Lagrangian scene, the factor of det M > 0
        on the contact manifold that is not a monomial (when it is irreducible)."""
        if self.contact_space is None:
            return self._declared_positive
        from .canonical import present_factor
        from .mechanics import mass_determinant

        inverse = mass_determinant(self.contact_space.M.applyfunc(self.freeze))
        monomial, rest = inverse.denominator_split()
        sign = known_sign(monomial / inverse.numerator_expr(), self._declared_positive)
        if sign is None or rest == 1:
            return self._declared_positive
        form, scale = present_factor(rest, inverse.pairs)
        return self._declared_positive + ((1 if scale > 0 else -1) * sign * form,)

    @cached_property
    def accelerations(self) -> dict:
        """q'' for each coordinate (1.4); for a Lagrangian scene built on first request."""
        return dict(zip(self.coordinates, self.contact_space.accelerations))

    def _check(self, accelerations, parameters) -> None:
        if not self.contacts:
            raise SceneError("a scene needs at least one Contact.")
        for contact in self.contacts:
            q = contact.coordinate
            if isinstance(q, sp.core.function.AppliedUndef) and q not in self.coordinates:
                raise SceneError(
                    f"contact coordinate {q} is not among the coordinates {list(self.coordinates)}; add it."
                )
        reactions = {c.reaction for c in self.contacts}
        if len(reactions) != len(self.contacts):
            raise SceneError("two contacts share one reaction symbol; give each contact its own.")
        if self.contact_space is not None:  # Lagrangian: the gap gradients carry the reactions
            space = self.contact_space
            stated = [*space.M, *space.F, *space.W] + [
                x for term in space.friction if term for x in (*term[0], term[1])
            ]
        else:
            if len(self.accelerations) != len(self.coordinates):
                raise SceneError("give each coordinate exactly one acceleration.")
            if not any(g.has(*reactions) for g in self.accelerations.values()):
                raise SceneError(
                    f"no acceleration depends on the reactions {sorted(map(str, reactions))}; "
                    "the contacts must act on the system (check the reaction symbols)."
                )
            stated = list(self.accelerations.values())
        if parameters is not None:
            declared = set(parameters) | reactions | {self.eps}
            unknown = {s for g in stated for s in sp.sympify(g).free_symbols} - declared - {t}
            if unknown:
                raise SceneError(
                    f"symbols {sorted(map(str, unknown))} are not among the declared parameters; "
                    "declare them or fix the spelling."
                )

    # --- the contact manifold (1.1) ----------------------------------------------

    @property
    def k(self) -> int:
        """Number of contacts."""
        return len(self.contacts)

    @property
    def reactions(self) -> tuple[sp.Symbol, ...]:
        return tuple(c.reaction for c in self.contacts)

    @cached_property
    def gaps(self) -> tuple[sp.Expr, ...]:
        return tuple(c.coordinate for c in self.contacts)

    @cached_property
    def gap_accelerations(self) -> tuple[sp.Expr, ...]:
        """g_j'' with the accelerations (1.4) substituted."""
        rates = {sp.diff(q, t, 2): g for q, g in self.accelerations.items()}
        return tuple(sp.diff(g, t, 2).subs(rates) for g in self.gaps)

    @cached_property
    def frozen_symbols(self) -> dict:
        """Plain symbols for the slow state frozen in the fast subsystem: q(t) -> q, q' -> qdot."""
        symbols = {sp.diff(q, t): _plain(q, "dot") for q in self.coordinates}
        symbols.update({q: _plain(q) for q in self.coordinates})
        return symbols

    def _plain(self, expr: sp.Expr) -> sp.Expr:
        rates = {d: s for d, s in self.frozen_symbols.items() if isinstance(d, sp.Derivative)}
        return sp.sympify(expr).subs(rates).subs(self.frozen_symbols)

    @cached_property
    def manifold(self) -> dict:
        """Substitution that puts the frozen state on the contact manifold g = 0, g' = 0.

        Coordinates and rates are eliminated where the gaps are linear in them; the
        scene's ``at`` mapping (coordinates or parameters at contact) fixes the rest.
        """
        at = {self._plain(key): self._plain(value) for key, value in self.at.items()}
        gaps = [self._plain(g).subs(at) for g in self.gaps]
        positions = [self.frozen_symbols[q] for q in reversed(self.coordinates)]
        at.update(_solve_linear(gaps, [p for p in positions if p not in at]))
        residual = [g for g in (sp.expand(g.subs(at)) for g in gaps) if g != 0]
        if residual:
            raise SceneError(
                f"cannot place the state on the contact manifold: gaps {residual} do not vanish; "
                "pass at={...} giving coordinates or parameters at contact."
            )
        rates = [self._plain(sp.diff(g, t)).subs(at) for g in self.gaps]
        # eliminate first the rates of the coordinates whose positions the gaps fixed
        order = sorted(reversed(self.coordinates), key=lambda q: self.frozen_symbols[q] not in at)
        velocities = [self.frozen_symbols[sp.diff(q, t)] for q in order]
        at.update(_solve_linear(rates, velocities))
        if any(sp.expand(r.subs(at)) != 0 for r in rates):
            raise SceneError("the contact rates g_j' cannot all vanish: the contacts are redundant or inconsistent.")
        return at

    @cached_property
    def free_coordinates(self) -> tuple:
        """The coordinates (dynamicsymbols) that rigid contact leaves free to move."""
        fixed = set(self.manifold)
        return tuple(
            q for q in self.coordinates if self._plain(q) not in fixed and self._plain(sp.diff(q, t)) not in fixed
        )

    def freeze(self, expr: sp.Expr) -> sp.Expr:
        """Evaluate on the contact manifold with the slow state frozen (plain symbols)."""
        return self._plain(expr).subs(self.manifold)

    # --- sign patterns ------------------------------------------------------------

    @cached_property
    def fixed_signs(self) -> dict:
        """Switching functions whose sign the scene fixes (unilateral contacts: u_j > 0)."""
        fast = self.fast_subsystem()
        fixed = {}
        for u, contact in zip(fast.u, self.contacts):
            if contact.unilateral:
                fixed[u] = 1
        return fixed

    def sign_patterns(self) -> list[tuple[int, ...]]:
        """All admissible sign patterns of the switching functions (fixed ones kept)."""
        switching = self.fast_subsystem().switching
        choices = [(self.fixed_signs[s],) if s in self.fixed_signs else (1, -1) for s in switching]
        return list(itertools.product(*choices))

    def check_signs(self, signs) -> tuple:
        """Validate a sign pattern against the switching functions of the fast subsystem."""
        switching = self.fast_subsystem().switching
        signs = tuple(signs)
        if len(signs) != len(switching):
            raise SignPatternError(
                f"the sign pattern {signs} has length {len(signs)}, but scene '{self.name}' has "
                f"{len(switching)} switching functions {list(switching)}; give one sign (+1 or -1) each."
            )
        for value, s in zip(signs, switching):
            if isinstance(value, bool) or value not in (1, -1):
                raise SignPatternError(f"sign {value!r} for {s} must be +1 or -1.")
            if self.fixed_signs.get(s, value) != value:
                raise SignPatternError(f"{s} > 0 on the unilateral contact; its sign must be +1.")
        return signs

    # --- stages -------------------------------------------------------------------

    def _stage(self, key, build):
        if key not in self._stage_cache:
            self._stage_cache[key] = build()
        return self._stage_cache[key]

    def regularized(self):
        """The system (1.7)/(1.9) in slow and fast variables (see :mod:`contactsym.regularize`)."""
        from .regularize import Regularized

        return self._stage("regularized", lambda: Regularized(self))

    def fast_subsystem(self):
        """The associated system (2.1): ``u' = Phi v + Psi f(u)``, ``v' = f(u)``."""
        from .fast import FastSubsystem

        return self._stage("fast", lambda: FastSubsystem(self))

    def equilibria(self, signs=None):
        """Equilibria of the fast subsystem, one branch per sign pattern (4.2)."""
        from .equilibria import Equilibria

        key = None if signs is None else self.check_signs(signs)
        return self._stage(("equilibria", key), lambda: Equilibria(self, key))

    def linearization(self, signs=None):
        """Jacobian A (4.3), the matrix (4.5) and the characteristic polynomial (4.6)."""
        from .linear import Linearization

        key = None if signs is None else self.check_signs(signs)
        return self._stage(("linear", key), lambda: Linearization(self, key))

    def stability(self, signs=None):
        """Hurwitz conditions (4.7) and the robustness classification (Props. 3-8)."""
        from .stability import Stability

        return self._stage(("stability", signs and tuple(signs)), lambda: Stability(self.linearization(signs)))

    def regions(self, signs=None) -> dict:
        """Named closed-form regions: stable / unstable for every law, law-dependent, Hopf line."""
        from .regions import scene_regions

        return self._stage(("regions", signs and tuple(signs)), lambda: scene_regions(self, signs))

    def equilibrium_counts(self) -> dict:
        """Named closed-form regions by the number of equilibria (see :mod:`contactsym.counts`)."""
        from .counts import count_regions

        return self._stage("counts", lambda: count_regions(self))

    def reduced_system(self, signs=None):
        """The comparison system (2.2): slow motion with reactions from f(u*) = 0."""
        from .regularize import ReducedSystem

        key = None if signs is None else self.check_signs(signs)
        return self._stage(("reduced", key), lambda: ReducedSystem(self, key))

    # --- presentation -------------------------------------------------------------

    @cached_property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The symbols of the fast subsystem other than u, v: loads, geometry, frozen state."""
        fast = self.fast_subsystem()
        exprs = list(fast.f) + list(fast.Phi) + list(fast.Psi)
        free = set().union(*(e.free_symbols for e in exprs)) - set(fast.u) - set(fast.v)
        return tuple(sorted(free, key=str))

    def present(self, expr: sp.Expr, signs=None, presentation: dict | None = None) -> sp.Expr:
        """Rewrite in the scene's presentation variables (e.g. kappa, v_j, mu_pm).

        ``signs`` gives the sign pattern of ``expr`` when it belongs to one piece, so
        that the presentation's sign symbols (v_j = kappa s_j mu_j) take its values;
        ``presentation`` replaces the scene's own substitutions.
        """
        from .algebra import reduce_signs, sign_symbols

        expr = sp.sympify(expr)
        presentation = self.presentation if presentation is None else presentation
        if not presentation or expr in (sp.true, sp.false):
            return expr
        if isinstance(expr, (sp.core.relational.Relational, sp.logic.boolalg.BooleanFunction)):
            return expr.func(*[self.present(arg, signs, presentation) for arg in expr.args])
        if signs is not None:
            values = dict(zip(sign_symbols(len(signs)), signs))
            presentation = {k: sp.sympify(v).subs(values) for k, v in presentation.items()}
        replaced = expr.subs(presentation)
        if isinstance(replaced, sp.MatrixBase):
            return replaced.applyfunc(lambda e: reduce_signs(sp.cancel(sp.expand(e))))
        return reduce_signs(sp.cancel(sp.expand(replaced)))

    def __repr__(self) -> str:
        return f"<Scene '{self.name}': {len(self.coordinates)} coordinates, k = {self.k} contacts>"

    def _repr_latex_(self) -> str:
        from .latex import _repr_latex

        return _repr_latex(self)
