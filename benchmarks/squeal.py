"""squeal: a squeal atlas from the Hopf normal form against simulation, per point and in accuracy.

Ours: ``atlas.quantities.squeal("mu")`` over a 40 x 40 grid (mu across the Hopf line, F_y) of the
brake with Hertz pads: one Hopf point per grid line (``numerics.normal_form``), then amplitude,
frequency and the estimated error of every point of the line in array operations. Baseline:
the ``cycle`` quantity's way, ``numerics.fast_cycle`` from scratch at each point (timed on a
few points past the line). Accuracy: at a sample of the points the normal form gave, a long
simulation of the fast subsystem from inside and outside the predicted cycle (0.8x and 1.2x,
1.5/alpha in tau: the two runs bracket the cycle), error = |predicted - mean| / mean.
"""

from __future__ import annotations

import json
import time

import numpy as np

import contactsym as cs
from contactsym import atlas, numerics
from contactsym.atlas.quantities import squeal
from contactsym.laws.library import Hertz

from . import record

LAWS = {0: Hertz(), 1: Hertz()}
DISC = {"m": 1, "alpha": np.pi / 2, "F_x": 0}


def _grid(side: int) -> dict:
    h = numerics.hopf_point(cs.scene("brake"), {**DISC, "F_y": -4, "mu": 1.0}, "mu", laws=LAWS)
    return {"mu": h.value * (1 + np.linspace(-0.01, 0.02, side)), "F_y": np.linspace(-4.4, -3.6, side)}


def _long_simulation(values: dict) -> tuple[float, float]:
    """Reaction amplitude of the cycle by two long runs that bracket it, and their spread."""
    h = numerics.hopf_point(cs.scene("brake"), values, "mu", laws=LAWS)
    mu = values["mu"]
    duration, period = 1.5 / abs(h.dalpha * (mu - h.value)), 2 * np.pi / h.omega
    amplitudes = []
    for factor in (0.8, 1.2):
        run = numerics.simulate_fast(
            cs.scene("brake"), values, (0, duration), initial=h.cycle_start(mu, factor), laws=LAWS,
            method="DOP853", rtol=1e-6, t_eval=np.linspace(duration - 2 * period, duration, 1000),
        )  # fmt: skip
        amplitudes.append(float(np.max(np.ptp(run.reactions, axis=1)) / 2))
    return float(np.mean(amplitudes)), abs(amplitudes[1] - amplitudes[0]) / 2


def _baseline_per_point(grid, count: int) -> tuple[float, list[str]]:
    """Seconds per point of fast_cycle from scratch, on ``count`` points 1-2% past the line."""
    seconds, notes = [], []
    for mu in np.quantile(grid["mu"][grid["mu"] > grid["mu"].mean()], np.linspace(0.2, 1, count)):
        started = time.process_time()
        try:
            found = numerics.fast_cycle(cs.scene("brake"), {**DISC, "F_y": -4.0, "mu": float(mu)}, laws=LAWS)
            notes.append("ok" if found.converged else "no convergence")
        except Exception as error:  # noqa: BLE001 - the baseline's failures are reported, not raised
            notes.append(type(error).__name__)
        seconds.append(time.process_time() - started)
    return float(np.median(seconds)), notes


def run(quick: bool, out) -> list[dict]:
    side, sample, baseline_points = (20, 4, 1) if quick else (40, 30, 4)  # --quick: part of a 3-minute bench
    grid = _grid(side)
    atlas.sweep("brake", squeal("mu", laws=LAWS, simulate=False), {"mu": grid["mu"][:2]}, values={**DISC, "F_y": -4.0})
    started = time.process_time()
    ds = atlas.sweep("brake", squeal("mu", laws=LAWS, simulate=False), grid, values=DISC, scheduler="sync")
    ours = (time.process_time() - started) / ds.amplitude.size
    baseline, outcomes = _baseline_per_point(grid, baseline_points)
    method = ds.method.values
    unexplained = int(np.sum(np.isnan(ds.amplitude.values) & (ds.reason_code.values == 0)))
    by_method = {int(k): int(np.sum(method == k)) for k in (0, 1)}
    nan_reasons = sorted({str(r).split(";")[0] for r in json.loads(ds.attrs["reasons"]) if r})
    records = [
        record(
            f"squeal/atlas-{side}x{side}-per-point",
            ours,
            baseline,
            unexplained,
            ds.amplitude.size,
            f"brake, Hertz pads, {side} x {side} grid (mu from -1% to +2% of the line, F_y); CPU s per point; "
            f"methods: {by_method[0]} stable equilibrium, {by_method[1]} normal form, "
            f"{int(np.sum(np.isnan(method)))} NaN (reasons: {', '.join(nan_reasons) or 'none'}); "
            f"error = NaN points without a reason; baseline = fast_cycle from scratch per point "
            f"(median of {baseline_points} points 1-2% past the line: {', '.join(outcomes)}); target >= 1000x",
        )
    ]
    normal = np.argwhere(method == 1)
    rng = np.random.default_rng(23)
    picked = normal[rng.choice(len(normal), min(sample, len(normal)), replace=False)]
    errors, estimates = [], []
    started = time.process_time()
    for i, j in picked:
        values = {**DISC, "F_y": float(grid["F_y"][j]), "mu": float(grid["mu"][i])}
        simulated, _ = _long_simulation(values)
        errors.append(abs(ds.amplitude.values[i, j] - simulated) / simulated)
        estimates.append(float(ds.error.values[i, j]))
    simulation_s = (time.process_time() - started) / max(len(picked), 1)
    errors = np.array(errors)
    past = [float(ds.amplitude.values[i, j]) for i, j in normal]
    records.append(
        record(
            "squeal/normal-form-accuracy",
            ours,
            simulation_s,
            float(errors.max()) if errors.size else None,
            len(picked),
            f"{len(picked)} of the {len(normal)} normal-form points, against two long simulations each "
            f"(0.8x and 1.2x the predicted cycle, 1.5/alpha in tau); relative amplitude error max "
            f"{errors.max():.3g}, median {np.median(errors):.3g} (target <= 0.02); error / estimate |c1| r^2/omega: "
            f"median {np.median(errors / np.maximum(estimates, 1e-300)):.3g}, max "
            f"{np.max(errors / np.maximum(estimates, 1e-300)):.3g} (default tol 0.002 on the estimate); "
            f"amplitudes {min(past):.3g}..{max(past):.3g}; baseline_s = one such simulation per point (CPU s)",
        )
    )
    return records
