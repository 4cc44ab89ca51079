"""Report speed (issue 23 item 3): the report's own work against the derivation it presents.

For each built-in scene, in a fresh process: the derivation (stability, regions, equilibria,
counts) is timed first; then the report's own work as ``contactsym report`` does it
(``conditions`` for the JSON, ``report_tex``, ``conditions`` again for the summary), once as
the package does it now (``conditions`` computed once and shared; the display form by cheap
rules, ``factor`` only on small numerators) and once the old way (both limits lifted:
``cancel`` and ``factor`` on every coefficient, ``conditions`` computed twice). The table gives
the report's time over the derivation's, old and new, side by side in one run.

``python -m benchmarks.report_speed`` prints the table (Markdown).
"""

from __future__ import annotations

import json
import sys
import time

from . import fresh_process

SCENES = (
    "sliding-point",
    "painleve-klein-rod",
    "painleve-klein-guides",
    "brake",
    "double-pendulum-tip",
    "painleve-rod",
    "two-leg-block",
)


def _worker(name: str, mode: str) -> None:
    import contactsym as cs
    from contactsym.report import document, summary, typesetting

    if mode == "old":
        typesetting.TIDY_NODES = typesetting.TIDY_FACTOR_WORK = float("inf")
    started = time.perf_counter()
    scene = cs.scene(name)
    scene.stability()
    scene.regions()
    _ = scene.equilibria().branches
    try:
        scene.equilibrium_counts()
    except Exception:  # a scene without counts: the report says so, as here
        pass
    derived = time.perf_counter()
    summary.conditions(scene)
    document.report_tex(scene)
    if mode == "old":
        summary._COMPUTED.clear()  # the old way: the summary computed the conditions again
    summary.summary_text(summary.conditions(scene))
    done = time.perf_counter()
    print(json.dumps({"derivation_s": derived - started, "report_s": done - derived}))


def main(timeout: float = 900) -> int:
    rows = ["| scene | derivation s | report s, old | report s, new | old / derivation | new / derivation |"]
    rows.append("|---|---|---|---|---|---|")
    totals = [0.0, 0.0, 0.0]
    for name in SCENES:
        old = fresh_process("benchmarks.report_speed", name, "old", timeout=timeout)
        new = fresh_process("benchmarks.report_speed", name, "new", timeout=timeout)
        if old is None or new is None:
            rows.append(f"| {name} | out of time ({timeout:.0f} s) | | | | |")
            continue
        derivation = (old["derivation_s"] + new["derivation_s"]) / 2
        totals[0] += derivation
        totals[1] += old["report_s"]
        totals[2] += new["report_s"]
        rows.append(
            f"| {name} | {derivation:.1f} | {old['report_s']:.1f} | {new['report_s']:.1f} | "
            f"{old['report_s'] / derivation:.2f} | {new['report_s'] / derivation:.2f} |"
        )
    d, o, n = totals
    rows.append(f"| all | {d:.1f} | {o:.1f} | {n:.1f} | {o / d:.2f} | {n / d:.2f} |")
    print("\n".join(rows))
    return 0


if __name__ == "__main__":  # pragma: no cover
    if len(sys.argv) == 3:
        _worker(sys.argv[1], sys.argv[2])
    else:
        sys.exit(main())
