"""Run the benchmarks: ``python -m benchmarks.run [--quick] [--jobs N] [--json FILE] [--only NAME ...]``.

Writes ``results/README.md`` (a Markdown table of the records) and the PNG plots to the
output folder, and the JSON list of records to ``--json``. With ``--jobs N`` (the default
for ``--quick``: every core) the modules run in N fresh interpreters at a time, the longest
first; each module's ratios are measured side by side within that module, so they stay
comparable, while its absolute times include the other jobs' load (the table says how many
ran at once).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import tempfile
import time
from importlib import import_module
from pathlib import Path

from . import BENCHMARKS

RESULTS = Path(__file__).resolve().parent / "results"

#: The modules by their CPU seconds under ``--quick`` (the last measured run), longest first: with
#: several jobs the longest starts first, so the others fill the remaining cores around it. Measured
#: 2026-11-28 15:14-15:21 UTC (2 at a time, load 4-7; CPU seconds vary by ~20% at that load): work_precision ~43,
#: atlas ~32, scaling ~26, hopf_direction ~25, squeal ~25, spatial ~24, derivation ~23, classification ~20,
#: counts ~16, robustness ~13, closed_forms_k3 ~13, imports ~10, regions_k3 ~7, region_evaluate ~7 (289 CPU s in
#: all); flint not measured (python-flint not installed there: no rows), kept after spatial where it stood.
LONGEST_FIRST = (
    "work_precision",
    "atlas",
    "scaling",
    "hopf_direction",
    "squeal",
    "spatial",
    "flint",
    "derivation",
    "classification",
    "counts",
    "robustness",
    "closed_forms_k3",
    "imports",
    "regions_k3",
    "region_evaluate",
)


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
    jobs: int = 1,
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
        f"{platform.python_version()}, {seconds:.0f} s wall in all{used}{loaded}, "
        f"{'the modules one after the other' if jobs == 1 else f'{jobs} modules at a time, each in a fresh interpreter'}. "
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


def _positive_int(text: str) -> int:
    if not text.isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"{text!r} is not a positive whole number")
    return int(text)


def _one_module(name: str, quick: bool, out: Path) -> tuple[list[dict], float, float]:
    """(records, wall s, CPU s) of one benchmark module, run in this interpreter."""
    t0, c0 = time.perf_counter(), _cpu_seconds()
    found = import_module(f"benchmarks.{name}").run(quick, out)
    return found, time.perf_counter() - t0, _cpu_seconds() - c0


def _kill(processes) -> None:
    for process in processes:
        if process.poll() is None:
            process.kill()
            process.wait()


def _in_fresh_interpreters(names: list[str], quick: bool, out: Path, jobs: int):
    """Yield (name, records, wall s, CPU s) as the modules finish, each in a fresh interpreter, ``jobs`` at a
    time, the longest first (unknown modules before all); a module's output is printed when it ends."""
    order = sorted(names, key=lambda n: LONGEST_FIRST.index(n) if n in LONGEST_FIRST else -1)
    root = Path(__file__).resolve().parent.parent
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in (str(root), os.environ.get("PYTHONPATH")) if p)}
    running: dict[str, tuple] = {}
    with tempfile.TemporaryDirectory(prefix="contactsym-bench-") as scratch:
        try:
            while order or running:
                while order and len(running) < jobs:
                    name = order.pop(0)
                    result, log = Path(scratch, f"{name}.json"), Path(scratch, f"{name}.log")
                    command = [sys.executable, "-m", "benchmarks.run", "--module", name, "--out", str(out)]
                    command += ["--json", str(result)] + (["--quick"] if quick else [])
                    with open(log, "w") as stream:
                        process = subprocess.Popen(command, cwd=root, env=env, stdout=stream, stderr=subprocess.STDOUT)
                    running[name] = (process, result, log)
                time.sleep(0.2)
                for name in [n for n, (process, _, _) in running.items() if process.poll() is not None]:
                    process, result, log = running.pop(name)
                    print(log.read_text(), end="", flush=True)
                    if process.returncode:
                        raise RuntimeError(f"the benchmark {name} failed (exit code {process.returncode}); see above.")
                    data = json.loads(result.read_text())
                    yield name, data["records"], data["wall"], data["cpu"]
        finally:
            _kill(process for process, _, _ in running.values())


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="contactsym bench", description="Run the contactsym benchmarks.")
    parser.add_argument(
        "--quick",
        action="store_true",
        help="smaller sweeps (aim: under 3 minutes on 2 quiet cores; ~290 CPU s at load 4-7)",
    )
    parser.add_argument("--json", metavar="FILE", help="write the records as a JSON list to FILE")
    parser.add_argument("--only", nargs="*", choices=BENCHMARKS, help="run only these benchmarks")
    parser.add_argument("--out", default=str(RESULTS), help="folder for the Markdown table and the PNG plots")
    parser.add_argument(
        "--jobs",
        type=_positive_int,
        metavar="N",
        help="modules run at once, each in a fresh interpreter (default: every core with --quick, else 1)",
    )
    parser.add_argument("--module", choices=BENCHMARKS, help=argparse.SUPPRESS)  # one module, for --jobs
    args = parser.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    if args.module:  # a worker of --jobs: the records, wall and CPU seconds of one module as JSON
        found, wall, used = _one_module(args.module, args.quick, out)
        Path(args.json).write_text(json.dumps({"records": found, "wall": wall, "cpu": used}))
        return 0
    jobs = args.jobs or ((os.cpu_count() or 1) if args.quick else 1)
    names = list(args.only or BENCHMARKS)
    started, cpu_started, load_started = time.perf_counter(), _cpu_seconds(), _load()
    done: dict[str, tuple[list[dict], float, float]] = {}
    finished = (
        ((name, *_one_module(name, args.quick, out)) for name in names)
        if jobs == 1
        else _in_fresh_interpreters(names, args.quick, out, jobs)
    )
    for name, found, wall, used in finished:
        done[name] = (found, wall, used)
        print(f"{name}: {len(found)} records in {wall:.1f} s ({used:.1f} CPU s)", flush=True)
        for r in found:
            print(
                f"  {r['name']}: ours {_cell(r['ours_s'])}  baseline {_cell(r['baseline_s'])}  "
                f"ratio {_cell(r['ratio'])}  error {_cell(r['error'])}",
                flush=True,
            )
    records = [r for name in names for r in done[name][0]]  # the table keeps the modules' own order
    modules = [(name, done[name][1], done[name][2]) for name in names]
    seconds, cpu = time.perf_counter() - started, _cpu_seconds() - cpu_started
    load = (load_started, _load())
    (out / "README.md").write_text(markdown(records, args.quick, seconds, cpu, modules, load, jobs))
    if args.json:
        Path(args.json).write_text(json.dumps(records, indent=1))
    for name, wall, used in sorted(modules, key=lambda m: -m[2]):
        print(f"  {name:<16} {used:7.1f} CPU s {wall:7.1f} s wall")
    print(
        f"done in {seconds:.0f} s wall ({cpu:.0f} CPU s, {jobs} at a time, load average {load[0]} -> {load[1]}); "
        f"table in {out / 'README.md'}"
    )
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
