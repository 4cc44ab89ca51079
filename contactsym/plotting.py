"""Figures drawn from the derived regions, never by hand.

Every figure is a pair: a ``*_data`` function (pure computation: grids, masks, roots,
closed-form regions) and a ``*_plot(data, ax=None)`` that draws the data on a given
matplotlib Axes and returns the artists it added. Regions are hatched (single hatching:
stable for every contact law; double hatching: unstable for every law; none: the
stability depends on the law), as in the paper's Fig. 1.

- :func:`region_data`, :func:`region_plot`: any :class:`~contactsym.regions.Region` in
  a plane of two of its symbols (``Region.plot`` calls :func:`region_plot`);
- :func:`fig1_data`, :func:`fig1_plot`: Fig. 1a/1b, the (v1, v2) plane of the guides;
- :func:`rod_f_data`, :func:`rod_f_plot`: f(u) of the rod in the three cases of §3;
- :func:`brake_map_data`, :func:`brake_map_plot`: the brake's (alpha, mu) map;
- :func:`brake_hopf_data`, :func:`brake_hopf_plot`: its Hopf line at alpha = 90 deg;
- :func:`phase_portrait_data`, :func:`phase_portrait_plot`: the fast subsystem (2.1).
- :func:`fast_trajectories_plot`, :func:`reactions_plot`, :func:`cycle_plot`: results of
  :mod:`contactsym.numerics` (simulated trajectories, reactions N_j(t), a fast cycle).

:func:`paper_figures` ``(directory)`` writes all of them as PNG files and returns their
paths (``fig1a_guides.png``, ``fig1b_guides.png``, ``rod_f_cases.png``,
``rod_phase_portrait.png``, ``brake_alpha_mu.png``, ``brake_hopf.png``,
``sliding_point_phase_portrait.png``); :func:`scene_figures` ``(scene, directory)``
writes one scene's figures and returns ``{caption: path}``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import sympy as sp

from .latex import tex
from .regions import Region, closed_form

__all__ = [
    "ROD_CASES",
    "brake_hopf_data",
    "brake_hopf_plot",
    "brake_map_data",
    "brake_map_plot",
    "fig1_data",
    "fig1_plot",
    "paper_figures",
    "scene_figures",
    "phase_portrait_data",
    "phase_portrait_plot",
    "fast_trajectories_plot",
    "reactions_plot",
    "cycle_plot",
    "region_data",
    "region_plot",
    "rod_f_data",
    "rod_f_plot",
]

#: Hatches: stable for every law (single), unstable for every law (double), as in Fig. 1.
STABLE_HATCH = "///"
UNSTABLE_HATCH = "xxx"


def _axes(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.gca()
    return ax


def _name(symbol) -> str:
    return symbol if isinstance(symbol, str) else str(symbol)


def _float(value) -> float:
    return float(sp.N(value)) if isinstance(value, sp.Basic) else float(value)


def _values_for(region: Region, values: dict, shape) -> np.ndarray:
    """Evaluate a region with the values it depends on (others ignored), broadcast to shape."""
    needed = {name for name in region._by_name}
    missing = needed - set(values)
    if missing:
        raise ValueError(f"give values for {sorted(missing)} (in fixed=...); the region depends on them.")
    mask = region.evaluate(**{name: values[name] for name in needed})
    return np.broadcast_to(mask, shape)


def _relational_fields(condition, values: dict, shape) -> list[np.ndarray]:
    """lhs - rhs of every inequality/equation in a condition, on a grid (zero sets = boundaries)."""
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


# --- any region ------------------------------------------------------------------------------


@dataclass(frozen=True)
class RegionData:
    """A region on a grid: ``mask[i, j]`` is membership at ``(X[i, j], Y[i, j])``."""

    x: str
    y: str
    X: np.ndarray
    Y: np.ndarray
    mask: np.ndarray
    region: Region


def region_data(region: Region, *, x, y, fixed=None, xlim=(-1.0, 1.0), ylim=(-1.0, 1.0), resolution=300):
    """Evaluate a region on a grid of the (x, y) plane.

    Parameters
    ----------
    region : Region
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
    return RegionData(_name(x), _name(y), X, Y, _values_for(region, values, X.shape).copy(), region)


def region_plot(
    region: Region,
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
):
    """Hatch a region in the (x, y) plane.

    Parameters
    ----------
    region : Region
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
    list of Artist
        The filled contour set, and the legend proxy when ``label`` is given.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> a, b = sp.symbols("a b", real=True)
    >>> fig, ax = plt.subplots()
    >>> artists = Region(a + b < 1).plot(ax=ax, x="a", y="b", resolution=20, label="a + b < 1")
    >>> len(artists), ax.get_legend_handles_labels()[1]
    (2, ['a + b < 1'])
    >>> plt.close(fig)
    """
    ax = _axes(ax)
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
    return artists


def _boundary_plot(ax, X, Y, fields, **style):
    artists = []
    for values in fields:
        if np.nanmin(values) < 0 < np.nanmax(values):
            artists.append(ax.contour(X, Y, values, levels=[0.0], **style))
    return artists


# --- Fig. 1: the guides in the (v1, v2) plane ---------------------------------------------------


def _angle_parameter(scene, angle):
    """The presentation parameter p for a scene angle theta, from sin(theta), cos(theta) -> f(p)."""
    for key, value in scene.presentation.items():
        if isinstance(key, sp.sin):
            theta = key.args[0]
            tangent = sp.cancel(value / scene.presentation[sp.cos(theta)])
            (parameter,) = tangent.free_symbols
            solutions = [s for s in sp.solve(sp.Eq(tangent, sp.tan(angle)), parameter) if s.is_positive]
            return theta, parameter, solutions[0]
    raise ValueError(f"scene '{scene.name}' presents no angle.")


def _degrees(angle) -> str:
    value = math.degrees(_float(angle))
    return f"{value:.0f}" if abs(value - round(value)) < 1e-9 else f"{value:.1f}"


@dataclass(frozen=True)
class Fig1Data:
    """The (v1, v2) plane of the guides at one angle phi (Fig. 1)."""

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


def fig1_data(phi, *, extent=4.0, resolution=400) -> Fig1Data:
    """Fig. 1: stability and count regions of the guides in the (v1, v2) plane at angle phi.

    Parameters
    ----------
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
    >>> data = fig1_data(sp.pi / 3, resolution=41)
    >>> data.kappa, data.panel, data.threshold
    (sqrt(3)/3, 'a', atan(sqrt(2)))
    >>> sorted(data.counts)
    ['one or three', 'two or none', 'unique']
    """
    from .counts import square_threshold
    from .scenes import scene

    guides = scene("painleve-klein-guides")
    phi = sp.nsimplify(phi) if not isinstance(phi, sp.Basic) else phi
    theta, parameter, value = _angle_parameter(guides, phi)
    threshold = square_threshold(guides)
    panel = "a" if threshold.inside.subs(theta, phi) == sp.true else "b"
    grid = np.linspace(-extent, extent, resolution)
    V1, V2 = np.meshgrid(grid, grid)
    values = {"v_1": V1, "v_2": V2, str(parameter): _float(value)}
    regions = guides.regions()
    names = ("stable for every law", "unstable for every law", "law-dependent")
    masks = {name: _values_for(regions[name], values, V1.shape).copy() for name in names}
    count_regions = guides.equilibrium_counts()
    counts = {name: _values_for(r, values, V1.shape).copy() for name, r in count_regions.items()}
    lines = _relational_fields(sp.Or(*[r.condition for r in count_regions.values()]), values, V1.shape)
    return Fig1Data(phi, value, panel, threshold.angle, V1, V2, masks, counts, lines, regions, count_regions)


_COUNT_LABELS = {"unique": "1", "two or none": "0 or 2", "one or three": "1 or 3"}


def _label_points(mask) -> list[tuple[int, int]]:
    """One grid index per connected piece of a mask, as far from its edges as possible.

    Pieces that touch only at a corner (the half-strips at the square's vertices) are
    separated by eroding one grid step first.
    """
    from scipy import ndimage

    core = ndimage.binary_erosion(mask)
    labels, count = ndimage.label(core)
    distance = ndimage.distance_transform_edt(core)
    points = []
    for piece in range(1, count + 1):
        inside = np.where(labels == piece, distance, -1.0)
        points.append(np.unravel_index(int(np.argmax(inside)), mask.shape))
    return points


def fig1_plot(data: Fig1Data, ax=None, *, legend=True):
    """Draw Fig. 1 on an Axes: stability hatched, the four dashed lines, the counts written in.

    Returns
    -------
    list of Artist

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> artists = fig1_plot(fig1_data(sp.pi / 4, resolution=41), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$v_1$', '$v_2$')
    >>> plt.close(fig)
    """
    ax = _axes(ax)
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
    artists += _boundary_plot(ax, X, Y, data.lines, colors="black", linestyles="dashed", linewidths=1.2)
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
    return artists


# --- §3: f(u) of the rod ----------------------------------------------------------------------

#: Parameter choices for the three cases of §3, in the paper's symbols (phi in radians).
ROD_CASES = {
    "unique": {"phi": sp.pi / 4, "mu_+": 1.2, "mu_-": 0.4, "Y^*_1": 1.0, "Y^*_2": 1.0, "loads": (-1.0,)},
    "fold": {"phi": sp.pi / 4, "mu_+": 3.2, "mu_-": 2.8, "Y^*_1": 1.0, "Y^*_2": -1.0, "loads": (-4.0, 0.0)},
    "cusp": {"phi": sp.pi / 4, "mu_+": 2.7, "mu_-": 0.3, "Y^*_1": 2.0, "Y^*_2": 2.0, "loads": (-0.6, 2.0)},
}


def _piece_roots(f, corners):
    """Roots of a continuous f, affine between the sorted corners, with the slope at each."""
    edges = [-math.inf, *sorted(corners), math.inf]
    roots = []
    for a, b in zip(edges, edges[1:]):
        if b - a < 1e-12:
            continue
        if a == -math.inf:
            t1, t2 = b - 2.0, b - 1.0
        elif b == math.inf:
            t1, t2 = a + 1.0, a + 2.0
        else:
            t1, t2 = a + (b - a) / 3, b - (b - a) / 3
        slope = (f(t2) - f(t1)) / (t2 - t1)
        if abs(slope) > 1e-12:
            root = t1 - f(t1) / slope
            if a < root < b:
                roots.append((root, slope))
    return roots


@dataclass(frozen=True)
class RodFData:
    """f(u) of the Painlevé–Klein rod for one parameter choice and several loads X*."""

    case: str
    values: dict
    count: str
    condition: sp.Basic
    ordering: sp.Basic
    corners: tuple
    corner_labels: tuple
    u: np.ndarray
    curves: list  # (X*, f(u) array, [(u*, slope), ...])


def rod_f_data(case="cusp", *, values=None, points=400) -> RodFData:
    """f(u) (3.6) of the rod with the classification of its count region.

    Parameters
    ----------
    case : str
        A key of :data:`ROD_CASES` (or a label when ``values`` is given).
    values : dict, optional
        Values of phi, mu_+, mu_-, Y^*_1, Y^*_2 and ``loads`` (values of X^*).
    points : int
        Samples of u.

    Returns
    -------
    RodFData
        ``count`` is the name of the count region that holds (derived), ``condition``
        its closed form within the corner ordering ``ordering``.

    Examples
    --------
    >>> data = rod_f_data("cusp", points=50)
    >>> data.count, str(data.condition), str(data.ordering)
    ('one or three', '(mu_+ > 2) & (Abs(mu_-) < 2)', 'Y^*_1 + Y^*_2 > 0')
    >>> [len(roots) for _, _, roots in data.curves]
    [3, 1]
    """
    from .counts import corner_cases
    from .scenes import scene

    rod = scene("painleve-klein-rod")
    values = dict(values or ROD_CASES[case])
    loads = values.pop("loads")
    numeric = {k: _float(v) for k, v in values.items()}
    fast = rod.fast_subsystem()
    (u,) = fast.u
    f = rod.present(fast.f[0])
    symbols = sorted(f.free_symbols - {u}, key=str)
    function = sp.lambdify([u, *symbols], f, "numpy")
    counts = rod.equilibrium_counts()
    (count,) = [n for n, r in counts.items() if bool(r.evaluate(**{s: numeric[s] for s in r._by_name}))]
    for candidate in corner_cases(rod):
        if bool(
            Region(candidate.ordering).evaluate(**{str(s): numeric[str(s)] for s in candidate.ordering.free_symbols})
        ):
            chosen = candidate
            break
    corners = tuple(_float(c.subs({sp.Symbol(k, real=True): v for k, v in numeric.items()})) for c in chosen.corners)
    low, high = min(corners) - 4.0, max(corners) + 4.0
    grid = np.linspace(low, high, points)
    curves = []
    for load in loads:
        args = [load if str(s) == "X^*" else numeric[str(s)] for s in symbols]

        def g(t, args=args):
            return function(t, *args)

        roots = _piece_roots(g, corners)
        curves.append((load, np.asarray(g(grid), float), roots))
    return RodFData(
        case,
        {**values, "loads": loads},
        count,
        chosen.regions[count],
        chosen.ordering,
        corners,
        tuple(tex(c) for c in chosen.corners),
        grid,
        curves,
    )


_CASE_TITLES = {
    "unique stable": "unique stable root",
    "two or none": "fold: two roots or none",
    "one or three": "cusp: one root or three",
}


def rod_f_plot(data: RodFData, ax=None, *, legend=True):
    """Draw f(u) for each load, roots marked (filled: stable, f' > 0; open: unstable).

    Parameters
    ----------
    data : RodFData
        From :func:`rod_f_data`.
    ax : matplotlib Axes, optional
        Default: the current Axes.
    legend : bool
        Add a legend.

    Returns
    -------
    list of Artist

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> artists = rod_f_plot(rod_f_data("fold", points=20), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$u = R$', '$f(u)$')
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    artists = [ax.axhline(0.0, color="0.4", lw=0.8)]
    styles = ["-", "--", ":", "-."]
    for (load, values, roots), style in zip(data.curves, styles):
        word = {0: "no root", 1: "1 root"}.get(len(roots), f"{len(roots)} roots")
        (line,) = ax.plot(data.u, values, style, color="black", lw=1.5, label=f"$X^* = {load:g}$: {word}")
        artists.append(line)
        for root, slope in roots:
            marker = {"marker": "o", "ms": 7, "mec": "black", "mfc": "black" if slope > 0 else "white"}
            artists += ax.plot([root], [0.0], ls="none", **marker)
    for corner, label in zip(data.corners, data.corner_labels):
        artists.append(ax.axvline(corner, color="0.6", lw=0.8, ls=":"))
        artists.append(
            ax.annotate(
                f"$u = {label}$",
                (corner, 0.97),
                xycoords=("data", "axes fraction"),
                ha="center",
                va="top",
                fontsize=8,
                bbox={"boxstyle": "round,pad=0.15", "facecolor": "white", "edgecolor": "none"},
            )
        )
    kinds = {slope > 0 for _, _, roots in data.curves for _, slope in roots}
    for stable in sorted(kinds, reverse=True):
        face, word = ("black", "stable root, $f' > 0$") if stable else ("white", "unstable root, $f' < 0$")
        artists += ax.plot([], [], "o", ms=7, mec="black", mfc=face, label=word)
    ax.set_xlabel("$u = R$")
    ax.set_ylabel("$f(u)$")
    condition = tex(data.condition)
    ordering = tex(data.ordering)
    ax.set_title(f"{_CASE_TITLES.get(data.count, data.count)}\n${condition}$, ${ordering}$", fontsize=10)
    if legend:
        artists.append(ax.legend(fontsize=8, loc="best"))
    return artists


# --- §6: the brake ----------------------------------------------------------------------------


@dataclass(frozen=True)
class BrakeMapData:
    """The brake's (alpha, mu) plane: stable for every law, law-dependent, mu = |cot alpha|."""

    alpha: np.ndarray  # radians
    mu: np.ndarray
    masks: dict
    boundary: list
    regions: dict = field(repr=False)


def brake_map_data(*, mu_max=2.0, resolution=300) -> BrakeMapData:
    """Regions of the brake in the (alpha, mu) plane (6.3), from ``scene("brake").regions()``.

    Examples
    --------
    >>> data = brake_map_data(resolution=30)
    >>> sorted(data.masks), str(data.regions["stable for every law"].condition)
    (['law-dependent', 'stable for every law'], 'mu <= Abs(cot(alpha))')
    """
    from .scenes import scene

    regions = scene("brake").regions()
    alphas = np.linspace(0.02, math.pi - 0.02, resolution)
    mus = np.linspace(0.0, mu_max, resolution)
    A, M = np.meshgrid(alphas, mus)
    values = {"alpha": A, "mu": M}
    names = ("stable for every law", "law-dependent")
    masks = {name: _values_for(regions[name], values, A.shape).copy() for name in names}
    boundary = _relational_fields(regions["stable for every law"].condition, values, A.shape)
    return BrakeMapData(A, M, masks, boundary, {name: regions[name] for name in names})


def brake_map_plot(data: BrakeMapData, ax=None, *, legend=True):
    """Draw the (alpha, mu) map; alpha in degrees.

    Parameters
    ----------
    data : BrakeMapData
        From :func:`brake_map_data`.
    ax : matplotlib Axes, optional
        Default: the current Axes.
    legend : bool
        Add a legend.

    Returns
    -------
    list of Artist

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> artists = brake_map_plot(brake_map_data(resolution=20), ax=ax)
    >>> print(ax.get_ylabel())
    $\\mu$
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    X = np.degrees(data.alpha)
    region = data.regions["stable for every law"]
    grid = RegionData("alpha", "mu", X, data.mu, data.masks["stable for every law"], region)
    label = f"stable for every law (6.3): ${tex(region.condition)}$"
    artists = region_plot(region, ax, x="alpha", y="mu", data=grid, hatch=STABLE_HATCH, color="tab:blue", label=label)
    (proxy,) = ax.fill([], [], facecolor="white", edgecolor="0.5", label="depends on the law (Hopf possible)")
    artists.append(proxy)
    artists += _boundary_plot(ax, X, data.mu, data.boundary, colors="black", linewidths=1.5)
    (line,) = ax.plot([], [], "k-", lw=1.5, label=r"$\mu = |\cot\alpha|$")
    artists.append(line)
    ax.set_xlabel(r"$\alpha$ (degrees)")
    ax.set_ylabel(r"$\mu$")
    ax.set_xticks([0, 45, 90, 135, 180])
    ax.set_title("brake (§6): robustness with respect to the contact law", fontsize=10)
    if legend:
        artists.append(ax.legend(loc="upper center", fontsize=8, framealpha=0.95))
    return artists


@dataclass(frozen=True)
class BrakeHopfData:
    """The brake at alpha = 90 deg, Phi_j = Phi, Psi_j = Psi: (mu, Phi) plane at fixed Psi, m."""

    mu: np.ndarray
    Phi: np.ndarray
    fixed: dict
    stable: Region
    hopf: Region
    frequency: sp.Expr  # omega on the Hopf line, in the stretched time
    masks: dict
    hopf_field: list


def brake_hopf_data(*, Psi=-1.0, m=1.0, mu_max=3.0, Phi_min=-10.0, resolution=300) -> BrakeHopfData:
    """Hurwitz stability (6.4) and the Hopf line of the brake at alpha = 90 deg, equal laws.

    The closed forms come from ``scene("brake").stability()`` with alpha = pi/2,
    Phi_1 = Phi_2 = Phi, Psi_1 = Psi_2 = Psi substituted.

    Examples
    --------
    >>> data = brake_hopf_data(resolution=30)
    >>> data.stable.condition
    -Phi*m*mu**2 < Psi**2*(mu**2 + 1)
    >>> data.hopf.condition
    Eq(Phi*m*mu**2 + Psi**2*mu**2 + Psi**2, 0)
    >>> data.frequency
    -Psi*(mu**2 + 1)/(m*mu)
    """
    from .scenes import scene

    brake = scene("brake")
    stability, lin = brake.stability(), brake.linearization()
    Phi_, Psi_ = sp.symbols("Phi Psi", negative=True)
    alpha = next(s for s in brake.parameters if str(s) == "alpha")
    equal = {alpha: sp.pi / 2, **dict.fromkeys(lin.Phi, Phi_), **dict.fromkeys(lin.Psi, Psi_)}
    stable = closed_form(sp.And(*[sp.Gt(h, 0) for h in stability.hurwitz]).subs(equal), brake)
    hopf = closed_form(stability.hopf.subs(equal), brake)
    (on_line,) = sp.solve(hopf.lhs - hopf.rhs, Phi_)  # the Hopf line as Phi(mu); small expressions
    frequency = sp.powsimp(sp.factor(stability.hopf_frequency.subs(equal).subs(Phi_, on_line)))
    mus = np.linspace(0.02, mu_max, resolution)
    Phis = np.linspace(Phi_min, -1e-3, resolution)
    MU, PHI = np.meshgrid(mus, Phis)
    values = {"mu": MU, "Phi": PHI, "Psi": Psi, "m": m}
    stable_region = Region(stable, name="asymptotically stable (6.4)")
    hopf_region = Region(hopf, name="Hopf line")
    mask = _values_for(stable_region, values, MU.shape).copy()
    masks = {"stable": mask, "unstable": ~mask}
    field_ = _relational_fields(hopf, values, MU.shape)
    return BrakeHopfData(MU, PHI, {"Psi": Psi, "m": m}, stable_region, hopf_region, frequency, masks, field_)


def brake_hopf_plot(data: BrakeHopfData, ax=None, *, legend=True):
    """Draw the (mu, Phi) plane: stable single-hatched, unstable double-hatched, the Hopf line.

    Parameters
    ----------
    data : BrakeHopfData
        From :func:`brake_hopf_data`.
    ax : matplotlib Axes, optional
        Default: the current Axes.
    legend : bool
        Add a legend.

    Returns
    -------
    list of Artist

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> artists = brake_hopf_plot(brake_hopf_data(resolution=20), ax=ax)
    >>> print(ax.get_xlabel(), ax.get_ylabel())
    $\\mu$ $\\Phi$
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    grid = RegionData("mu", "Phi", data.mu, data.Phi, data.masks["stable"], data.stable)
    stable_label = f"stable: ${tex(data.stable.condition)}$"
    artists = region_plot(
        data.stable, ax, x="mu", y="Phi", data=grid, hatch=STABLE_HATCH, color="tab:blue", label=stable_label
    )
    unstable = RegionData("mu", "Phi", data.mu, data.Phi, data.masks["unstable"], ~data.stable)
    artists += region_plot(
        ~data.stable, ax, x="mu", y="Phi", data=unstable, hatch=UNSTABLE_HATCH, color="tab:red", label="unstable"
    )
    artists += _boundary_plot(ax, data.mu, data.Phi, data.hopf_field, colors="black", linewidths=2)
    hopf = tex(data.hopf.condition)
    (line,) = ax.plot([], [], "k-", lw=2, label=f"Hopf line: ${hopf}$")
    artists.append(line)
    ax.set_xlabel(r"$\mu$")
    ax.set_ylabel(r"$\Phi$")
    fixed = ", ".join(f"${tex(sp.Symbol(k))} = {v:g}$" for k, v in data.fixed.items())
    ax.set_title(
        f"brake at $\\alpha = 90^\\circ$, $\\Phi_j = \\Phi$, $\\Psi_j = \\Psi$ ({fixed})\n"
        f"squeal frequency on the Hopf line: $\\omega = {tex(data.frequency)}$",
        fontsize=9,
    )
    if legend:
        artists.append(ax.legend(loc="lower right", fontsize=8, framealpha=0.95))
    return artists


# --- (2.1): a phase portrait -------------------------------------------------------------------


@dataclass(frozen=True)
class PhasePortraitData:
    """The fast subsystem (2.1) of a k = 1 scene on a (u, v) grid, with its equilibria."""

    scene: str
    count: str
    title: str
    u: np.ndarray
    v: np.ndarray
    du: np.ndarray
    dv: np.ndarray
    equilibria: list  # (u*, stable)
    values: dict


#: Numeric values for the phase portraits, in each scene's presentation symbols.
PORTRAIT_VALUES = {
    "painleve-klein-rod": {
        **{k: v for k, v in ROD_CASES["cusp"].items() if k != "loads"},
        "X^*": ROD_CASES["cusp"]["loads"][0],
    },
    "sliding-point": {"m": 1.0, "b": 0.25, "Y": -1.0},
}


def _by_name(expr, values: dict):
    """Substitute numbers by name for symbols and for applied functions such as Y(x, xdot)."""
    expr = sp.sympify(expr)
    mapping = {s: values[str(s)] for s in expr.free_symbols if str(s) in values}
    for applied in expr.atoms(sp.core.function.AppliedUndef):
        if applied.func.__name__ in values:
            mapping[applied] = values[applied.func.__name__]
    return expr.xreplace({k: sp.Float(_float(v)) for k, v in mapping.items()})


def phase_portrait_data(
    scene="painleve-klein-rod", values=None, *, Phi=-1.0, Psi=-0.5, extent=(6.0, 6.0), resolution=60
) -> PhasePortraitData:
    """The fast subsystem u' = Phi v + Psi f(u), v' = f(u) (3.1) of a k = 1 scene on a grid.

    Parameters
    ----------
    scene : str or Scene
        A built-in scene with one contact, or a key of :data:`ROD_CASES` (the rod in that
        case, at its first load), or any Scene with one contact (then ``values`` has no
        default).
    values : dict, optional
        Numbers for its presentation symbols (by name; a load such as ``Y(x, xdot)`` by
        its function name); default :data:`PORTRAIT_VALUES`.
    Phi, Psi : float
        The law's constants, where the law is generic (a Kelvin–Voigt law fixes its own).
    extent : pair of float
        Half-widths of the (u, v) window, centred on the equilibria.
    resolution : int
        Grid points per axis.

    Returns
    -------
    PhasePortraitData
        The field (u', v') on the grid and the equilibria (u*, stable), from the scene's
        equilibrium branches; stable when f'(u*) > 0 (Proposition 3, for every law).

    Examples
    --------
    >>> data = phase_portrait_data(resolution=10)
    >>> data.count, [stable for _, stable in data.equilibria]
    ('one or three', [True, False, True])
    >>> phase_portrait_data("sliding-point", resolution=10).equilibria
    [(1.0, True)]
    >>> len(phase_portrait_data("fold", resolution=10).equilibria)
    2
    """
    from .scenes import scene as built_in

    name = scene if isinstance(scene, str) else scene.name
    if not isinstance(scene, str):  # a Scene object: its own values only, never a built-in's by name
        defaults = {}
    elif name in ROD_CASES:
        case = {k: v for k, v in ROD_CASES[name].items() if k != "loads"}
        defaults, name = {**case, "X^*": ROD_CASES[name]["loads"][0]}, "painleve-klein-rod"
        scene = built_in(name)
    else:
        defaults = PORTRAIT_VALUES.get(name, {})
        scene = built_in(name)
    values = dict(defaults if values is None else values)
    fast = scene.fast_subsystem()
    if scene.k != 1:
        raise ValueError(f"phase portraits are for one contact; '{name}' has k = {scene.k}.")
    (u,), (v,) = fast.u, fast.v
    laws = {law: value for law, value in ((fast.Phi[0], Phi), (fast.Psi[0], Psi)) if isinstance(law, sp.Symbol)}
    rhs = _by_name(scene.present(fast.rhs.subs(laws)), values)
    function = sp.lambdify([u, v], list(rhs), "numpy")
    equilibria = []
    for branch in scene.equilibria():
        if _by_name(scene.present(branch.condition), values) != sp.true:
            continue
        root = float(_by_name(scene.present(branch.u_star[0]), values))
        slope = float(_by_name(scene.present(scene.linearization(signs=branch.signs).A[0]), values))
        equilibria.append((root, slope > 0))
    equilibria.sort()
    try:
        counts = scene.equilibrium_counts()
    except (ValueError, NotImplementedError):  # a scene whose counts are not derived: the title says so
        counts = {}
    known = [(n, r) for n, r in counts.items() if set(r._by_name) <= set(values)]
    count = next((n for n, r in known if bool(r.evaluate(**{k: values[k] for k in r._by_name}))), "undecided")
    centre = float(np.mean([r for r, _ in equilibria])) if equilibria else 0.0
    us = np.linspace(centre - extent[0], centre + extent[0], resolution)
    vs = np.linspace(-extent[1], extent[1], resolution)
    U, V = np.meshgrid(us, vs)
    du, dv = (np.broadcast_to(np.asarray(c, float), U.shape) for c in function(U, V))
    shown = [f"${tex(law)} = {value:g}$" for law, value in laws.items()]
    shown += [f"${tex(sp.Symbol(k))} = {value:g}$" for k, value in values.items() if k in ("X^*", "b", "Y")]
    title = f"fast subsystem (2.1), {name} ({_CASE_TITLES.get(count, count)}): " + ", ".join(shown)
    return PhasePortraitData(name, count, title, U, V, du, dv, equilibria, values)


def phase_portrait_plot(data: PhasePortraitData, ax=None, *, legend=True):
    """Stream lines of (u', v'), equilibria (u*, 0) marked: filled stable, open unstable.

    Parameters
    ----------
    data : PhasePortraitData
        From :func:`phase_portrait_data`.
    ax : matplotlib Axes, optional
        Default: the current Axes.
    legend : bool
        Add a legend.

    Returns
    -------
    list of Artist

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> artists = phase_portrait_plot(phase_portrait_data("sliding-point", resolution=10), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$u$', '$v$')
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    before = set(ax.patches)
    speed = np.hypot(data.du, data.dv)
    stream = ax.streamplot(
        data.u[0],
        data.v[:, 0],
        data.du,
        data.dv,
        color="0.35",
        density=1.2,
        linewidth=0.5 + np.tanh(speed / speed.mean()),
    )
    arrows = [p for p in ax.patches if p not in before]  # StreamplotSet.arrows is never added to the Axes
    artists = [stream.lines, *arrows]
    for stable in (True, False):
        points = [r for r, s in data.equilibria if s == stable]
        if points:
            label = "stable equilibrium ($f' > 0$)" if stable else "unstable equilibrium ($f' < 0$)"
            face = "black" if stable else "white"
            artists += ax.plot(points, [0.0] * len(points), "o", ms=9, mec="tab:red", mfc=face, mew=2, label=label)
    ax.set_xlabel("$u$")
    ax.set_ylabel("$v$")
    ax.set_title(data.title, fontsize=9)
    if legend and data.equilibria:
        artists.append(ax.legend(loc="upper right", fontsize=8, framealpha=0.95))
    return artists


# --- all figures --------------------------------------------------------------------------------


def _fig1_caption(data: Fig1Data) -> str:
    where = (
        "the unique square (5.8) lies inside the region stable for every law (5.9)"
        if data.panel == "a"
        else "part of the unique square (5.8) lies where stability depends on the contact law"
    )
    return (
        f"Fig. 1{data.panel}: the (v1, v2) plane of the guides at phi = {_degrees(data.phi)} deg "
        f"(threshold arctan sqrt(2) = {_degrees(data.threshold)} deg). Single hatching: stable for every "
        "contact law (5.6); double hatching: unstable for every law (5.7); dashed: the lines "
        "+-v1 +- v2 = 2 kappa^2 bounding the unique square (5.8), the sectors with two solutions or none "
        f"(5.10) and the half-strips with one or three. Here {where}."
    )


def _portrait_caption(data: PhasePortraitData) -> str:
    stable = sum(1 for _, s in data.equilibria if s)
    unstable = len(data.equilibria) - stable
    return (
        f"Phase portrait of the fast subsystem (2.1) of {data.scene} ({_CASE_TITLES.get(data.count, data.count)}): "
        f"{stable} stable and {unstable} unstable equilibria (u*, 0); filled markers stable (f' > 0), "
        "open markers unstable (Proposition 3)."
    )


def _figures_of(name: str, resolution: int):
    """(file name, caption, draw(figure)) for one scene's figures."""
    from matplotlib.figure import Figure

    def single(size, data, plot):
        def draw():
            figure = Figure(figsize=size)
            plot(data, ax=figure.add_subplot())
            return figure

        return draw

    if name == "painleve-klein-guides":
        out = []
        for file, phi in (("fig1a_guides.png", sp.pi / 3), ("fig1b_guides.png", sp.pi / 4)):
            data = fig1_data(phi, resolution=resolution)
            out.append((file, _fig1_caption(data), single((6.0, 6.6), data, fig1_plot)))
        return out
    if name == "painleve-klein-rod":

        def rod_cases():
            figure = Figure(figsize=(15.0, 4.6))
            for i, case in enumerate(ROD_CASES, 1):
                rod_f_plot(rod_f_data(case, points=max(50, resolution)), ax=figure.add_subplot(1, 3, i))
            figure.subplots_adjust(wspace=0.3)
            return figure

        caption = (
            "f(u) of the Painleve-Klein rod (3.6) in the three cases of section 3: a unique stable root "
            "((3.8), (3.9)), a fold with two roots or none (impact-type catastrophe), a cusp with one root or "
            "three; each panel's condition is its derived count region. Filled dots: stable roots (f' > 0); "
            "open dots: unstable."
        )
        portrait = phase_portrait_data(name, resolution=max(20, resolution // 8))
        return [
            ("rod_f_cases.png", caption, rod_cases),
            ("rod_phase_portrait.png", _portrait_caption(portrait), single((7.0, 5.0), portrait, phase_portrait_plot)),
        ]
    if name == "brake":
        hopf = brake_hopf_data(resolution=resolution)
        return [
            (
                "brake_alpha_mu.png",
                "The brake in the (alpha, mu) plane: stable for every contact law where mu <= |cot alpha| (6.3); "
                "above the curve mu = |cot alpha| stability depends on the contact law (a Hopf bifurcation, "
                "brake squeal, is possible).",
                single((6.5, 4.5), brake_map_data(resolution=resolution), brake_map_plot),
            ),
            (
                "brake_hopf.png",
                f"The brake at alpha = 90 deg with Phi_j = Phi, Psi_j = Psi: asymptotically stable where "
                f"{sp.sstr(hopf.stable.condition)} ((6.4) with the mass m), unstable beyond the Hopf line "
                f"{sp.sstr(hopf.hopf.condition.lhs)} = 0, on which the squeal frequency is "
                f"omega = {sp.sstr(hopf.frequency)} (stretched time).",
                single((6.5, 4.8), hopf, brake_hopf_plot),
            ),
        ]
    if name == "sliding-point":
        portrait = phase_portrait_data(name, extent=(3.0, 3.0), resolution=max(20, resolution // 8))
        return [
            (
                "sliding_point_phase_portrait.png",
                _portrait_caption(portrait),
                single((7.0, 5.0), portrait, phase_portrait_plot),
            )
        ]
    return []


def scene_figures(scene, directory, *, resolution=400, dpi=150) -> dict[str, Path]:
    """Write one scene's figures as PNGs into ``directory``; returns {caption: path}.

    Parameters
    ----------
    scene : Scene or str
        A built-in scene (others have no figures: an empty dict).
    directory : str or Path
        Created when missing.
    resolution : int
        Grid points per axis for the region plots (lower is faster).
    dpi : int

    Returns
    -------
    dict of str to Path
        Caption (plain text, from the computed data) -> PNG file.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     written = scene_figures("brake", directory, resolution=20, dpi=20)
    ...     sorted(p.name for p in written.values())
    ['brake_alpha_mu.png', 'brake_hopf.png']
    """
    name = scene if isinstance(scene, str) else scene.name
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    written = {}
    for file, caption, draw in _figures_of(name, resolution):
        path = directory / file
        draw().savefig(path, dpi=dpi, bbox_inches="tight")
        written[caption] = path
    return written


#: The order of :func:`paper_figures`.
FIGURE_SCENES = ("painleve-klein-guides", "painleve-klein-rod", "brake", "sliding-point")


def paper_figures(directory, *, resolution=400, dpi=150) -> list[Path]:
    """Write every figure as a PNG into ``directory``; returns the paths.

    Parameters
    ----------
    directory : str or Path
        Created when missing.
    resolution : int
        Grid points per axis for the region plots (lower is faster).
    dpi : int

    Returns
    -------
    list of Path
        ``fig1a_guides.png``, ``fig1b_guides.png``, ``rod_f_cases.png``,
        ``rod_phase_portrait.png``, ``brake_alpha_mu.png``, ``brake_hopf.png``,
        ``sliding_point_phase_portrait.png``.
    """
    paths = []
    for name in FIGURE_SCENES:
        paths.extend(scene_figures(name, directory, resolution=resolution, dpi=dpi).values())
    return paths


# --- simulations (contactsym.numerics) ------------------------------------------------


def fast_trajectories_plot(data: dict, ax=None) -> list:
    """Draw :func:`contactsym.numerics.fast_trajectories_data`; returns the matplotlib artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import numpy as np
    >>> data = {"labels": ("u", "v"), "trajectories": [np.array([[0, 1], [0, 1]])], "impact": [False],
    ...         "field": None, "equilibria": [(1.0, 1.0)], "title": "demo"}
    >>> fig, ax = plt.subplots()
    >>> len(fast_trajectories_plot(data, ax))
    2
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    artists = []
    if data.get("field") is not None:
        X, Y, U, V = data["field"]
        norm = np.hypot(U, V)
        norm[norm == 0] = 1
        artists.append(ax.quiver(X, Y, U / norm, V / norm, norm, cmap="Greys", alpha=0.6, angles="xy"))
    for trajectory, impact in zip(data["trajectories"], data["impact"]):
        (line,) = ax.plot(trajectory[0], trajectory[1], lw=1.2, ls="--" if impact else "-")
        artists.append(line)
    if data["equilibria"]:
        xs, ys = zip(*data["equilibria"])
        (points,) = ax.plot(xs, ys, "ko", ms=6, label="equilibria")
        artists.append(points)
    ax.set_xlabel(data["labels"][0])
    ax.set_ylabel(data["labels"][1])
    ax.set_title(data.get("title", ""))
    return artists


def reactions_plot(run, ax=None, *, names=None) -> list:
    """Plot the reactions of a simulation against its time; returns the lines.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import contactsym as cs
    >>> from contactsym.numerics import simulate_fast
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}
    >>> run = simulate_fast(cs.scene("painleve-klein-rod"), values, (0, 10))
    >>> fig, ax = plt.subplots()
    >>> [line.get_label() for line in reactions_plot(run, ax)]
    ['u']
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    chosen = names or run.reaction_names
    lines = []
    for name in chosen:
        (line,) = ax.plot(run.t, run[name], label=name)
        lines.append(line)
    ax.set_xlabel("tau (stretched time)" if run.time == "tau" else "t")
    ax.set_ylabel("normal reaction")
    ax.legend()
    return lines


def cycle_plot(cycle, ax=None) -> list:
    """The reactions over one period of a fast cycle, with their means; returns the artists.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import numpy as np
    >>> from contactsym.numerics import Cycle
    >>> c = Cycle(True, 1.0, 2*np.pi, np.linspace(0, 1, 4, endpoint=False), np.zeros((2, 4)),
    ...           np.array([[1.0, 2.0, 1.0, 0.0]]), np.array([1.0]), ("Q", "V"), ("u",), True, "")
    >>> fig, ax = plt.subplots()
    >>> len(cycle_plot(c, ax))
    2
    >>> plt.close(fig)
    """
    ax = _axes(ax)
    artists = []
    for row, name in enumerate(cycle.reaction_names):
        (line,) = ax.plot(cycle.tau, cycle.reactions[row], label=f"{name}(tau)")
        mean = ax.axhline(cycle.mean_reactions[row], color=line.get_color(), ls=":", label=f"mean {name}")
        artists += [line, mean]
    ax.set_xlabel("tau over one period")
    ax.set_ylabel("normal reaction")
    ax.legend()
    return artists
