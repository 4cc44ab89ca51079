"""Equilibrium counts decided at numeric points, lift-off included, and a plot of them.

:func:`count_equilibria` counts the solutions of f(u) = 0 (with lift-off for unilateral
contacts) for arrays of parameter values and loads, by enumerating the orthants of the
scene's map (:mod:`contactsym.orthants`); :func:`decide_counts` names the counts that the
loads can produce at one parameter point: exactly from the determinant and cross
determinant signs for k <= 2 (:func:`contactsym.plmap.k2_label`), and for k >= 3 from the
degree and a load in every cell of the facet images. Points on a boundary (a vanishing
determinant, a load on a facet image) are reported as undecided, never guessed.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from .errors import ContactsymError
from .orthants import scene_map
from .plmap import OrthantMap, count_label, k2_label, k2_quadrants

__all__ = ["CountDecision", "count_equilibria", "decide_counts", "count_map_data", "count_map_plot"]

#: Relative size below which a determinant counts as zero (the point is then undecided).
TOLERANCE = 1e-9


def _compiled(scene):
    def build():
        G = scene_map(scene)
        exprs = [G.plus, G.minus, G.load]
        symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=str)
        return symbols, sp.lambdify(symbols, exprs, "numpy")

    return scene._stage("orthant map numeric", build)


def _arrays(scene, values: dict):
    symbols, function = _compiled(scene)
    missing = sorted(str(s) for s in symbols if str(s) not in values)
    if missing:
        raise ContactsymError(f"give values for {missing}: the counts of scene '{scene.name}' depend on them.")
    arguments = [np.asarray(values[str(s)], dtype=float) for s in symbols]
    if any(not np.all(np.isfinite(a)) for a in arguments):
        raise ContactsymError("parameter values must be finite numbers.")
    shape = np.broadcast_shapes(*(a.shape for a in arguments)) if arguments else ()
    plus, minus, load = (_as_array(matrix, shape) for matrix in function(*arguments))
    return OrthantMap(plus, minus), load[..., 0]


def _as_array(matrix, shape) -> np.ndarray:
    """A lambdified matrix as an array (*shape, rows, cols)."""
    rows = [[np.broadcast_to(np.asarray(e, dtype=float), shape) for e in row] for row in matrix]
    return np.moveaxis(np.array(rows, dtype=float), (0, 1), (-2, -1))


def count_equilibria(scene, **values) -> tuple[np.ndarray, np.ndarray]:
    """The number of equilibria (lift-off included) for arrays of values, and where it is undecided.

    Parameters
    ----------
    scene : Scene
    **values : array_like
        Every parameter and load of the scene's map by name; arrays broadcast.

    Returns
    -------
    counts, undecided : ndarray
        ``undecided`` marks points where a solution lies on a face of its orthant.

    Examples
    --------
    >>> import contactsym as cs
    >>> block = cs.scene("two-leg-block")
    >>> point = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)
    >>> count_equilibria(block, Y=[-24.5, 0.0], M=[-3.1, 5.0], **point)[0]
    array([0, 2])
    """
    G, load = _arrays(scene, values)
    return G.count(load, TOLERANCE)


@dataclass(frozen=True)
class CountDecision:
    """The counts the loads can produce at one parameter point.

    Attributes
    ----------
    label : str
        'unique', 'two or none', 'one or three', ..., or 'undecided'.
    counts : frozenset
        The counts that occur (empty when undecided).
    degree : int or None
        The degree of the map (its parity is that of every count).
    determinants : dict
        The orthant determinants, by sign pattern.
    method : str
        How it was decided, or why it was not.
    """

    label: str
    counts: frozenset
    degree: int | None
    determinants: dict
    method: str


def decide_counts(scene, **values) -> CountDecision:
    """Decide the counts over all loads at one parameter point (loads need not be given).

    Examples
    --------
    >>> import contactsym as cs
    >>> point = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)
    >>> decide_counts(cs.scene("two-leg-block"), **point).label
    'two or none'
    >>> decide_counts(cs.scene("painleve-rod"), m=1, l=1, mu=2, theta=1.1).label
    'two or none'
    """
    symbols, _ = _compiled(scene)
    filled = {str(s): values.get(str(s), 0.0) for s in symbols}
    filled.update(values)
    G, _ = _arrays(scene, {k: float(v) for k, v in filled.items()})
    dets = {p: float(d) for p, d in G.determinants().items()}
    scale = float(np.abs(G.vertices()).max()) ** scene.k or 1.0
    if any(abs(d) <= TOLERANCE * scale for d in dets.values()):
        return CountDecision("undecided", frozenset(), None, dets, "an orthant determinant vanishes: a boundary")
    if scene.k == 1:
        counts = {1} if dets[(1,)] * dets[(-1,)] > 0 else {0, 2}
        return CountDecision(count_label(counts), frozenset(counts), _k1_degree(dets), dets, "slope signs")
    if scene.k == 2:
        vertices = [G.vertices()[i] for i in (0, 1, 2, 3)]

        def cross(i):
            return np.sign(np.linalg.det(np.column_stack([vertices[i % 4], vertices[(i + 2) % 4]])))

        signs = {q: int(np.sign(dets[q])) for q in k2_quadrants}
        label = k2_label(signs, cross)
        counts = {"unique": {1}, "two or none": {0, 2}, "one or three": {1, 3}, "none, two or four": {0, 2, 4}}[label]
        return CountDecision(label, frozenset(counts), G.degree(), dets, "determinant and cross determinant signs")
    counts = G.count_set()
    return CountDecision(count_label(counts), frozenset(counts), G.degree(), dets, "a load in every cell")


def _k1_degree(dets) -> int:
    return int((np.sign(dets[(1,)]) + np.sign(dets[(-1,)])) // 2)
