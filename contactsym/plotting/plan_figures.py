"""Figures for any scene from its figure plan: region maps over two parameters, the phase portrait.

A scene file's ``[figures]`` table gives the plan (:class:`contactsym.mechanism.files.reader.FigurePlan`):
the two parameters of the plane, their ranges and numbers for the other symbols. The
figures are decided by the Scene object and its plan, never by the scene's name. The reader
checks the plan against the scene's declarations; whether its values are complete depends on
the derived regions, so a figure that lacks values is skipped with a note that names them all
(:func:`missing_values`).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp

from ..errors import ContactsymError
from ..printing.latex_output import tex
from . import (
    STABLE_HATCH,
    UNSTABLE_HATCH,
    ContactPlot,
    axes_or_current,
    boundary_contours,
    phase_portrait_data,
    phase_portrait_plot,
    region_data,
    region_plot,
    relational_fields,
    save_figure,
)

__all__ = ["RegionMapData", "missing_values", "plan_figures", "region_map_data", "region_map_plot"]

_HATCHES = {"stable for every law": (STABLE_HATCH, "tab:blue"), "unstable for every law": (UNSTABLE_HATCH, "tab:red")}
_OTHER_HATCHES = [("\\\\\\", "tab:green"), ("...", "tab:purple"), ("++", "tab:orange"), ("--", "tab:brown")]


@dataclass(frozen=True)
class RegionMapData:
    """The scene's closed-form regions on a grid of the plan's (x, y) plane."""

    title: str
    x: str
    y: str
    grids: dict  # region name -> plotting.RegionData
    curves: dict  # name of a region that is a curve (the Hopf line) -> (X, Y, [fields whose zero sets draw it])
    skipped: dict  # region name -> why it is not drawn


def _named(expr) -> sp.Expr:
    """A load such as Y(x, xdot) takes one number by its function's name, arguments and all."""
    return expr.xreplace({a: sp.Symbol(a.func.__name__) for a in expr.atoms(sp.core.function.AppliedUndef)})


def missing_values(expr, plan) -> list[str]:
    """The names of ``expr``'s symbols that the plan neither puts on an axis nor gives a value for.

    Examples
    --------
    >>> from contactsym.mechanism.files.spec import FigurePlan
    >>> a, mu, m = sp.symbols("alpha mu m", positive=True)
    >>> missing_values(sp.Lt(mu * m, sp.cot(a) + sp.Symbol("Phi_1")), FigurePlan("alpha", "mu", (0, 1), (0, 1), {"m": 1}))
    ['Phi_1']
    """
    given = {plan.x, plan.y, *plan.values}
    return sorted({str(s) for s in _named(expr).free_symbols} - given)


def region_map_data(scene, plan, *, resolution: int = 200) -> RegionMapData:
    """Evaluate each region of ``scene.regions()`` on the plan's grid.

    A region that needs a value the plan does not give is skipped, with the reason.

    Examples
    --------
    >>> from pathlib import Path
    >>> from contactsym.mechanism.files.reader import load_scene
    >>> brake = load_scene(Path(__file__).parents[2] / "examples" / "brake.toml")
    >>> data = region_map_data(brake, brake.figure_plan, resolution=20)
    >>> sorted(data.grids), sorted(data.curves), data.x, data.y
    (['law-dependent', 'stable for every law'], ['Hopf line'], 'alpha', 'mu')
    """
    grids, curves, skipped = {}, {}, {}
    X, Y = np.meshgrid(np.linspace(*plan.x_range, resolution), np.linspace(*plan.y_range, resolution))
    for name, region in scene.regions().items():
        if region.condition in (sp.true, sp.false):
            skipped[name] = "it is empty" if region.condition == sp.false else "it is the whole parameter space"
            continue
        missing = missing_values(region.condition, plan)
        if missing:  # every missing name at once, in the names the plan uses
            skipped[name] = f"give [figures] values for {', '.join(missing)}"
            continue
        if isinstance(region.condition, sp.Equality):  # a curve: drawn as the zero set of lhs - rhs
            try:
                fields = relational_fields(region.condition, {**plan.values, plan.x: X, plan.y: Y}, X.shape)
            except KeyError as missing:
                skipped[name] = f"give [figures] values for {missing}"
                continue
            curves[name] = (X, Y, fields)
            continue
        try:
            grid = region_data(
                region,
                x=plan.x,
                y=plan.y,
                fixed=plan.values,
                xlim=plan.x_range,
                ylim=plan.y_range,
                resolution=resolution,
            )
        except (ValueError, TypeError, ContactsymError) as error:  # a missing value, or a non-numeric one
            skipped[name] = str(error)
            continue
        if grid.mask.any():
            grids[name] = grid
        else:  # a legend entry for nothing drawn would read as a region too thin to see
            skipped[name] = "no grid point of this plane is in it at the [figures] values"
    title = f"{scene.name}: regions in the (${tex(sp.Symbol(plan.x))}$, ${tex(sp.Symbol(plan.y))}$) plane"
    return RegionMapData(title, plan.x, plan.y, grids, curves, skipped)


def region_map_plot(data: RegionMapData, ax=None, *, legend: bool = True) -> ContactPlot:
    """Hatch each region: single for stable for every law, double for unstable, others in turn.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from pathlib import Path
    >>> from contactsym.mechanism.files.reader import load_scene
    >>> brake = load_scene(Path(__file__).parents[2] / "examples" / "brake.toml")
    >>> fig, ax = plt.subplots()
    >>> artists = region_map_plot(region_map_data(brake, brake.figure_plan, resolution=20), ax=ax)
    >>> ax.get_xlabel(), len(ax.get_legend_handles_labels()[1])
    ('$\\\\alpha$', 3)
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    artists, others = [], iter(_OTHER_HATCHES * 4)
    for name, grid in data.grids.items():
        hatch, color = _HATCHES.get(name) or next(others)
        label = name if len(tex(grid.region.condition)) > 80 else f"{name}: ${tex(grid.region.condition)}$"
        artists += region_plot(grid.region, ax, x=grid.x, y=grid.y, data=grid, hatch=hatch, color=color, label=label)
    for name, (X, Y, fields) in data.curves.items():
        drawn = boundary_contours(ax, X, Y, fields, colors="black", linewidths=1.5)
        if drawn:
            artists += [*drawn, *ax.plot([], [], "k-", lw=1.5, label=name)]
    ax.set_xlabel(f"${tex(sp.Symbol(data.x))}$")
    ax.set_ylabel(f"${tex(sp.Symbol(data.y))}$")
    ax.set_title(data.title, fontsize=10)
    if legend and artists:
        artists.append(ax.legend(loc="best", fontsize=8, framealpha=0.95))
    return ContactPlot.of(ax, artists)


def _portrait_needs(scene) -> set[str]:
    """Names the phase portrait needs numbers for: the presented (2.1) without u, v and the law's constants."""
    fast = scene.fast_subsystem()
    rhs = sp.Matrix(scene.present(fast.rhs))
    laws = {s for s in (fast.Phi[0], fast.Psi[0]) if isinstance(s, sp.Symbol)}
    symbols = _named(rhs).free_symbols - set(fast.u) - set(fast.v) - laws
    return {str(s) for s in symbols}


def plan_figures(scene, directory, *, resolution: int = 200, dpi: int = 150) -> tuple[list, list]:
    """Draw a scene's planned figures into ``directory``: ([(path, LaTeX caption)], [notes]).

    The region map needs ``scene.figure_plan`` (a scene file's ``[figures]``); the phase
    portrait of the fast subsystem (2.1) is drawn for one contact, at the plan's values.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    plan = getattr(scene, "figure_plan", None)
    if plan is None:
        return [], [
            "No figures: give the scene a [figures] table (x, y, x_range, y_range, values) to draw them; a plane "
            "whose axis is fixed by --set (or with_values) is not drawn."
        ]
    drawn, notes = [], []
    data = region_map_data(scene, plan, resolution=resolution)
    notes += [f"Region '{name}' is not drawn: {why}" for name, why in data.skipped.items()]
    if data.grids or data.curves:
        path = save_figure(directory / "regions.png", lambda f: region_map_plot(data, f.add_subplot()), dpi=dpi)
        caption = f"The closed-form regions of this scene in the $({tex(sp.Symbol(plan.x))}, {tex(sp.Symbol(plan.y))})$ plane."
        drawn.append((path, caption))
    if scene.k == 1:
        try:
            values = {k: v for k, v in plan.values.items() if k not in ("Phi", "Psi")}
            laws = {k: plan.values[k] for k in ("Phi", "Psi") if k in plan.values}
            missing = _portrait_needs(scene) - set(values)
            if missing:
                raise ValueError(f"give [figures] values for {', '.join(sorted(missing))}")
            portrait = phase_portrait_data(scene, values, **laws)
            path = save_figure(
                directory / "phase_portrait.png", lambda f: phase_portrait_plot(portrait, f.add_subplot()), dpi=dpi
            )
            drawn.append(
                (path, "Phase portrait of the fast subsystem (2.1) of this scene, at the values of [figures].")
            )
        except (ValueError, TypeError, ZeroDivisionError, ContactsymError) as error:
            notes.append(f"No phase portrait: {error}")
    return drawn, notes
