"""Run the benchmarks: ``python -m benchmarks.run [--quick] [--json FILE] [--only NAME ...]``.

Writes ``results/README.md`` (a Markdown table of the records) and the PNG plots to the
output folder, and the JSON list of records to ``--json``.
"""

from __future__ import annotations

import argparse
import json
import math
import os
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


def _load() -> str:
    try:
        return f"{os.getloadavg()[0]:.1f}"
    except (AttributeError, OSError):  # not on this platform
        return "?"


def markdown(
    records: list[dict],
    quick: bool,
    seconds: float,
    cpu: float | None = None,
    modules: list[tuple[str, float, float]] | None = None,
    load: tuple[str, str] | None = None,
) -> str:
    """The Markdown table of ``records``; the header says the wall and CPU seconds in all (CPU: this process
    and the fresh processes it waited for), the load average at start and end, and ``modules``
    ``(name, wall s, CPU s)`` when given."""
    used = f" ({cpu:.0f} CPU s)" if cpu is not None else ""
    loaded = f" (load average {load[0]} at the start, {load[1]} at the end)" if load else ""
    lines = [
        "# Benchmark results",
        "",
        f"`contactsym bench{' --quick' if quick else ''}` on {platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}, {seconds:.0f} s wall in all{used}{loaded}, the modules one after the other. "
        "ratio = baseline_s / ours_s. "
        "Plots: `classification.png`, `work_precision.png`, `derivation.png`, `robustness.png`, `counts.png`, `scaling.png`, `atlas.png`, `closed_forms_k3.png`, `flint.png` (not committed; rerun to make them).",
        "",
    ]
    if modules:
        lines += ["Per module, wall / CPU s: " + ", ".join(f"{n} {w:.0f} / {c:.0f}" for n, w, c in modules) + ".", ""]
    lines += [
        "| name | ours_s | baseline_s | ratio | error | n | notes |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in records:
        cells = [r["name"], r["ours_s"], r["baseline_s"], r["ratio"], r["error"], r["n"], r["notes"]]
        lines.append("| " + " | ".join(_cell(c).replace("|", "/") for c in cells) + " |")
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="contactsym bench", description="Run the contactsym benchmarks.")
    parser.add_argument(
        "--quick", action="store_true", help="smaller sweeps: under 3 minutes on 2 quiet cores (~150 CPU s)"
    )
    parser.add_argument("--json", metavar="FILE", help="write the records as a JSON list to FILE")
    parser.add_argument("--only", nargs="*", choices=BENCHMARKS, help="run only these benchmarks")
    parser.add_argument("--out", default=str(RESULTS), help="folder for the Markdown table and the PNG plots")
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    started, cpu_started, load_started = time.perf_counter(), _cpu_seconds(), _load()
    records: list[dict] = []
    modules: list[tuple[str, float, float]] = []
    for name in args.only or BENCHMARKS:
        t0, c0 = time.perf_counter(), _cpu_seconds()
        module = import_module(f"benchmarks.{name}")
        found = module.run(args.quick, out)
        records += found
        modules.append((name, time.perf_counter() - t0, _cpu_seconds() - c0))
        print(f"{name}: {len(found)} records in {modules[-1][1]:.1f} s ({modules[-1][2]:.1f} CPU s)", flush=True)
        for r in found:
            print(
                f"  {r['name']}: ours {_cell(r['ours_s'])}  baseline {_cell(r['baseline_s'])}  "
                f"ratio {_cell(r['ratio'])}  error {_cell(r['error'])}",
                flush=True,
            )
    seconds, cpu = time.perf_counter() - started, _cpu_seconds() - cpu_started
    load = (load_started, _load())
    (out / "README.md").write_text(markdown(records, args.quick, seconds, cpu, modules, load))
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1))
    for name, wall, used in sorted(modules, key=lambda m: -m[2]):
        print(f"  {name:<16} {used:7.1f} CPU s {wall:7.1f} s wall")
    print(
        f"done in {seconds:.0f} s wall ({cpu:.0f} CPU s, load average {load[0]} -> {load[1]}); table in {out / 'README.md'}"
    )
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
