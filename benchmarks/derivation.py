"""derivation: cold time of the whole symbolic chain, ours against the naive SymPy way.

Each case runs in a fresh Python process (scenes are cached by ``cs.scene``; a fresh
process also empties SymPy's caches). Ours: scene build, fast subsystem, equilibria,
linearization and characteristic polynomial from the principal minors of A, Hurwitz
conditions (Liénard–Chipart, fraction-free), robust classification, Hopf set and Hopf
frequency. Naive: the same scene and A, then ``(lambda I - M).det()`` of the 2k x 2k
matrix (4.5), ``expand``, and every Hurwitz minor by Berkowitz, expanded. Generic k
contacts: q_i'' = sum_j a_ij N_j + b_i with every a_ij symbolic and generic laws.
The import of contactsym is excluded from both and reported in the notes.
"""

from __future__ import annotations

from pathlib import Path

from . import fresh_process, record

ROOT = Path(__file__).resolve().parent.parent
PAPER_SCENES = ("sliding-point", "painleve-klein-rod", "painleve-klein-guides", "brake")
NAIVE_QUICK = ("painleve-klein-guides", "brake")


def _worker(mode: str, target: str, timeout: float, *extra: str) -> dict | None:
    return fresh_process("benchmarks._derive_worker", mode, target, *extra, timeout=timeout)


def run(quick: bool, out_dir) -> list[dict]:
    records, bars = [], []
    # --quick (under 3 minutes in all): the generic k = 3 ours alone (each row a fresh interpreter, ~2 CPU s of
    # imports); k = 1, 2 (hundredths and tenths of a second both ways), the naive k = 3 (minutes) and both k = 4
    # rows are for the full bench
    naive_timeout = {1: 60, 2: 60, 3: None if quick else 900, 4: None if quick else 900}
    ours_timeout = 120 if quick else 900
    total_ours = 0.0
    for name in PAPER_SCENES:
        o = _worker("ours", name, ours_timeout)
        # --quick: the naive way for the two scenes where it is slower (each row a fresh interpreter)
        n = _worker("naive", name, 120) if not quick or name in NAIVE_QUICK else None
        total_ours += o["seconds"]
        records.append(
            record(
                f"derivation/{name}",
                o["seconds"],
                n["seconds"] if n else None,
                (0 if n["agree"] else 1) if n else None,
                1,
                f"cold, fresh process; {o['conditions']} Hurwitz conditions; import {o['import_s']:.2f} s excluded; "
                + (
                    "error = 1 if the naive characteristic polynomial differed"
                    if n
                    else "naive not run in --quick (the full bench runs it)"
                ),
            )
        )
        timed_out = n is None and (not quick or name in NAIVE_QUICK)
        bars.append((name, o["seconds"], n["seconds"] if n else (120.0 if timed_out else None), timed_out))
    records.append(record("derivation/paper-scenes-total", total_ours, None, 0, 4, "target: under 10 s in total"))
    for k in (3,) if quick else (1, 2, 3, 4):
        o = _worker("ours", f"generic-{k}", ours_timeout)
        timeout = naive_timeout[k]
        n = _worker("naive", f"generic-{k}", timeout) if timeout else None
        notes = f"generic k = {k}: A = (a_ij) all symbolic, generic Phi_j, Psi_j"
        if o is None:
            notes += f"; ours timed out at {ours_timeout} s"
        if timeout and n is None:
            notes += f"; naive timed out at {timeout} s: baseline_s is that bound and the ratio a lower bound"
        if not timeout:
            notes += "; naive not run in --quick (minutes; the full bench runs it with a 900 s limit)"
        ours_s = o["seconds"] if o else float(ours_timeout)
        baseline_s = n["seconds"] if n else (float(timeout) if timeout else None)
        error = (0 if n["agree"] else 1) if n else None
        records.append(record(f"derivation/generic-k{k}", ours_s, baseline_s, error, 1, notes))
        bars.append((f"generic k={k}", ours_s, baseline_s, bool(timeout) and n is None))
    _plot(out_dir, bars)
    return records


def _plot(out_dir, bars):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, ax = plt.subplots(figsize=(8, 4.2))
    positions = np.arange(len(bars))
    ours = [b[1] for b in bars]
    naive = [b[2] if b[2] is not None else np.nan for b in bars]
    ax.bar(positions - 0.2, ours, 0.4, label="contactsym (principal minors, generic Hurwitz minors)")
    ax.bar(positions + 0.2, naive, 0.4, label="naive: det(lambda I - M), expand, Berkowitz minors")
    for position, bar in zip(positions, bars):
        if bar[3]:
            ax.annotate(f"timed out: > {bar[2]:.0f} s", (position + 0.2, bar[2]), ha="center", va="bottom", fontsize=7)
        elif bar[2] is None:
            ax.annotate("not run", (position + 0.2, bar[1]), ha="center", va="bottom", fontsize=7)
    ax.set_yscale("log")
    ax.set_xticks(positions, [b[0] for b in bars], rotation=20, ha="right")
    ax.set_ylabel("cold time [s] (log scale)")
    ax.set_title("Derivation chain, cold, one fresh process per bar")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out_dir / "derivation.png", dpi=110)
    plt.close(fig)
