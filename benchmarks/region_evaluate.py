"""region_evaluate: points per second of ``Region.evaluate`` on 10^6 points, per scene region.

Ours: the closed-form region of ``scene.regions()`` evaluated vectorised with numpy.
Baseline: the same region decided exactly, point by point, with ``Region.contains``
(timed on a subsample and extrapolated). error = disagreements between the two on the
subsample, away from the boundary (points within 1e-9 of it are left out).
"""

from __future__ import annotations

import math
import time

import numpy as np

import contactsym as cs

from . import record

CASES = [
    ("brake", "stable for every law", {"alpha": (0.05, math.pi - 0.05), "mu": (0.0, 3.0)}),
    ("painleve-klein-guides", "stable for every law", {"kappa": (0.05, 3.0), "v_1": (-6, 6), "v_2": (-6, 6)}),
    ("painleve-klein-guides", "unstable for every law", {"kappa": (0.05, 3.0), "v_1": (-6, 6), "v_2": (-6, 6)}),
]


def _sample(rng, ranges, n):
    return {name: rng.uniform(low, high, n) for name, (low, high) in ranges.items()}


def _near_boundary(region, values, index) -> bool:
    """True when a relative nudge of 1e-9 changes the answer: too close to decide by floats."""
    point = {k: v[index] for k, v in values.items()}
    answers = {bool(region.evaluate(**{k: v * (1 + s * 1e-9) for k, v in point.items()})) for s in (-1, 0, 1)}
    return len(answers) > 1


def run(quick: bool, out) -> list[dict]:
    rng = np.random.default_rng(3)
    n, subsample = 1_000_000, (200 if quick else 2000)
    records = []
    for scene_name, region_name, ranges in CASES:
        region = cs.scene(scene_name).regions()[region_name]
        values = _sample(rng, ranges, n)
        region.evaluate(**{k: v[:10] for k, v in values.items()})  # compile once, not timed
        t0 = time.perf_counter()
        inside = region.evaluate(**values)
        ours = time.perf_counter() - t0
        t0 = time.perf_counter()
        exact = [region.contains(**{k: float(v[i]) for k, v in values.items()}) for i in range(subsample)]
        baseline = (time.perf_counter() - t0) / subsample * n
        disagreements = sum(
            1 for i in range(subsample) if exact[i] != bool(inside[i]) and not _near_boundary(region, values, i)
        )
        notes = (
            f"{scene_name}: {region_name} = {region.condition}; {n / ours:.3g} points/s vectorised; "
            f"baseline Region.contains (exact rationals) on {subsample} points, extrapolated; "
            f"fraction inside {inside.mean():.3f}"
        )
        records.append(record(f"region-evaluate/{scene_name}/{region_name}", ours, baseline, disagreements, n, notes))
    return records
