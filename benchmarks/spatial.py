"""spatial: the spatial scenes from their scene files, to the derivation and to the report.

For ``examples/painleve-rod-3d.toml`` and ``examples/stool-3d.toml``, each in a fresh process
with a time limit: read the file and derive the stability, the regions and (for numbers) the
robust classification; and, in another fresh process, read the file and write the whole report
(``write_report``, the PDF too where pdflatex is installed). Target: the report in < 60 s each
(issue 22). ``--quick`` times the report alone (the separate derivation runs took about a quarter of
the module's CPU time). There is no baseline: before scene files took ``dimensions = 3`` these
scenes could be stated only in Python. A row that does not finish reports its time limit.

``python -m benchmarks.spatial`` prints the table (Markdown).
"""

from __future__ import annotations

import json
import sys
import tempfile
import time
from pathlib import Path

from . import fresh_process, record

ROOT = Path(__file__).resolve().parent.parent
FILES = {"painleve-rod-3d": ROOT / "examples" / "painleve-rod-3d.toml", "stool-3d": ROOT / "examples" / "stool-3d.toml"}
TARGET = 60.0


def _worker(name: str, mode: str) -> None:
    import contactsym as cs

    started = time.perf_counter()
    scene = cs.load_scene(FILES[name])
    if mode == "derive":
        scene.stability()
        scene.regions()
        signs = scene.sign_patterns()[0]
        values = {s: 1 for s in scene.linearization(signs=signs).A.free_symbols}
        if values and scene.k > 1:  # the robust classification needs numbers: all parameters at 1
            from contactsym.robustness.classify import decide_robustness

            decide_robustness(scene.linearization(signs=signs).A.xreplace(values))
    else:
        from contactsym.report import write_report

        with tempfile.TemporaryDirectory() as directory:
            write_report(scene, Path(directory) / name)
    print(json.dumps({"seconds": time.perf_counter() - started}))


def run(quick: bool, out_dir) -> list[dict]:
    limit = 300.0 if quick else 900.0
    records = []
    for name in FILES:
        # --quick: the report alone (the derivation is timed on its own in the full bench)
        derived = None if quick else fresh_process("benchmarks.spatial", name, "derive", timeout=limit)
        report = fresh_process("benchmarks.spatial", name, "report", timeout=limit)
        derive_s = derived["seconds"] if derived else None
        report_s = report["seconds"] if report else limit
        notes = f"from {FILES[name].name}; cold, fresh process, time limit {limit:.0f} s; " + (
            "derivation not timed on its own in --quick"
            if quick
            else f"derivation {derive_s:.1f} s"
            if derive_s
            else f"derivation over {limit:.0f} s"
        )
        notes += f"; report target < {TARGET:.0f} s" + ("" if report else f"; report did not finish in {limit:.0f} s")
        records.append(record(f"spatial/{name} report", report_s, None, None, 1, notes))
    return records


def main() -> int:
    rows = ["| scene | derivation s | report s | target s |", "|---|---|---|---|"]
    for r in run(False, None):
        rows.append(f"| {r['name']} | {r['notes']} | {r['ours_s']:.1f} | {TARGET:.0f} |")
    print("\n".join(rows))
    return 0


if __name__ == "__main__":  # pragma: no cover
    if len(sys.argv) == 3:
        _worker(sys.argv[1], sys.argv[2])
    else:
        sys.exit(main())
