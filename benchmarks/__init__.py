"""Benchmarks of contactsym: run time against error, ours and a baseline side by side.

Run them with ``contactsym bench [--quick] [--json FILE]`` or
``python -m benchmarks.run``. Each benchmark module has ``run(quick, out_dir)``
returning records ``{"name", "ours_s", "baseline_s", "ratio", "error", "n", "notes"}``
and writes its PNG plots to ``out_dir``.
"""

BENCHMARKS = (
    "imports",
    "classification",
    "region_evaluate",
    "work_precision",
    "derivation",
    "scaling",
    "atlas",
    "robustness",
    "counts",
    "regions_k3",
    "closed_forms_k3",
    "hopf_direction",
    "squeal",
    "spatial",
    "flint",
)


def fresh_process(module: str, *args: str, timeout: float) -> dict | None:
    """Run ``python -m module args`` from the source tree; its last stdout line as JSON, or
    None when it does not finish within ``timeout`` seconds (a cold run: empty caches)."""
    import json
    import os
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    env = dict(os.environ)
    env["PYTHONPATH"] = str(root) + os.pathsep + env.get("PYTHONPATH", "")
    command = [sys.executable, "-m", module, *args]
    try:
        done = subprocess.run(command, cwd=root, env=env, capture_output=True, text=True, timeout=timeout, check=True)
    except subprocess.TimeoutExpired:
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def load_pipeline():
    """Import the modules a derivation uses: ``import contactsym`` alone loads almost nothing (its
    subpackages load on first use), so a worker that excludes the import from its timing calls this
    before starting the clock. A subpackage an older checkout (a baseline) does not have is skipped."""
    from importlib import import_module

    import contactsym

    for name in ("mechanism", "stages", "scenes", "inequalities", "robustness"):
        try:
            import_module(f"contactsym.{name}")
        except ModuleNotFoundError as error:
            if error.name != f"contactsym.{name}":
                raise
    return contactsym


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
