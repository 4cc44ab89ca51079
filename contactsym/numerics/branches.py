"""The squeal along grid lines crossing a Hopf line: the normal form near it, continued cycles farther out.

Each line is a set of values of one parameter p at fixed other values, with its Hopf point
(:func:`contactsym.numerics.normal_form`). On the stable side the equilibrium is the answer
(method 0). On the unstable side of a supercritical line:

1. a *probe*: the farthest point where the normal form's raw error estimate ``|c1| r^2 / omega``
   is within ``tol`` (else the nearest point) is solved by shooting from the normal form's cycle
   (:func:`contactsym.numerics.continuation.shoot`); the normal form's measured error there,
   divided by its raw estimate, calibrates the estimate on the whole line (the leading error term
   grows like r^2, i.e. like the distance to the line);
2. where the calibrated estimate is within ``tol`` and the pads keep contact, the normal form
   gives amplitude and frequency (method 1, one array operation for the line);
3. the other points are continued from the probe, outwards and inwards, each Newton solve
   started from the neighbouring point's cycle extrapolated along the line (method 3). All lines
   advance together: one integration of the batch per Newton step.

Every point gets its estimated relative error, the Floquet multiplier that decides its stability
(the largest nontrivial one; for the normal form ``exp(-2 alpha T)``, for the equilibrium
``exp(Re lambda T)``) and whether the pads lose contact on the cycle.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .continuation import FastField, Orbits, hopf_guess, sample_orbits, shoot

__all__ = ["LineResult", "squeal_lines"]

STABLE, NORMAL_FORM, SIMULATION, CONTINUATION = 0, 1, 2, 3


@dataclass
class LineResult:
    """Per point of one line: amplitude, omega, method, error, contact loss, multiplier, and reasons."""

    amplitude: np.ndarray
    omega: np.ndarray
    method: np.ndarray
    error: np.ndarray
    contact_loss: np.ndarray
    multiplier: np.ndarray
    reasons: list = field(default_factory=list)
    calibration: float = float("nan")  # measured nf error / raw estimate at the probe

    @classmethod
    def empty(cls, n: int) -> LineResult:
        nan = np.full(n, np.nan)
        return cls(nan.copy(), nan.copy(), nan.copy(), nan.copy(), nan.copy(), nan.copy(), [""] * n)

    def set(self, i: int, amplitude, omega, method, error, loss, multiplier) -> None:
        self.amplitude[i], self.omega[i], self.method[i] = amplitude, omega, method
        self.error[i], self.contact_loss[i], self.multiplier[i] = error, loss, multiplier


@dataclass
class _Line:
    form: object  # NormalForm
    base: list  # parameter values of the field (numbers), the swept one included
    where: int  # index of the swept parameter in field.params
    p: np.ndarray
    result: LineResult
    chains: list = field(default_factory=list)  # lists of point indices, in continuation order
    known: list = field(default_factory=list)  # per chain: [(p, start, period)] converged so far
    calibration: float | None = None  # measured normal-form error / raw estimate, at the probe
    probe: tuple | None = None  # (index, start, period) of the probe's cycle
    pivot: int = -1  # the probe's index


def _params(field_: FastField, lines: list, values: np.ndarray) -> list:
    """The field's parameters for a batch: one entry per line of ``lines`` with the swept value of ``values``."""
    columns = np.array([line.base for line in lines], dtype=float)
    columns[:, lines[0].where] = values
    return list(columns.T)


def squeal_lines(
    field_: FastField,
    forms: list,
    bases: list,
    where: int,
    values: list,
    *,
    tol: float = 0.002,
    rtol: float = 1e-9,
    samples: int = 256,
) -> list[LineResult]:
    """The squeal on each line: ``forms[i]`` (a supercritical NormalForm), ``bases[i]`` (the field's
    parameter values on the line), ``values[i]`` (the swept parameter's values, index ``where``).

    Examples
    --------
    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> from contactsym.numerics.normal_form import normal_form
    >>> from contactsym.numerics.continuation import fast_field
    >>> laws, point = {0: Hertz(), 1: Hertz()}, {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4, "mu": 1.0}
    >>> nf = normal_form(cs.scene("brake"), point, "mu", laws=laws)
    >>> field = fast_field(cs.scene("brake"), laws=laws)
    >>> mu = nf.hopf.value * np.array([0.99, 1.001, 1.005, 1.015])
    >>> (line,) = squeal_lines(field, [nf], [[0, -4, np.pi / 2, 1, 1.0]], 4, [mu], tol=0.01)
    >>> line.method.tolist()
    [0.0, 1.0, 3.0, 3.0]
    >>> bool(np.all(line.multiplier[1:] < 1)), bool(line.amplitude[3] > line.amplitude[2] > line.amplitude[1] > 0)
    (True, True)
    """
    lines = []
    for form, base, p in zip(forms, bases, values):
        line = _Line(form, list(base), where, np.asarray(p, dtype=float), LineResult.empty(len(p)))
        lines.append(line)
        _stable_side(field_, line)
    probes = [(line, _probe(line, tol)) for line in lines]
    probes = [(line, i) for line, i in probes if i is not None]
    for line, i in probes:
        line.pivot = i
    if probes:
        _solve_probes(field_, probes, rtol, samples)
    for line in lines:
        _normal_form_points(line, tol)
    _continue(field_, [line for line in lines if line.pivot >= 0], rtol, samples)
    return [line.result for line in lines]


def _unstable(line: _Line) -> np.ndarray:
    h = line.form.hopf
    return h.dalpha * (line.p - h.value) > 0


def _stable_side(field_: FastField, line: _Line) -> None:
    h, r = line.form.hopf, line.result
    omega = line.form.omega(line.p)
    alpha = h.dalpha * (line.p - h.value)
    for i in np.flatnonzero(~_unstable(line)):
        r.set(i, 0.0, omega[i], STABLE, 0.0, 0.0, np.exp(2 * np.pi * alpha[i] / omega[i]))


def _raw_error(line: _Line) -> np.ndarray:
    return line.form.error(line.p)


def _probe(line: _Line, tol: float):
    """The farthest unstable point whose raw normal-form estimate is within tol, else the nearest one."""
    unstable = np.flatnonzero(_unstable(line))
    if unstable.size == 0:
        return None
    order = unstable[np.argsort(np.abs(line.p[unstable] - line.form.hopf.value))]
    raw = _raw_error(line)
    within = [i for i in order if raw[i] <= tol]
    return int(within[-1] if within else order[0])


def _solve_probes(field_: FastField, probes: list, rtol: float, samples: int) -> None:
    lines = [line for line, _ in probes]
    values = np.array([line.p[i] for line, i in probes])
    p = _params(field_, lines, values)
    start, period = _guesses(field_, lines, values, p)
    orbits = shoot(field_, p, start, period, rtol=rtol, scale=_scale(start))
    _record(field_, lines, [i for _, i in probes], orbits, p, rtol, samples)
    for n, (line, i) in enumerate(probes):
        if line.result.method[i] != CONTINUATION:
            continue
        line.probe = (i, orbits.start[n].copy(), float(orbits.period[n]))
        nf = np.max(line.form.amplitude(line.p[i : i + 1])[0])
        raw = _raw_error(line)[i]
        if raw > 0 and np.isfinite(nf):
            line.calibration = abs(nf - line.result.amplitude[i]) / line.result.amplitude[i] / raw
            line.result.calibration = line.calibration


def _guesses(field_: FastField, lines: list, values: np.ndarray, p: list) -> tuple[np.ndarray, np.ndarray]:
    starts, periods = [], []
    for n, (line, value) in enumerate(zip(lines, values)):
        s, T = hopf_guess(line.form.hopf, field_, [x[n : n + 1] for x in p], value)
        starts.append(s[0])
        periods.append(T[0])
    return np.array(starts), np.array(periods)


def _scale(start: np.ndarray) -> np.ndarray:
    return np.maximum(np.max(np.abs(start), axis=0), 1e-3 * max(np.max(np.abs(start)), 1e-12))


def _record(field_: FastField, lines: list, index: list, orbits: Orbits, p: list, rtol: float, samples: int) -> None:
    """Amplitude, omega, stability and contact loss of the shot cycles into their lines."""
    _, reactions = sample_orbits(field_, p, orbits, samples, rtol=rtol, scale=_scale(orbits.start))
    multiplier = orbits.leading_multiplier
    for n, (line, i) in enumerate(zip(lines, index)):
        r = line.result
        if orbits.contact_loss[n]:
            r.contact_loss[i] = 1.0
            r.reasons[i] = "contact loss: a pad opens (N = 0) on the way to this cycle; the shooting stops at that kink"
            continue
        if not orbits.converged[n]:
            r.reasons[i] = "continuation: Newton's method did not converge to a cycle (shooting)"
            continue
        if not multiplier[n] < 1:
            r.reasons[i] = f"continuation: the cycle found is unstable (Floquet multiplier |mu| = {multiplier[n]:.6g})"
            continue
        N = reactions[n]
        scale = max(float(np.max(np.abs(N))), 1e-300)
        amplitude = float(np.max(np.ptp(N, axis=1)) / 2)
        loss = float(np.any(np.min(N, axis=1) <= 1e-9 * scale))
        # the sampled extremes miss at most (pi/samples)^2/2 of a smooth peak; the integration ~ 100 rtol
        error = max((np.pi / samples) ** 2 / 2, 100 * rtol, float(orbits.residual[n]))
        r.set(i, amplitude, 2 * np.pi / orbits.period[n], CONTINUATION, error, loss, multiplier[n])
        r.reasons[i] = ""


def _normal_form_points(line: _Line, tol: float) -> None:
    """Method 1 where the calibrated estimate is within tol; the rest into continuation chains."""
    r, form, h = line.result, line.form, line.form.hopf
    unstable = np.flatnonzero(_unstable(line) & np.isnan(r.method))
    if unstable.size == 0:
        return
    calibration = line.calibration
    raw = _raw_error(line)
    amplitude = form.amplitude(line.p)
    lost = np.any(amplitude >= h.u_star, axis=-1)
    omega = form.omega(line.p)
    alpha = h.dalpha * (line.p - h.value)
    rest = []
    for i in unstable:
        estimate = raw[i] * calibration if calibration is not None else np.inf
        if estimate <= tol and not lost[i]:
            r.set(
                i, np.max(amplitude[i]), omega[i], NORMAL_FORM, estimate, 0.0, np.exp(-4 * np.pi * alpha[i] / omega[i])
            )
        else:
            rest.append(i)
    distance = np.abs(line.p - h.value)
    pivot = line.pivot
    outward = sorted([i for i in rest if distance[i] > distance[pivot]], key=lambda i: distance[i])
    inward = sorted([i for i in rest if distance[i] < distance[pivot]], key=lambda i: -distance[i])
    line.chains = [[pivot, *outward], [pivot, *inward]]  # each chain starts at the probe, already solved
    seed = [] if line.probe is None else [(line.p[pivot], line.probe[1], line.probe[2])]
    line.known = [list(seed), list(seed)]


def _continue(field_: FastField, lines: list, rtol: float, samples: int) -> None:
    """Advance every chain of every line one point per round, all points of a round in one batch."""
    step = 1
    while True:
        batch = []
        for line in lines:
            for c, chain in enumerate(line.chains):
                if step >= len(chain):
                    continue
                if c == 0 and line.result.contact_loss[chain[step - 1]] == 1:
                    # outwards the cycle only grows: once a pad opens, it opens farther out too
                    line.result.contact_loss[chain[step]] = 1.0
                    line.result.reasons[chain[step]] = (
                        "contact loss: beyond a point of this line where a pad opens on the cycle"
                    )
                    continue
                batch.append((line, c, chain[step]))
        if not batch and all(step >= len(chain) for line in lines for chain in line.chains):
            return
        if not batch:
            step += 1
            continue
        blines = [b[0] for b in batch]
        values = np.array([line.p[i] for line, _, i in batch])
        p = _params(field_, blines, values)
        nf_start, nf_period = _guesses(field_, blines, values, p)
        start, period = nf_start.copy(), nf_period.copy()
        for n, (line, c, _) in enumerate(batch):
            previous = line.known[c]
            near = previous and abs(values[n] - previous[-1][0]) <= abs(previous[-1][0] - line.form.hopf.value)
            if len(previous) >= 2 and near:  # secant predictor along the line
                (p0, s0, T0), (p1, s1, T1) = previous[-2], previous[-1]
                w = (values[n] - p1) / (p1 - p0)
                start[n], period[n] = s1 + w * (s1 - s0), T1 + w * (T1 - T0)
            elif near:  # the neighbour's cycle; a far one (in units of its distance to the line) is worse than the nf
                start[n], period[n] = previous[-1][1], previous[-1][2]
        orbits = shoot(field_, p, start, period, rtol=rtol, scale=_scale(start))
        retry = np.flatnonzero(~orbits.converged)
        if retry.size:  # from the normal form's cycle instead
            sub = [x[retry] for x in p]
            again = shoot(field_, sub, nf_start[retry], nf_period[retry], rtol=rtol, scale=_scale(nf_start[retry]))
            for name in ("converged", "start", "period", "multipliers", "residual", "contact_loss"):
                getattr(orbits, name)[retry] = getattr(again, name)
        _record(field_, blines, [i for _, _, i in batch], orbits, p, rtol, samples)
        for n, (line, c, i) in enumerate(batch):
            if line.result.method[i] == CONTINUATION:
                line.known[c].append((values[n], orbits.start[n].copy(), float(orbits.period[n])))
        step += 1
