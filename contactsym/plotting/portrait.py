"""The phase portrait of the fast subsystem (2.1) of a scene with one contact.

:func:`phase_portrait_data` samples u' = Phi v + Psi f(u), v' = f(u) (3.1) on a grid and
finds the equilibria from the scene's equilibrium branches; :func:`phase_portrait_plot`
draws the stream lines with the equilibria marked (Proposition 3: stable where f' > 0).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..arguments import between, checked
from ..errors import ArgumentError
from ..printing.latex_output import tex
from ..scenes import paper_knowledge
from .common import CASE_TITLES, ContactPlot, _float, _scene, axes_or_current

__all__ = ["PhasePortraitData", "phase_portrait_caption", "phase_portrait_data", "phase_portrait_plot"]


@checked(nan=True)
@dataclass(frozen=True)
class PhasePortraitData:
    """The fast subsystem (2.1) of a k = 1 scene on a (u, v) grid, with its equilibria.

    Examples
    --------
    >>> import contactsym as cs
    >>> data = phase_portrait_data(cs.scene("sliding-point"), resolution=10)
    >>> isinstance(data, PhasePortraitData), data.u.shape, data.du.shape, data.count
    (True, (10, 10), (10, 10), 'unique stable')
    >>> data.equilibria  # (u*, stable)
    [(1.0, True)]
    """

    scene: str
    count: str
    title: str
    u: np.ndarray
    v: np.ndarray
    du: np.ndarray
    dv: np.ndarray
    equilibria: list  # (u*, stable)
    values: dict


def _by_name(expr, values: dict):
    """Substitute numbers by name for symbols and for applied functions such as Y(x, xdot)."""
    expr = sp.sympify(expr)
    mapping = {s: values[str(s)] for s in expr.free_symbols if str(s) in values}
    for applied in expr.atoms(sp.core.function.AppliedUndef):
        if applied.func.__name__ in values:
            mapping[applied] = values[applied.func.__name__]
    return expr.xreplace({k: sp.Float(_float(v)) for k, v in mapping.items()})


@checked(
    values="Mapping | None",
    Phi="float",
    Psi="float",
    extent="Sequence[float]",
    resolution=between(2, 4096),
)
def phase_portrait_data(
    scene, values=None, *, Phi=-1.0, Psi=-0.5, extent=(6.0, 6.0), resolution=60
) -> PhasePortraitData:
    """The fast subsystem u' = Phi v + Psi f(u), v' = f(u) (3.1) of a k = 1 scene on a grid.

    Parameters
    ----------
    scene : Scene
        A scene with one contact.
    values : dict, optional
        Numbers for its presentation symbols (by name; a load such as ``Y(x, xdot)`` by
        its function name). A built-in scene of the paper has default numbers
        (``PORTRAIT_VALUES`` of its module, see :func:`contactsym.scenes.paper_knowledge`);
        any other scene needs them.
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
    >>> import contactsym as cs
    >>> from contactsym.plotting import rod_portrait_values
    >>> rod = cs.scene("painleve-klein-rod")
    >>> data = phase_portrait_data(rod, resolution=10)
    >>> data.count, [stable for _, stable in data.equilibria]
    ('one or three', [True, False, True])
    >>> phase_portrait_data(cs.scene("sliding-point"), resolution=10).equilibria
    [(1.0, True)]
    >>> len(phase_portrait_data(rod, rod_portrait_values("fold"), resolution=10).equilibria)
    2
    """
    scene = _scene(scene)
    if values is None:
        values = paper_knowledge(scene, "PORTRAIT_VALUES")
        if values is None:
            raise ArgumentError(
                f"give values=... for the symbols of '{scene.name}'; only the paper's scenes have defaults."
            )
    values = dict(values)
    if scene.k != 1:
        raise ArgumentError(f"phase portraits are for one contact; '{scene.name}' has k = {scene.k}.")
    fast = scene.fast_subsystem()
    (u,), (v,) = fast.u, fast.v
    laws = {law: value for law, value in ((fast.Phi[0], Phi), (fast.Psi[0], Psi)) if isinstance(law, sp.Symbol)}
    rhs = _by_name(scene.present(fast.rhs.subs(laws)), values)
    function = sp.lambdify([u, v], list(rhs), "numpy")
    equilibria = _equilibria(scene, values)
    count = _count_at(scene, values)
    centre = float(np.mean([r for r, _ in equilibria])) if equilibria else 0.0
    us = np.linspace(centre - extent[0], centre + extent[0], resolution)
    vs = np.linspace(-extent[1], extent[1], resolution)
    U, V = np.meshgrid(us, vs)
    du, dv = (np.broadcast_to(np.asarray(c, float), U.shape) for c in function(U, V))
    shown = [f"${tex(law)} = {value:g}$" for law, value in laws.items()]
    shown += [f"${tex(sp.Symbol(k))} = {value:g}$" for k, value in values.items() if k in ("X^*", "b", "Y")]
    title = f"fast subsystem (2.1), {scene.name} ({CASE_TITLES.get(count, count)}): " + ", ".join(shown)
    return PhasePortraitData(scene.name, count, title, U, V, du, dv, equilibria, values)


def _equilibria(scene, values: dict) -> list[tuple[float, bool]]:
    """(u*, stable) of the equilibrium branches that exist at ``values``, stable when f'(u*) > 0."""
    equilibria = []
    for branch in scene.equilibria():
        if _by_name(scene.present(branch.condition), values) != sp.true:
            continue
        root = float(_by_name(scene.present(branch.u_star[0]), values))
        slope = float(_by_name(scene.present(scene.linearization(signs=branch.signs).A[0]), values))
        equilibria.append((root, slope > 0))
    return sorted(equilibria)


def _count_at(scene, values: dict) -> str:
    """The name of the scene's count region that holds at ``values``, or "undecided"."""
    try:
        counts = scene.equilibrium_counts()
    except (ValueError, NotImplementedError):  # a scene whose counts are not derived: the title says so
        counts = {}
    known = [(n, r) for n, r in counts.items() if set(r.symbol_names) <= set(values)]
    return next((n for n, r in known if bool(r.evaluate(**{k: values[k] for k in r.symbol_names}))), "undecided")


@checked(ax="Axes | None", legend="bool")
def phase_portrait_plot(data: PhasePortraitData, ax=None, *, legend=True) -> ContactPlot:
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
    ContactPlot

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> import contactsym as cs
    >>> fig, ax = plt.subplots()
    >>> artists = phase_portrait_plot(phase_portrait_data(cs.scene("sliding-point"), resolution=10), ax=ax)
    >>> ax.get_xlabel(), ax.get_ylabel()
    ('$u$', '$v$')
    >>> plt.close(fig)
    """
    ax = axes_or_current(ax)
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
    return ContactPlot.of(ax, artists)


@checked
def phase_portrait_caption(data: PhasePortraitData) -> str:
    """A LaTeX caption for a phase portrait, from its data.

    Examples
    --------
    >>> import contactsym as cs
    >>> print(phase_portrait_caption(phase_portrait_data(cs.scene("sliding-point"), resolution=5)))
    Phase portrait of the fast subsystem (2.1) of sliding-point (unique stable root): 1 stable and 0 unstable equilibria $(u^*, 0)$; filled markers stable ($f' > 0$), open markers unstable (Proposition 3).
    """
    stable = sum(1 for _, s in data.equilibria if s)
    unstable = len(data.equilibria) - stable
    return (
        f"Phase portrait of the fast subsystem (2.1) of {data.scene} ({CASE_TITLES.get(data.count, data.count)}): "
        f"{stable} stable and {unstable} unstable equilibria $(u^*, 0)$; filled markers stable ($f' > 0$), "
        "open markers unstable (Proposition 3)."
    )
