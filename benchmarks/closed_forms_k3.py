"""closed forms k=3/4: cold time of the Hopf frequency, the Hopf set and ``Scene.regions()``.

Scenes: the three-legged stool of ``tests/stool.py`` sliding and spinning on a rough floor
(k = 3) with its feet at fixed, unequal positions (4-digit rationals), mu, h and the sign
symbols symbolic, and

- ``stool-numbers``: mass and inertias numbers;
- ``stool-masses``: mass m and inertias I_1..I_3 symbolic too;
- ``stool-feet``: feet (x_j, y_j) and slip directions (c_j, d_j) symbolic as well;

and the generic scenes q_i'' = sum_j a_ij N_j + b_i for k = 3 and k = 4.

Ours is this source tree; the baseline is the main branch (``/work/main``, or
``$CONTACTSYM_BASELINE``) run by the same worker (``benchmarks/_derive_worker.py``, stage
mode, run as a script with the tree's ``contactsym`` on PYTHONPATH), both measured side by
side in one run. Each measurement is a fresh process (scene build included, import
excluded) with a time limit, ours and the baseline alternating, best of two (one with
``--quick``); a baseline that does not finish counts as the limit (the ratio is then a lower
bound). When the baseline is this very tree (the benchmark run in ``/work/main`` itself) it is not
run: the same code twice measures only noise; the rows then say so and have no baseline. The
notes give the CPU seconds too: on a loaded machine they vary less than the wall time. The plot
``closed_forms_k3.png`` shows both trees' wall times by row, with the targets, and their CPU times.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = Path(os.environ.get("CONTACTSYM_BASELINE", "/work/main"))
WORKER = Path(__file__).resolve().parent / "_derive_worker.py"

#: (scene, stage, target seconds or None): the rows, in order.
CASES = (
    ("stool-numbers", "frequency", 5.0),
    ("stool-numbers", "regions", 5.0),
    ("stool-masses", "frequency", 5.0),
    ("stool-masses", "regions", 5.0),
    ("stool-feet", "frequency", None),
    ("generic-3", "hopf", 10.0),
    ("generic-4", "hopf", 60.0),
)


def _worker(source: Path, scene: str, stage: str, timeout: float) -> dict | None:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(source)
    command = [sys.executable, str(WORKER), "stage", scene, stage]
    try:
        done = subprocess.run(command, cwd=source, env=env, capture_output=True, text=True, timeout=timeout, check=True)
    except subprocess.TimeoutExpired:
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def run(quick: bool, out_dir) -> list[dict]:
    from . import record

    limit = 120 if quick else 600
    # --quick: the stool with numbers (both stages) and generic k = 3, one run each; the symbolic masses and
    # feet and k = 4 (the long rows) in the full bench
    cases = [c for c in CASES if not (quick and c[0] in ("stool-masses", "stool-feet", "generic-4"))]
    rows, measured = [], []
    repeats = 1 if quick else 2
    # the same tree twice is no comparison (only the noise of a shared machine): then ours alone
    baseline = BASELINE.is_dir() and BASELINE.resolve() != ROOT.resolve()
    for scene, stage, target in cases:
        ours, old = [], []
        for _ in range(repeats):  # alternating, best of each: the load of a shared machine drifts
            ours.append(_worker(ROOT, scene, stage, limit))
            old.append(_worker(BASELINE, scene, stage, limit) if baseline else None)
        ours, old = _best(ours), _best(old)
        ours_s = ours["seconds"] if ours else float(limit)
        old_s = (old["seconds"] if old else float(limit)) if baseline else None
        notes = f"cold, fresh process, scene build included, best of {repeats}; time limit {limit} s; " + (
            f"baseline {BASELINE}"
            if baseline
            else f"no baseline: {BASELINE} is {'this tree' if BASELINE.is_dir() else 'missing'} (set CONTACTSYM_BASELINE)"
        )
        if target is not None:
            notes += f"; target < {target:.0f} s; within target: {ours is not None and ours_s < target}"
        if ours:
            notes += f"; CPU ours {ours['cpu_s']:.3g} s" + (f", baseline {old['cpu_s']:.3g} s" if old else "")
            notes += f"; ops ours {ours['ops']}" + (f", baseline {old['ops']}" if old else "")
        if baseline and old is None:
            notes += "; the baseline timed out: baseline_s is the limit and the ratio a lower bound"
        rows.append(record(f"closed forms/{scene} {stage}", ours_s, old_s, None, 1, notes))
        cpu = (ours["cpu_s"] if ours else float("nan"), old["cpu_s"] if old else float("nan"))
        measured.append((f"{scene}\n{stage}", ours_s, old_s if old_s is not None else float("nan"), target, *cpu))
    closed_forms_plot(measured, Path(out_dir) / "closed_forms_k3.png")
    return rows


def _best(results: list) -> dict | None:
    finished = [r for r in results if r is not None]
    return min(finished, key=lambda r: r["seconds"]) if finished else None


def closed_forms_plot(measured: list[tuple], path: Path) -> None:
    """Bars of ours and the baseline by row (log seconds): wall time with the target of each row as a
    dashed tick, and CPU time (steadier on a loaded machine)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    labels = [m[0] for m in measured]
    where = np.arange(len(measured))
    fig, axes = plt.subplots(1, 2, figsize=(2.4 * len(measured) + 2, 3.8))
    for ax, (ours, old), title in zip(axes, ((1, 2), (4, 5)), ("wall", "CPU")):
        ax.bar(where - 0.2, [m[old] for m in measured], 0.4, label="baseline (main)", color="0.7")
        ax.bar(where + 0.2, [m[ours] for m in measured], 0.4, label="ours", color="tab:blue")
        for x, m in zip(where, measured):
            if m[3] is not None and title == "wall":
                ax.hlines(m[3], x - 0.45, x + 0.45, colors="tab:red", linestyles="--")
        ax.set_yscale("log")
        ax.set_xticks(where, labels, fontsize=6)
        ax.set_ylabel(f"{title} seconds (cold, fresh process)")
        ax.set_title(f"closed forms k = 3, 4: {title} time" + (" (dashed: target)" if title == "wall" else ""))
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
