"""Any region on a grid of two of its symbols, hatched; the zero sets that bound it.

Regions are duck-typed: anything with ``condition``, ``evaluate(**values)`` and the
``symbol_names`` mapping of its symbols (a :class:`contactsym.stages.regions.Region`) is drawn.
Draw a region with ``region_plot(region_data(region, ...), ax=ax)``; this module imports no stage.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import sympy as sp

from ..arguments import between, checked
from .common import STABLE_HATCH, ContactPlot, _float, _name, axes_or_current

__all__ = ["RegionData", "boundary_contours", "region_data", "region_mask", "region_plot", "relational_fields"]


@checked(region="Region", shape="tuple[int, ...]")
def region_mask(region, values: dict, shape) -> np.ndarray:
    """Membership of a region on a grid: evaluated with the values it depends on (others ignored),
    broadcast to ``shape``.

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.stages.regions import Region
    >>> x, y = sp.symbols("x y", real=True)
    >>> region_mask(Region(x > 0), {"x": np.array([-1.0, 1.0]), "y": 3.0}, (2,)).tolist()
    [False, True]
    """
    needed = {name for name in region.symbol_names}
    missing = needed - set(values)
    if missing:
        raise ValueError(f"give values for {sorted(missing)} (in fixed=...); the region depends on them.")
    mask = region.evaluate(**{name: values[name] for name in needed})
    return np.broadcast_to(mask, shape)


@checked(condition="sp.Basic", shape="tuple[int, ...]")
def relational_fields(condition, values: dict, shape) -> list[np.ndarray]:
    """lhs - rhs of every inequality/equation in a condition, on a grid: their zero sets are the boundaries.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y", real=True)
    >>> [f.tolist() for f in relational_fields(sp.And(x > 0, x + y < 2), {"x": np.array([0.0, 1.0]), "y": 1.0}, (2,))]
    [[0.0, 1.0], [-1.0, 0.0]]
    """
    fields = []
    seen = []
    for atom in sorted(sp.sympify(condition).atoms(sp.core.relational.Relational), key=sp.default_sort_key):
        expr = sp.expand(atom.lhs - atom.rhs)
        if any(sp.expand(expr - e) == 0 or sp.expand(expr + e) == 0 for e in seen):
            continue
        seen.append(expr)
        symbols = sorted(expr.free_symbols, key=str)
        function = sp.lambdify(symbols, expr, "numpy")
        fields.append(np.broadcast_to(np.asarray(function(*[values[str(s)] for s in symbols]), float), shape))
    return fields


@checked(nan=True)
@dataclass(frozen=True)
class RegionData:
    """A region on a grid: ``mask[i, j]`` is membership at ``(X[i, j], Y[i, j])``.

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.stages.regions import Region
    >>> a, b = sp.symbols("a b", real=True)
    >>> data = region_data(Region(a + b < 1), x="a", y="b", resolution=5)
    >>> isinstance(data, RegionData), data.x, data.y, data.X.shape
    (True, 'a', 'b', (5, 5))
    >>> bool(np.array_equal(data.mask, data.X + data.Y < 1))
    True
    """

    x: str
    y: str
    X: np.ndarray
    Y: np.ndarray
    mask: np.ndarray
    region: Any  # a Region, or anything with condition, evaluate and symbol_names


@checked(
    region="Region",
    x="sp.Symbol | str",
    y="sp.Symbol | str",
    fixed="Mapping | None",
    xlim="Sequence[float]",
    ylim="Sequence[float]",
    resolution=between(2, 4096),
)
def region_data(region, *, x, y, fixed=None, xlim=(-1.0, 1.0), ylim=(-1.0, 1.0), resolution=300):
    """Evaluate a region on a grid of the (x, y) plane.

    Parameters
    ----------
    region : Region or Region-like
    x, y : str or Symbol
        The plane's symbols.
    fixed : dict, optional
        Values of the region's other symbols (by name or symbol); extra entries are ignored.
    xlim, ylim : pair of float
    resolution : int
        Grid points per axis.

    Returns
    -------
    RegionData

    Examples
    --------
    >>> import sympy as sp
    >>> from contactsym.stages.regions import Region
    >>> a, b = sp.symbols("a b", real=True)
    >>> data = region_data(Region(a + b < 1), x="a", y="b", resolution=3)
    >>> data.mask.tolist()
    [[True, True, True], [True, True, False], [True, False, False]]
    """
    xs = np.linspace(*map(float, xlim), resolution)
    ys = np.linspace(*map(float, ylim), resolution)
    X, Y = np.meshgrid(xs, ys)
    values = {_name(k): _float(v) for k, v in (fixed or {}).items()}
    values.update({_name(x): X, _name(y): Y})
    return RegionData(_name(x), _name(y), X, Y, region_mask(region, values, X.shape).copy(), region)


@checked(
    region="Region",
    ax="Axes | None",
    x="sp.Symbol | str",
    y="sp.Symbol | str",
    fixed="Mapping | None",
    xlim="Sequence[float]",
    ylim="Sequence[float]",
    resolution=between(2, 4096),
    hatch="str | None",
    color="str | None",
    label="str | None",
)
def region_plot(
    region,
    ax=None,
    *,
    x,
    y,
    fixed=None,
    xlim=(-1.0, 1.0),
    ylim=(-1.0, 1.0),
    resolution=300,
    hatch=STABLE_HATCH,
    color="black",
    label=None,
    data: RegionData | None = None,
) -> ContactPlot:
    """Hatch a region in the (x, y) plane.

    Parameters
    ----------
    region : Region or Region-like
    ax : matplotlib Axes, optional
        Default: the current Axes.
    x, y, fixed, xlim, ylim, resolution
        As in :func:`region_data` (unused when ``data`` is given).
    hatch : str
        A matplotlib hatch pattern ('///' single, 'xxx' double).
    color : str
        Hatch colour.
    label : str, optional
        Legend entry (an empty hatched patch is added for it).
    data : RegionData, optional
        A grid already computed by :func:`region_data`.

    Returns
    -------
    ContactPlot
        The filled contour set, and the legend proxy when ``label`` is given.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from contactsym.stages.regions import Region
    >>> a, b = sp.symbols("a b", real=True)
    >>> fig, ax = plt.subplots()
    >>> artists = region_plot(Region(a + b < 1), ax=ax, x="a", y="b", resolution=20, label="a + b < 1")
    >>> len(artists), ax.get_legend_handles_labels()[1]
    (2, ['a + b < 1'])
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    if data is None:
        data = region_data(region, x=x, y=y, fixed=fixed, xlim=xlim, ylim=ylim, resolution=resolution)
    artists = []
    if data.mask.any():
        filled = ax.contourf(data.X, data.Y, data.mask.astype(float), levels=[0.5, 1.5], colors="none", hatches=[hatch])
        if hasattr(filled, "set_hatchcolor"):
            filled.set_hatchcolor(color)
        filled.set_edgecolor(color)
        filled.set_linewidth(0)
        artists.append(filled)
    if label is not None:
        (proxy,) = ax.fill([], [], facecolor="none", edgecolor=color, hatch=hatch, label=label)
        artists.append(proxy)
    return ContactPlot.of(ax, artists)


@checked(ax="Axes | None", X="RealArray", Y="RealArray", fields="Sequence")
def boundary_contours(ax, X, Y, fields, **style) -> list:
    """Draw the zero contour of each field (from :func:`relational_fields`) that changes sign on the grid;
    returns the contour sets drawn.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> X, Y = np.meshgrid(np.linspace(-2, 2, 41), np.linspace(-2, 2, 41))
    >>> fig, ax = plt.subplots()
    >>> len(boundary_contours(ax, X, Y, [X**2 + Y**2 - 1, X**2 + Y**2 + 1]))  # the circle; the other has no zero
    1
    >>> plt.close(fig)
    """
    artists = []
    for values in fields:
        if np.nanmin(values) < 0 < np.nanmax(values):
            artists.append(ax.contour(X, Y, values, levels=[0.0], **style))
    return artists
