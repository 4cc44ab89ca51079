"""Run the benchmarks: ``python -m benchmarks.run [--quick] [--json FILE] [--only NAME ...]``.

Writes ``results/README.md`` (a Markdown table of the records) and the PNG plots to the
output folder, and the JSON list of records to ``--json``.
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import time
from importlib import import_module
from pathlib import Path

from . import BENCHMARKS

RESULTS = Path(__file__).resolve().parent / "results"


def _cell(value) -> str:
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, float):
        return f"{value:.3g}"
    return str(value)


def _cpu_seconds() -> float:
    """CPU seconds of this process and of the processes it waited for (fresh interpreters, workers): on a
    shared machine the wall time also counts the other jobs."""
    try:
        import resource
    except ImportError:  # not on POSIX: this process alone
        return time.process_time()
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def markdown(records: list[dict], quick: bool, seconds: float, cpu: float | None = None) -> str:
    used = f" ({cpu:.0f} CPU s)" if cpu is not None else ""
    lines = [
        "# Benchmark results",
        "",
        f"`contactsym bench{' --quick' if quick else ''}` on {platform.machine()}, Python "
        f"{platform.python_version()}, {seconds:.0f} s in all{used}. ratio = baseline_s / ours_s. "
        "Plots: `classification.png`, `work_precision.png`, `derivation.png`, `robustness.png`, `counts.png`, `scaling.png`, `atlas.png`, `closed_forms_k3.png`, `flint.png` (not committed; rerun to make them).",
        "",
        "| name | ours_s | baseline_s | ratio | error | n | notes |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in records:
        cells = [r["name"], r["ours_s"], r["baseline_s"], r["ratio"], r["error"], r["n"], r["notes"]]
        lines.append("| " + " | ".join(_cell(c).replace("|", "/") for c in cells) + " |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="contactsym bench", description="Run the contactsym benchmarks.")
    parser.add_argument("--quick", action="store_true", help="smaller sweeps: under 3 minutes on 2 cores")
    parser.add_argument("--json", metavar="FILE", help="write the records as a JSON list to FILE")
    parser.add_argument("--only", nargs="*", choices=BENCHMARKS, help="run only these benchmarks")
    parser.add_argument("--out", default=str(RESULTS), help="folder for the Markdown table and the PNG plots")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started, cpu_started = time.perf_counter(), _cpu_seconds()
    records: list[dict] = []
    for name in args.only or BENCHMARKS:
        t0, c0 = time.perf_counter(), _cpu_seconds()
        module = import_module(f"benchmarks.{name}")
        found = module.run(args.quick, out)
        records += found
        print(
            f"{name}: {len(found)} records in {time.perf_counter() - t0:.1f} s ({_cpu_seconds() - c0:.1f} CPU s)",
            flush=True,
        )
        for r in found:
            print(
                f"  {r['name']}: ours {_cell(r['ours_s'])}  baseline {_cell(r['baseline_s'])}  "
                f"ratio {_cell(r['ratio'])}  error {_cell(r['error'])}",
                flush=True,
            )
    seconds, cpu = time.perf_counter() - started, _cpu_seconds() - cpu_started
    (out / "README.md").write_text(markdown(records, args.quick, seconds, cpu))
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1))
    print(f"done in {seconds:.0f} s ({cpu:.0f} CPU s); table in {out / 'README.md'}")
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
