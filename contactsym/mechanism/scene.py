"""Scenes: a mechanical system with compliant frictional contacts, written once.

A scene holds the accelerations (1.4) ``q'' = G(t, q, q', N)`` of its coordinates and
its contacts (:mod:`contactsym.mechanism.contact`). Each contact has a gap: a coordinate that must
vanish (1.1), or a gap function ``g_j(q)`` for Lagrangian scenes. The scene is this
mechanical input plus a thin cache: the fast subsystem is derived from it, and every
later stage from the stage before (``Linearization(fast, signs)``, ``Stability(lin)``,
``Equilibria(fast)``), computed on first request and cached here.
"""

from __future__ import annotations

from functools import cached_property

import sympy as sp

from ..algebra.basic import expanded_if_small, known_sign, present
from ..algebra.canonical_form import present_factor
from ..arguments import checked
from ..errors import SceneError
from ..parse import sympy_only
from ..printing.latex_output import Formula, LatexReprMixin, tex
from ..validate import lagrangian_parts, scene_options, scene_parts, shorten
from .checks import check_eps, check_equations, check_inertia, check_scene, user_names, with_friction
from .contact import Contact, contact_manifold, frozen_symbol, plain_symbol
from .contact_space import contact_space, mass_determinant, slip_speeds, t
from .equation_numbers import NUMBERS, paper_equations
from .fixed_values import checked_values, substituted
from .friction_geometry import check_friction_geometry
from .scene_stages import SceneStages

__all__ = ["Contact", "Scene", "paper_equations", "plain_symbol", "t"]


class Scene(SceneStages, LatexReprMixin):
    """A mechanical system with k compliant contacts.

    Build one with :meth:`from_accelerations` or :meth:`from_lagrangian`, or take a
    built-in one with :func:`contactsym.mechanism.scene`. Treat a scene as immutable: each stage
    (``fast_subsystem()``, ``linearization()``, ...) is computed on first request and cached.

    Parameters
    ----------
    coordinates : sequence of dynamicsymbols
        The generalized coordinates q.
    accelerations : sequence of sympy expressions
        q'' for each coordinate (1.4), in q, q', the reactions and parameters. Every
        expression given to contactsym is a SymPy object or a number: text is refused
        (:func:`contactsym.parse_expression` reads a formula with declared names).
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
    equations : dict, optional
        The paper's equation numbers of the example the scene reproduces,
        ``{formula key: (numbers, note)}`` (a built-in scene passes its module's ``EQUATIONS``).
    count_presentation : dict, optional
        The presentation the equilibrium counts use instead of ``presentation`` (e.g.
        ``mu_j = |v_j|/kappa`` where the counts do not depend on the signs).
    figure_plan : FigurePlan, optional
        What the report draws (a scene file's ``[figures]``,
        :class:`contactsym.mechanism.files.FigurePlan`).
    inertia : 'proved', optional
        The masses and inertias are already proved positive for every admissible value (as
        :meth:`with_values` knows of a scene proved so): the check is not repeated.

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
        equations: dict | None = None,
        count_presentation: dict | None = None,
        figure_plan=None,
        inertia: str | None = None,
    ):
        derived = contact_space is not None
        coordinates, accelerations, contacts = scene_parts(coordinates, accelerations, contacts, derived=derived)
        scene_options(name, description, at, presentation, parameters, positive, solve_for)
        self.name = name
        self.description = description
        self.coordinates = tuple(coordinates)
        self.contacts = tuple(contacts)
        #: Lagrange's equations in contact-space parts (``mechanics.ContactSpace``), or None.
        self.contact_space = contact_space
        if accelerations is not None:
            self.accelerations = dict(zip(self.coordinates, (sympy_only(g, "an acceleration") for g in accelerations)))
        #: The symbols declared as parameters (they are never the pipeline's frozen state).
        self.declared_parameters = tuple(parameters) if parameters is not None else ()
        self.at = {sympy_only(k, "a key of at"): sympy_only(v, "a value of at") for k, v in (at or {}).items()}
        self.eps = check_eps(eps, self._user_names)
        self.presentation = {
            sympy_only(k, "a presentation key"): sympy_only(v, "a presentation value")
            for k, v in (presentation or {}).items()
        }
        #: The presentation of the equilibrium counts, or None for ``presentation``.
        self.count_presentation = None
        if count_presentation is not None:
            if not isinstance(count_presentation, dict):
                raise SceneError(
                    f"count_presentation must be a dict {{symbol: expression}}, not {shorten(count_presentation)}."
                )
            self.count_presentation = {
                sympy_only(k, "a count_presentation key"): sympy_only(v, "a count_presentation value")
                for k, v in count_presentation.items()
            }
        if figure_plan is not None and not all(
            hasattr(figure_plan, k) for k in ("x", "y", "x_range", "y_range", "values")
        ):
            raise SceneError(
                f"figure_plan = {shorten(figure_plan)} must be a FigurePlan (contactsym.FigurePlan) or None."
            )
        #: What a report draws for this scene (region maps, phase portrait), or None.
        self.figure_plan = figure_plan
        self._declared_positive = tuple(self.plain(e) for e in positive)
        #: The paper's own equation numbers of this scene, {formula key: (numbers, note)}.
        self.equations = check_equations(equations)
        #: The parameter that closed-form regions are solved for, where possible.
        self.solve_for = solve_for
        self._stage_cache: dict = {}
        check_scene(self, parameters)
        #: How the masses and inertias were found positive: 'proved', 'sampled' or 'unchecked'.
        self.inertia = "proved" if inertia == "proved" else check_inertia(self)
        #: The parameters fixed at numbers by :meth:`with_values`, {Symbol: number} (empty: none).
        self.fixed_values: dict = {}

    def with_values(self, values: dict) -> Scene:
        """A new scene with some parameters fixed at exact numbers before the derivation.

        ``values`` maps parameters (symbols or their names) to finite real numbers; a float is
        read as the decimal it prints. Every stage of the new scene is derived from the
        substituted input, so it is smaller (masses and lengths fixed, angles and friction
        symbolic is the usual case). The new scene's ``fixed_values`` lists what was fixed.
        See :mod:`contactsym.mechanism.fixed_values` for the checks (a name that is not a
        parameter, a value against a declared sign or interval: a SceneError).

        Examples
        --------
        >>> import contactsym as cs
        >>> brake = cs.scene("brake").with_values({"m": 2, "J": 0.5, "r": 1})
        >>> brake.fixed_values
        {m: 2, J: 1/2, r: 1}
        >>> brake.linearization().A[0, 1]
        mu*sin(alpha)/2 - cos(alpha)/2
        >>> try:
        ...     cs.scene("brake").with_values({"x": 1})
        ... except cs.SceneError as error:
        ...     print(str(error).split(";")[0])
        'x' is not a parameter of the scene 'brake'
        """
        fixed = checked_values(self, values)
        # proved positive for every admissible value: so for the admissible values left (a slice)
        scene = Scene(**substituted(self, fixed), inertia=self.inertia if self.inertia == "proved" else None)
        scene.fixed_values = {**self.fixed_values, **fixed}
        return scene

    @property
    def declared_positive(self) -> tuple:
        """The expressions declared positive (``positive=``, a file's intervals), on plain symbols."""
        return self._declared_positive

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
        coordinates, accelerations, contacts = scene_parts(coordinates, accelerations, contacts)
        accelerations = with_friction(coordinates, accelerations, contacts)
        return cls(coordinates, accelerations, contacts, **options)

    @classmethod
    def from_lagrangian(cls, lagrangian, coordinates, contacts, loads=(), frame=None, **options) -> Scene:
        """A scene from a Lagrangian, via ``sympy.physics.mechanics.LagrangesMethod``.

        See :func:`contactsym.mechanism.contact_space.lagrangian_accelerations`. Friction at a point
        is refused unless its direction is a unit vector and, in the plane, the gap is the distance
        of the point from its surface (:func:`contactsym.mechanism.friction_geometry.check_friction_geometry`).
        """
        coordinates, _, contacts = scene_parts(coordinates, None, contacts, derived=True)
        lagrangian = sympy_only(lagrangian, "the Lagrangian")
        lagrangian_parts(lagrangian, loads, frame)
        space = contact_space(lagrangian, coordinates, contacts, loads, frame)
        scene = cls(coordinates, None, contacts, contact_space=space, **options)
        check_friction_geometry(scene, frame)  # a unit direction, a gap that is the distance
        return scene

    @cached_property
    def positive_expressions(self) -> tuple:
        """Expressions positive throughout the scene's domain: the declared ones (e.g.
        sin(alpha), 0 < alpha < pi) and, for a Lagrangian scene, ``mass_matrix_factor``."""
        factor = self.mass_matrix_factor
        return self._declared_positive + (() if factor is None else (factor,))

    @cached_property
    def mass_matrix_factor(self) -> sp.Expr | None:
        """For a Lagrangian scene, the factor of det M > 0 on the contact manifold that is not a
        monomial, with the sign that makes it positive (M is positive definite); else None."""
        if self.contact_space is None:
            return None
        inverse = mass_determinant(self.contact_space.M.applyfunc(self.freeze))
        monomial, rest = inverse.denominator_split()
        sign = known_sign(monomial / inverse.numerator_expr(), self._declared_positive)
        if sign is None or rest == 1:
            return None
        form, scale = present_factor(rest, inverse.pairs)
        return (1 if scale > 0 else -1) * sign * form

    @cached_property
    def slip_speeds(self) -> tuple:
        """Per contact, the sliding speed (plain symbols) its Coulomb law takes to be positive, or None
        (see :func:`contactsym.mechanism.contact_space.slip_speeds`); simulations stop where one reaches 0."""
        speeds = slip_speeds(self.contacts, self.coordinates, self.contact_space)
        return tuple(None if v is None else self.plain(v) for v in speeds)

    @cached_property
    def accelerations(self) -> dict:
        """q'' for each coordinate (1.4); for a Lagrangian scene built on first request."""
        return dict(zip(self.coordinates, self.contact_space.accelerations))

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
        return tuple(_replaced(sp.diff(g, t, 2), rates) for g in self.gaps)

    @cached_property
    def frozen_symbols(self) -> dict:
        """Plain symbols for the slow state frozen in the fast subsystem: q(t) -> q, q' -> qdot.

        A declared parameter of the same name (``parameters=[ydot]``) stays the user's: the
        frozen state is then a ``PaperSymbol`` printed with a hat (``ydothat``).
        """
        taken = {str(p) for p in self.declared_parameters}
        symbols = {sp.diff(q, t): frozen_symbol(q, "dot", taken) for q in self.coordinates}
        symbols.update({q: frozen_symbol(q, "", taken) for q in self.coordinates})
        return symbols

    @cached_property
    def _user_names(self) -> frozenset:
        """The names of the symbols the user gave (parameters, reactions, coordinates), without the frozen state."""
        return user_names(self)

    @cached_property
    def symbol_names(self) -> frozenset:
        """The printed names of the scene's own symbols: its parameters, reactions and frozen state.

        The pipeline's symbols (u_j, v_j, epsilon, tau) avoid these names when they print.
        """
        return self._user_names | {str(s) for s in self.frozen_symbols.values()}

    @checked
    def plain(self, expr: sp.Expr) -> sp.Expr:
        """``expr`` with the slow state in plain symbols: q(t) -> q, q'(t) -> qdot (see ``frozen_symbols``)."""
        expr = sympy_only(expr, "the expression")
        frozen = expr.xreplace(self.frozen_symbols)  # rates first: xreplace matches q' before entering it
        if not frozen.has(t):
            return frozen
        rates = {d: s for d, s in self.frozen_symbols.items() if isinstance(d, sp.Derivative)}
        return expr.subs(rates).subs(self.frozen_symbols)  # e.g. a derivative of a product: subs knows how

    @cached_property
    def manifold(self) -> dict:
        """Substitution that puts the frozen state on the contact manifold g = 0, g' = 0.

        Coordinates and rates are eliminated where the gaps are linear in them; the
        scene's ``at`` mapping (coordinates or parameters at contact) fixes the rest.
        """
        return contact_manifold(self.plain, self.frozen_symbols, self.coordinates, self.gaps, self.at)

    @cached_property
    def free_coordinates(self) -> tuple:
        """The coordinates (dynamicsymbols) that rigid contact leaves free to move."""
        fixed = set(self.manifold)
        return tuple(
            q for q in self.coordinates if self.plain(q) not in fixed and self.plain(sp.diff(q, t)) not in fixed
        )

    @checked
    def freeze(self, expr: sp.Expr) -> sp.Expr:
        """Evaluate on the contact manifold with the slow state frozen (plain symbols)."""
        return _replaced(self.plain(expr), self.manifold)

    # --- presentation -------------------------------------------------------------

    @property
    def parameters(self) -> tuple[sp.Symbol, ...]:
        """The symbols of the fast subsystem other than u, v: loads, geometry, frozen state."""
        return self.fast_subsystem().parameters

    @checked(expr="sp.Basic | sp.MatrixBase")
    def present(self, expr: sp.Expr, signs=None, presentation: dict | None = None) -> sp.Expr:
        """Rewrite in the scene's presentation variables (e.g. kappa, v_j, mu_pm).

        ``signs`` gives the sign pattern of ``expr`` when it belongs to one piece, so that the
        presentation's sign symbols (v_j = kappa s_j mu_j) take its values; ``presentation``
        replaces the scene's own substitutions (see :func:`contactsym.algebra.basic.present`).
        """
        return present(expr, self.presentation if presentation is None else presentation, signs)

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """The accelerations (1.4) and, for gap functions, the contact accelerations g_j''."""

        def row(key, lhs, rhs, detail):
            return NUMBERS.formula(key, lhs, rhs, k=self.k, own=self.equations, detail=detail)

        rows = []
        for q in self.coordinates:
            plain = self.plain(q)
            rows.append(
                row("accelerations", r"\ddot{" + tex(plain) + "}", self.plain(self.accelerations[q]), str(plain))
            )
        if all(gap in self.coordinates for gap in self.gaps):
            return tuple(rows)  # the contact accelerations are among the accelerations above
        for j, g in enumerate(self.gap_accelerations, 1):
            lhs = r"\ddot{q}" + (f"_{{{j}}}" if self.k > 1 else "")
            rows.append(row("contact accelerations", lhs, expanded_if_small(self.freeze(g)), str(j)))
        return tuple(rows)

    def __repr__(self) -> str:
        return f"<Scene '{self.name}': {len(self.coordinates)} coordinates, k = {self.k} contacts>"


def _replaced(expr: sp.Basic, substitution: dict) -> sp.Basic:
    """``expr.subs(substitution)``, by ``xreplace`` when the values hold no key (the same result, in a
    fraction of the time on large expressions: the stool's contact accelerations 5.7 s -> 0.03 s)."""
    if any(value.has(*substitution) for value in substitution.values()):
        return expr.subs(substitution)  # sequential substitution: a value's keys are replaced too
    return expr.xreplace(substitution)
