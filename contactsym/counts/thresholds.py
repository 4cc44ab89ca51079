"""Where the unique count region stops lying inside the region stable for every law (5.9).

:func:`square_threshold` finds the parameter value: a vertex of the unique region (the
intersections of the lines of its ``|.|`` pieces) meets the boundary of the stable region; for
the guides, kappa = sqrt(2)/2, that is phi = arctan(sqrt(2)). :func:`threshold_angle`
returns that angle.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.core.relational import Relational

from ..arguments import checked, require
from ..errors import ContactsymError
from ..stages.regions import Region
from .conditions import count_presentation

__all__ = ["Threshold", "square_threshold", "threshold_angle"]


@checked
@dataclass(frozen=True)
class Threshold:
    """Where the unique region stops lying inside the region stable for every law.

    Attributes
    ----------
    parameter : Symbol
        The parameter that moves the regions (kappa for the guides).
    value : sympy expression
        Its critical value, exact.
    inside : sympy Boolean
        Where the unique region lies inside the stable region, in the parameter, or in
        the angle when the scene presents one (phi >= atan(sqrt(2)) for the guides).
    angle : sympy expression or None
        The critical angle, when the parameter is a cotangent of a scene angle.
    vertex : tuple
        The vertex of the unique region that meets the boundary there.

    Examples
    --------
    For the guides the parameter is kappa = cot(phi), so the critical value and angle agree:

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> th = square_threshold(cs.scene("painleve-klein-guides"))
    >>> isinstance(th, Threshold), th.parameter, sp.cot(th.angle) == th.value
    (True, kappa, True)
    """

    parameter: sp.Symbol
    value: sp.Expr
    inside: sp.Basic
    angle: sp.Expr | None = None
    vertex: tuple = ()


def _atoms(condition) -> list[Relational]:
    return [a for a in sp.sympify(condition).atoms(Relational)]


def _abs_lines(condition, plane) -> list[sp.Expr]:
    """The lines (expressions = 0) along which the atoms of a condition with |.| change."""
    lines = []
    for atom in _atoms(condition):
        expr = atom.lhs - atom.rhs
        absolutes = sorted(expr.atoms(sp.Abs), key=sp.default_sort_key)
        for choice in itertools.product((1, -1), repeat=len(absolutes)):
            # innermost first: replace an Abs whose argument has no Abs left
            line = expr
            for a, s in sorted(zip(absolutes, choice), key=lambda pair: sp.count_ops(pair[0])):
                line = line.xreplace({a: s * a.args[0]})
            line = sp.expand(line)
            if line.free_symbols & set(plane) and line not in lines and -line not in lines:
                lines.append(line)
    return lines


def _closure(condition):
    weak = {sp.StrictLessThan: sp.Le, sp.StrictGreaterThan: sp.Ge}
    return sp.sympify(condition).replace(lambda e: type(e) in weak, lambda e: weak[type(e)](e.lhs, e.rhs))


def _vertices(condition, plane) -> list[dict]:
    lines = _abs_lines(condition, plane)
    closed = _closure(condition)
    vertices = []
    for a, b in itertools.combinations(lines, 2):
        solution = sp.solve([a, b], list(plane), dict=True)
        if len(solution) != 1 or set(solution[0]) != set(plane):
            continue
        point = solution[0]
        if closed.xreplace(point) == sp.true and point not in vertices:
            vertices.append(point)
    return vertices


def _inside_on_grid(unique: Region, stable: Region, plane, parameter, value: float, vertices, size=161) -> bool:
    """Every grid point of the unique region lies in the stable region (decides a side only)."""
    corners = np.array([[float(v[x].subs(parameter, value)) for x in plane] for v in vertices])
    low, high = corners.min(axis=0), corners.max(axis=0)
    axes = [np.linspace(lo, hi, size) for lo, hi in zip(low, high)]
    grid = np.meshgrid(*axes, indexing="ij")
    arrays = {str(x): g for x, g in zip(plane, grid)}
    arrays[str(parameter)] = np.full(grid[0].shape, value)
    chosen = unique.evaluate(**{k: v for k, v in arrays.items() if k in unique.symbol_names})
    chosen = np.broadcast_to(chosen, grid[0].shape)
    good = stable.evaluate(**{k: v for k, v in arrays.items() if k in stable.symbol_names})
    return bool(np.all(np.broadcast_to(good, grid[0].shape)[chosen]))


@checked(scene="Scene")
def square_threshold(scene, unique: str = "unique", stable: str = "stable for every law") -> Threshold:
    """The parameter value at which the unique region leaves the region stable for every law.

    A vertex of the unique region (intersections of the lines of its |.| pieces) meets
    the boundary of the stable region (a factor of one of its inequalities vanishes):
    the candidates are solved exactly; a grid test on each side of every candidate picks
    the one where containment changes.

    Parameters
    ----------
    scene : Scene
        A scene whose count regions and stability regions live in one plane and one parameter.
    unique, stable : str
        Names of the two regions.

    Returns
    -------
    Threshold

    Examples
    --------
    >>> import contactsym as cs
    >>> th = square_threshold(cs.scene("painleve-klein-guides"))
    >>> th.value, th.angle, th.inside
    (sqrt(2)/2, atan(sqrt(2)), phi >= atan(sqrt(2)))
    """
    return scene.cached(("square threshold", unique, stable), lambda: _square_threshold(scene, unique, stable))


@checked(scene="Scene")
def threshold_angle(scene, unique: str = "unique", stable: str = "stable for every law") -> sp.Expr:
    """The angle at which the unique region leaves the region stable for every law (5.9).

    Examples
    --------
    >>> import contactsym as cs
    >>> threshold_angle(cs.scene("painleve-klein-guides"))
    atan(sqrt(2))
    """
    angle = square_threshold(scene, unique, stable).angle
    if angle is None:
        raise ContactsymError(f"scene '{scene.name}' presents no angle; use square_threshold(...).value.")
    return angle


def _square_threshold(scene, unique: str, stable: str) -> Threshold:
    require(unique in scene.equilibrium_counts(), "square_threshold", "unique", unique, "a key of equilibrium_counts()")
    require(stable in scene.regions(), "square_threshold", "stable", stable, "a key of scene.regions()")
    inner = scene.equilibrium_counts()[unique]
    outer = scene.regions()[stable]
    plane = sorted({s for a in inner.condition.atoms(sp.Abs) for s in a.free_symbols}, key=str)
    rest = (inner.condition.free_symbols | outer.condition.free_symbols) - set(plane)
    if len(plane) != 2 or len(rest) != 1:
        raise ContactsymError(
            f"square_threshold needs a plane of two variables and one parameter; found plane {plane}, "
            f"parameters {sorted(map(str, rest))}."
        )
    (parameter,) = rest
    vertices = _vertices(inner.condition, plane)
    factors = []
    for atom in _atoms(outer.condition):
        for base, _ in sp.factor_list(sp.expand(atom.lhs - atom.rhs))[1]:
            if base.free_symbols & set(plane) and base not in factors:
                factors.append(base)
    candidates = {}
    for vertex in vertices:
        for factor in factors:
            meeting = sp.expand(factor.xreplace(vertex))
            if meeting == 0 or parameter not in meeting.free_symbols:
                continue
            for root in sp.solve(meeting, parameter):
                if root.is_real and (root.is_positive or not parameter.is_positive):
                    candidates.setdefault(root, tuple(vertex[x] for x in plane))
    if not candidates:
        raise ContactsymError(f"no vertex of '{unique}' meets the boundary of '{stable}'.")
    values = sorted(candidates, key=float)
    floats = [float(v) for v in values]
    samples = [floats[0] / 2, *[(a + b) / 2 for a, b in zip(floats, floats[1:])], floats[-1] * 2]
    inside = [_inside_on_grid(inner, outer, plane, parameter, s, vertices) for s in samples]
    flips = [i for i in range(len(values)) if inside[i] != inside[i + 1]]
    if len(flips) != 1:
        raise ContactsymError(f"containment changes at {len(flips)} candidates {values}; expected one.")
    (i,) = flips
    value = values[i]
    at_value = _inside_on_grid(inner, outer, plane, parameter, floats[i], vertices)
    below = inside[i]  # containment for parameters just below the value
    if below:
        condition = (sp.Le if at_value else sp.Lt)(parameter, value)
    else:
        condition = (sp.Ge if at_value else sp.Gt)(parameter, value)
    angle, in_angle = _as_angle(scene, parameter, value, condition, samples[i] if below else samples[i + 1])
    return Threshold(parameter, value, in_angle if in_angle is not None else condition, angle, candidates[value])


def _as_angle(scene, parameter, value, condition, inside_sample):
    """The angle theta with the parameter a function of it through sin(theta), cos(theta)."""
    presentation = {**scene.presentation, **count_presentation(scene)}
    for key in presentation:
        if not isinstance(key, sp.sin):
            continue
        theta = key.args[0]
        tangent = sp.cancel(presentation[key] / presentation.get(sp.cos(theta), sp.nan))
        if tangent.has(sp.nan) or parameter not in tangent.free_symbols:
            continue
        angle = sp.atan(tangent.subs(parameter, value))
        sample = float(sp.atan(tangent.subs(parameter, inside_sample)))
        above = sample > float(angle)
        weak = isinstance(condition, (sp.LessThan, sp.GreaterThan))
        op = (sp.Ge if weak else sp.Gt) if above else (sp.Le if weak else sp.Lt)
        return angle, op(theta, angle)
    return None, None
