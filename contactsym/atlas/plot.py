"""An atlas drawn with the scene's closed-form region boundaries over it.

The boundaries come from ``scene.regions()`` (the derived inequalities, never typed in),
evaluated on a fine grid over the atlas with the sweep's fixed values: where the numerical
atlas changes (the squeal's amplitude leaves zero, the stable fraction leaves 1), a derived
line should pass.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from ..mechanism.scene import Scene
from ..plotting import ContactPlot, axes_or_current, relational_fields
from ..scenes import scene as scene_by_name
from ..validate import checked_fields, flag, shorten
from .grid import AtlasError

__all__ = ["AtlasData", "atlas_data", "atlas_plot"]

#: Colours of the region boundaries, in the order of ``scene.regions()``.
_COLOURS = ("black", "tab:red", "magenta", "tab:orange", "tab:cyan")
_REGION_LABELS = {1.0: "stable for every law", -1.0: "unstable for every law", 0.0: "law-dependent"}


@dataclass(frozen=True)
class AtlasData:
    """One variable of an atlas over its axes, with the closed-form boundaries on a fine grid.

    ``values`` has shape (len(y), len(x)) (a 2-D atlas) or (len(x),) (a 1-D one);
    ``boundaries`` maps a region's name to (its LaTeX, the fields whose zero sets bound it),
    sampled on ``fine`` (the (X, Y) meshes, or the x samples).

    Examples
    --------
    A 1-D atlas of the brake's verdict along mu:

    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", "classification", {"mu": [0.5, 1.5]}, values={"alpha": 1.0, "m": 1},
    ...                  scheduler="threads")
    >>> data = atlas_data(ds, "region", resolution=20)
    >>> isinstance(data, AtlasData), data.x, data.y, data.values.shape
    (True, 'mu', None, (2,))
    """

    variable: str
    x: str
    y: str | None
    xs: np.ndarray
    ys: np.ndarray | None
    values: np.ndarray
    title: str
    fine: tuple
    boundaries: dict = field(default_factory=dict)
    skipped: tuple = ()

    def __post_init__(self):
        checked_fields(self, AtlasError)
        arrays = isinstance(self.xs, np.ndarray) and isinstance(self.values, np.ndarray)
        if not arrays or not (self.ys is None or isinstance(self.ys, np.ndarray)) or not isinstance(self.fine, tuple):
            raise AtlasError(
                "AtlasData holds NumPy arrays xs, values (and ys, or None) and a tuple fine; use atlas_data()."
            )


def _check_atlas_arguments(ds, variable, x, y, scene, resolution) -> None:
    if not (hasattr(ds, "data_vars") and hasattr(ds, "attrs")):
        raise AtlasError(f"{shorten(ds)} is not an atlas; give the xarray.Dataset that sweep() returned.")
    for what, name in (("variable", variable), ("x", x), ("y", y)):
        if name is not None and not isinstance(name, str):
            raise AtlasError(f"{what} = {shorten(name)} must be the name of a variable or an axis (text), or None.")
    if scene is not None and not isinstance(scene, (str, Scene)):
        raise AtlasError(f"scene = {shorten(scene)} must be a Scene, a built-in scene's name, or None.")
    if isinstance(resolution, bool) or not isinstance(resolution, (int, np.integer)) or not 2 <= resolution <= 5000:
        raise AtlasError(f"resolution = {shorten(resolution)} must be a whole number from 2 to 5000.")


def _fixed_values(ds) -> dict:
    try:
        return json.loads(ds.attrs.get("fixed", "{}"))
    except json.JSONDecodeError:
        return {}


def atlas_data(
    ds, variable: str | None = None, *, x: str | None = None, y: str | None = None, scene=None, resolution: int = 300
) -> AtlasData:
    """The data of :func:`atlas_plot`: one variable of ``ds`` and the scene's region boundaries.

    Regions whose symbols are not among the atlas's axes and fixed numeric values (e.g. the
    guides' regions in the presentation variables kappa, v_j) are listed in ``skipped``.

    Examples
    --------
    >>> import numpy as np
    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", "classification", {"alpha": np.linspace(0.3, 2.8, 6), "mu": [0.5, 1.5]},
    ...                  values={"m": 1})
    >>> data = atlas_data(ds, "region", resolution=50)
    >>> data.x, data.y, sorted(data.boundaries), data.skipped
    ('alpha', 'mu', ['law-dependent', 'stable for every law'], ('Hopf line',))
    """
    _check_atlas_arguments(ds, variable, x, y, scene, resolution)
    names = [v for v in ds.data_vars if v != "reason_code"]
    variable = variable or names[0]
    if variable not in ds.data_vars:
        raise AtlasError(f"the atlas has no variable {variable!r}; it has {names}.")
    dims = list(ds[variable].dims)
    if len(dims) not in (1, 2):
        raise AtlasError(f"{variable} has {len(dims)} axes {dims}; select one or two (ds.sel / ds.isel) to plot.")
    x = x or dims[0]
    if y is None and len(dims) == 2:
        y = next(d for d in dims if d != x)
    values = ds[variable].transpose(*([y, x] if y else [x])).values.astype(float)
    xs = ds[x].values.astype(float)
    ys = ds[y].values.astype(float) if y else None
    scene = scene_by_name(ds.attrs["scene"]) if scene is None else scene
    cut = {str(c): float(ds[c]) for c in ds.coords if ds[c].ndim == 0}  # an axis fixed by ds.sel(...)
    known = {**_fixed_values(ds), **cut, x: None, **({y: None} if y else {})}
    fine_x = np.linspace(xs.min(), xs.max(), resolution)
    if y:
        fine = np.meshgrid(fine_x, np.linspace(ys.min(), ys.max(), resolution))
        grid_values = {x: fine[0], y: fine[1]}
    else:
        fine = (fine_x,)
        grid_values = {x: fine_x}
    shape = fine[0].shape
    boundaries, skipped = {}, []
    for name, region in scene.regions().items():
        symbols = {str(s) for s in region.condition.free_symbols}
        if not symbols or not symbols <= set(known):
            skipped += [name] if symbols else []
            continue
        numbers = {k: v for k, v in known.items() if v is not None}
        fields = relational_fields(region.condition, {**numbers, **grid_values}, shape)
        boundaries[name] = (region.latex(), fields)
    title = f"{ds.attrs.get('scene', '')}: {variable}"
    return AtlasData(variable, x, y, xs, ys, values, title, tuple(fine), boundaries, tuple(skipped))


def atlas_plot(data, ax=None, *, variable: str | None = None, legend: bool = True, **data_options) -> ContactPlot:
    """Draw an atlas (a Dataset from :func:`~contactsym.atlas.sweep`, or :class:`AtlasData`) with the
    closed-form region boundaries over it; returns the artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", "classification", {"alpha": np.linspace(0.3, 2.8, 6), "mu": [0.5, 1.5]},
    ...                  values={"m": 1})
    >>> fig, ax = plt.subplots()
    >>> artists = atlas_plot(ds, ax=ax, variable="region", resolution=50)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('alpha', 'mu')
    >>> plt.close(fig)
    """
    flag(legend, "legend", AtlasError)
    if not isinstance(data, AtlasData):
        data = atlas_data(data, variable, **data_options)
    if ax is not None and not hasattr(ax, "pcolormesh"):
        raise AtlasError(f"ax = {shorten(ax)} must be a matplotlib Axes (or None).")
    ax = axes_or_current(ax)
    artists = []
    if data.y is None:
        (line,) = ax.plot(data.xs, data.values, "o-", label=data.variable)
        artists.append(line)
    else:
        mesh = ax.pcolormesh(data.xs, data.ys, np.ma.masked_invalid(data.values), shading="nearest", cmap="viridis")
        artists += [mesh, ax.figure.colorbar(mesh, ax=ax, label=data.variable)]
    drawn = False
    for colour, (name, (latex, fields)) in zip(_COLOURS, data.boundaries.items()):
        lines = _boundaries(ax, data, fields, colour)
        if lines:  # a legend entry only for a boundary that passes through the atlas
            label = f"{name}: ${latex}$" if len(latex) <= 80 else name  # a long closed form would hide the plot
            (proxy,) = ax.plot([], [], "-", color=colour, lw=1.5, label=label)
            artists += [*lines, proxy]
            drawn = True
    ax.set_xlabel(data.x)
    ax.set_ylabel(data.y or data.variable)
    ax.set_title(data.title, fontsize=10)
    if legend and drawn:
        artists.append(ax.legend(fontsize=7, loc="best", framealpha=0.9))
    return ContactPlot.of(ax, artists)


def _boundaries(ax, data: AtlasData, fields, colour) -> list:
    """Zero sets of the fields: contour lines in 2-D, vertical lines at the sign changes in 1-D."""
    artists = []
    for values in fields:
        if not np.nanmin(values) < 0 < np.nanmax(values):
            continue
        if data.y is not None:
            artists.append(ax.contour(*data.fine, values, levels=[0.0], colors=colour, linewidths=1.5))
            continue
        xs = data.fine[0]
        for i in np.nonzero(np.sign(values[:-1]) * np.sign(values[1:]) < 0)[0]:
            at = xs[i] - values[i] * (xs[i + 1] - xs[i]) / (values[i + 1] - values[i])
            artists.append(ax.axvline(at, color=colour, lw=1.5))
    return artists
