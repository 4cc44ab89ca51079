"""Where a simulation leaves its scene: a Coulomb contact whose sliding speed reaches zero.

A scene's Coulomb law is mu |N| against a given sliding direction
(:attr:`contactsym.Scene.slip_speeds`): it describes the motion while each such contact slides
that way. Where a sliding speed reaches zero the contact sticks or slides back, which the scene
does not describe, so the simulations (full, reduced, averaged) end their run there (status ``"sliding stops"``) instead of
integrating on with friction pushing the wrong way; a start that already slides backwards is
refused.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace

import numpy as np
import sympy as sp

from ..errors import NumericsError
from .codegen import lambdify_cse
from .integration import Simulation
from .values import NumericValues, substitute

__all__ = ["check_sliding_start", "stop_where_sliding_stops"]

#: The status of a run cut where a contact stops sliding.
SLIDING_STOPS = "sliding stops"


def _speeds(scene, vals: NumericValues, fixed: Mapping, on_manifold: bool) -> list[tuple[int, sp.Expr]]:
    """The speeds with the values put in; ``on_manifold``: the coordinates the contacts fix (and their
    rates) first put on the contact manifold g = 0, g' = 0, as the reduced and averaged systems are."""
    held = {k: v if isinstance(v, sp.Basic) else sp.Float(float(v)) for k, v in fixed.items()}
    known = NumericValues({**vals.numbers, **held}, vals.functions)
    manifold = scene.manifold if on_manifold else {}
    return [
        (j, sp.sympify(substitute(v.xreplace(manifold), known)))
        for j, v in enumerate(scene.slip_speeds)
        if v is not None
    ]


def check_sliding_start(scene, vals: NumericValues, state: Mapping, on_manifold: bool = False) -> None:
    """Refuse a start whose contact slides against the direction its Coulomb law assumes.

    ``state`` maps the plain coordinates and rates (symbols) to numbers; ``on_manifold`` for the
    reduced and averaged systems, whose state lies on the contact manifold.

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> from contactsym.numerics.values import numeric_values
    >>> s = cs.scene("sliding-point")
    >>> check_sliding_start(s, numeric_values(s, {"m": 1}), {sp.Symbol("xdot", real=True): -1.0})
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: at the start contact 1 slides backwards: its sliding speed xdot is -1 < 0, against the direction its Coulomb law assumes; start with it > 0, or reverse the friction direction of the scene.
    """
    for j, speed in _speeds(scene, vals, state, on_manifold):
        if speed.free_symbols:
            continue
        value = float(speed)
        if value < 0:
            raise NumericsError(
                f"at the start contact {j + 1} slides backwards: its sliding speed {scene.slip_speeds[j]} is "
                f"{value:.6g} < 0, against the direction its Coulomb law assumes; start with it > 0, or reverse the "
                "friction direction of the scene."
            )


def stop_where_sliding_stops(
    scene, vals: NumericValues, run: Simulation, fixed: Mapping | None = None, on_manifold: bool = False
) -> Simulation:
    """``run`` up to the first time a contact's sliding speed reaches zero, with status ``"sliding stops"``.

    The speeds are evaluated at the run's points (the state by name, ``fixed`` for coordinates held
    constant; ``on_manifold`` as for :func:`check_sliding_start`); the crossing itself is found on
    the dense output where the run has one (else it is the last point before it) and appended as the
    run's last point. A run that never stops sliding, or whose speeds cannot be evaluated from its
    state, is returned as it is.
    """
    speeds = _speeds(scene, vals, dict(fixed or {}), on_manifold)
    if not speeds or run.t.size == 0:
        return run
    rows = {name: run.y[i] for i, name in enumerate(run.names)}
    symbols = sorted(set().union(*(v.free_symbols for _, v in speeds)), key=str)
    if any(str(s) not in rows for s in symbols):
        return run
    function = lambdify_cse(symbols, [v for _, v in speeds])
    values = np.array(
        [np.broadcast_to(np.asarray(v, dtype=float), run.t.shape) for v in function(*(rows[str(s)] for s in symbols))]
    )
    backwards = np.nonzero((values < 0).any(axis=0))[0]
    if backwards.size == 0 or backwards[0] == 0:
        return run
    i = int(backwards[0])
    which = int(np.argmin(values[:, i]))
    crossing = _crossing(run, function, symbols, which, i)
    j = speeds[which][0]
    message = (
        f"contact {j + 1} stops sliding at {run.time} = {crossing:.6g} (its sliding speed {scene.slip_speeds[j]} "
        "reaches 0): its Coulomb law assumes sliding one way, so the run ends there; sticking or sliding back "
        "is another scene (friction the other way)."
    )
    return _cut(run, i, crossing, SLIDING_STOPS, message)


def _crossing(run: Simulation, function, symbols, which: int, i: int) -> float:
    before, after = float(run.t[i - 1]), float(run.t[i])
    if run.sol is None:
        return before

    def speed(time: float) -> float:
        state = run.sol(time)
        return float(function(*(state[run.names.index(str(s))] for s in symbols))[which])

    from scipy.optimize import brentq

    low, high = speed(before), speed(after)
    if not (low >= 0 > high):
        return before
    return float(brentq(speed, before, after, xtol=1e-14 * max(1.0, abs(after)), rtol=1e-12))


def _cut(run: Simulation, i: int, crossing: float, status: str, message: str) -> Simulation:
    """The run's points before index ``i`` and the state at ``crossing`` (dense output, else the last point)."""
    if run.sol is not None and crossing > run.t[i - 1]:
        last = np.asarray(run.sol(crossing), dtype=float)
        weight = (crossing - run.t[i - 1]) / (run.t[i] - run.t[i - 1])
        reactions = (1 - weight) * run.reactions[:, i - 1] + weight * run.reactions[:, i]
        t = np.append(run.t[:i], crossing)
        y = np.column_stack([run.y[:, :i], last])
        reactions = np.column_stack([run.reactions[:, :i], reactions])
    else:
        t, y, reactions = run.t[:i], run.y[:, :i], run.reactions[:, :i]
    return replace(run, t=t, y=y, reactions=reactions, status=status, message=message)
