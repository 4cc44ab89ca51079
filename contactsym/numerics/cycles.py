"""Stable cycles of the fast subsystem (Proposition 2) and the averaged system (2.7)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from ..arguments import between, checked
from ..errors import NumericsError
from ..mechanism.scene import t as _time
from .codegen import lambdify_cse
from .fastsystem import FastProblem
from .integration import Simulation, integrate
from .sliding import check_sliding_start, stop_where_sliding_stops
from .systems import OdeSystem, _coordinates, _free_coordinates, _manifold_parameters
from .values import (
    NumericValues,
    _check_free,
    _check_span,
    _evaluate,
    _positive,
    _state_values,
    _with,
    numeric_values,
    substitute,
)


@checked(nan=True)
@dataclass(frozen=True, eq=False)
class Cycle:
    """A stable periodic solution of the fast subsystem (Proposition 2).

    Attributes
    ----------
    converged : bool
        True when successive returns to the Poincaré section agreed to ``tol``.
    period, omega : float
        Period and angular frequency in the stretched time tau (omega/eps in t).
    tau, states, reactions : ndarray
        One period, uniformly sampled (``samples`` points, endpoint excluded).
    mean_reactions : ndarray
        The reactions averaged over the period: the reactions of the averaged system (2.7).
    contact_loss : bool
        Some reaction vanishes on part of the cycle (a unilateral contact opens).
    message : str

    Examples
    --------
    Check ``converged`` before using a cycle: too few periods to settle give none (NaN period), with the
    reason (:func:`fast_cycle` shows a converged one):

    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> cycle = fast_cycle(cs.scene("brake"), values, periods=3, samples=64)
    >>> isinstance(cycle, Cycle), cycle.converged, cycle.message
    (True, False, 'no convergence to a cycle within 3 linear periods.')
    """

    converged: bool
    period: float
    omega: float
    tau: np.ndarray
    states: np.ndarray
    reactions: np.ndarray
    mean_reactions: np.ndarray
    names: tuple
    reaction_names: tuple
    contact_loss: bool
    message: str


def _no_cycle(system: OdeSystem, message: str) -> Cycle:
    empty = np.empty((len(system.names), 0))
    return Cycle(
        False,
        math.nan,
        math.nan,
        np.empty(0),
        empty,
        np.empty((len(system.reaction_names), 0)),
        np.full(len(system.reaction_names), math.nan),
        system.names,
        system.reaction_names,
        False,
        message,
    )


@checked(scene="Scene", unilateral="bool | None", periods=between(1, 10**7), samples=between(2, 10**8))
def fast_cycle(
    scene,
    values: Mapping | None,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    initial=None,
    periods: int = 3000,
    tol: float = 1e-7,
    rtol: float = 1e-10,
    samples: int = 4096,
    method: str = "DOP853",
) -> Cycle:
    """Find a stable cycle of the fast subsystem by integration to a Poincaré section.

    Starting near the equilibrium (or at ``initial``), the fast subsystem is integrated
    (DOP853 by default: in tau the fast subsystem is not stiff, and a contact that opens
    and closes makes the force discontinuous, which implicit methods pass only with tiny
    steps) until successive upward crossings of ``v_1 = 0`` (``V_1 = 0``) agree to ``tol``
    (relative to the typical magnitudes) and are near their limit: a slow spiral into a
    stable equilibrium, whose returns agree to ``tol`` long before it arrives, is no cycle.
    The last period is then sampled and the reactions averaged over it.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> from contactsym.numerics import equilibrium_reactions
    >>> equilibrium_reactions(cs.scene("brake"), values)
    [((1, 1), [1.0000000000000002, 3.0])]
    >>> cycle = fast_cycle(cs.scene("brake"), values, samples=512, tol=1e-6)
    >>> cycle.converged, cycle.contact_loss, round(cycle.period, 3)
    (True, True, 4.901)
    """
    tol = _positive(tol, "tol", "successive returns to the section must agree to a positive tolerance")
    rtol = _positive(rtol, "rtol", "it is the integrator's relative tolerance")
    problem = FastProblem.at(scene, values, laws=laws, unilateral=unilateral, form=form)
    system, N_scale = problem.system, problem.reaction_scale
    k = scene.k
    if problem.branch is None:
        return _no_cycle(system, f"no cycle is sought: {problem.why_no_branch()}")
    z_eq = problem.state_at(problem.u_star)
    scale = problem.scales(z_eq)
    eigenvalues = np.linalg.eigvals(system.jac(0.0, z_eq))
    omega0 = float(np.max(np.abs(eigenvalues.imag)))
    if omega0 == 0:
        return _no_cycle(system, "the linearization has no oscillatory mode; no cycle is born here.")
    T0 = 2 * math.pi / omega0
    if initial is None:
        z = z_eq.copy()
        z[0] += 1e-2 * scale[0]
    else:
        z = np.asarray(initial, dtype=float)

    section = _section(k)
    solve = {"method": method, "rtol": rtol, "atol": rtol * scale}
    found = _returns(system, z, z_eq, scale, T0, periods, tol, N_scale, section, solve)
    if isinstance(found, str):
        return _no_cycle(system, found)
    return _sampled_cycle(system, found, samples, N_scale, section, solve)


def _section(k: int):
    """The Poincaré section: upward crossings of v_1 = 0 (V_1 = 0)."""

    def section(t, y):
        return y[k]

    section.direction = 1
    return section


def _returns(
    system: OdeSystem, z, z_eq, scale, T0: float, periods: int, tol: float, N_scale, section, solve
) -> tuple | str:
    """(last return to the section, period) once the returns have converged to a cycle, else why not.

    The system is integrated in blocks of 50 linear periods ``T0``, at most ``periods`` of them.
    Successive returns that agree to ``tol`` are not enough: near a weakly damped equilibrium
    they agree to ``tol`` while still spiralling in, a "cycle" of amplitude ~ tol / (1 - r) for a
    contraction r per turn. So the returns also have to be close to their limit, estimated from
    the contraction of the last two steps (`_distance_to_limit`): within ``tol`` or 1% of their
    distance from the equilibrium, whichever is larger. A spiral into the equilibrium never
    passes (its limit is the equilibrium itself) and ends as "settles on the equilibrium".
    """
    hits: list[np.ndarray] = []
    times: list[float] = []
    elapsed = 0.0
    while elapsed < periods * T0:
        block = 50 * T0
        run = integrate(system, (elapsed, elapsed + block), z, reaction_bound=1e6 * N_scale, events=[section], **solve)
        if run.status == "impact":
            return "the fast motion escapes: " + run.message
        if run.status != "ok":
            return run.message
        for t_hit, y_hit in zip(run.extra["t_events"][0], run.extra["y_events"][0]):
            times.append(float(t_hit))
            hits.append(np.asarray(y_hit))
        z = run.y[:, -1]
        elapsed += block
        if len(hits) >= 3:
            change = np.max(np.abs(hits[-1] - hits[-2]) / scale)
            distance = np.max(np.abs(hits[-1] - z_eq) / scale)
            if distance < tol:
                return "the fast motion settles on the equilibrium: it is stable, no cycle."
            steady = abs((times[-1] - times[-2]) - (times[-2] - times[-3])) < 1e2 * tol * T0
            near_limit = _distance_to_limit(hits[-3:], scale) < max(tol, 1e-2 * distance)
            if change < tol and steady and near_limit:
                return hits[-1], times[-1] - times[-2]
    return f"no convergence to a cycle within {periods} linear periods."


def _distance_to_limit(last: list, scale) -> float:
    """How far the last of three successive returns is from their limit (scaled max norm).

    For returns converging geometrically, h_n - h_inf = (h_n - h_(n-1)) r / (1 - r) with r the
    contraction per return, estimated as |h_n - h_(n-1)| / |h_(n-1) - h_(n-2)|. Returns that do not
    contract (r >= 1) give no estimate (inf: integrate on); after two identical returns the distance is
    the last step; identical returns are at their limit.
    """
    step = np.max(np.abs(last[2] - last[1]) / scale)
    before = np.max(np.abs(last[1] - last[0]) / scale)
    if step == 0:
        return 0.0
    if before == 0 or step >= before:
        return float(step) if before == 0 else math.inf
    r = step / before
    return float(step * r / (1 - r))


def _sampled_cycle(system: OdeSystem, found: tuple, samples: int, N_scale: float, section, solve) -> Cycle:
    """One period from the last return, sampled uniformly, with its reactions and their means."""
    start, period = found
    final = integrate(system, (0.0, 1.25 * period), start, dense_output=True, events=[section], **solve)
    crossings = [t for t in final.extra["t_events"][0] if t > 0.5 * period]
    if crossings:
        period = float(crossings[0])
    tau = np.linspace(0.0, period, samples, endpoint=False)
    states = final.sol(tau)
    reactions = np.column_stack([system.reactions(ti, states[:, i]) for i, ti in enumerate(tau)])
    loss = bool(np.any(np.abs(reactions) <= 1e-12 * N_scale))
    return Cycle(
        True,
        period,
        2 * math.pi / period,
        tau,
        states,
        reactions,
        reactions.mean(axis=1),
        system.names,
        system.reaction_names,
        loss,
        f"cycle of period {period:.6g} in tau",
    )


def simulate_averaged(
    scene,
    values: Mapping | None,
    span,
    initial: Mapping,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    method: str = "DOP853",
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    cycle_options: Mapping | None = None,
) -> Simulation:
    """Simulate the averaged system (2.7): slow motion driven by cycle-averaged forces.

    Where the fast subsystem has a stable cycle (Proposition 2), the slow coordinates
    follow their accelerations averaged over the cycle at the frozen slow state,
    ``<G(x, N(tau))>``, not G at the averaged reactions. When the fast subsystem does
    not depend on the slow state (the brake), the cycle is computed once. The output
    reactions are the cycle means.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4, "J": 1, "r": 1,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> run = simulate_averaged(cs.scene("brake"), values, (0, 1), {"theta": 0, "thetadot": -5},
    ...                         cycle_options={"samples": 512, "tol": 1e-6})
    >>> run.names, run.status
    (('theta', 'thetadot'), 'ok')
    """
    span = _check_span(span, "span")
    free_state, z0, base = _averaged_start(scene, numeric_values(scene, values), initial)
    check_sliding_start(scene, base, dict(zip(free_state, z0)), on_manifold=True)
    fast_f = [substitute(f, base) for f in scene.fast_subsystem().f]
    depends = any(f.free_symbols & set(free_state) for f in fast_f)
    options = dict(cycle_options or {})
    cache: dict = {}

    def cycle_at(y) -> Cycle:
        key = tuple(np.round(y, 12)) if depends else ()
        if key not in cache:
            frozen = _with(base, dict(zip(free_state, y))) if depends else base
            found = fast_cycle(scene, frozen, laws=laws, unilateral=unilateral, form=form, **options)
            if not found.converged:
                raise NumericsError(
                    f"no stable cycle of the fast subsystem at the slow state "
                    f"{ {str(s): round(float(v), 6) for s, v in zip(free_state, y)} }: {found.message}"
                )
            cache[key] = found
        return cache[key]

    system = _averaged_system(scene, base, free_state, cycle_at)
    run = integrate(
        system, span, z0, method=method, jacobian=False, rtol=rtol, atol=atol, t_eval=t_eval, dense_output=True
    )
    run = replace(run, extra={**run.extra, "cycle": cache.get(()) if not depends else None})
    return stop_where_sliding_stops(scene, base, run, on_manifold=True)


def _averaged_start(scene, vals: NumericValues, initial) -> tuple[list, np.ndarray, NumericValues]:
    """(the free coordinates and rates, their initial values, the values with the fixed state and parameters)."""
    free = _free_coordinates(scene)
    free_state = [q for q, _ in free] + [r for _, r in free]
    positions_all, rates_all = _coordinates(scene)
    state_all = positions_all + rates_all
    given = _state_values([str(s) for s in state_all], state_all, initial, f"averaged system of '{scene.name}'")
    missing = [str(s) for s in free_state if s not in given]
    if missing:
        raise NumericsError(f"give the initial values of {missing} for the averaged system.")
    fixed_state = {s: v for s, v in given.items() if s not in free_state}
    base = _with(vals, fixed_state)
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in base.numbers:
            base = _with(base, {parameter: _evaluate(expr, base, f"the parameter {parameter}")})
    return free_state, np.array([given[s] for s in free_state], dtype=float), base


def _averaged_system(scene, base: NumericValues, free_state: list, cycle_at) -> OdeSystem:
    """The slow coordinates driven by their accelerations averaged over the cycle ``cycle_at(state)``."""
    m = len(free_state) // 2
    by_plain = {scene.plain(q): q for q in scene.coordinates}
    G = [substitute(scene.freeze(scene.accelerations[by_plain[q]]), base) for q in free_state[:m]]
    reactions = list(scene.reactions)
    _check_free(G, set(free_state) | set(reactions) | {_time}, "the averaged system")
    G_function = lambdify_cse([_time, *free_state, *reactions], G)

    def averaged(t, y):
        cycle = cycle_at(y)
        values_G = G_function(t, *y, *cycle.reactions)
        mean = [float(np.mean(np.broadcast_to(np.asarray(g, dtype=float), cycle.tau.shape))) for g in values_G]
        return np.concatenate([y[m:], mean])

    def reactions_out(t, y):
        return cycle_at(y).mean_reactions

    return OdeSystem(
        tuple(str(s) for s in free_state),
        averaged,
        lambda t, y: None,
        reactions_out,
        tuple(str(r) for r in reactions),
        "t",
        f"averaged system (2.7) of '{scene.name}'",
    )
