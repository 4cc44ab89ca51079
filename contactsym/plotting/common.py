"""What every figure shares: the return type of the ``*_plot`` functions, the hatches, small helpers.

Every ``*_plot(data, ax=None, ...)`` of contactsym returns a :class:`ContactPlot`: the
figure, the Axes, the artists it added and the Axes' legend. It behaves like the list of
artists that the ``*_plot`` functions returned before (it iterates, indexes and has a
length), so ``(line,) = reactions_plot(run, ax)`` and ``artists[0]`` keep working.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import sympy as sp

from ..arguments import checked
from ..errors import SceneError
from ..validate import shorten

__all__ = ["ContactPlot", "STABLE_HATCH", "UNSTABLE_HATCH", "axes_or_current"]

#: The hatch of "stable for every law" regions (single lines), as in Fig. 1.
#:
#: >>> from contactsym.plotting import STABLE_HATCH
#: >>> STABLE_HATCH
#: '///'
STABLE_HATCH = "///"
#: The hatch of "unstable for every law" regions (crossed lines), as in Fig. 1.
#:
#: >>> from contactsym.plotting import UNSTABLE_HATCH
#: >>> UNSTABLE_HATCH
#: 'xxx'
UNSTABLE_HATCH = "xxx"

#: Titles of the rod's three cases of §3 by the name of their count region.
CASE_TITLES = {
    "unique stable": "unique stable root",
    "two or none": "fold: two roots or none",
    "one or three": "cusp: one root or three",
}


@checked
@dataclass(frozen=True, eq=False)
class ContactPlot(Sequence):
    """What a ``*_plot`` function drew: the figure, the Axes, the artists and the legend.

    A sequence of its artists (in the order they were added, the legend last when the
    function added one), so code written for the list of artists keeps working.

    Attributes
    ----------
    artists : tuple of Artist
        Everything the function added to the Axes.
    axes : matplotlib Axes
    figure : matplotlib Figure (or SubFigure)
        The figure of ``axes``.
    legend : matplotlib Legend or None
        The Axes' legend after drawing, if it has one.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> drawn = ContactPlot.of(ax, ax.plot([0, 1], [0, 1], label="a line"))
    >>> len(drawn), drawn.figure is fig, drawn.legend is None
    (1, True, True)
    >>> (line,) = drawn
    >>> line is drawn[0] is drawn.artists[0]
    True
    >>> plt.close(fig)
    """

    artists: tuple
    axes: Any
    figure: Any
    legend: Any = None

    @classmethod
    def of(cls, ax, artists) -> ContactPlot:
        """The plot of ``artists`` drawn on ``ax``, with its figure and current legend."""
        return cls(tuple(artists), ax, ax.figure, ax.get_legend())

    def __getitem__(self, index):
        return self.artists[index]

    def __len__(self) -> int:
        return len(self.artists)

    def __repr__(self) -> str:
        kinds = ", ".join(type(a).__name__ for a in self.artists[:4]) + (", ..." if len(self) > 4 else "")
        return f"<ContactPlot: {len(self)} artists ({kinds}) on {type(self.axes).__name__}>"


@checked(ax="Axes | None")
def axes_or_current(ax):
    """``ax``, or the current pyplot Axes when none is given: the ``ax=`` of every ``*_plot``.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> axes_or_current(ax) is ax
    True
    >>> plt.close(fig)
    """
    if ax is None:
        import matplotlib.pyplot as plt  # pyplot only when the caller gives no Axes

        ax = plt.gca()
    return ax


def _scene(scene):
    """The Scene a ``*_data`` function draws; a name is refused, since figures follow the object, not its name.

    Examples
    --------
    >>> _scene("brake")
    Traceback (most recent call last):
    ...
    contactsym.errors.SceneError: give the Scene object, e.g. contactsym.scene('brake'), not its name 'brake'.
    """
    if isinstance(scene, str):
        name = shorten(scene)
        raise SceneError(f"give the Scene object, e.g. contactsym.scene({name}), not its name {name}.")
    if not callable(getattr(scene, "fast_subsystem", None)):
        raise SceneError(f"give a Scene object, e.g. contactsym.scene('brake'), not {type(scene).__name__}.")
    return scene


def _name(symbol) -> str:
    return symbol if isinstance(symbol, str) else str(symbol)


def _float(value) -> float:
    return float(sp.N(value)) if isinstance(value, sp.Basic) else float(value)


def _degrees(angle) -> str:
    value = math.degrees(_float(angle))
    return f"{value:.0f}" if abs(value - round(value)) < 1e-9 else f"{value:.1f}"
