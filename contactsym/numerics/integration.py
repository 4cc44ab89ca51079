"""Integration of a generated system with ``scipy.integrate.solve_ivp``, within a budget.

Compliant contacts are stiff, so the default solver is Radau with the analytic Jacobian
(LSODA has been seen to take millions of steps on them). An impact-type catastrophe
(no equilibrium of the fast subsystem: the reaction grows without bound on the fast time
scale) stops the integration through a ``solve_ivp`` event and is reported in the
result's ``status``.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace

import numpy as np
from scipy.integrate import solve_ivp

from .. import validate
from ..arguments import checked
from ..errors import NumericsError
from ..progress import Budget, Progress
from .systems import OdeSystem
from .values import _check_span, _positive

_IMPLICIT = ("Radau", "BDF", "LSODA")


_IMPLICIT = ("Radau", "BDF", "LSODA")


class _Budget(Exception):
    pass


class _NotFinite(Exception):
    pass


@checked(nan=True)
@dataclass(frozen=True, eq=False)
class Simulation:
    """The result of a simulation.

    Attributes
    ----------
    t : ndarray
        Output times (t, or tau for the fast subsystem).
    y : ndarray
        States, one row per component of ``names``.
    reactions : ndarray
        Normal reactions N_j at the output times, one row per contact.
    status : str
        ``"ok"``; ``"impact"`` when the reaction grew past ``reaction_bound`` (impact-type
        catastrophe, no equilibrium of the fast subsystem); ``"failed"`` otherwise.
    message : str
        What happened, in words.
    nfev : int
        Right-hand-side evaluations, including those of finite-difference Jacobians.
    njev, nlu : int
        Jacobian evaluations and LU decompositions reported by the solver.
    cpu_s, wall_s : float
        Process (CPU) time and wall time of the integration.
    sol : OdeSolution or None
        Dense output when requested.

    Examples
    --------
    A point sliding on the floor under constant forces X, Y < 0: N = -Y, and xdot grows at X - mu N:

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> from contactsym.numerics import simulate_reduced
    >>> x, xdot = sp.symbols("x xdot", real=True)
    >>> X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)
    >>> sim = simulate_reduced(cs.scene("sliding-point"), {"m": 1, "b": 1, "mu": 0.5, X: 2, Y: -1},
    ...                        (0, 1), {x: 0, xdot: 1})
    >>> isinstance(sim, Simulation), sim.status, sim.names, sim.reaction_names
    (True, 'ok', ('x', 'xdot'), ('N',))
    >>> bool(abs(sim.at(1.0, "xdot") - (1 + (2 - 0.5 * 1) * 1.0)) < 1e-9), float(sim.reactions[0, -1])
    (True, 1.0)
    """

    t: np.ndarray
    y: np.ndarray
    names: tuple
    reactions: np.ndarray
    reaction_names: tuple
    status: str
    message: str
    method: str
    analytic_jacobian: bool
    nfev: int
    njev: int
    nlu: int
    cpu_s: float
    wall_s: float
    time: str = "t"
    sol: object = None
    extra: dict = field(default_factory=dict)

    def __getitem__(self, name: str) -> np.ndarray:
        if name in self.names:
            return self.y[self.names.index(name)]
        if name in self.reaction_names:
            return self.reactions[self.reaction_names.index(name)]
        raise KeyError(f"{name!r} is none of {self.names + self.reaction_names}")

    def at(self, time_value: float, name: str) -> float:
        """One component at one time (dense output, else linear interpolation)."""
        if self.sol is not None and name in self.names:
            return float(self.sol(time_value)[self.names.index(name)])
        return float(np.interp(time_value, self.t, self[name]))

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def _budget_message(method: str, analytic: bool, counter: dict, max_rhs: int, budget, span, time_name) -> str:
    """What ran out, how far the run got, and advice that is not what was already done."""
    start, end = span
    spent = (
        f"{budget.elapsed:.0f} s (max_seconds = {budget.max_seconds:g})"
        if counter["n"] <= max_rhs
        else f"{max_rhs} right-hand-side evaluations (max_rhs)"
    )
    reached = (
        f"it reached {time_name} = {counter['t']:.6g}, {100 * (counter['t'] - start) / (end - start):.3g}% of the span"
    )
    if analytic:  # the stiff solver with the exact Jacobian was already in use: the work itself is large
        advice = (
            f"{method} already had the analytic Jacobian, so the cost is the number of fast time scales in the "
            "span: shorten the span, take a larger eps, or use the reduced system (simulate_reduced) for the "
            "slow motion; raise the limit only if the whole run is needed"
        )
    elif method in _IMPLICIT:
        advice = "pass jacobian=True so that the solver gets the analytic Jacobian"
    else:
        advice = f"{method} is explicit and contacts are stiff: use method='Radau' or 'BDF' with the analytic Jacobian"
    return f"{method} used up its budget of {spent}; {reached}. {advice}."


def integrate(
    system: OdeSystem,
    span,
    z0,
    *,
    method: str = "Radau",
    jacobian: bool = True,
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = False,
    max_rhs: int = 2_000_000,
    reaction_bound: float | None = None,
    events: Sequence = (),
    progress: Progress | None = None,
    max_seconds: float | None = None,
) -> Simulation:
    """Integrate a generated system with ``scipy.integrate.solve_ivp``.

    Parameters
    ----------
    method : str
        Any ``solve_ivp`` method; Radau (default) and BDF are robust for stiff contacts.
    jacobian : bool
        Give the implicit methods the analytic Jacobian (True) or let SciPy use finite
        differences (False).
    atol : float or array, optional
        Default ``rtol`` times the magnitude of the initial state (at least 1e-12 of it).
    max_rhs : int
        Stop with status ``"failed"`` after this many right-hand-side evaluations.
    reaction_bound : float, optional
        Stop with status ``"impact"`` when some |N_j| exceeds it.
    progress : callable, optional
        ``progress(fraction of the span done, message)``, a few times per second.
    max_seconds : float, optional
        Stop with status ``"failed"`` after this much wall time, saying how far the run got.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -1}
    >>> from contactsym.numerics import fast_system
    >>> fs = fast_system(cs.scene("painleve-klein-rod"), values)
    >>> run = integrate(fs, (0, 40), [0.0, 0.0], rtol=1e-10, atol=1e-12)
    >>> run.status, round(float(run.reactions[0, -1]), 5)
    ('ok', -0.68247)
    """
    # long only by its keyword options (those of solve_ivp, and the budget); the steps are helpers below
    start, end = _check_span(span, "span")
    method = validate.solver_method(method)
    t_eval = validate.output_times(t_eval, (start, end))
    z0 = _initial_state(system, z0)
    rtol = _positive(rtol, "rtol", "it is the relative tolerance")
    atol = _default_atol(z0, rtol) if atol is None else atol
    counter = {"n": 0, "t": start}  # t: the furthest time evaluated, for progress and for a spent budget
    budget = Budget(progress, max_seconds)
    solver_events = list(events) + ([] if reaction_bound is None else [_impact_event(system, reaction_bound)])
    analytic = bool(jacobian) and method in _IMPLICIT
    options = {"jac": system.jac} if analytic else {}
    started, cpu = time.perf_counter(), time.process_time()
    status, message, result = "ok", "integrated to the end", None
    try:
        result = solve_ivp(
            _counted(system, counter, budget, max_rhs, (start, end)),
            (start, end),
            z0,
            method=method,
            t_eval=t_eval,
            dense_output=dense_output,
            events=solver_events or None,
            rtol=rtol,
            atol=atol,
            **options,
        )
        status, message = _outcome(system, result, method, reaction_bound)
    except _Budget:
        status = "failed"
        message = _budget_message(method, analytic, counter, max_rhs, budget, (start, end), system.time)
    except _NotFinite as stop:
        status = "failed"
        message = f"the right-hand side is not finite at {system.time} = {stop.args[0]:.6g}; check the parameters."
    wall, cpu = time.perf_counter() - started, time.process_time() - cpu
    if status == "ok":
        budget.report(1.0, f"{system.time} = {end:.4g}")
    run = Simulation(
        np.empty(0),
        np.empty((len(system.names), 0)),
        system.names,
        np.empty((len(system.reaction_names), 0)),
        system.reaction_names,
        status,
        message,
        method,
        analytic,
        counter["n"],
        0,
        0,
        cpu,
        wall,
        system.time,
    )
    return run if result is None else _with_solution(run, system, result, keep_event=t_eval is not None)


def integrate_with_impact_bound(
    system: OdeSystem,
    span,
    z0,
    *,
    reaction_scale: float,
    reaction_bound: float | None,
    bound_factor: float,
    equilibrium,
    extra: dict,
    **options,
) -> Simulation:
    """The tail of :func:`~contactsym.numerics.simulate_fast` and :func:`~contactsym.numerics.simulate_full`:
    :func:`integrate` with the impact bound ``reaction_bound`` (default ``bound_factor`` times the
    reaction scale), the scale, the bound, ``extra`` and the ``equilibrium`` sign pattern in the result's ``extra``.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym.numerics.fastsystem import FastProblem
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> problem = FastProblem.at(cs.scene("brake"), values)
    >>> run = integrate_with_impact_bound(problem.system, (0, 1), [0.0] * 4, reaction_scale=3.0,
    ...     reaction_bound=None, bound_factor=10, equilibrium=(1, 1), extra={"form": problem.form})
    >>> run.extra["reaction_bound"], run.extra["form"], run.extra["equilibrium"], run.status
    (30.0, 'deformation', (1, 1), 'ok')
    """
    bound = reaction_bound if reaction_bound is not None else bound_factor * reaction_scale
    run = integrate(system, span, z0, reaction_bound=bound, **options)
    scales = {"reaction_scale": reaction_scale, "reaction_bound": bound}
    return replace(run, extra={**run.extra, **scales, **extra, "equilibrium": equilibrium})


def _initial_state(system: OdeSystem, z0) -> np.ndarray:
    z0 = validate.real_array(z0, "the initial state").ravel()
    if z0.shape != (len(system.names),):
        raise NumericsError(
            f"the initial state has {z0.size} components; {system.description} has {len(system.names)}."
        )
    if not np.all(np.isfinite(z0)):
        raise NumericsError(f"the initial state {z0.tolist()} is not finite.")
    return z0


def _default_atol(z0: np.ndarray, rtol: float) -> np.ndarray:
    """``rtol`` times the magnitude of each component, at least 1e-12 of the largest (``rtol`` at rest)."""
    magnitude = np.abs(z0)
    if not magnitude.any():
        return np.full_like(z0, rtol)
    return rtol * np.maximum(magnitude, max(1e-12 * float(magnitude.max(initial=0.0)), 1e-300))


def _counted(system: OdeSystem, counter: dict, budget: Budget, max_rhs: int, span) -> Callable:
    """The right-hand side, counting its calls, reporting progress and stopping when the budget is spent."""
    start, end = span

    def fun(t, y):
        counter["n"] += 1
        counter["t"] = max(counter["t"], t)
        if counter["n"] > max_rhs:
            raise _Budget
        if counter["n"] % 64 == 0 and budget.report((counter["t"] - start) / (end - start), f"{system.time} = {t:.4g}"):
            raise _Budget
        out = system.fun(t, y)
        if not np.isfinite(out).all():  # the method: NumPy's function form costs as much again per call
            raise _NotFinite(t)
        return out

    return fun


def _impact_event(system: OdeSystem, reaction_bound: float) -> Callable:
    """A terminal event where some |N_j| reaches ``reaction_bound``."""

    def impact(t, y):
        return reaction_bound - float(np.max(np.abs(system.reactions(t, y))))

    impact.terminal = True
    impact.direction = -1
    return impact


def _outcome(system: OdeSystem, result, method: str, reaction_bound: float | None) -> tuple[str, str]:
    """(status, message) of a finished ``solve_ivp`` run."""
    if result.status == -1:
        return "failed", f"{method} failed: {result.message}"
    if reaction_bound is not None and result.t_events[-1].size:
        return "impact", (
            f"impact-type catastrophe: |N| passed {reaction_bound:.3g} at {system.time} = "
            f"{result.t_events[-1][0]:.6g}; the fast subsystem has no stable equilibrium to settle on "
            "and the reaction grows without bound on the fast time scale."
        )
    return "ok", "integrated to the end"


def _with_solution(run: Simulation, system: OdeSystem, result, *, keep_event: bool) -> Simulation:
    """``run`` with the solver's states, the reactions along them and its counts."""
    if run.status == "impact" and keep_event:
        # keep the state where the catastrophe was detected
        times = np.append(result.t, result.t_events[-1][0])
        states = np.column_stack([result.y, result.y_events[-1][0]])
    else:
        times, states = result.t, result.y
    reactions = (
        np.column_stack([system.reactions(ti, states[:, i]) for i, ti in enumerate(times)])
        if times.size
        else (np.empty((len(system.reaction_names), 0)))
    )
    status, message = run.status, run.message
    if status == "ok" and not (np.all(np.isfinite(states)) and np.all(np.isfinite(reactions))):
        status, message = "failed", "the solution is not finite; check the parameters."
    return replace(
        run,
        t=times,
        y=states,
        reactions=reactions,
        status=status,
        message=message,
        njev=int(result.njev),
        nlu=int(result.nlu),
        sol=result.sol,
        extra={"t_events": result.t_events, "y_events": result.y_events},
    )
