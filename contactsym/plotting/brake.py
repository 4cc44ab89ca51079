"""§6 of the paper, derived: the brake's (alpha, mu) map (6.3) and its Hopf line (6.4).

:func:`brake_map_data` evaluates the scene's regions in the (alpha, mu) plane;
:func:`brake_hopf_data` draws the paper's special case (6.4), alpha = 90 deg with equal
contact laws, which the scene's module derives once (``special_cases`` in
:mod:`contactsym.scenes.brake`, asked for through :func:`contactsym.scenes.paper_knowledge`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from ..arguments import between, checked
from ..printing.latex_output import tex
from ..scenes import paper_knowledge
from ..stages.regions import Region
from .common import STABLE_HATCH, UNSTABLE_HATCH, ContactPlot, _scene, axes_or_current
from .regionplot import RegionData, boundary_contours, region_mask, region_plot, relational_fields

__all__ = ["BrakeHopfData", "BrakeMapData", "brake_hopf_data", "brake_hopf_plot", "brake_map_data", "brake_map_plot"]


@checked(nan=True)
@dataclass(frozen=True)
class BrakeMapData:
    """The brake's (alpha, mu) plane: stable for every law, law-dependent, mu = |cot alpha|.

    Examples
    --------
    The mask of the region stable for every law is the closed form mu <= |cot alpha| on the grid:

    >>> import contactsym as cs
    >>> data = brake_map_data(cs.scene("brake"), resolution=30)
    >>> isinstance(data, BrakeMapData), data.alpha.shape
    (True, (30, 30))
    >>> bool(np.array_equal(data.masks["stable for every law"], data.mu <= np.abs(1 / np.tan(data.alpha))))
    True
    """

    alpha: np.ndarray  # radians
    mu: np.ndarray
    masks: dict
    boundary: list
    regions: dict = field(repr=False)


@checked(mu_max="float", resolution=between(2, 4096))
def brake_map_data(scene, *, mu_max=2.0, resolution=300) -> BrakeMapData:
    """Regions of the brake in the (alpha, mu) plane (6.3), from ``scene.regions()``.

    Examples
    --------
    >>> import contactsym as cs
    >>> data = brake_map_data(cs.scene("brake"), resolution=30)
    >>> sorted(data.masks), str(data.regions["stable for every law"].condition)
    (['law-dependent', 'stable for every law'], 'mu <= Abs(cot(alpha))')
    """
    scene = _scene(scene)
    regions = scene.regions()
    alphas = np.linspace(0.02, math.pi - 0.02, resolution)
    mus = np.linspace(0.0, mu_max, resolution)
    A, M = np.meshgrid(alphas, mus)
    values = {"alpha": A, "mu": M}
    names = ("stable for every law", "law-dependent")
    masks = {name: region_mask(regions[name], values, A.shape).copy() for name in names}
    boundary = relational_fields(regions["stable for every law"].condition, values, A.shape)
    return BrakeMapData(A, M, masks, boundary, {name: regions[name] for name in names})


@checked(ax="Axes | None", legend="bool")
def brake_map_plot(data: BrakeMapData, ax=None, *, legend=True) -> ContactPlot:
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
    ContactPlot

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> import contactsym as cs
    >>> artists = brake_map_plot(brake_map_data(cs.scene("brake"), resolution=20), ax=ax)
    >>> print(ax.get_ylabel())
    $\\mu$
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    X = np.degrees(data.alpha)
    region = data.regions["stable for every law"]
    grid = RegionData("alpha", "mu", X, data.mu, data.masks["stable for every law"], region)
    label = f"stable for every law (6.3): ${tex(region.condition)}$"
    artists = list(
        region_plot(region, ax, x="alpha", y="mu", data=grid, hatch=STABLE_HATCH, color="tab:blue", label=label)
    )
    (proxy,) = ax.fill([], [], facecolor="white", edgecolor="0.5", label="depends on the law (Hopf possible)")
    artists.append(proxy)
    artists += boundary_contours(ax, X, data.mu, data.boundary, colors="black", linewidths=1.5)
    (line,) = ax.plot([], [], "k-", lw=1.5, label=r"$\mu = |\cot\alpha|$")
    artists.append(line)
    ax.set_xlabel(r"$\alpha$ (degrees)")
    ax.set_ylabel(r"$\mu$")
    ax.set_xticks([0, 45, 90, 135, 180])
    ax.set_title("brake (§6): robustness with respect to the contact law", fontsize=10)
    if legend:
        artists.append(ax.legend(loc="upper center", fontsize=8, framealpha=0.95))
    return ContactPlot.of(ax, artists)


@checked(nan=True)
@dataclass(frozen=True)
class BrakeHopfData:
    """The brake at alpha = 90 deg, Phi_j = Phi, Psi_j = Psi: (mu, Phi) plane at fixed Psi, m.

    Examples
    --------
    At Psi = -1, m = 1 the stable mask is -Phi mu^2 < mu^2 + 1 (6.4) on the grid:

    >>> import contactsym as cs
    >>> data = brake_hopf_data(cs.scene("brake"), Psi=-1.0, m=1.0, resolution=30)
    >>> isinstance(data, BrakeHopfData), data.fixed, sorted(data.masks)
    (True, {'Psi': -1.0, 'm': 1.0}, ['stable', 'unstable'])
    >>> bool(np.array_equal(data.masks["stable"], -data.Phi * data.mu**2 < data.mu**2 + 1))
    True
    """

    mu: np.ndarray
    Phi: np.ndarray
    fixed: dict
    stable: Region
    hopf: Region
    frequency: sp.Expr  # omega on the Hopf line, in the stretched time
    masks: dict
    hopf_field: list


@checked(Psi="float", m="float", mu_max="float", Phi_min="float", resolution=between(2, 4096))
def brake_hopf_data(scene, *, Psi=-1.0, m=1.0, mu_max=3.0, Phi_min=-10.0, resolution=300) -> BrakeHopfData:
    """Hurwitz stability (6.4) and the Hopf line of the brake at alpha = 90 deg, equal laws.

    The closed forms are the scene's special cases (``paper_knowledge(scene, "special_cases")``):
    (6.4) derived from ``scene.stability()`` with alpha = pi/2, Phi_1 = Phi_2 = Phi,
    Psi_1 = Psi_2 = Psi substituted, and the frequency on its boundary, the Hopf line.

    Examples
    --------
    >>> import contactsym as cs
    >>> data = brake_hopf_data(cs.scene("brake"), resolution=30)
    >>> data.stable.condition
    -Phi*m*mu**2 < Psi**2*(mu**2 + 1)
    >>> data.hopf.condition
    Eq(Phi*m*mu**2 + Psi**2*mu**2 + Psi**2, 0)
    >>> data.frequency
    -Psi*(mu**2 + 1)/(m*mu)
    """
    scene = _scene(scene)
    cases = {case.key: case for case in paper_knowledge(scene, "special_cases", lambda scene: [])(scene)}
    if "special" not in cases or "hopf frequency" not in cases:
        raise ValueError(f"scene '{scene.name}' has no special case (6.4) with a Hopf frequency; only the brake has.")
    stable = cases["special"].rhs
    if not isinstance(stable, (sp.StrictLessThan, sp.StrictGreaterThan)):
        raise ValueError(f"(6.4) of '{scene.name}' is not one strict inequality: {stable}")
    # (6.4) is one inequality; its boundary, where the last Hurwitz determinant vanishes, is the Hopf line
    hopf = sp.Eq(sp.expand(stable.gts - stable.lts), 0)
    mus = np.linspace(0.02, mu_max, resolution)
    Phis = np.linspace(Phi_min, -1e-3, resolution)
    MU, PHI = np.meshgrid(mus, Phis)
    values = {"mu": MU, "Phi": PHI, "Psi": Psi, "m": m}
    stable_region = Region(stable, name="asymptotically stable (6.4)")
    hopf_region = Region(hopf, name="Hopf line")
    mask = region_mask(stable_region, values, MU.shape).copy()
    masks = {"stable": mask, "unstable": ~mask}
    field_ = relational_fields(hopf, values, MU.shape)
    frequency = cases["hopf frequency"].rhs
    return BrakeHopfData(MU, PHI, {"Psi": Psi, "m": m}, stable_region, hopf_region, frequency, masks, field_)


@checked(ax="Axes | None", legend="bool")
def brake_hopf_plot(data: BrakeHopfData, ax=None, *, legend=True) -> ContactPlot:
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
    ContactPlot

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> import contactsym as cs
    >>> artists = brake_hopf_plot(brake_hopf_data(cs.scene("brake"), resolution=20), ax=ax)
    >>> print(ax.get_xlabel(), ax.get_ylabel())
    $\\mu$ $\\Phi$
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    grid = RegionData("mu", "Phi", data.mu, data.Phi, data.masks["stable"], data.stable)
    stable_label = f"stable: ${tex(data.stable.condition)}$"
    artists = list(
        region_plot(
            data.stable, ax, x="mu", y="Phi", data=grid, hatch=STABLE_HATCH, color="tab:blue", label=stable_label
        )
    )
    unstable = RegionData("mu", "Phi", data.mu, data.Phi, data.masks["unstable"], ~data.stable)
    artists += region_plot(
        ~data.stable, ax, x="mu", y="Phi", data=unstable, hatch=UNSTABLE_HATCH, color="tab:red", label="unstable"
    )
    artists += boundary_contours(ax, data.mu, data.Phi, data.hopf_field, colors="black", linewidths=2)
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
    return ContactPlot.of(ax, artists)
