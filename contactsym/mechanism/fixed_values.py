"""Partly numeric scenes: parameters fixed at exact numbers before the derivation.

Users often fix masses and lengths and keep angles and friction symbolic. Substituting the
numbers into the mechanical input (the mass matrix, the forces, the gap gradients and the
friction terms of a scene in contact space, or the accelerations) makes every later stage
smaller. :meth:`contactsym.Scene.with_values` checks the values here and hands the
substituted input to a new scene.

A value must be a finite real number: an int, a float, a fraction, or an exact SymPy number
(``pi/2``, ``sqrt(2)/2``; the command line's ``--set alpha=pi/2`` reads the same text with the
package's own formula parser). A float is read as the decimal it prints (0.1 is 1/10). Sines
and cosines of a fixed angle are exact: SymPy evaluates them at the rational multiples of pi it
knows (``sin(pi/4) = sqrt(2)/2``), and the canonical form ties any other pair sin c, cos c by
sin^2 c + cos^2 c = 1 (``pi/7``, a float's decimal 157/200), so that identity never survives in
a printed condition. A float is not kept as a float: the pipeline is exact, and measured on the
brake (alpha fixed at 0.7853981633974483) a kept Float evaluates sin and cos at once and turns
sin^2 + cos^2 into a rational that is not exactly 1 (coefficients of 50 digits that differ in the
17th), where the decimal's rational keeps sin^2 + cos^2 = 1 and prints sin(c) once per term.
Multiple angles of a fixed parameter (``sin(2*alpha)``) are expanded before the value is put in,
so that only sin c and cos c of the value itself appear. A name must be a parameter of the
scene (a symbol of its input other than the coordinates, the reactions and eps), not one
that ``at`` places on the contact manifold; the value must agree with the symbol's declared
sign and keep every declared positive expression positive (an interval 0 < alpha < pi gives
sin(alpha) > 0).
"""

from __future__ import annotations

import dataclasses
import math
from fractions import Fraction
from numbers import Real

import sympy as sp

from ..errors import SceneError
from ..validate import shorten

__all__ = ["input_symbols", "checked_values", "described", "substituted"]


def input_symbols(scene) -> dict[str, sp.Symbol]:
    """The parameters of a scene's mechanical input by name (what :meth:`Scene.with_values` may fix).

    Examples
    --------
    >>> import contactsym as cs
    >>> sorted(input_symbols(cs.scene("brake")))
    ['F_x', 'F_y', 'J', 'alpha', 'm', 'mu', 'r']
    """
    exprs = list(scene.gaps) + list(scene.at.values()) + list(scene.declared_parameters)
    space = scene.contact_space
    if space is not None:
        exprs += [*space.M, *space.F, *space.W] + [x for term in space.friction if term for x in (*term[0], term[1])]
    else:
        exprs += list(scene.accelerations.values())
    taken = {*scene.reactions, *scene.at, scene.eps}
    found = set().union(*[sp.sympify(e).free_symbols for e in exprs])
    found -= {s for s in found if s in taken or getattr(s, "name", "") == "t"}
    return {str(s): s for s in sorted(found, key=str)}


def _exact(value, name: str) -> sp.Expr:
    """``value`` as an exact SymPy number: a rational, or a real constant such as ``pi/2`` or ``sqrt(2)/2``."""
    exact_number = isinstance(value, sp.Expr) and not isinstance(value, sp.Float) and value.is_number
    if isinstance(value, bool) or not (isinstance(value, (Real, sp.Number, Fraction)) or exact_number):
        raise SceneError(f"the value of {name} is {shorten(value)}; give a finite real number (e.g. {name}=1.5).")
    if isinstance(value, float):
        if not math.isfinite(value):
            raise SceneError(f"the value of {name} is {value}; give a finite real number.")
        return sp.Rational(repr(value))
    number = sp.nsimplify(value) if isinstance(value, sp.Float) else sp.sympify(value)
    if not (number.is_Rational or (number.is_real is True and number.is_finite is True)):
        raise SceneError(f"the value of {name} is {shorten(value)}; give a finite real number.")
    if number.atoms(sp.Float):
        raise SceneError(f"the value of {name} is {shorten(value)}; give it exactly, without a float inside.")
    return number


def _holds(number: sp.Expr, sign: str) -> bool:
    """Whether the exact real ``number`` is ``sign`` (positive, negative, nonnegative); SymPy decides a
    constant's sign exactly where it can, else by evaluation with a certified error (``sign`` of N)."""
    known = getattr(number, f"is_{sign}")
    if known is None:
        value = sp.sign(number.evalf(30, strict=True)) if number.is_number else None
        known = {"positive": value == 1, "negative": value == -1, "nonnegative": value in (0, 1)}[sign]
    return bool(known)


def checked_values(scene, values) -> dict[sp.Symbol, sp.Expr]:
    """``values`` ({symbol or name: number}) as {Symbol: exact number}, each checked (module docstring).

    Examples
    --------
    >>> import contactsym as cs
    >>> checked_values(cs.scene("brake"), {"m": 2, "J": 0.5, "alpha": sp.pi/4})
    {m: 2, J: 1/2, alpha: pi/4}
    >>> try:
    ...     checked_values(cs.scene("brake"), {"m": -1})
    ... except cs.SceneError as error:
    ...     print(error)
    m = -1 is not admissible: m is declared positive.
    """
    if not isinstance(values, dict):
        raise SceneError(f"values must be a dict {{parameter: number}}, not {shorten(values)}.")
    known = input_symbols(scene)
    out = {}
    for key, value in values.items():
        name = key if isinstance(key, str) else str(key)
        if isinstance(key, sp.Symbol) and key in scene.at or name in {str(k) for k in scene.at}:
            raise SceneError(
                f"{name} is placed on the contact manifold by the scene's at ({name} = ...); it cannot be fixed."
            )
        if name not in known or (isinstance(key, sp.Symbol) and known[name] != key):
            raise SceneError(
                f"{shorten(key)} is not a parameter of the scene '{scene.name}'; its parameters are "
                f"{', '.join(known) or 'none'}."
            )
        symbol, number = known[name], _exact(value, name)
        for sign in ("positive", "negative", "nonnegative"):
            if getattr(symbol, f"is_{sign}") and not _holds(number, sign):
                raise SceneError(f"{name} = {number} is not admissible: {name} is declared {sign}.")
        out[symbol] = number
    for expr in scene.declared_positive:
        fixed = expr.xreplace(out)
        if fixed.free_symbols == set() and fixed.is_positive is False:
            raise SceneError(
                f"the values {', '.join(f'{k} = {v}' for k, v in out.items())} make {expr} = {fixed}, which the "
                "scene declares positive (a declared interval); choose values inside it."
            )
    return out


def described(description: str, values: dict) -> str:
    """The description with the fixed values said, so that every output (report, conditions) says them.

    Examples
    --------
    >>> described("a rod", {sp.Symbol("m"): sp.Rational(1, 2)})
    'a rod (fixed: m = 1/2)'
    """
    said = ", ".join(f"{k} = {v}" for k, v in values.items())
    return f"{description} (fixed: {said})" if description else f"fixed: {said}"


def _put(expr, values: dict):
    """``expr`` (an expression or a matrix) with ``values`` put in, sin and cos of sums and multiples of a
    fixed parameter expanded first (``sin(2 alpha)`` -> ``2 sin(alpha) cos(alpha)``): each fixed angle then
    enters only as sin and cos of its value, which the canonical form ties by sin^2 + cos^2 = 1.

    Examples
    --------
    >>> a, b = sp.symbols("alpha beta", positive=True)
    >>> _put(sp.cos(2*a) + sp.sin(b), {a: sp.pi/7})
    sin(beta) - 1 + 2*cos(pi/7)**2
    """
    fixed = set(values)

    def multiple(node) -> bool:
        return (
            isinstance(node, (sp.sin, sp.cos))
            and not node.args[0].is_Symbol
            and bool(node.args[0].free_symbols & fixed)
        )

    if expr.has(sp.sin, sp.cos):
        expr = expr.replace(multiple, lambda node: sp.expand_trig(node.func(sp.expand(node.args[0]))))
    return expr.xreplace(values)


def _replaced(law, values):
    """A law (a frozen dataclass) with the values put into its SymPy fields."""
    if law is None or not dataclasses.is_dataclass(law):
        return law
    changes = {
        f.name: _put(getattr(law, f.name), values)
        for f in dataclasses.fields(law)
        if isinstance(getattr(law, f.name), sp.Basic)
    }
    return dataclasses.replace(law, **changes) if changes else law


def substituted(scene, values: dict) -> dict:
    """The keyword arguments of a Scene equal to ``scene`` with ``values`` ({Symbol: number}) put in.

    Examples
    --------
    >>> import contactsym as cs
    >>> parts = substituted(cs.scene("brake"), {sp.Symbol("m", positive=True): 2})
    >>> parts["contact_space"].M[0, 0]
    2
    """

    def put(expr):
        return _put(sp.sympify(expr), values)

    space = scene.contact_space
    if space is not None:
        friction = tuple(None if term is None else (put(term[0]), put(term[1])) for term in space.friction)
        space = dataclasses.replace(space, M=put(space.M), F=put(space.F), W=put(space.W), friction=friction)
    contacts = [
        dataclasses.replace(c, coordinate=put(c.coordinate), friction=_replaced(c.friction, values))
        for c in scene.contacts
    ]
    plan = scene.figure_plan
    if plan is not None:
        fixed = {str(s) for s in values}
        plan = (
            None
            if {plan.x, plan.y} & fixed
            else dataclasses.replace(plan, values={k: v for k, v in plan.values.items() if k not in fixed})
        )
    count = scene.count_presentation
    return dict(
        coordinates=scene.coordinates,
        accelerations=None if space is not None else [put(scene.accelerations[q]) for q in scene.coordinates],
        contacts=contacts,
        contact_space=space,
        name=scene.name,
        description=described(scene.description, values),
        parameters=[p for p in scene.declared_parameters if p not in values] or None,
        at={k: put(v) for k, v in scene.at.items()},
        presentation={k: put(v) for k, v in scene.presentation.items() if k not in values},
        positive=tuple(e for e in (put(p) for p in scene.declared_positive) if e.free_symbols),
        solve_for=None if scene.solve_for in values else scene.solve_for,
        eps=scene.eps,
        count_presentation=None if count is None else {k: put(v) for k, v in count.items() if k not in values},
        figure_plan=plan,
    )
