"""Periodic orbits of the fast subsystem (2.1) by shooting, continued along a parameter.

A cycle of period T is a fixed point of the flow map over one period: with the time scaled to
``s = tau / T`` in [0, 1], the state z(s) solves ``z' = T F(z)``, and the unknowns
(z(0), T) solve ``z(1) - z(0) = 0`` with the phase fixed by ``V_1(0) = 0`` (the Poincaré
section of :func:`contactsym.numerics.fast_cycle`). Newton's method needs the monodromy
matrix ``dz(1)/dz(0)``, integrated with the state from the variational equations
``Phi' = T J(z) Phi`` (J generated analytically), and ``dz(1)/dT = F(z(1))``. The monodromy
of the converged cycle gives its Floquet multipliers: one is 1 (the phase), the cycle is stable
when the others lie inside the unit circle.

The field (:mod:`contactsym.numerics.generated_field`) is generated once per scene and laws with
the parameters as arguments (the scaled deformations ``Q_j`` and rates ``V_j`` of
:func:`contactsym.numerics.fast_system`, unilateral contacts cut to N = 0 where they open), so a batch of points on a grid is integrated as one
system by :func:`scipy.integrate.solve_ivp`: the cost of a Newton step is shared by the batch.
Continuation along a grid line starts each point from its neighbour's cycle.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp

from ..errors import NumericsError
from .generated_field import FastField, fast_field
from .values import numeric_values

__all__ = ["FastField", "Orbits", "equilibria", "fast_field", "hopf_guess", "periodic_orbit", "sample_orbits", "shoot"]


@dataclass(frozen=True, eq=False)
class Orbits:
    """Cycles found by :func:`shoot`, one row per point of the batch.

    Attributes
    ----------
    converged : ndarray of bool
        Newton's method met its tolerance.
    start : ndarray (M, 2k)
        A state on the cycle, on the section ``V_1 = 0`` (upward crossing for a cycle that turns that way).
    period : ndarray (M,)
        The period in the stretched time tau.
    multipliers : ndarray (M, 2k) complex
        The Floquet multipliers (eigenvalues of the monodromy matrix), largest modulus first,
        the trivial one (nearest 1) last.
    residual : ndarray (M,)
        ``max |z(T) - z(0)| / scale`` at the last step (relative to the state's scales).
    iterations : int
        Newton steps taken by the batch.
    contact_loss : ndarray of bool
        A contact opened on the way (N = 0): the point is given up, the field has a kink there.
    """

    converged: np.ndarray
    start: np.ndarray
    period: np.ndarray
    multipliers: np.ndarray
    residual: np.ndarray
    iterations: int
    contact_loss: np.ndarray

    @property
    def leading_multiplier(self) -> np.ndarray:
        """The largest modulus among the nontrivial multipliers: < 1 for a stable cycle."""
        return np.abs(self.multipliers[:, 0])


def _flow(field: FastField, z0, T, p, *, variational: bool, rtol: float, scale, samples=None, stop_on_opening=False):
    """z(1) (and the monodromy) of ``z' = T F(z)`` for a batch, as one system for solve_ivp; with
    ``stop_on_opening``, also which points saw a contact open (their integration is stopped there)."""
    M, n = z0.shape
    width = n + n * n if variational else n

    opened = np.zeros(M, dtype=bool)

    def fun(s, y):
        Y = y.reshape(M, width)
        z = Y[:, :n].T
        out = np.empty_like(Y)
        if not variational:
            out[:, :n] = (T * field.rhs(z, p)).T
            return out.ravel()
        rhs, J = field.rhs_and_jac(z, p)
        if stop_on_opening:  # the field has a kink where a contact opens: such a point stops (frozen) here
            opened[field.opened(z, p)] = True
        out[:, :n] = (T * rhs).T
        out[:, n:] = (T[:, None, None] * (J @ Y[:, n:].reshape(M, n, n))).reshape(M, n * n)
        out[opened] = 0.0
        return out.ravel()

    y0 = z0 if not variational else np.hstack([z0, np.tile(np.eye(n).ravel(), (M, 1))])
    atol = (
        np.tile(np.concatenate([rtol * scale, np.full(width - n, rtol)]), M)
        if variational
        else np.tile(rtol * scale, M)
    )
    t_eval = None if samples is None else np.linspace(0.0, 1.0, samples, endpoint=False)
    run = solve_ivp(fun, (0.0, 1.0), y0.ravel(), method="DOP853", rtol=rtol, atol=atol, t_eval=t_eval)
    if not run.success:
        raise NumericsError(f"the shooting integration failed: {run.message}")
    if samples is not None:
        return run.y.reshape(M, width, -1)
    end = run.y[:, -1].reshape(M, width)
    return end[:, :n], (end[:, n:].reshape(M, n, n) if variational else None), opened


def shoot(
    field: FastField,
    p,
    start: np.ndarray,
    period: np.ndarray,
    *,
    scale: np.ndarray | None = None,
    tol: float = 1e-9,
    rtol: float = 1e-10,
    max_steps: int = 12,
) -> Orbits:
    """Newton's method for a batch of cycles of ``field`` from guesses ``start`` (M, 2k) and ``period`` (M,).

    ``p`` holds the parameters (arrays of length M or numbers) in the order of ``field.params``;
    ``scale`` (2k,) the typical size of each state component (default: ones). The phase is fixed
    by ``V_1 = 0`` at the start. Points that converge are frozen while the others go on.

    Examples
    --------
    A cycle of the brake with Hertz pads 1% past its Hopf line, from the normal form's guess:

    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> from contactsym.numerics import hopf_point
    >>> laws, point = {0: Hertz(), 1: Hertz()}, {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
    >>> h = hopf_point(cs.scene("brake"), {**point, "mu": 1.0}, "mu", laws=laws)
    >>> field = fast_field(cs.scene("brake"), laws=laws)
    >>> mu, p = 1.01 * h.value, [0, -4, np.pi / 2, 1, 1.01 * h.value]  # in the order of field.params
    >>> start, period = hopf_guess(h, field, p, mu)
    >>> orbits = shoot(field, p, start, period)
    >>> bool(orbits.converged[0]), bool(orbits.leading_multiplier[0] < 1), round(float(orbits.period[0]), 4)
    (True, True, 3.1309)
    """
    z = np.array(start, dtype=float, copy=True)
    T = np.array(period, dtype=float, copy=True)
    M, n = z.shape
    k = n // 2
    scale = np.ones(n) if scale is None else np.asarray(scale, dtype=float)
    p = [np.broadcast_to(np.asarray(x, dtype=float), (M,)) for x in p]
    z[:, k] = 0.0  # the phase condition V_1 = 0
    free = [i for i in range(n) if i != k]
    converged = np.zeros(M, dtype=bool)
    contact_loss = np.zeros(M, dtype=bool)
    given_up = np.zeros(M, dtype=bool)
    residual = np.full(M, np.inf)
    monodromy = np.full((M, n, n), np.nan)
    steps = 0
    for _ in range(max_steps):
        todo = np.flatnonzero(~converged & ~given_up)
        if todo.size == 0:
            break
        steps += 1
        sub = [x[todo] for x in p]
        end, Phi, opened = _flow(
            field, z[todo], T[todo], sub, variational=True, rtol=rtol, scale=scale, stop_on_opening=True
        )
        contact_loss[todo[opened]] = True
        R = end - z[todo]
        residual[todo] = np.max(np.abs(R) / scale, axis=1)
        monodromy[todo] = Phi
        done = (residual[todo] <= tol) & ~opened
        converged[todo[done]] = True
        # Newton: [(Phi - I) without column k | F(z(1))] d = -R, d = (dz without z_k, dT)
        A = Phi - np.eye(n)
        A[:, :, k] = field.rhs(end.T, sub).T  # dz(1)/dT = F(z(1))
        with np.errstate(all="ignore"):
            try:
                d = np.linalg.solve(A, -R[..., None])[..., 0]
            except np.linalg.LinAlgError:
                d = np.stack([np.linalg.lstsq(a, -r, rcond=None)[0] for a, r in zip(A, R)])
        step = ~done & np.all(np.isfinite(d), axis=1) & ~opened
        rows = todo[step]
        z[np.ix_(rows, free)] += d[step][:, free]
        T[rows] += d[step][:, k]
        lost = todo[~done & ~step]
        residual[lost] = np.nan
        converged[lost] = False
        given_up[lost] = True  # a singular Newton step or an opening contact
    bad = ~converged | ~np.isfinite(T) | (T <= 0)
    with np.errstate(all="ignore"):  # a rest state is a "cycle" of any period: refuse it
        speed = np.max(np.abs(T * field.rhs(z.T, p)).T / scale, axis=1)
    converged &= ~bad & (speed > 1e-6) & ~contact_loss
    multipliers = np.full((M, n), np.nan, dtype=complex)
    ok = np.flatnonzero(np.all(np.isfinite(monodromy), axis=(1, 2)))
    if ok.size:
        eig = np.linalg.eigvals(monodromy[ok])
        trivial = np.argmin(np.abs(eig - 1), axis=1)
        for row, values, t in zip(ok, eig, trivial):
            rest = np.delete(values, t)
            multipliers[row] = np.concatenate([rest[np.argsort(-np.abs(rest))], values[t : t + 1]])
    return Orbits(converged, z, T, multipliers, residual, steps, contact_loss)


def equilibria(field: FastField, p, guess: np.ndarray, *, tol: float = 1e-12, max_steps: int = 30) -> np.ndarray:
    """Rest states (Q*, 0) of a batch, (M, 2k), by Newton's method on ``f(N(Q, 0)) = 0`` from ``guess``."""
    z = np.array(guess, dtype=float, copy=True)
    M, n = z.shape
    k = n // 2
    z[:, k:] = 0.0
    p = [np.broadcast_to(np.asarray(x, dtype=float), (M,)) for x in p]
    for _ in range(max_steps):
        F = field.rhs(z.T, p).T[:, k:]
        if np.all(np.abs(F) <= tol * (1 + np.abs(z[:, :k]))):
            break
        J = field.jac(z.T, p)[:, k:, :k]
        with np.errstate(all="ignore"):
            step = np.linalg.solve(J, -F[..., None])[..., 0]
        z[:, :k] += np.where(np.isfinite(step), step, 0.0)
    return z


def hopf_guess(hopf, field: FastField, p, values) -> tuple[np.ndarray, np.ndarray]:
    """Starts on the section ``V_1 = 0`` and periods of the normal form's cycles at parameter ``values``.

    ``hopf`` is a :class:`~contactsym.numerics.hopf.HopfCoefficient` with its crossing
    (:func:`~contactsym.numerics.hopf_point`); the cycle ``z* + 2 r Re(q e^{i theta})`` is
    centred on the equilibrium at each value, at the phase where ``V_1`` crosses 0 upwards.
    """
    values = np.atleast_1d(np.asarray(values, dtype=float))
    M, k = values.size, field.k
    q = hopf.vectors.q
    r2 = -hopf.dalpha * (values - hopf.value) / hopf.vectors.c1.real
    r = np.sqrt(np.maximum(r2, 0.0))
    theta = -np.pi / 2 - np.angle(q[k])
    centre = equilibria(field, p, np.tile(hopf.state, (M, 1)))
    start = centre + 2 * r[:, None] * np.real(q * np.exp(1j * theta))[None, :]
    start[:, k] = 0.0
    omega = hopf.omega + hopf.vectors.c1.imag * np.maximum(r2, 0.0)
    return start, 2 * np.pi / omega


def sample_orbits(field: FastField, p, orbits: Orbits, samples: int = 512, *, rtol: float = 1e-10, scale=None):
    """States (M, 2k, samples) and reactions (M, k, samples) over one period of each converged cycle."""
    rows = np.flatnonzero(orbits.converged)
    M, n = orbits.start.shape
    states = np.full((M, n, samples), np.nan)
    reactions = np.full((M, field.k, samples), np.nan)
    if rows.size:
        scale = np.ones(n) if scale is None else np.asarray(scale, dtype=float)
        sub = [np.broadcast_to(np.asarray(x, dtype=float), (M,))[rows] for x in p]
        run = _flow(
            field,
            orbits.start[rows],
            orbits.period[rows],
            sub,
            variational=False,
            rtol=rtol,
            scale=scale,
            samples=samples,
        )
        states[rows] = run
        z = np.moveaxis(run, 0, 1).reshape(n, -1)  # (n, rows * samples), rows major
        wide = [np.repeat(x, samples) for x in sub]
        reactions[rows] = np.moveaxis(field.reactions(z, wide).reshape(field.k, rows.size, samples), 0, 1)
    return states, reactions


def periodic_orbit(
    scene, values: Mapping, start, period: float, *, laws: Mapping | None = None, unilateral=None, tol: float = 1e-9
) -> dict:
    """One cycle of the fast subsystem by shooting from a guess: state, period, multipliers, reactions.

    Examples
    --------
    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> from contactsym.numerics import hopf_point
    >>> laws, point = {0: Hertz(), 1: Hertz()}, {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
    >>> h = hopf_point(cs.scene("brake"), {**point, "mu": 1.0}, "mu", laws=laws)
    >>> cycle = periodic_orbit(cs.scene("brake"), {**point, "mu": 1.02 * h.value}, h.cycle_start(1.02 * h.value),
    ...                        2 * np.pi / h.omega, laws=laws)
    >>> cycle["converged"], cycle["stable"], round(cycle["amplitude"], 4)
    (True, True, 1.6601)
    """
    vals = numeric_values(scene, values)
    field = fast_field(scene, laws=laws, unilateral=unilateral, functions=vals.functions)
    p = field.parameter_values(vals)
    orbits = shoot(field, p, np.atleast_2d(np.asarray(start, dtype=float)), np.array([float(period)]), tol=tol)
    states, reactions = sample_orbits(field, p, orbits)
    amplitude = float(np.max(np.ptp(reactions[0], axis=1)) / 2) if orbits.converged[0] else float("nan")
    return {
        "converged": bool(orbits.converged[0]),
        "period": float(orbits.period[0]),
        "omega": float(2 * np.pi / orbits.period[0]),
        "multipliers": orbits.multipliers[0],
        "stable": bool(orbits.leading_multiplier[0] < 1),
        "states": states[0],
        "reactions": reactions[0],
        "amplitude": amplitude,
    }
