"""§3 of the paper, derived: f(u) (3.6) of the Painlevé–Klein rod in its three cases.

:func:`rod_f_data` samples f(u) for the loads of one case of :data:`ROD_CASES`, finds its
roots piece by piece and names the count region (3.8), (3.9) that holds;
:func:`rod_f_plot` draws the curves with the roots marked.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..arguments import between, checked, require
from ..counts.regions import corner_cases
from ..printing.latex_output import tex
from .common import CASE_TITLES, ContactPlot, _float, _scene, axes_or_current

__all__ = ["ROD_CASES", "RodFData", "rod_f_data", "rod_f_plot", "rod_portrait_values"]

#: Parameter choices for the three cases of §3, in the paper's symbols (phi in radians).
#:
#: >>> from contactsym.plotting import ROD_CASES
#: >>> sorted(ROD_CASES)
#: ['cusp', 'fold', 'unique']
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


def _corner_case_at(scene, numeric: dict):
    """The scene's count case (:func:`contactsym.counts.regions.corner_cases`) whose corner ordering holds at ``numeric``."""
    for candidate in corner_cases(scene):
        ordering = candidate.ordering
        if bool(ordering.subs({s: numeric[str(s)] for s in ordering.free_symbols})):
            return candidate
    raise ValueError(f"no corner ordering of '{scene.name}' holds at {numeric}.")


@checked
def rod_portrait_values(case: str) -> dict:
    """Numbers for the rod's phase portrait in one of :data:`ROD_CASES`, at its first load X^*.

    Examples
    --------
    >>> rod_portrait_values("fold")["X^*"]
    -4.0
    """
    require(case in ROD_CASES, "rod_portrait_values", "case", case, f"one of {', '.join(ROD_CASES)}")
    return {**{k: v for k, v in ROD_CASES[case].items() if k != "loads"}, "X^*": ROD_CASES[case]["loads"][0]}


@checked(nan=True)
@dataclass(frozen=True)
class RodFData:
    """f(u) of the Painlevé–Klein rod for one parameter choice and several loads X*.

    Examples
    --------
    Each curve carries its equilibria (u*, slope); f vanishes there:

    >>> import contactsym as cs
    >>> data = rod_f_data(cs.scene("painleve-klein-rod"), "cusp", points=50)
    >>> isinstance(data, RodFData), data.u.shape, data.corners
    (True, (50,), (-2.0, 2.0))
    >>> all(abs(np.interp(u, data.u, f)) < 1e-9 for _, f, roots in data.curves for u, _ in roots)
    True
    """

    case: str
    values: dict
    count: str
    condition: sp.Basic
    ordering: sp.Basic
    corners: tuple
    corner_labels: tuple
    u: np.ndarray
    curves: list  # (X*, f(u) array, [(u*, slope), ...])


@checked(case="str", values="Mapping | None", points=between(2, 100_000))
def rod_f_data(scene, case="cusp", *, values=None, points=400) -> RodFData:
    """f(u) (3.6) of the rod with the classification of its count region.

    Parameters
    ----------
    scene : Scene
        The rod (``contactsym.scene("painleve-klein-rod")``), or a scene with its symbols.
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
    >>> import contactsym as cs
    >>> data = rod_f_data(cs.scene("painleve-klein-rod"), "cusp", points=50)
    >>> data.count, str(data.condition), str(data.ordering)
    ('one or three', '(mu_+ > 2) & (Abs(mu_-) < 2)', 'Y^*_1 + Y^*_2 > 0')
    >>> [len(roots) for _, _, roots in data.curves]
    [3, 1]
    """
    scene = _scene(scene)
    require(values is not None or case in ROD_CASES, "rod_f_data", "case", case, f"one of {', '.join(ROD_CASES)}")
    require(values is None or "loads" in values, "rod_f_data", "values", values, "values with 'loads' (values of X^*)")
    values = dict(values or ROD_CASES[case])
    loads = values.pop("loads")
    numeric = {k: _float(v) for k, v in values.items()}
    fast = scene.fast_subsystem()
    (u,) = fast.u
    f = scene.present(fast.f[0])
    symbols = sorted(f.free_symbols - {u}, key=str)
    function = sp.lambdify([u, *symbols], f, "numpy")
    counts = scene.equilibrium_counts()
    (count,) = [n for n, r in counts.items() if bool(r.evaluate(**{s: numeric[s] for s in r.symbol_names}))]
    chosen = _corner_case_at(scene, numeric)
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


@checked(ax="Axes | None", legend="bool")
def rod_f_plot(data: RodFData, ax=None, *, legend=True) -> ContactPlot:
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
    ContactPlot

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> import contactsym as cs
    >>> artists = rod_f_plot(rod_f_data(cs.scene("painleve-klein-rod"), "fold", points=20), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$u = R$', '$f(u)$')
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
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
    ax.set_title(f"{CASE_TITLES.get(data.count, data.count)}\n${condition}$, ${ordering}$", fontsize=10)
    if legend:
        artists.append(ax.legend(fontsize=8, loc="best"))
    return ContactPlot.of(ax, artists)
