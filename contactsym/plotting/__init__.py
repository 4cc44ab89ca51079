"""Figures drawn from the derived regions, never by hand.

Every figure is a pair: a ``*_data`` function (pure computation: grids, masks, roots,
closed-form regions) that takes the Scene it draws, and a ``*_plot(data, ax=None)`` that
draws the data on a given matplotlib Axes and returns a :class:`ContactPlot` (the figure,
the Axes, the artists it added and the legend; it iterates like the list of artists).
Regions are hatched (single hatching: stable for every contact law; double hatching:
unstable for every law; none: the stability depends on the law), as in the paper's Fig. 1.

- :mod:`~contactsym.plotting.regionplot`: :func:`region_data`, :func:`region_plot` for any
  :class:`~contactsym.stages.regions.Region` in a plane of two of its symbols;
- :mod:`~contactsym.plotting.guides`: :func:`fig1_data`, :func:`fig1_plot`, Fig. 1a/1b;
- :mod:`~contactsym.plotting.rod`: :func:`rod_f_data`, :func:`rod_f_plot`, f(u) of the rod
  in the three cases of §3;
- :mod:`~contactsym.plotting.brake`: :func:`brake_map_data`, :func:`brake_map_plot`, the
  brake's (alpha, mu) map; :func:`brake_hopf_data`, :func:`brake_hopf_plot`, its Hopf line;
- :mod:`~contactsym.plotting.portrait`: :func:`phase_portrait_data`,
  :func:`phase_portrait_plot`, the fast subsystem (2.1);
- :mod:`~contactsym.plotting.simulation`: :func:`fast_trajectories_plot`,
  :func:`reactions_plot`, :func:`cycle_plot`, results of :mod:`contactsym.numerics`;
- :mod:`~contactsym.plotting.figures`: :func:`scene_figures` ``(scene, directory)`` writes
  one scene's figures (chosen and captioned by ``figures`` in the scene's module) and
  returns ``{caption: path}``; :func:`paper_figures` ``(directory)`` writes those of the
  paper's scenes (``fig1a_guides.png``, ``fig1b_guides.png``, ``rod_f_cases.png``,
  ``rod_phase_portrait.png``, ``brake_alpha_mu.png``, ``brake_hopf.png``,
  ``sliding_point_phase_portrait.png``).
"""

from .brake import BrakeHopfData, BrakeMapData, brake_hopf_data, brake_hopf_plot, brake_map_data, brake_map_plot
from .common import STABLE_HATCH, UNSTABLE_HATCH, ContactPlot, axes_or_current
from .figures import FIGURE_SCENES, paper_figures, save_figure, scene_figures
from .guides import Fig1Data, fig1_data, fig1_plot
from .portrait import PhasePortraitData, phase_portrait_caption, phase_portrait_data, phase_portrait_plot
from .regionplot import RegionData, boundary_contours, region_data, region_mask, region_plot, relational_fields
from .rod import ROD_CASES, RodFData, rod_f_data, rod_f_plot, rod_portrait_values
from .simulation import cycle_plot, fast_trajectories_plot, reactions_plot

__all__ = [
    "FIGURE_SCENES",
    "ROD_CASES",
    "STABLE_HATCH",
    "UNSTABLE_HATCH",
    "BrakeHopfData",
    "BrakeMapData",
    "ContactPlot",
    "Fig1Data",
    "PhasePortraitData",
    "RegionData",
    "RodFData",
    "axes_or_current",
    "boundary_contours",
    "brake_hopf_data",
    "brake_hopf_plot",
    "brake_map_data",
    "brake_map_plot",
    "cycle_plot",
    "fast_trajectories_plot",
    "fig1_data",
    "fig1_plot",
    "paper_figures",
    "phase_portrait_caption",
    "phase_portrait_data",
    "phase_portrait_plot",
    "reactions_plot",
    "region_data",
    "region_mask",
    "region_plot",
    "relational_fields",
    "rod_f_data",
    "rod_f_plot",
    "rod_portrait_values",
    "save_figure",
    "scene_figures",
]
