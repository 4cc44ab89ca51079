"""Fig. 1 of the paper, derived: the (v1, v2) plane of the Painlevé–Klein guides (§5).

:func:`fig1_data` evaluates the guides' stability regions (5.6), (5.7) and count regions
(5.8), (5.10) on a grid at one angle phi; :func:`fig1_plot` hatches them, draws the
dashed lines and writes the counts in.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from ..arguments import between, checked
from ..counts.regions import square_threshold
from ..errors import ArgumentError
from .common import STABLE_HATCH, UNSTABLE_HATCH, ContactPlot, _degrees, _float, _scene, axes_or_current
from .regionplot import RegionData, boundary_contours, region_mask, region_plot, relational_fields

__all__ = ["Fig1Data", "fig1_data", "fig1_plot"]


def _angle_parameter(scene, angle):
    """The presentation parameter p for a scene angle theta, from sin(theta), cos(theta) -> f(p)."""
    for key, value in scene.presentation.items():
        if isinstance(key, sp.sin):
            theta = key.args[0]
            tangent = sp.cancel(value / scene.presentation[sp.cos(theta)])
            (parameter,) = tangent.free_symbols
            solutions = [s for s in sp.solve(sp.Eq(tangent, sp.tan(angle)), parameter) if s.is_positive]
            return theta, parameter, solutions[0]
    raise ArgumentError(f"scene '{scene.name}' presents no angle; fig1_data draws a scene with an angle phi.")


@checked(nan=True)
@dataclass(frozen=True)
class Fig1Data:
    """The (v1, v2) plane of the guides at one angle phi (Fig. 1).

    Examples
    --------
    The three stability regions never overlap on the grid:

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> data = fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 3, resolution=41)
    >>> isinstance(data, Fig1Data), data.V1.shape, sorted(data.masks)
    (True, (41, 41), ['law-dependent', 'stable for every law', 'unstable for every law'])
    >>> int(sum(mask.astype(int) for mask in data.masks.values()).max())
    1
    """

    phi: sp.Expr
    kappa: sp.Expr
    panel: str
    threshold: sp.Expr
    V1: np.ndarray
    V2: np.ndarray
    masks: dict  # stability region name -> mask
    counts: dict  # count region name -> mask
    lines: list  # fields whose zero sets are the dashed lines
    regions: dict = field(repr=False)
    count_regions: dict = field(repr=False)


@checked(phi="sp.Expr", extent="float", resolution=between(2, 4096))
def fig1_data(scene, phi, *, extent=4.0, resolution=400) -> Fig1Data:
    """Fig. 1: stability and count regions of the guides in the (v1, v2) plane at angle phi.

    Parameters
    ----------
    scene : Scene
        The guides (``contactsym.scene("painleve-klein-guides")``, or a scene that presents
        the same angle and the variables v_1, v_2).
    phi : sympy expression or float
        The rod's angle, in radians (e.g. ``sp.pi/3``).
    extent : float
        The plane shown is ``[-extent, extent]^2``.
    resolution : int
        Grid points per axis.

    Returns
    -------
    Fig1Data
        Masks of "stable for every law", "unstable for every law", "law-dependent" and
        of the count regions; ``panel`` is "a" when phi >= the derived threshold (5.9).

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> data = fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 3, resolution=41)
    >>> data.kappa, data.panel, data.threshold
    (sqrt(3)/3, 'a', atan(sqrt(2)))
    >>> sorted(data.counts)
    ['one or three', 'two or none', 'unique']
    """
    scene = _scene(scene)
    phi = sp.nsimplify(phi) if not isinstance(phi, sp.Basic) else phi
    theta, parameter, value = _angle_parameter(scene, phi)
    threshold = square_threshold(scene)
    panel = "a" if threshold.inside.subs(theta, phi) == sp.true else "b"
    grid = np.linspace(-extent, extent, resolution)
    V1, V2 = np.meshgrid(grid, grid)
    values = {"v_1": V1, "v_2": V2, str(parameter): _float(value)}
    regions = scene.regions()
    names = ("stable for every law", "unstable for every law", "law-dependent")
    masks = {name: region_mask(regions[name], values, V1.shape).copy() for name in names}
    count_regions = scene.equilibrium_counts()
    counts = {name: region_mask(r, values, V1.shape).copy() for name, r in count_regions.items()}
    lines = relational_fields(sp.Or(*[r.condition for r in count_regions.values()]), values, V1.shape)
    return Fig1Data(phi, value, panel, threshold.angle, V1, V2, masks, counts, lines, regions, count_regions)


_COUNT_LABELS = {"unique": "1", "two or none": "0 or 2", "one or three": "1 or 3"}


def _label_points(mask) -> list[tuple[int, int]]:
    """One grid index per connected piece of a mask, as far from its edges as possible.

    Pieces that touch only at a corner (the half-strips at the square's vertices) are
    separated by eroding one grid step first.
    """
    from scipy import ndimage  # a quarter of the package's import time: load it when labels are drawn

    core = ndimage.binary_erosion(mask)
    labels, count = ndimage.label(core)
    distance = ndimage.distance_transform_edt(core)
    points = []
    for piece in range(1, count + 1):
        inside = np.where(labels == piece, distance, -1.0)
        points.append(np.unravel_index(int(np.argmax(inside)), mask.shape))
    return points


@checked(ax="Axes | None", legend="bool")
def fig1_plot(data: Fig1Data, ax=None, *, legend=True) -> ContactPlot:
    """Draw Fig. 1 on an Axes: stability hatched, the four dashed lines, the counts written in.

    Returns
    -------
    ContactPlot

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> import contactsym as cs
    >>> artists = fig1_plot(fig1_data(cs.scene("painleve-klein-guides"), sp.pi / 4, resolution=41), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$v_1$', '$v_2$')
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    artists = []
    X, Y = data.V1, data.V2
    styles = {
        "stable for every law": (STABLE_HATCH, "tab:blue", "stable for every law (5.6)"),
        "unstable for every law": (UNSTABLE_HATCH, "tab:red", "unstable for every law (5.7)"),
    }
    for name, (hatch, color, label) in styles.items():
        region = data.regions[name]
        grid = RegionData("v_1", "v_2", X, Y, data.masks[name], region)
        artists += region_plot(region, ax, x="v_1", y="v_2", data=grid, hatch=hatch, color=color, label=label)
    (proxy,) = ax.fill([], [], facecolor="white", edgecolor="0.5", label="depends on the contact law")
    artists.append(proxy)
    artists += boundary_contours(ax, X, Y, data.lines, colors="black", linestyles="dashed", linewidths=1.2)
    (line_proxy,) = ax.plot([], [], "k--", lw=1.2, label=r"$\pm v_1 \pm v_2 = 2\kappa^2$")
    artists.append(line_proxy)
    for name, mask in data.counts.items():
        for i, j in _label_points(mask):
            text = ax.text(
                X[i, j],
                Y[i, j],
                _COUNT_LABELS.get(name, name),
                ha="center",
                va="center",
                fontsize=9,
                bbox={"boxstyle": "round,pad=0.2", "facecolor": "white", "edgecolor": "0.6"},
            )
            artists.append(text)
    ax.set_xlabel("$v_1$")
    ax.set_ylabel("$v_2$")
    ax.set_aspect("equal")
    ax.set_xlim(X.min(), X.max())
    ax.set_ylim(Y.min(), Y.max())
    side = r"\geq" if data.panel == "a" else "<"
    ax.set_title(
        f"Fig. 1{data.panel}: $\\varphi = {_degrees(data.phi)}^\\circ {side} \\arctan\\sqrt{{2}} "
        f"\\approx {_degrees(data.threshold)}^\\circ$, $\\kappa = \\cot\\varphi = {_float(data.kappa):.3g}$",
        fontsize=10,
    )
    if legend:
        artists.append(ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.11), ncol=2, fontsize=8))
    return ContactPlot.of(ax, artists)
