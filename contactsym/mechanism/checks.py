"""Checks of a scene's mechanical input, with messages that say how to fix it.

The small parameter eps (1.6), the paper's numbers of a built-in scene, the friction of
attached laws folded into the accelerations (1.4), the consistency of coordinates,
contacts, reactions and declared parameters, and the names the user's symbols take (the
pipeline's own symbols print apart from them). Positive masses and inertias (a positive
definite mass matrix) are checked in :mod:`contactsym.mechanism.admissibility`.
"""

from __future__ import annotations

import sympy as sp

from ..algebra.basic import PaperSymbol
from ..arguments import checked
from ..errors import SceneError
from ..parse import sympy_only
from ..printing.glyphs import look_alike
from ..validate import finite_expression, positive_parameter, reactions_act, shorten
from .admissibility import check_delassus, check_inertia, frictionless_part
from .contact import plain_symbol
from .contact_space import t

__all__ = [
    "check_delassus",
    "check_eps",
    "check_equations",
    "check_inertia",
    "check_scene",
    "frictionless_part",
    "user_names",
    "with_friction",
]


@checked(taken="Sequence | set | frozenset")
def check_eps(eps, taken=()) -> sp.Expr:
    """eps is the small positive parameter of (1.6): a positive symbol or number.

    By default the paper's ``epsilon``, a ``PaperSymbol`` (``epsilonhat`` when a symbol of the
    scene, ``taken``, is called epsilon).

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.errors import SceneError
    >>> check_eps(None), check_eps(sp.Rational(1, 100))
    (epsilon, 1/100)
    >>> try:
    ...     check_eps(-1)
    ... except SceneError as error:
    ...     print(error)
    eps = -1 must be > 0: it is the small time scale of the deformations (1.6).
    """
    if eps is None:
        free = [n for n in ("epsilon", "epsilonhat", "epsiloncheck", "epsilontilde") if n not in taken]
        if not free:
            raise SceneError("the scene's symbols take every name of eps; pass eps=<a positive Symbol> yourself.")
        return PaperSymbol(free[0], positive=True)
    why = "it is the small time scale of the deformations (1.6)"
    eps = sympy_only(eps, "eps")
    positive_parameter(eps, "eps", why)
    if eps.is_positive:
        return eps
    if eps.is_positive is False:
        raise SceneError(f"eps = {shorten(eps)} must be > 0: {why}.")
    raise SceneError(
        f"cannot show eps = {shorten(eps)} > 0; use sympy.Symbol('epsilon', positive=True) or a positive number."
    )


@checked(equations="Mapping | None")
def check_equations(equations) -> dict:
    """The paper's numbers of a scene: ``{formula key: (tuple of numbers, note)}``.

    Examples
    --------
    >>> from contactsym.errors import SceneError
    >>> check_equations({"A": (("6.2",), "")})
    {'A': (('6.2',), '')}
    >>> try:
    ...     check_equations({"A": "6.2"})
    ... except SceneError as error:
    ...     print(error)
    equations['A'] must be (numbers, note), e.g. (("6.2",), ""), not '6.2'.
    """
    equations = dict(equations or {})
    for key, value in equations.items():
        if not (isinstance(key, str) and isinstance(value, tuple) and len(value) == 2):
            raise SceneError(f'equations[{key!r}] must be (numbers, note), e.g. (("6.2",), ""), not {value!r}.')
        numbers, note = value
        if not (isinstance(numbers, tuple) and all(isinstance(n, str) for n in numbers) and isinstance(note, str)):
            raise SceneError(f"equations[{key!r}] must be (tuple of str, str), not {value!r}.")
    return equations


@checked(coordinates="Sequence", accelerations="Sequence", contacts="Sequence[Contact]")
def with_friction(coordinates, accelerations, contacts) -> list[sp.Expr]:
    """The accelerations (1.4) with the force of each contact's attached friction law added.

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> x, y = dynamicsymbols("x y")
    >>> N, mu = sp.symbols("N mu", real=True)
    >>> contact = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1}))
    >>> with_friction([x, y], [0, N - 1], [contact])
    [-mu*Abs(N), N - 1]
    """
    accelerations = [sympy_only(g, "an acceleration") for g in accelerations]
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
    return accelerations


@checked(scene="Scene", parameters="Sequence[sp.Symbol] | None")
def check_scene(scene, parameters) -> None:
    """Contacts, reactions and (when declared) parameters of a scene are consistent.

    Every :class:`~contactsym.mechanism.Scene` runs it when it is made, so an inconsistent scene is
    never built.

    Examples
    --------
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> check_scene(cs.scene("brake"), None) is None
    True
    >>> y = dynamicsymbols("y")
    >>> N, M = sp.symbols("N M", real=True)
    >>> try:  # the acceleration names M, not the contact's reaction N
    ...     cs.Scene.from_accelerations([y], [M - 1], [cs.Contact(coordinate=y, reaction=N)])
    ... except cs.SceneError as error:
    ...     print(str(error).split(";")[0])
    no acceleration depends on the reactions ['N']
    """
    if not scene.contacts:
        raise SceneError("a scene needs at least one Contact.")
    for contact in scene.contacts:
        q = contact.coordinate
        if isinstance(q, sp.core.function.AppliedUndef) and q not in scene.coordinates:
            raise SceneError(f"contact coordinate {q} is not among the coordinates {list(scene.coordinates)}; add it.")
    reactions = {c.reaction for c in scene.contacts}
    if len(reactions) != len(scene.contacts):
        raise SceneError("two contacts share one reaction symbol; give each contact its own.")
    if scene.contact_space is not None:  # Lagrangian: the gap gradients carry the reactions
        space = scene.contact_space
        stated = [*space.M, *space.F, *space.W] + [x for term in space.friction if term for x in (*term[0], term[1])]
        for g in stated:
            finite_expression(sp.sympify(g), "a term of the equations of motion")
    else:
        for q, g in scene.accelerations.items():
            finite_expression(g, f"the acceleration of {q}")
        if len(scene.accelerations) != len(scene.coordinates):
            raise SceneError("give each coordinate exactly one acceleration.")
        if not any(g.has(*reactions) for g in scene.accelerations.values()):
            raise SceneError(
                f"no acceleration depends on the reactions {sorted(map(str, reactions))}; "
                "the contacts must act on the system (check the reaction symbols)."
            )
        reactions_act(scene.accelerations, scene.contacts)
        stated = list(scene.accelerations.values())
    if parameters is not None:
        declared = set(parameters) | reactions | {scene.eps}
        unknown = {s for g in stated for s in sp.sympify(g).free_symbols} - declared - {t}
        if unknown:
            raise SceneError(
                f"symbols {sorted(map(str, unknown))} are not among the declared parameters; "
                "declare them or fix the spelling."
            )


def user_names(scene) -> frozenset:
    """The names of the symbols the user gave a scene (parameters, reactions, coordinates and their rates),
    each also in the spelling of its glyph (``lambda_`` prints as ``lambda``: :func:`~contactsym.printing.look_alike`),
    the time of the coordinates q(t) apart (a user's own ``t`` is a different symbol and counts)."""
    if scene.contact_space is not None:
        space = scene.contact_space
        stated = [*space.M, *space.F, *space.W] + [x for term in space.friction if term for x in (*term[0], term[1])]
    else:
        stated = list(scene.accelerations.values())
    stated += [*scene.gaps, *scene.reactions, *scene.at, *scene.at.values(), *scene.declared_parameters]
    for contact in scene.contacts:
        stated += [*contact.compliance.parameters()]
    names = {str(s) for x in stated for s in sp.sympify(x).free_symbols if s != t}
    for q in scene.coordinates:
        names |= {str(plain_symbol(q)), str(plain_symbol(q, "dot"))}
    return frozenset(names | {look_alike(name) for name in names})
