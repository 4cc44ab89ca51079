"""The full compliant system (1.9) simulated in the original time t, with tolerances fitted to its scales."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, replace

import numpy as np
import sympy as sp

from ..errors import NumericsError
from ..progress import Progress
from .codegen import lambdify_cse
from .integration import Simulation, integrate_with_impact_bound
from .reduced import _reaction_scale, _try_branch
from .sliding import check_sliding_start, stop_where_sliding_stops
from .systems import _contact_law, _coordinates, _invert_law, _law_scaled, _manifold_parameters, full_system
from .values import (
    _UNIT,
    NumericValues,
    _check_span,
    _evaluate,
    _plain_expr,
    _positive,
    _state_values,
    _with,
    numeric_values,
    substitute,
)


def simulate_full(
    scene,
    values: Mapping | None,
    eps,
    span,
    initial: Mapping,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    start: str = "rigid",
    signs=None,
    method: str = "Radau",
    jacobian: bool = True,
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = True,
    reaction_bound: float | None = None,
    bound_factor: float = 1e6,
    max_rhs: int = 2_000_000,
    progress: Progress | None = None,
    max_seconds: float | None = None,
) -> Simulation:
    """Simulate the full compliant system (1.9) at ``eps`` in the original time t.

    Parameters
    ----------
    initial : mapping
        Initial coordinates and rates (plain symbols or names, e.g. ``x``, ``xdot``).
        Coordinates fixed by the contacts may be left out: ``start="rigid"`` puts them
        on the contact manifold (g = 0, g' = 0; the reactions start from 0 and pass an
        initial layer), ``start="slow"`` deforms the contacts so that the reactions start
        at the equilibrium u* (to leading order on the slow manifold).
    laws, unilateral
        See :func:`full_system`.
    progress, max_seconds
        Progress reports and a wall-time limit; see :func:`integrate`.
    reaction_bound : float, optional
        |N_j| beyond which the run stops as an impact-type catastrophe; default
        ``bound_factor`` times the scale of the reactions (|u*|, or the loads'
        |f_j(0) / a_jj| when no equilibrium exists).
    atol : optional
        Default: ``rtol`` times a typical magnitude of each component (the contact
        deformations are O(eps**2), their rates O(eps)), but not below what the rounding
        of the gap expressions allows (a gap such as h - l sin(phi) - y is a difference
        of O(1) numbers). Where the deformations themselves are below that rounding, a
        :class:`NumericsError` says so instead of letting the solver's steps collapse.

    Examples
    --------
    >>> import contactsym as cs
    >>> rod = cs.scene("painleve-klein-rod")
    >>> values = {"phi": 0.785, "mu_1": 3, "mu_2": 0.5, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -1}
    >>> from contactsym.numerics import equilibrium_reactions
    >>> equilibrium_reactions(rod, values)
    []
    >>> run = simulate_full(rod, values, 1e-3, (0, 1), {"x_1": 0, "xdot_1": 1})
    >>> run.status
    'impact'
    >>> bool(run.t[-1] < 0.1)
    True
    """
    # long by its keyword options and docstring; each step is a helper below
    eps = _positive(eps, "eps", "it is the time scale of the contact deformations (1.6)")
    span = _check_span(span, "span")
    if start not in ("rigid", "slow"):
        raise NumericsError(f"start = {start!r}; use 'rigid' (on the contact manifold) or 'slow' (N = u*).")
    vals, z0 = _rigid_start(scene, numeric_values(scene, values), initial)
    positions, rates = _coordinates(scene)
    check_sliding_start(scene, vals, dict(zip(positions + rates, z0)))
    system = full_system(scene, vals, eps, laws=laws, unilateral=unilateral)
    frozen = _with(vals, dict(zip(positions + rates, z0)))
    branch = _try_branch(scene, frozen, signs)
    if start == "slow" and branch is None:
        raise NumericsError("start='slow' needs a consistent equilibrium u* at the initial state; none was found.")
    N_scale = _reaction_scale(scene, frozen, branch)
    u_star = None if branch is None else [float(substitute(u, frozen)) for u in branch.u_star]
    gaps = _contact_gaps(scene, system, vals, z0, eps, span[0])
    if start == "slow":
        z0 = _slow_start(scene, gaps, vals, laws, u_star, z0, eps)
    scale, gap_scale, fast_squared = _full_scales(system, gaps, z0, N_scale, u_star, span)
    gap_noise = _gap_noise(gaps.exprs, positions, z0)
    if np.any(gap_noise > gap_scale):
        j = int(np.argmax(gap_noise / gap_scale))
        raise NumericsError(
            f"at eps = {eps:g} the deformation of contact {j + 1} (about {gap_scale[j]:.1e}) is lost in the "
            f"rounding of its gap {gaps.exprs[j]} (about {gap_noise[j]:.1e} with a safety margin) in these "
            "coordinates; use a larger eps (the reduced system is then the answer to this accuracy) or "
            "write the scene with the gap as a coordinate."
        )
    if atol is None:
        atol = np.maximum(
            rtol * scale, _roundoff_floor(gap_noise, len(positions), gaps.determined, gaps.Dg, fast_squared)
        )
    run = integrate_with_impact_bound(
        system,
        span,
        z0,
        reaction_scale=N_scale,
        reaction_bound=reaction_bound,
        bound_factor=bound_factor,
        equilibrium=None if branch is None else branch.signs,
        extra={"eps": eps, "atol": atol},
        method=method,
        jacobian=jacobian,
        rtol=rtol,
        atol=atol,
        t_eval=t_eval,
        dense_output=dense_output,
        max_rhs=max_rhs,
        progress=progress,
        max_seconds=max_seconds,
    )
    if branch is None and run.status == "impact":
        run = replace(run, extra={**run.extra, "no_equilibrium": True})
    return stop_where_sliding_stops(scene, vals, run)


def _rigid_start(scene, vals: NumericValues, initial) -> tuple[NumericValues, np.ndarray]:
    """The values with the parameters the contact manifold fixes, and the initial state on the manifold."""
    positions, rates = _coordinates(scene)
    state = positions + rates
    given = _state_values([str(s) for s in state], state, initial, f"full system of '{scene.name}'")
    for symbol in vals.numbers:
        if symbol in state:
            raise NumericsError(f"{symbol} is a state variable of the full system; give it in initial, not in values.")
    with_state = _with(vals, given)
    # parameters fixed by the contact manifold (h = l sin(phi) for the guides), from the initial state
    fixed = {}
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in vals.numbers:
            fixed[parameter] = _evaluate(expr, with_state, f"the parameter {parameter} (fixed by the contacts)")
    vals = _with(vals, fixed)
    with_state = _with(with_state, fixed)
    z0 = []
    for symbol in state:
        if symbol in given:
            z0.append(given[symbol])
        elif symbol in scene.manifold:
            z0.append(_evaluate(scene.manifold[symbol], with_state, f"the initial value of {symbol}"))
        else:
            raise NumericsError(f"give the initial value of {symbol} in initial.")
    return vals, np.array(z0, dtype=float)


@dataclass(frozen=True, eq=False)
class _Gaps:
    """The contacts' gaps g_j(positions): expressions, generated code, and at the start their Jacobian
    ``Dg`` and the stiffness ``S_j = |dN_j/dg_j|``; ``determined`` lists the coordinates they fix."""

    exprs: list
    function: Callable
    jacobian: Callable
    Dg: np.ndarray
    S: np.ndarray
    determined: list


def _contact_gaps(scene, system, vals: NumericValues, z0: np.ndarray, eps: float, t0: float) -> _Gaps:
    positions, rates = _coordinates(scene)
    determined = [i for i, (q, r) in enumerate(zip(positions, rates)) if q in scene.manifold or r in scene.manifold]
    exprs = [substitute(_plain_expr(scene, c.coordinate), vals) for c in scene.contacts]
    function = lambdify_cse(positions, exprs)
    jacobian = lambdify_cse(positions, sp.Matrix(exprs).jacobian(positions))
    n, k = len(positions), scene.k
    stiffness = np.abs(np.asarray(system.extra["law_jac"](t0, *z0), dtype=float).reshape(k, 2 * n)[:, :n])
    Dg = np.asarray(jacobian(*z0[:n]), dtype=float).reshape(k, n)
    S = np.array([max(float(np.max(np.abs(stiffness[j]) / np.maximum(np.abs(Dg[j]), 1e-300))), 0.0) for j in range(k)])
    return _Gaps(exprs, function, jacobian, Dg, np.where(S > 0, S, 1.0 / eps**2), determined)


def _slow_start(scene, gaps: _Gaps, vals: NumericValues, laws, u_star, z0: np.ndarray, eps: float) -> np.ndarray:
    """The initial state with the contacts deformed so that the reactions start at u*."""
    Qv = sp.Symbol("Q", real=True)
    targets = []
    for j in range(scene.k):
        law = _contact_law(scene, j, laws)
        N_of_Q = lambdify_cse([Qv], _law_scaled(scene, j, law, vals, Qv, sp.S.Zero))
        targets.append(
            eps**2 * _invert_law(lambda Q, f=N_of_Q: float(f(Q)), u_star[j], abs(u_star[j]) / (gaps.S[j] * eps**2))
        )
    n = gaps.Dg.shape[1]
    return _place_gaps(z0, n, gaps.determined, gaps.function, gaps.jacobian, np.array(targets))


def _full_scales(system, gaps: _Gaps, z0: np.ndarray, N_scale: float, u_star, span) -> tuple:
    """(typical magnitude of each state component, of each gap, squared fast frequency of each contact).

    The deformations are N/S, their rates N/S times the contact's fast frequency; the free
    coordinates move by their rates and accelerations over the span.
    """
    k, n = gaps.Dg.shape
    determined = gaps.determined
    _, dGdN = system.extra["acc_jac"](span[0], *z0, *system.reactions(span[0], z0))
    a = np.abs(np.diag(gaps.Dg @ np.asarray(dGdN, dtype=float).reshape(n, k)))
    gap_scale = N_scale / gaps.S
    rate_scale = gap_scale * np.sqrt(gaps.S * np.where(a > 0, a, 1.0))
    scale = np.abs(z0).copy()
    if determined:
        inverse = np.abs(np.linalg.pinv(gaps.Dg[:, determined]))
        for row, i in enumerate(determined):
            scale[i] = max(scale[i], float(inverse[row] @ gap_scale))
            scale[n + i] = max(scale[n + i], float(inverse[row] @ rate_scale))
    duration = span[1] - span[0]
    if u_star is None:
        acceleration = np.abs(system.fun(span[0], z0)[n:])
    else:
        acceleration = np.abs(np.asarray(system.extra["acc_value"](span[0], *z0, *u_star)))
    for i in range(n):
        if i not in determined:
            scale[i] = max(scale[i], abs(z0[n + i]) * duration, acceleration[i] * duration**2 / 2)
            scale[n + i] = max(scale[n + i], acceleration[i] * duration)
    top = float(scale.max(initial=0.0))
    return np.maximum(scale, 1e-12 * top if top > 0 else 1.0), gap_scale, gaps.S * a


def _gap_noise(gap_exprs, positions, z0) -> np.ndarray:
    """Rounding error of each gap in floating point, with a margin of 10^4.

    A gap such as h - l sin(phi) - y is a difference of O(1) numbers: evaluated in floating
    point it carries an error of about u (|h| + |l sin(phi)| + |y|), which the law divides
    by eps^2.
    """
    magnitude = lambdify_cse(positions, [sp.Add(*[sp.Abs(t) for t in sp.Add.make_args(g)]) for g in gap_exprs])
    return 1e4 * _UNIT * np.abs(np.asarray(magnitude(*z0[: len(positions)]), dtype=float)).reshape(-1)


def _roundoff_floor(gap_noise, n: int, determined, Dg, fast_squared) -> np.ndarray:
    """The least absolute tolerance of each state component that the gaps' rounding allows:
    asking the solver for more in the coordinates fixed by the contacts makes its steps
    collapse."""
    floor = np.zeros(2 * n)
    if not determined:
        return floor
    rate_noise = gap_noise * np.sqrt(np.where(fast_squared > 0, fast_squared, 1.0))
    inverse = np.abs(np.linalg.pinv(Dg[:, determined]))
    for row, i in enumerate(determined):
        floor[i], floor[n + i] = inverse[row] @ gap_noise, inverse[row] @ rate_noise
    return floor


def _place_gaps(z0, n, determined, gap_function, gap_jacobian, targets) -> np.ndarray:
    """Move the determined coordinates so that the gaps equal ``targets`` and their rates vanish."""
    z = np.array(z0, dtype=float)
    if len(determined) != len(targets):
        raise NumericsError("start='slow' needs as many contact-determined coordinates as contacts.")
    for _ in range(50):
        g = np.asarray(gap_function(*z[:n]), dtype=float) - targets
        D = np.asarray(gap_jacobian(*z[:n]), dtype=float).reshape(len(targets), n)
        step = np.linalg.solve(D[:, determined], g)
        z[determined] -= step
        if np.all(np.abs(step) <= 4 * _UNIT * np.maximum(np.abs(z[determined]), np.abs(targets).max(initial=0))):
            break
    D = np.asarray(gap_jacobian(*z[:n]), dtype=float).reshape(len(targets), n)
    free = [i for i in range(n) if i not in determined]
    rhs = -D[:, free] @ z[n:][free] if free else np.zeros(len(targets))
    z[[n + i for i in determined]] = np.linalg.solve(D[:, determined], rhs)
    return z
