"""The equilibrium branches of the fast subsystem at numeric values, and the comparison system (2.2)."""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
import sympy as sp

from ..arguments import checked
from ..errors import NumericsError
from ..mechanism.scene import t as _time
from .certified import decide
from .codegen import _cached
from .integration import Simulation, integrate
from .sliding import check_sliding_start, stop_where_sliding_stops
from .systems import OdeSystem, _coordinates, _first_order, _free_coordinates, _manifold_parameters
from .values import (
    NumericValues,
    _check_free,
    _check_span,
    _evaluate,
    _merge,
    _state_values,
    _with,
    numeric_values,
    substitute,
)


def _branch_at(scene, vals: NumericValues, signs=None):
    """The equilibrium branch to use at frozen values: the given pattern or the unique consistent one."""
    if signs is not None:
        return scene.equilibria(signs).branches[0]
    branches = _consistent(scene, vals)
    if len(branches) == 1:
        return branches[0]
    raise NumericsError(_why_no_branch(scene, vals, branches) + ("; choose one with signs=..." if branches else ""))


def _consistent(scene, vals: NumericValues) -> list:
    return [b for b in scene.equilibria() if decide(substitute(b.condition, vals), {}) is True]


def _why_no_branch(scene, vals: NumericValues, branches: list | None = None) -> str:
    """Why there is no single equilibrium branch at the values: several consistent, unilateral
    contacts that lift off (an equilibrium with them open is consistent here), else an impact-type
    catastrophe."""
    branches = _consistent(scene, vals) if branches is None else branches
    if branches:
        return f"{len(branches)} equilibria are consistent at these values (signs {[b.signs for b in branches]})"
    lifted = [lift for lift in scene.equilibria().lift_offs if decide(substitute(lift.condition, vals), {}) is True]
    if lifted:
        opened = sorted({j + 1 for lift in lifted for j in lift.open})
        which = (
            f"contact {opened[0]} lifts off (the loads pull it"
            if len(opened) == 1
            else (f"contacts {', '.join(map(str, opened))} lift off (the loads pull them")
        )
        return (
            f"no equilibrium of the fast subsystem with every contact closed at these values: {which} open; see "
            "scene.equilibria().lift_offs), so there is no equilibrium in contact to linearize or to follow here; "
            "choose values where the contacts press."
        )
    return (
        "no equilibrium of the fast subsystem is consistent at these values: an impact-type catastrophe "
        "(no reduced system exists); simulate the full or fast system to see the reaction grow."
    )


@checked(scene="Scene")
def equilibrium_reactions(scene, values: Mapping | None, state: Mapping | None = None) -> list[tuple]:
    """Consistent equilibria (sign pattern, u*) of the fast subsystem at numeric values.

    ``state`` gives the frozen slow state (plain symbols or names), merged into values.
    Consistency of each branch is decided with :func:`decide` (exact near the boundary).

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> [(s, [round(u, 6) for u in us]) for s, us in equilibrium_reactions(cs.scene("painleve-klein-rod"), values)]
    [((-1, -1), [-0.682472])]
    """
    vals = _merge(scene, values, state)
    found = []
    for branch in scene.equilibria():
        if decide(substitute(branch.condition, vals), {}) is True:
            found.append((branch.signs, [float(substitute(u, vals)) for u in branch.u_star]))
    return found


@checked(scene="Scene")
def reduced_system(scene, values: Mapping | None, *, signs=None, state: Mapping | None = None) -> OdeSystem:
    """The comparison system (2.2) on one equilibrium branch, as generated code.

    The branch is ``signs`` or, with ``signs=None``, the unique branch consistent at
    ``state`` (the initial state). Coordinates fixed by the contacts (e.g. the angle of
    the Painlevé–Klein rod) are constants taken from ``state``.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> reduced_system(cs.scene("painleve-klein-rod"), values).names
    ('x_1', 'xdot_1')
    """
    merged = _merge(scene, values, state)
    free = _free_coordinates(scene)
    free_symbols = {s for pair in free for s in pair}
    frozen = NumericValues({k: v for k, v in merged.numbers.items() if k not in free_symbols}, merged.functions)
    branch = _branch_at(scene, frozen, signs)
    key = ("reduced", frozen.key(), branch.signs)

    def build():
        reduced = scene.reduced_system(branch.signs)
        positions = [q for q, _ in free]
        rates = [r for _, r in free]
        accelerations = [substitute(reduced.accelerations[q], frozen) for q in positions]
        outputs = [substitute(u, frozen) for u in branch.u_star]
        _check_free(accelerations + outputs, set(positions) | set(rates) | {_time}, "the reduced system")
        return _first_order(
            _time,
            positions + rates,
            rates + accelerations,
            outputs,
            names=[str(s) for s in positions + rates],
            reaction_names=[str(r) for r in scene.reactions],
            time="t",
            description=f"reduced system (2.2) of '{scene.name}', signs {branch.signs}",
        )

    return _cached(scene, key, build)


def _reaction_scale(scene, frozen: NumericValues, branch) -> float:
    """A typical magnitude of the reactions: |u*|, or |f_j(0) / a_jj| without an equilibrium."""
    if branch is not None:
        scale = max((abs(float(substitute(u, frozen))) for u in branch.u_star), default=0.0)
        if scale > 0 and math.isfinite(scale):
            return scale
    fast = scene.fast_subsystem()
    zero = dict.fromkeys(fast.u, 0)
    estimates = []
    for j, fj in enumerate(fast.f):
        f0 = substitute(fj.xreplace(zero), frozen)
        slope = substitute(sp.diff(fj, fast.u[j]).xreplace(zero), frozen)
        if not f0.free_symbols and not slope.free_symbols and float(slope) != 0:
            estimates.append(abs(float(f0) / float(slope)))
    scale = max(estimates, default=0.0)
    return scale if scale > 0 and math.isfinite(scale) else 1.0


def _try_branch(scene, frozen: NumericValues, signs):
    try:
        return _branch_at(scene, frozen, signs)
    except NumericsError:
        return None


def simulate_reduced(
    scene,
    values: Mapping | None,
    span,
    initial: Mapping,
    *,
    signs=None,
    method: str = "DOP853",
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = True,
    max_rhs: int = 2_000_000,
) -> Simulation:
    """Simulate the comparison system (2.2): the classical rigid-contact motion.

    ``initial`` gives the free coordinates and rates, and any coordinate the contacts
    fix that the accelerations still need (e.g. the rod's angle phi for the guides).
    The reactions output is u* along the motion.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> run = simulate_reduced(cs.scene("painleve-klein-rod"), values, (0, 1), {"x_1": 0, "xdot_1": 1})
    >>> round(run.at(1.0, "xdot_1"), 6)
    1.390085
    """
    span = _check_span(span, "span")
    vals = numeric_values(scene, values)
    positions, rates = _coordinates(scene)
    state = positions + rates
    given = _state_values([str(s) for s in state], state, initial, f"reduced system of '{scene.name}'")
    frozen_given = {s: v for s, v in given.items()}
    with_state = _with(vals, frozen_given)
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in vals.numbers:
            with_state = _with(with_state, {parameter: _evaluate(expr, with_state, f"the parameter {parameter}")})
    free = _free_coordinates(scene)
    free_state = [q for q, _ in free] + [r for _, r in free]
    missing = [str(s) for s in free_state if s not in given]
    if missing:
        raise NumericsError(f"give the initial values of {missing} for the reduced system.")
    fixed_values = {s: v for s, v in given.items() if s not in free_state}
    system = reduced_system(
        scene,
        NumericValues(dict(with_state.numbers), vals.functions),
        signs=signs,
        state={**fixed_values, **{s: given[s] for s in free_state}},
    )
    z0 = np.array([given[s] for s in free_state], dtype=float)
    held = {k: v for k, v in with_state.numbers.items() if k not in free_state and k not in vals.numbers}
    check_sliding_start(scene, vals, {**held, **dict(zip(free_state, z0))}, on_manifold=True)
    if atol is None:
        duration = span[1] - span[0]
        rhs = np.abs(system.fun(span[0], z0))
        m = len(free)
        scale = np.abs(z0).copy()
        scale[:m] = np.maximum(scale[:m], np.maximum(np.abs(z0[m:]) * duration, rhs[m:] * duration**2 / 2))
        scale[m:] = np.maximum(scale[m:], rhs[m:] * duration)
        top = float(scale.max(initial=0.0))
        atol = rtol * np.maximum(scale, 1e-12 * top if top > 0 else 1.0)
    run = integrate(
        system, span, z0, method=method, rtol=rtol, atol=atol, t_eval=t_eval, dense_output=dense_output, max_rhs=max_rhs
    )
    return stop_where_sliding_stops(scene, vals, run, held, on_manifold=True)
