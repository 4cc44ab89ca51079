"""The fast subsystem of a scene in contact space: f(u) = b + W^T M^-1 L m(u).

The load b and the reaction part W^T M^-1 L m(u) (the columns of L the gap gradients and the
friction directions, m(u) = (u, phi(u))), see :mod:`contactsym.mechanism.contact_space`, and the
switching functions read from m(u) alone: only whether a coefficient of W^T M^-1 L is zero
matters there, which one exact point decides.
"""

from __future__ import annotations

import logging

import sympy as sp
from sympy.polys.matrices import DomainMatrix
from sympy.polys.matrices.exceptions import DMNonInvertibleMatrixError

from ..algebra.canonical_form import TrigField
from ..algebra.fraction_free import rational_point, solve_fraction_free, t, value_at
from .pieces import switching_functions

__all__ = [
    "contact_accelerations",
    "reaction_part",
    "reaction_factors",
    "switching_of_factors",
    "rational_point",
    "value_at",
]

#: Stage messages for long derivations: ``logging.basicConfig(level=logging.INFO)`` shows them.
log = logging.getLogger("contactsym")


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


def switching_of_factors(M, W, loads, multipliers, u) -> tuple | None:
    """The switching functions of W^T M^-1 L m(u) (see :func:`reaction_factors`), read from m(u), or
    None when one exact point does not decide them.

    A switching function of multiplier m_c is one of the reaction part when some coefficient
    (W^T M^-1 L)_(i, c) is nonzero: a nonzero value at an exact point (:func:`rational_point`)
    proves it; a zero there, or a switching function shared by two multipliers (their terms
    might cancel), leaves the question to the whole reaction part (None).

    Examples
    --------
    >>> u, mu = sp.symbols("u mu", real=True)
    >>> M, W = sp.Matrix([[2]]), sp.Matrix([[1]])
    >>> switching_of_factors(M, W, sp.Matrix([[1, 1]]), [u, -mu * sp.Abs(u)], (u,))
    (u,)
    >>> switching_of_factors(M, W, sp.Matrix([[1, 0]]), [u, -mu * sp.Abs(u)], (u,)) is None
    True
    """
    own = [set(switching_functions([m], u)) for m in multipliers]
    found = set().union(*own)
    if not found:
        return ()
    if any(sum(sigma in mine for mine in own) > 1 for sigma in found):
        return None
    field = TrigField([*M, *W, *loads])
    point = rational_point(field)
    if point is None:
        return None
    try:
        Mv, Wv, Lv = (_at_point(field, X, point) for X in (M, W, loads))
        rows = (Wv.transpose() * Mv.inv() * Lv).to_list()
    except (ZeroDivisionError, DMNonInvertibleMatrixError):
        return None  # a pole of an entry, or M singular at the point: decide symbolically
    if any(mine and all(row[c] == 0 for row in rows) for c, mine in enumerate(own)):
        return None
    return switching_functions(multipliers, u)


def _at_point(field, X: sp.Matrix, point) -> DomainMatrix:
    """The matrix X at an exact point of the field's generators."""
    return DomainMatrix.from_list([[value_at(field.element(x), point) for x in row] for row in X.tolist()], sp.QQ)
