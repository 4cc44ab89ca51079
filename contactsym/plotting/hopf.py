"""Plots of the Hopf bifurcation of the fast subsystem: cycle amplitude against the distance to the line."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from . import ContactPlot, axes_or_current

__all__ = ["hopf_amplitude_data", "hopf_amplitude_plot"]


def hopf_amplitude_data(hopf, distances: Sequence[float], simulated: Sequence[float] | None = None, *, contact=0):
    """Predicted (and simulated) amplitude of reaction ``contact`` at relative distances past the line.

    ``distances`` are relative: ``parameter = value* (1 + d)`` on the side where the small
    cycle lives (past the line for l1 < 0, before it for l1 > 0).

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym import numerics
    >>> from contactsym.laws.library import Hertz
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 0, "F_y": -4}
    >>> h = numerics.hopf_point(cs.scene("brake"), values, "mu", laws={0: Hertz(), 1: Hertz()})
    >>> data = hopf_amplitude_data(h, [0.01, 0.04])
    >>> round(float(data["predicted"][1] / data["predicted"][0]), 6)
    2.0
    """
    side = np.sign(hopf.dalpha) * (-1 if hopf.l1 > 0 else 1)
    distances = np.asarray(distances, dtype=float)
    predicted = np.array([hopf.amplitude(hopf.value * (1 + side * d))[contact] for d in distances])
    return {
        "distance": distances,
        "predicted": predicted,
        "simulated": None if simulated is None else np.asarray(simulated, dtype=float),
        "direction": hopf.direction,
        "parameter": str(hopf.parameter),
    }


def hopf_amplitude_plot(data: dict, ax=None, *, label: str = "") -> ContactPlot:
    """Amplitude against distance on log-log axes: the prediction as a line, simulations as dots.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> data = {"distance": np.array([0.01, 0.04]), "predicted": np.array([0.1, 0.2]), "simulated": None,
    ...         "direction": "supercritical", "parameter": "mu"}
    >>> fig, ax = plt.subplots()
    >>> drawn = hopf_amplitude_plot(data, ax=ax, label="Hertz")
    >>> len(drawn), drawn.axes is ax, drawn.legend is not None
    (1, True, True)
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
    fine = np.geomspace(data["distance"].min(), data["distance"].max(), 50) if len(data["distance"]) > 1 else None
    artists = []
    if fine is not None:
        scale = data["predicted"][0] / np.sqrt(data["distance"][0])
        artists += ax.plot(fine, scale * np.sqrt(fine), "-", label=f"{label} predicted ({data['direction']})")
    else:
        artists += ax.plot(data["distance"], data["predicted"], "x", label=f"{label} predicted ({data['direction']})")
    if data["simulated"] is not None:
        color = artists[0].get_color()
        artists += ax.plot(data["distance"], data["simulated"], "o", color=color, label=f"{label} simulated")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(f"relative distance to the Hopf line in {data['parameter']}")
    ax.set_ylabel("reaction amplitude")
    ax.legend(fontsize="small")
    return ContactPlot.of(ax, artists)
