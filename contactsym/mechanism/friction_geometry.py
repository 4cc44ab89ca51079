"""Friction at a point: a unit direction, and a gap that is the distance of the point from its surface.

Friction of contact j acts at its point P along the unit vector d with magnitude ``mu |N_j|``
(Coulomb), N_j the multiplier of the gap's gradient in Lagrange's equations (1.4). Both
scale the friction silently when they are not what they seem: a direction of length 2 doubles
mu, a gap growing twice as fast as the distance halves it. :func:`check_friction_geometry`
refuses such scenes (``Scene.from_lagrangian`` calls it; scene files in the plane and in space
share :func:`unit_vector_problem` and :func:`vanishes`).

Identities are decided exactly where the trigonometric field of
:mod:`contactsym.algebra.trig_field` decides them, otherwise at random points of the declared
domain (:func:`sample_points`), never by simplifying a large expression.
"""

from __future__ import annotations

import itertools
import random

import sympy as sp
from sympy.physics.vector import Point, Vector

from ..algebra.basic import node_count
from ..algebra.canonical_form import TrigField
from ..errors import SceneError
from ..laws import Coulomb
from ..parse import sympy_only
from .contact import plain_symbol
from .contact_space import t

__all__ = ["check_friction_geometry", "sample_points", "unit_vector_problem", "vanishes"]

#: Random points of the domain at which an identity not proved exactly is checked.
SAMPLES = 6
_RELATIVE = sp.Float("1e-15", 40)  # a zero evaluated with 40 digits is far below this, any value far above


def _plain_everywhere(exprs) -> list:
    """Coordinates q(t), their rates and other unknown functions as plain real symbols."""
    rates = {d: plain_symbol(d.expr, "dot") for e in exprs for d in e.atoms(sp.Derivative)}
    exprs = [e.xreplace(rates) for e in exprs]
    functions = {f: plain_symbol(f) for e in exprs for f in e.atoms(sp.core.function.AppliedUndef)}
    return [e.xreplace(functions) for e in exprs]


def _ranges(symbols, positive) -> dict:
    """(low, high) per symbol: an angle whose sin or cos is declared positive stays in that quadrant."""
    ranges = {}
    for s in symbols:
        low, high = (0.25, 3.0) if s.is_positive or s.is_nonnegative else (-3.0, -0.25) if s.is_negative else (-3, 3)
        sine, cosine = sp.sin(s) in positive, sp.cos(s) in positive
        if sine or cosine:
            low, high = (0.05 if sine else -1.5, 1.52 if cosine else 3.09)
        ranges[s] = (low, high)
    return ranges


def sample_points(exprs, positive=(), count: int = SAMPLES, seed: int = 0) -> list[dict]:
    """Random points (40-digit floats) of the domain of ``exprs``: each symbol of its declared sign, an
    angle in the quadrant where its declared positive sin and cos hold, and every expression of
    ``positive`` positive there; fewer than ``count`` (none) where the domain is hard to hit.

    Coordinates q(t), rates and unknown functions become plain real symbols, as :func:`plain_symbol`
    names them; sign symbols (integers) are +1 or -1. Deterministic: the same points for the same seed.

    Examples
    --------
    >>> a, m = sp.Symbol("a", real=True), sp.Symbol("m", positive=True)
    >>> points = sample_points([m * sp.sin(a)], positive=[sp.sin(a), sp.cos(a)], count=3)
    >>> len(points), all(0 < p[a] < sp.pi / 2 and p[m] > 0 for p in points)
    (3, True)
    """
    exprs, positive = _plain_everywhere(list(exprs)), _plain_everywhere(list(positive))
    symbols = sorted(set().union(*(e.free_symbols for e in (*exprs, *positive))), key=str)
    ranges, draw, points = _ranges(symbols, set(positive)), random.Random(seed), []
    for _ in range(100 * count):
        point = {
            s: sp.Integer(draw.choice((-1, 1))) if s.is_integer else sp.Float(draw.uniform(*ranges[s]), 40)
            for s in symbols
        }
        if all(_positive_at(p, point) for p in positive):
            points.append(point)
            if len(points) == count:
                break
    return points


def _positive_at(expr, point) -> bool:
    value = expr.evalf(40, subs=point)
    return bool(value.is_extended_real and value.is_finite and value > 0)


def _vanishes_at(expr, point) -> bool | None:
    """``expr`` is zero at a point, to 40 digits against its largest term (the scale it cancels from);
    None where it has no finite value there (a pole)."""
    value, terms = expr.evalf(40, subs=point), sp.Add.make_args(expr)
    scale = [abs(value), *(abs(term.evalf(40, subs=point)) for term in terms if len(terms) > 1)]
    if not all(x.is_number and x.is_finite for x in scale):
        return None
    return value == 0 or abs(value) <= _RELATIVE * max(scale)


def _untan(expr: sp.Expr) -> sp.Expr:
    """tan and cot written with sin and cos, which the trigonometric field relates."""
    expr = expr.replace(sp.tan, lambda x: sp.sin(x) / sp.cos(x))
    return expr.replace(sp.cot, lambda x: sp.cos(x) / sp.sin(x))


def vanishes(expr, positive=(), points=None) -> bool:
    """Whether ``expr`` is zero throughout its domain: exactly where the trigonometric field decides
    it (modulo sin^2 + cos^2 = 1), otherwise at random points of the domain (:func:`sample_points`).

    False only where it was shown not to vanish: not zero at a random point, or not zero in the field
    where no point can be taken (an identity the field cannot see, tan(a) cos(a) = sin(a), is
    checked at the points). No simplification is tried.

    Examples
    --------
    >>> a, l = sp.Symbol("a", real=True), sp.Symbol("l", positive=True)
    >>> vanishes(sp.cos(a) ** 2 + sp.sin(a) ** 2 - 1), vanishes(l * sp.tan(a) * sp.cos(a) - l * sp.sin(a))
    (True, True)
    >>> vanishes(sp.sqrt(l**2) - l), vanishes(2 * sp.cos(a) - 1)
    (True, False)
    """
    expr = _untan(_plain_everywhere([sympy_only(expr, "an expression")])[0])
    try:
        if not TrigField([expr]).element(expr):
            return True
        undecided = False
    except (ValueError, TypeError, NotImplementedError, ZeroDivisionError):
        undecided = True  # outside the field's rational functions: the points decide
    points = sample_points([expr], positive) if points is None else points
    found = [v for v in (_vanishes_at(expr, p) for p in points) if v is not None]
    return all(found) if found else undecided


def unit_vector_problem(components, positive=(), what: str = "the direction", of: str = "") -> str | None:
    """Why a direction given by its components is not a unit vector (and the fix), or None.

    Shared by scene files in the plane and in space and by ``Scene.from_lagrangian``; ``positive``
    are the expressions declared positive, ``what`` names the vector in the message (``of``: whose).

    Examples
    --------
    >>> b = sp.Symbol("beta", real=True)
    >>> unit_vector_problem([sp.cos(b), sp.sin(b)]) is None
    True
    >>> unit_vector_problem([2, 0])
    'the direction [2, 0] is not a unit vector (its length is 2); divide it by its length'
    """
    components = [sp.sympify(c) for c in components]
    square = sum(c**2 for c in components)
    if vanishes(square - 1, positive):
        return None
    length = sp.sqrt(square)
    length = length if node_count(length, 40) < 40 else "not 1"
    shown = "[" + ", ".join(str(c) for c in _plain_everywhere(components)) + "]"
    return f"{what} {shown}{of and ' '}{of} is not a unit vector (its length is {length}); divide it by its length"


def _listed(components) -> str:
    return "[" + ", ".join(str(c) for c in _plain_everywhere([sp.sympify(c) for c in components])) + "]"


def _refusal(index: int, key: str, message: str) -> SceneError:
    """A SceneError about contact ``index`` (0-based), with the key of a file's contact it is about."""
    error = SceneError(message)
    error.contact, error.key = index, key
    return error


def _factor(gradient, normal, positive, points) -> tuple[str, str, str]:
    """How many times as fast as the distance a gap grows (gradient = c * normal), and the fix."""
    try:
        return _named_factor(gradient, normal, positive, points)
    except (TypeError, ValueError, ZeroDivisionError, IndexError):  # no point, or a pole at the point
        return "a factor that is not 1", "write the distance", "mu over that factor"


def _named_factor(gradient, normal, positive, points) -> tuple[str, str, str]:
    i = max(range(len(normal)), key=lambda k: abs(normal[k].evalf(40, subs=points[0])))
    c = gradient[i] / normal[i]
    value = c.evalf(40, subs=points[0])
    constant = sp.nsimplify(sp.Float(value, 15), rational=True, tolerance=1e-12)
    if all(vanishes(g - constant * n, positive, points) for g, n in zip(gradient, normal)):
        c = abs(constant)
    elif node_count(c, 80) < 80:
        c = sp.trigsimp(sp.cancel(_untan(c)))
        c = -c if c.could_extract_minus_sign() else c  # the gap or the normal may point either way
    else:
        shown = f"a factor that is not 1 ({abs(value):.4g} at {_shown_point(points[0])})"
        return shown, "write the distance", "mu over that factor"
    fix = f"multiply it by {1 / c}" if sp.count_ops(1 / c) < sp.count_ops(c) else f"divide it by {c}"
    return str(c), fix, str(sp.Symbol("mu") / c)


def _shown_point(point: dict) -> str:
    return ", ".join(f"{k} = {float(v):.4g}" for k, v in sorted(point.items(), key=lambda kv: str(kv[0])))


def check_friction_geometry(scene, frame) -> None:
    """Refuse friction at a point that is not what the theory takes it to be.

    Friction of contact j acts at its point P along the unit vector d: ``mu |N_j|`` for Coulomb,
    N_j the multiplier of the gap's gradient. So d must be a unit vector, and where the contact
    moves in the plane of ``frame`` (x, y), the gap must be the distance of P from the surface to
    first order at the contact: its gradient in q equals n . dP/dq with n = +-(z x d), the unit
    normal, on the contact manifold. A gap c times the distance makes the friction mu/c times the
    normal force. Viscous friction (independent of N) needs only the direction tangent (the
    gradient parallel to n . dP/dq), a frictionless contact nothing. Checked exactly where
    possible, else at random points of the domain (:func:`vanishes`); a contact moving out of the
    plane is checked for its unit direction only. Raises SceneError (its ``contact``: the index,
    its ``key``: "friction" or "gap").

    Examples
    --------
    >>> import contactsym as cs
    >>> from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, dynamicsymbols
    >>> x, y = dynamicsymbols("x y")
    >>> O, o = ReferenceFrame("O"), Point("o")
    >>> P = o.locatenew("P", x * O.x + y * O.y)
    >>> P.set_vel(O, P.pos_from(o).dt(O))
    >>> L = Lagrangian(O, Particle("p", P, 1))
    >>> N, mu = sp.symbols("N mu", real=True)
    >>> contact = cs.Contact(coordinate=2 * y, reaction=N, friction=cs.Coulomb(mu, O.x, P))
    >>> try:
    ...     cs.Scene.from_lagrangian(L, [x, y], [contact], frame=O)
    ... except cs.SceneError as error:
    ...     print(str(error).split(", so")[0])
    the gap 2*y of contact 1 grows 2 times as fast as the distance of P along the normal [0, 1] of the friction direction [1, 0]
    """
    positive = scene.declared_positive
    rates = [sp.diff(q, t) for q in scene.coordinates]
    for j, contact in enumerate(scene.contacts):
        law = contact.friction
        if law is None or not isinstance(law.direction, Vector) or not isinstance(law.point, Point):
            continue
        d = [law.direction.dot(axis) for axis in (frame.x, frame.y, frame.z)]
        problem = unit_vector_problem(d, positive, "the friction direction", f"of contact {j + 1}")
        if problem:
            raise _refusal(j, "friction", problem)
        velocity = law.point.vel(frame)
        if not (vanishes(d[2], positive) and vanishes(velocity.dot(frame.z), positive)):
            continue  # in space: the normal is not fixed by d
        normal_rate = velocity.dot(-d[1] * frame.x + d[0] * frame.y)
        try:
            gradient = [scene.freeze(sp.diff(contact.coordinate, q)) for q in scene.coordinates]
            normal = [scene.freeze(sp.diff(normal_rate, r)) for r in rates]
        except SceneError:
            continue  # no contact manifold: the pipeline says so when it needs one
        points = sample_points([*gradient, *normal], positive)
        if any(all(vanishes(g - s * n, positive, points) for g, n in zip(gradient, normal)) for s in (1, -1)):
            continue
        where = (
            f"of {law.point.name} along the normal {_listed([-d[1], d[0]])} of the friction direction {_listed(d[:2])}"
        )
        pairs = itertools.combinations(range(len(gradient)), 2)
        parallel = all(vanishes(gradient[a] * normal[b] - gradient[b] * normal[a], positive, points) for a, b in pairs)
        if not parallel or all(vanishes(n, positive, points) for n in normal):
            raise _refusal(
                j,
                "friction",
                f"the friction direction {_listed(d[:2])} of contact {j + 1} is not along its surface: the gap "
                f"{_listed([contact.coordinate])[1:-1]} does not change as the distance {where}; give the "
                f"direction of sliding of {law.point.name} along the surface (a unit vector tangent to it), "
                f"or a gap that is the distance of {law.point.name} from the surface",
            )
        if isinstance(law, Coulomb):
            factor, fix, scaled = _factor(gradient, normal, positive, points)
            raise _refusal(
                j,
                "gap",
                f"the gap {_listed([contact.coordinate])[1:-1]} of contact {j + 1} grows {factor} times as fast "
                f"as the distance {where}, so its friction mu |N| would be {scaled} times the normal force: "
                f"write the distance, e.g. {fix}",
            )
