"""squeal: a squeal atlas from the theory (normal form, continued cycles) against simulation, per point and in accuracy.

Ours: ``atlas.quantities.squeal("mu")`` over a 40 x 40 grid around the brake's Hopf line (Hertz pads;
mu from -3% to +4% of the line at F_y = -4, F_y from -4.2 to -3.8, so that every line of the grid
crosses it): one Hopf point per line, the normal form near it (its error calibrated by one shot
cycle per line), cycles continued by shooting farther out, all lines of the chunk in one batch.
Baseline: the ``cycle`` quantity's way, ``numerics.fast_cycle`` from scratch at each point (timed on
a few points 1-2% past the line; ``--quick``: one point, cut at ``BASELINE_PERIODS_QUICK`` linear periods, a
lower bound). Accuracy: at a sample of the points where the cycle is small (no
contact loss), a long simulation of the fast subsystem from inside and outside the normal form's
cycle (0.9x and 1.1x, 2/alpha in tau: the two runs bracket the cycle), error = |ours - mean| / mean.
The normal form's own error is measured against the continued cycles at every method-3 point.
"""

from __future__ import annotations

import json
import re
import time

import numpy as np

import contactsym as cs
from contactsym import atlas, numerics
from contactsym.atlas.quantities import squeal
from contactsym.laws.library import Hertz
from contactsym.numerics.normal_form import normal_form

from . import record

LAWS = {0: Hertz(), 1: Hertz()}
#: --quick: the baseline's fast_cycle cut at this many linear periods (it converges after ~600 at 2% past the line,
#: ~15-18 CPU s on 2026-11-28): its time is then a lower bound; the full bench runs it to convergence (3000 at most)
BASELINE_PERIODS_QUICK = 300
DISC = {"m": 1, "alpha": np.pi / 2, "F_x": 0}


def _grid(side: int) -> dict:
    h = numerics.hopf_point(cs.scene("brake"), {**DISC, "F_y": -4, "mu": 1.0}, "mu", laws=LAWS)
    return {"mu": h.value * (1 + np.linspace(-0.03, 0.04, side)), "F_y": np.linspace(-4.2, -3.8, side)}


def _long_simulation(values: dict) -> tuple[float, float, float]:
    """(amplitude, half spread of the two bracketing runs, distance past the line) by long runs."""
    h = numerics.hopf_point(cs.scene("brake"), values, "mu", laws=LAWS)
    mu = values["mu"]
    alpha = abs(h.dalpha * (mu - h.value))
    duration, period = 2.0 / alpha, 2 * np.pi / h.omega
    amplitudes = []
    for factor in (0.9, 1.1):
        run = numerics.simulate_fast(
            cs.scene("brake"), values, (0, duration), initial=h.cycle_start(mu, factor), laws=LAWS,
            method="DOP853", rtol=1e-7, t_eval=np.linspace(duration - 2 * period, duration, 2000),
        )  # fmt: skip
        amplitudes.append(float(np.max(np.ptp(run.reactions, axis=1)) / 2))
    return float(np.mean(amplitudes)), abs(amplitudes[1] - amplitudes[0]) / 2, mu / h.value - 1


def _baseline_per_point(grid, count: int, periods: int = 3000) -> tuple[float, list[str]]:
    """Seconds per point of fast_cycle from scratch, on ``count`` points 1-2% past the line at F_y = -4
    (one point: 2%, where it converges fastest), at most ``periods`` linear periods each."""
    h = numerics.hopf_point(cs.scene("brake"), {**DISC, "F_y": -4, "mu": 1.0}, "mu", laws=LAWS)
    seconds, notes = [], []
    for d in np.linspace(0.01, 0.02, count) if count > 1 else [0.02]:
        started = time.process_time()
        try:
            found = numerics.fast_cycle(
                cs.scene("brake"), {**DISC, "F_y": -4.0, "mu": h.value * (1 + d)}, laws=LAWS, periods=periods
            )
            notes.append("ok" if found.converged else f"not converged in {periods} linear periods")
        except Exception as error:  # noqa: BLE001 - the baseline's failures are reported, not raised
            notes.append(type(error).__name__)
        seconds.append(time.process_time() - started)
    return float(np.median(seconds)), notes


def _normal_form_error(grid, ds) -> tuple[np.ndarray, np.ndarray]:
    """(distance past the line, relative error of the leading-order amplitude) at every continued point."""
    distances, errors, forms = [], [], {}
    for i, j in np.argwhere(ds.method.values == 3):
        F_y = float(grid["F_y"][j])
        if F_y not in forms:
            forms[F_y] = normal_form(cs.scene("brake"), {**DISC, "F_y": F_y, "mu": 1.0}, "mu", laws=LAWS)
        nf, mu = forms[F_y], float(grid["mu"][i])
        exact = float(ds.amplitude.values[i, j])
        distances.append(mu / nf.hopf.value - 1)
        errors.append(abs(float(np.max(nf.amplitude([mu])[0])) - exact) / exact)
    return np.array(distances), np.array(errors)


def run(quick: bool, out) -> list[dict]:
    side, sample, baseline_points = (16, 1, 1) if quick else (40, 32, 4)  # --quick: part of a 3-minute bench
    grid = _grid(side)
    quantity = squeal("mu", laws=LAWS, simulate=False)
    atlas.sweep("brake", quantity, {"mu": grid["mu"][:2]}, values={**DISC, "F_y": -4.0}, scheduler="sync")  # codegen
    started = time.process_time()
    ds = atlas.sweep("brake", quantity, grid, values=DISC, scheduler="sync")
    ours = (time.process_time() - started) / ds.amplitude.size
    periods = BASELINE_PERIODS_QUICK if quick else 3000
    baseline, outcomes = _baseline_per_point(grid, baseline_points, periods)
    cut = any(o != "ok" for o in outcomes) and quick
    method = ds.method.values
    unexplained = int(np.sum(np.isnan(ds.amplitude.values) & (ds.reason_code.values == 0)))
    by_method = {k: int(np.sum(method == k)) for k in (0, 1, 3)}
    loss = int(np.sum(ds.contact_loss.values == 1))
    nan_reasons = sorted({re.split("[:;]", str(r))[0] for r in json.loads(ds.attrs["reasons"]) if r})
    records = [
        record(
            f"squeal/atlas-{side}x{side}-per-point",
            ours,
            baseline,
            unexplained,
            ds.amplitude.size,
            f"brake, Hertz pads, {side} x {side} grid (mu from -3% to +4% of the line at F_y = -4, F_y from -4.2 "
            f"to -3.8: every line crosses it); CPU s per point, simulate=False; methods: {by_method[0]} stable "
            f"equilibrium, {by_method[1]} normal form, {by_method[3]} continuation, {int(np.sum(np.isnan(method)))} "
            f"NaN (reasons: {', '.join(nan_reasons) or 'none'}; {loss} points labelled contact loss); error = NaN "
            f"points without a reason; baseline = fast_cycle from scratch per point (median of {baseline_points} "
            f"point{'s 1-2%' if baseline_points > 1 else ' 2%'} past the line: {', '.join(outcomes)}); target >= 1000x"
            + (
                f"; --quick: fast_cycle cut at {periods} linear periods (it converges after ~600 there): baseline_s "
                "and the ratio are lower bounds; the full bench runs it to convergence"
                if cut
                else ""
            ),
        )
    ]
    rng = np.random.default_rng(23)
    # small cycles (no contact loss); continued ones with amplitude >= 0.5 (about 0.15% past the line): closer, the
    # long runs (2/alpha) take minutes each, and the normal form's points are all that close
    small = np.argwhere(np.isin(method, (1, 3)) & (ds.contact_loss.values == 0))
    small = small[(method[tuple(small.T)] == 1) | (ds.amplitude.values[tuple(small.T)] >= 0.5)]
    by_kind = {k: small[method[tuple(small.T)] == k] for k in (1, 3)}
    if quick:  # one continued cycle near 1% past the line (amplitude ~1.2): the normal form's points are closer,
        # and their long runs take minutes
        continued = ds.amplitude.values[tuple(by_kind[3].T)]
        picked = by_kind[3][np.argsort(np.abs(continued - 1.2))[: min(sample, len(continued))]]
    else:
        take = {1: min(len(by_kind[1]), max(1, sample // 16)), 3: 0}
        take[3] = min(len(by_kind[3]), sample - take[1])
        picked = np.concatenate([by_kind[k][rng.choice(len(by_kind[k]), take[k], replace=False)] for k in (1, 3)])
    errors, spreads, kinds, distances = [], [], [], []
    started = time.process_time()
    for i, j in picked:
        values = {**DISC, "F_y": float(grid["F_y"][j]), "mu": float(grid["mu"][i])}
        simulated, spread, distance = _long_simulation(values)
        errors.append(abs(ds.amplitude.values[i, j] - simulated) / simulated)
        spreads.append(spread / simulated)
        kinds.append(int(method[i, j]))
        distances.append(distance)
    simulation_s = (time.process_time() - started) / max(len(picked), 1)
    errors, kinds, distances = np.array(errors), np.array(kinds), np.array(distances)
    nf_d, nf_e = _normal_form_error(grid, ds)
    within = nf_d[nf_e <= 0.02]
    slope = float(np.median(nf_e / nf_d)) if nf_d.size else float("nan")

    def stats(mask) -> str:
        return f"max {errors[mask].max():.3g}, median {np.median(errors[mask]):.3g}" if mask.any() else "none"

    records.append(
        record(
            "squeal/accuracy-vs-long-simulation",
            ours,
            simulation_s,
            float(errors.max()) if errors.size else None,
            len(picked),
            f"{len(picked)} points without contact loss ({int(np.sum(kinds == 1))} normal form, "
            f"{int(np.sum(kinds == 3))} continuation; {min(distances):.4f}..{max(distances):.4f} past the line), "
            f"each against two long simulations (0.9x and 1.1x the normal form's cycle, 2/alpha in tau); relative "
            f"amplitude error: all {stats(kinds > 0)}; normal form {stats(kinds == 1)}; continuation "
            f"{stats(kinds == 3)} (target <= 0.02); the two runs' half spread: max {max(spreads):.3g}; "
            f"baseline_s = one such pair of simulations per point (CPU s)"
            + (
                "; --quick: one continued cycle, amplitude nearest 1.2 (about 1% past the line), not a random "
                "sample of >= 30 with normal-form points (the full bench)"
                if quick
                else ""
            ),
        )
    )
    records.append(
        record(
            "squeal/normal-form-error-by-distance",
            None,
            None,
            slope,
            int(nf_d.size),
            f"the leading-order amplitude sqrt(-alpha/Re c1) against the continued cycle at all {nf_d.size} method-3 "
            f"points: relative error ~ {slope:.3g} x distance past the line (median ratio); within 2% up to "
            f"{within.max() if within.size else float('nan'):.4f} past the line, "
            f"{nf_e.max() if nf_e.size else float('nan'):.3g} at {nf_d.max() if nf_d.size else float('nan'):.4f}; "
            "error = that ratio",
        )
    )
    _plot(out, nf_d, nf_e, distances, errors, kinds)
    return records


def _plot(out, nf_d, nf_e, distances, errors, kinds) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    ax.plot(100 * nf_d, 100 * nf_e, ".", ms=3, color="0.6", label="normal form vs continued cycle")
    for kind, marker, name in ((1, "o", "atlas: normal form"), (3, "s", "atlas: continuation")):
        mask = kinds == kind
        ax.plot(100 * distances[mask], 100 * errors[mask], marker, mfc="none", label=f"{name} vs long simulation")
    ax.axhline(2, color="k", lw=0.8, ls="--")
    ax.set_xlabel("distance past the Hopf line (%)")
    ax.set_ylabel("relative amplitude error (%)")
    ax.set_yscale("symlog", linthresh=0.01)
    ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(f"{out}/squeal.png", dpi=120)
    plt.close(fig)
