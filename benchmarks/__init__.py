"""Benchmarks of contactsym: run time against error, ours and a baseline side by side.

Run them with ``contactsym bench [--quick] [--json FILE]`` or
``python -m benchmarks.run``. Each benchmark module has ``run(quick, out_dir)``
returning records ``{"name", "ours_s", "baseline_s", "ratio", "error", "n", "notes"}``
and writes its PNG plots to ``out_dir``.
"""

BENCHMARKS = (
    "classification",
    "region_evaluate",
    "work_precision",
    "derivation",
    "scaling",
    "atlas",
    "robustness",
    "counts",
    "regions_k3",
)


def record(name, ours_s, baseline_s, error, n, notes) -> dict:
    """One JSON record; ratio = baseline_s / ours_s (how many times faster ours is)."""
    ratio = baseline_s / ours_s if ours_s and baseline_s is not None else None
    return {
        "name": name,
        "ours_s": ours_s,
        "baseline_s": baseline_s,
        "ratio": ratio,
        "error": error,
        "n": n,
        "notes": notes,
    }
