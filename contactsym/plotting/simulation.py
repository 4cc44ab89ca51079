"""Results of :mod:`contactsym.numerics` drawn: simulated trajectories, reactions N_j(t), a fast cycle."""

from __future__ import annotations

import numpy as np

from ..arguments import checked, require
from .common import ContactPlot, axes_or_current

__all__ = ["cycle_plot", "fast_trajectories_plot", "reactions_plot"]


@checked(ax="Axes | None")
def fast_trajectories_plot(data: dict, ax=None) -> ContactPlot:
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
    keys = ("labels", "trajectories", "impact", "equilibria")
    require(all(k in data for k in keys), "fast_trajectories_plot", "data", data, "the dict of fast_trajectories_data")
    ax = axes_or_current(ax)
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
    return ContactPlot.of(ax, artists)


@checked(ax="Axes | None", names="Sequence[str] | None")
def reactions_plot(run, ax=None, *, names=None) -> ContactPlot:
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
    ax = axes_or_current(ax)
    require(all(hasattr(run, a) for a in ("t", "reaction_names")), "reactions_plot", "run", run, "a Simulation")
    chosen = names or run.reaction_names
    lines = []
    for name in chosen:
        (line,) = ax.plot(run.t, run[name], label=name)
        lines.append(line)
    ax.set_xlabel("tau (stretched time)" if run.time == "tau" else "t")
    ax.set_ylabel("normal reaction")
    ax.legend()
    return ContactPlot.of(ax, lines)


@checked(ax="Axes | None")
def cycle_plot(cycle, ax=None) -> ContactPlot:
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
    ax = axes_or_current(ax)
    artists = []
    needed = ("reaction_names", "tau", "reactions", "mean_reactions")
    require(all(hasattr(cycle, a) for a in needed), "cycle_plot", "cycle", cycle, "a Cycle of fast_cycle")
    for row, name in enumerate(cycle.reaction_names):
        (line,) = ax.plot(cycle.tau, cycle.reactions[row], label=f"{name}(tau)")
        mean = ax.axhline(cycle.mean_reactions[row], color=line.get_color(), ls=":", label=f"mean {name}")
        artists += [line, mean]
    ax.set_xlabel("tau over one period")
    ax.set_ylabel("normal reaction")
    ax.legend()
    return ContactPlot.of(ax, artists)
