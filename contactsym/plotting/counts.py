"""Equilibrium counts decided at numeric points, lift-off included, and a plot of them.

:func:`count_equilibria` counts the solutions of f(u) = 0 (with lift-off for unilateral
contacts) for arrays of parameter values and loads, by enumerating the orthants of the
scene's map (:mod:`contactsym.counts.orthants`); :func:`decide_counts` names the counts that the
loads can produce at one parameter point: exactly from the determinant and cross
determinant signs for k <= 2 (:func:`contactsym.counts.plmap.k2_label`), and for k >= 3 from the
degree and a load in every cell of the facet images. Points on a boundary (a vanishing
determinant, a load on a facet image) are reported as undecided, never guessed.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp

from ..counts.orthants import scene_map
from ..counts.plmap import OrthantMap, count_label, k2_label, k2_quadrants
from ..errors import ContactsymError
from .common import ContactPlot
from .figures import save_figure

__all__ = ["CountDecision", "CountMapData", "count_equilibria", "decide_counts", "count_map_data", "count_map_plot"]

#: Relative size below which a determinant counts as zero (the point is then undecided).
TOLERANCE = 1e-9


def _compiled(scene):
    def build():
        G = scene_map(scene)
        exprs = [G.plus, G.minus, G.load]
        functions = set().union(*(e.atoms(sp.core.function.AppliedUndef) for e in exprs))
        if functions:
            raise ContactsymError(
                f"scene '{scene.name}' has the functions {sorted(map(str, functions))} in f; numeric counts need "
                "plain symbols: build the scene with symbols for them."
            )
        symbols = sorted(set().union(*(e.free_symbols for e in exprs)), key=str)
        return symbols, sp.lambdify(symbols, exprs, "numpy")

    return scene.cached("orthant map numeric", build)


def _arrays(scene, values: dict):
    symbols, function = _compiled(scene)
    missing = sorted(str(s) for s in symbols if str(s) not in values)
    if missing:
        raise ContactsymError(f"give values for {missing}: the counts of scene '{scene.name}' depend on them.")
    arguments = [np.asarray(values[str(s)], dtype=float) for s in symbols]
    if any(not np.all(np.isfinite(a)) for a in arguments):
        raise ContactsymError("parameter values must be finite numbers.")
    shape = np.broadcast_shapes(*(a.shape for a in arguments)) if arguments else ()
    with np.errstate(all="ignore"):
        plus, minus, load = (_as_array(matrix, shape) for matrix in function(*arguments))
    if not (np.all(np.isfinite(plus)) and np.all(np.isfinite(minus)) and np.all(np.isfinite(load))):
        raise ContactsymError(f"f of scene '{scene.name}' is not finite at these values (a zero mass or length?).")
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
    G = scene_map(scene)
    needed = sorted(str(s) for s in G.plus.free_symbols | G.minus.free_symbols)
    missing = [name for name in needed if name not in values]
    if missing:
        raise ContactsymError(
            f"give values for {missing}: the orthant determinants of scene '{scene.name}' depend on them."
        )
    filled = {str(s): 0.0 for s in symbols}  # the loads do not change which counts occur
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
        if label == "none, two or four" and cross(0) == 0 == cross(1):
            reason = "V_0 || V_2 and V_1 || V_3: two does not occur, a boundary of the region"
            return CountDecision("undecided", frozenset(), 0, dets, reason)
        counts = {"unique": {1}, "two or none": {0, 2}, "one or three": {1, 3}, "none, two or four": {0, 2, 4}}[label]
        return CountDecision(label, frozenset(counts), G.degree(), dets, "determinant and cross determinant signs")
    counts = G.count_set()
    return CountDecision(count_label(counts), frozenset(counts), G.degree(), dets, "a load in every cell")


def _k1_degree(dets) -> int:
    return int((np.sign(dets[(1,)]) + np.sign(dets[(-1,)])) // 2)


# --- a plot of the counts over a plane of loads or parameters ------------------------------


@dataclass(frozen=True)
class CountMapData:
    """The number of equilibria on a grid of two variables, the others fixed."""

    x: str
    y: str
    X: np.ndarray
    Y: np.ndarray
    counts: np.ndarray  # -1 where undecided
    label: str  # what the fixed parameters give over all loads


def count_map_data(scene, x: str, y: str, x_range, y_range, size: int = 201, **fixed) -> CountMapData:
    """Counts of equilibria (lift-off included) over a grid in (x, y), e.g. two loads.

    Examples
    --------
    >>> import contactsym as cs
    >>> point = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)
    >>> data = count_map_data(cs.scene("two-leg-block"), "Y", "M", (-30, 30), (-10, 10), size=41, **point)
    >>> sorted(set(data.counts.ravel().tolist()) - {-1}), data.label
    ([0, 2], 'two or none')
    """
    X, Y = np.meshgrid(np.linspace(*x_range, size), np.linspace(*y_range, size))
    counts, undecided = count_equilibria(scene, **{**fixed, x: X, y: Y})
    loads = {x, y}
    parameters = {k: v for k, v in fixed.items() if k not in loads}
    plane_is_loads = all(str(s) not in loads for s in scene_map(scene).plus.free_symbols)
    label = decide_counts(scene, **parameters).label if plane_is_loads else "varies over the plane"
    return CountMapData(x, y, X, Y, np.where(undecided, -1, counts), label)


def count_map_plot(data: CountMapData, ax=None) -> ContactPlot:
    """Draw the counts as filled patches with a legend; returns the :class:`~contactsym.plotting.ContactPlot`.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import contactsym as cs
    >>> data = count_map_data(cs.scene("painleve-rod"), "mu", "thetadot", (0, 3), (0, 5), size=21,
    ...                       m=1, l=1, g=9.81, theta=1.1)
    >>> artists = count_map_plot(data)
    """
    import matplotlib.pyplot as plt  # matplotlib is heavy and optional: loaded only to draw
    from matplotlib.colors import BoundaryNorm, ListedColormap

    if ax is None:
        ax = plt.gca()
    top = max(4, int(data.counts.max()))
    colours = ["0.6"] + [plt.cm.viridis(i / top) for i in range(top + 1)]  # grey: undecided
    norm = BoundaryNorm(np.arange(-1.5, top + 1.5), len(colours))
    mesh = ax.pcolormesh(data.X, data.Y, data.counts, cmap=ListedColormap(colours), norm=norm, shading="auto")
    present = sorted(set(data.counts.ravel().tolist()))
    handles = [plt.Rectangle((0, 0), 1, 1, color=colours[c + 1]) for c in present]
    names = ["undecided" if c < 0 else f"{c} equilibri{'um' if c == 1 else 'a'}" for c in present]
    legend = ax.legend(handles, names, fontsize=8, loc="upper right")
    ax.set_xlabel(data.x)
    ax.set_ylabel(data.y)
    over = "" if data.label == "varies over the plane" else f" (over all loads: {data.label})"
    ax.set_title(f"number of equilibria, lift-off included{over}", fontsize=9)
    return ContactPlot.of(ax, [mesh, legend])


def count_map_figure(scene, path, x: str, y: str, x_range, y_range, **fixed):
    """Draw :func:`count_map_plot` for one plane into a PNG file and return its path (for reports)."""
    data = count_map_data(scene, x, y, x_range, y_range, **fixed)
    return save_figure(Path(path), lambda f: count_map_plot(data, ax=f.add_subplot()), size=(6.0, 4.2), dpi=130)
