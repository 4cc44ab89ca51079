"""Report speed (issue 23 item 3): the report's own work against the derivation it presents.

For each built-in scene, in a fresh process with the pipeline, the report and the plotting modules
imported before the clock (imports are the ``imports`` benchmark's): the derivation (stability,
regions, equilibria, counts) is timed first; then the report's own work as ``contactsym report``
does it (``conditions`` for the JSON, ``report_tex``, ``conditions`` again for the summary), once
as the package does it now (``conditions`` computed once and shared; the display form by cheap
rules, ``factor`` only on small numerators) and once the old way (both limits lifted: ``cancel``
and ``factor`` on every coefficient, ``conditions`` computed twice). A third process times the
whole report as ``write_report(pdf=False)`` writes it: the LaTeX, the JSON, the summary and the
figures (pdflatex is not timed: it is not this package's work). Times are CPU seconds of the
worker (``time.process_time``: the work is single-threaded, so on a quiet machine it is its wall
time, and on a shared one it does not count the other jobs). The table gives each report's time
over the derivation's, side by side in one run.

``python -m benchmarks.report_speed`` prints the table (Markdown).
"""

from __future__ import annotations

import json
import sys
import time

from . import fresh_process


def _derive(scene) -> None:
    """Everything the report presents, derived: stability, regions, equilibria, counts."""
    scene.stability()
    scene.regions()
    _ = scene.equilibria().branches
    try:
        scene.equilibrium_counts()
    except Exception:  # a scene without counts: the report says so, as here
        pass


def _worker(name: str, mode: str) -> None:
    import tempfile
    from pathlib import Path

    import contactsym as cs
    from contactsym import plotting  # noqa: F401  (imported before the clock, as the pipeline)
    from contactsym.report import build, document, summary, typesetting

    from . import load_pipeline

    load_pipeline()
    if mode == "old":
        typesetting.TIDY_NODES = typesetting.TIDY_FACTOR_WORK = float("inf")
    started = time.process_time()
    scene = cs.scene(name)
    _derive(scene)
    derived = time.process_time()
    if mode == "whole":
        with tempfile.TemporaryDirectory() as folder:
            build.write_report(scene, Path(folder) / "report", pdf=False)
    else:
        summary.conditions(scene)
        document.report_tex(scene)
        if mode == "old":
            summary._COMPUTED.clear()  # the old way: the summary computed the conditions again
        summary.summary_text(summary.conditions(scene))
    done = time.process_time()
    print(json.dumps({"derivation_s": derived - started, "report_s": done - derived}))


def main(timeout: float = 900) -> int:
    from contactsym.scenes import scene_names

    rows = [
        "| scene | derivation s | report s, old | report s, new | whole report s | old / derivation "
        "| new / derivation | whole / derivation |"
    ]
    rows.append("|---|---|---|---|---|---|---|---|")
    totals = [0.0, 0.0, 0.0, 0.0]
    for name in scene_names():
        runs = [
            fresh_process("benchmarks.report_speed", name, mode, timeout=timeout) for mode in ("old", "new", "whole")
        ]
        if any(run is None for run in runs):
            rows.append(f"| {name} | out of time ({timeout:.0f} s) | | | | | | |")
            continue
        derivation = sum(run["derivation_s"] for run in runs) / len(runs)
        times = [derivation] + [run["report_s"] for run in runs]
        totals = [total + t for total, t in zip(totals, times)]
        rows.append(_row(name, times))
    rows.append(_row("all", totals))
    print("\n".join(rows))
    return 0


def _row(name: str, times: list[float]) -> str:
    derivation, *reports = times
    return (
        f"| {name} | {derivation:.2f} | "
        + " | ".join(f"{t:.2f}" for t in reports)
        + " | "
        + " | ".join(f"{t / derivation:.2f}" for t in reports)
        + " |"
    )


if __name__ == "__main__":  # pragma: no cover
    if len(sys.argv) == 3:
        _worker(sys.argv[1], sys.argv[2])
    else:
        sys.exit(main())
