"""scaling: multi-link mechanisms from scene to stability, ours against today's way before it.

Ours: the contact-space derivation (Delassus matrix W^T M^-1 W by fraction-free
Faddeev–LeVerrier, the canonical rational form of several angles). Naive: the accelerations
by LU solve of the symbolic mass matrix, each expanded, then every stage with expand-based
normalization (how contactsym derived Lagrangian scenes before). Each run is a fresh process
with a time limit (from after its imports); a naive run that does not finish is reported as "did not finish in N s".
Cases: n-link chains with a frictional tip contact (n = 1..6), the stepladder (4 coordinates,
3 contacts), the paper's Lagrangian scenes. Reported: wall time from scene to Hurwitz
conditions and robust classification, and the operation counts of f, A and the conditions.

The mechanism table (:func:`mechanism_table`): chains of 1..6 links with 1..3 contacts,
rods and point masses, fully symbolic and partly numeric (masses and lengths fixed), and
the four-link, two-contact arm of ``examples/four-link-arm.toml`` (to its conditions, and in the full
bench to the whole report), against today's pipeline (a checkout named by the environment variable
``CONTACTSYM_BASELINE``).
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from . import fresh_process, record

ROOT = Path(__file__).resolve().parent.parent
TARGETS = {
    "chain n=6": 60.0,
    "chain n=3": 10.0,
    "stepladder": 30.0,
    "arm": 30.0,
    "arm-fixed": 5.0,
    "arm report": 60.0,
    "links-6-2-rods": 120.0,
    "links-6-2-points": 120.0,
    "links-6-3-rods-fixed": 60.0,
    "links-6-3-points-fixed": 60.0,
}
#: A checkout of today's pipeline to compare the mechanism table against (e.g. made by
#: ``git worktree add /tmp/base main``); without it the table has no baseline column.
BASELINE = os.environ.get("CONTACTSYM_BASELINE")
#: --quick: the naive way only for these (chain n = 1 finishes, n = 2 shows the 5 s cut); for the larger chains, the
#: brake and the guides it only ran into the cut (2026-11-28: none finished in 5 s), so --quick leaves it out
NAIVE_QUICK = ("chain-1", "chain-2")


def _in_tree(tree: Path, target: str, timeout: float, mode: str = "ours") -> dict | None:
    """The worker file of this checkout run in a fresh process on the contactsym of ``tree``."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    command = [sys.executable, str(Path(__file__).parent / "_scaling_worker.py"), mode, target]
    try:
        done = subprocess.run(command, cwd=tree, env=env, capture_output=True, text=True, timeout=timeout, check=True)
    except (subprocess.TimeoutExpired, subprocess.CalledProcessError):
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def mechanism_table(quick: bool) -> list[dict]:
    """Chains of 1..6 links with 1..3 contacts (rods and point masses, fully symbolic and with every
    mass and length fixed) and the four-link, two-contact arm: scene to Hurwitz conditions and
    robust classification, each in a fresh process with a time limit, against ``BASELINE``."""
    limit, base_limit = (60.0, 30.0) if quick else (300.0, 300.0)
    if quick:  # the arm with numbers (its target) and one symbolic chain; links-3-2-points-fixed in the full bench
        targets = ["arm-fixed", "links-2-2-rods"]
    else:
        targets = ["arm", "arm-fixed"] + [
            f"links-{n}-{c}-{kind}{suffix}"
            for n in range(1, 7)
            for c in range(1, min(3, n) + 1)
            for kind in ("rods", "points")
            for suffix in ("", "-fixed")
        ]
    records = [_mechanism_record(target, limit, base_limit) for target in targets]
    return records + [_mechanism_record(target, limit, base_limit, "report") for target in ([] if quick else ["arm"])]


def _mechanism_record(target: str, limit: float, base_limit: float, mode: str = "ours") -> dict:
    """One row: ``target`` to its Hurwitz conditions and robust classification (mode ``ours``), or to the
    whole report (mode ``report``: ``write_report``, the PDF where pdflatex is installed), against BASELINE."""
    ours = _in_tree(ROOT, target, limit, mode)
    base = _in_tree(Path(BASELINE), target, base_limit, mode) if BASELINE else None
    name = target if mode == "ours" else f"{target} report"
    if not ours:
        notes = [f"ours: not in {limit:.0f} s"]
    elif mode == "ours":
        hurwitz_cpu = ours.get("hurwitz_cpu_s", float("nan"))
        notes = [f"ours: Hurwitz {ours['hurwitz_s']:.1f} s (CPU {hurwitz_cpu:.1f} s), ops A {ours['ops_A']}"]
    else:
        notes = [f"write_report, CPU {ours['cpu_s']:.1f} s, PDF {'made' if ours['pdf'] else 'not made (no pdflatex)'}"]
    if BASELINE:
        notes.append(f"baseline: {base['seconds']:.1f} s" if base else f"baseline: not in {base_limit:.0f} s")
    if name in TARGETS:
        notes.append(f"target < {TARGETS[name]:.0f} s")
    base_s = (base["seconds"] if base else base_limit) if BASELINE else None
    return record(f"mechanisms/{name}", ours["seconds"] if ours else limit, base_s, None, None, "; ".join(notes))


#: Wall seconds a worker may take for its imports on top of its time limit (which counts from after them: at
#: load 6 on 2 cores the imports alone took ~5 s, and a 5 s limit on the whole process cut even chain n = 1).
IMPORT_SLACK = 60.0


def _worker(mode: str, target: str, timeout: float) -> dict | None:
    """One run in a fresh interpreter; None when it is not done ``timeout`` wall seconds after its imports."""
    return fresh_process("benchmarks._scaling_worker", mode, target, f"{timeout:g}", timeout=timeout + IMPORT_SLACK)


def _notes(o: dict | None, n: dict | None, ours_limit: float, naive_limit: float, naive_run: bool = True) -> str:
    parts = []
    if o:
        parts.append(f"ours: ops f {o['ops_f']}, A {o['ops_A']}, Hurwitz {o['ops_hurwitz']}")
        if "cpu_s" in o:  # wall times on a shared machine are several times the CPU times
            parts.append(f"ours CPU {o['cpu_s']:.1f} s (Hurwitz {o['hurwitz_cpu_s']:.1f} s)")
    else:
        parts.append(f"ours did not finish in {ours_limit:.0f} s")
    if n:
        parts.append(f"naive: ops f {n['ops_f']}, A {n['ops_A']}, Hurwitz {n['ops_hurwitz']}")
    elif not naive_run:
        parts.append(
            f"naive not run in --quick: it does not finish in {naive_limit:.0f} s (none of chain n >= 2, brake, guides "
            "did on 2026-11-28); the full bench runs it with a 600 s limit"
        )
    else:
        parts.append(f"naive did not finish in {naive_limit:.0f} s: baseline_s is that bound")
    return "; ".join(parts)


def run(quick: bool, out_dir) -> list[dict]:
    # --quick (under 3 minutes for the whole bench; each row a fresh interpreter, ~2 CPU s of imports): chains up to
    # n = 3 (its target), naive cut at 5 s and run only for NAIVE_QUICK; the full bench keeps the long rows (n = 5,
    # 6 and the stepladder, against their targets) and the rows that in --quick had ours alone: chain n = 4, the
    # brake and the guides (their cold derivations are also in benchmarks/derivation.py)
    ours_limit, naive_limit = (120.0, 5.0) if quick else (900.0, 600.0)
    cases = [(f"chain n={n}", f"chain-{n}", n) for n in range(1, 4 if quick else 7)]
    if not quick:
        cases += [("stepladder", "stepladder", 4), ("brake", "brake", 3), ("guides", "painleve-klein-guides", 3)]
    records, rows = [], []
    for label, target, size in cases:
        o = _worker("ours", target, ours_limit)
        naive_run = not quick or target in NAIVE_QUICK
        n = _worker("naive", target, naive_limit) if naive_run else None
        ours_s = o["seconds"] if o else ours_limit
        naive_s = (n["seconds"] if n else naive_limit) if naive_run else None
        notes = _notes(o, n, ours_limit, naive_limit, naive_run)
        if label in TARGETS:
            notes += f"; target < {TARGETS[label]:.0f} s"
        records.append(record(f"scaling/{label}", ours_s, naive_s, None, size, notes))
        rows.append((label, size, o, n, ours_s, naive_s))
    _plot(out_dir, [r for r in rows if r[0].startswith("chain")], naive_limit)
    return records + mechanism_table(quick)


def _plot(out_dir, rows, naive_limit):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    n = [r[1] for r in rows]
    left.semilogy(n, [r[4] for r in rows], "o-", label="contactsym (contact space)")
    naive_done = [(r[1], r[5]) for r in rows if r[3]]
    naive_cut = [(r[1], r[5]) for r in rows if not r[3] and r[5] is not None]
    if naive_done:
        left.semilogy(*zip(*naive_done), "s--", label="LU solve + expand")
    if naive_cut:
        left.semilogy(*zip(*naive_cut), "x", color="C1", markersize=10, label=f"naive: not done in {naive_limit:.0f} s")
    left.set_xlabel("links n")
    left.set_ylabel("scene to stability [s]")
    left.legend(fontsize=8)
    for key, style in (("ops_f", "o-"), ("ops_A", "s-"), ("ops_hurwitz", "^-")):
        points = [(r[1], r[2][key]) for r in rows if r[2]]
        if points:
            right.semilogy(*zip(*points), style, label=f"ours: {key[4:]}")
        naive_points = [(r[1], r[3][key]) for r in rows if r[3]]
        if naive_points:
            right.semilogy(*zip(*naive_points), style.replace("-", "--"), alpha=0.5, label=f"naive: {key[4:]}")
    right.set_xlabel("links n")
    right.set_ylabel("operations (sympy.count_ops)")
    right.legend(fontsize=7)
    fig.suptitle("n-link chain with a rough tip contact")
    fig.tight_layout()
    fig.savefig(Path(out_dir) / "scaling.png", dpi=110)
    plt.close(fig)
