"""Signals and killed runs of the command line: ``python -m benchmarks.signals [--sigint 50] [--kill 20]``.

Two trials, each on ``contactsym report sliding-point --no-pdf`` into a fresh folder with
its own ``TMPDIR``:

- SIGINT at a random moment of the run, after the interpreter's own start-up (``site``,
  its ``.pth`` files and ``runpy`` run before any line of contactsym, and Python prints its
  own traceback for a SIGINT there; :func:`interpreter_startup` measures that time): the run must
  exit with 130, print no traceback and no "Exception ignored", and leave no temporary
  folder (``.sliding-point.new-*``, ``.old-*``, ``contactsym-figures-*``) and no mix of old
  and new report.
- SIGKILL at a random moment, then one clean run into the same place: afterwards nothing
  of the killed run may be left.

``tests/test_atomic.py`` runs the same trials, a few of each.
"""

from __future__ import annotations

import argparse
import os
import random
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
COMMAND = [sys.executable, "-m", "contactsym", "report", "sliding-point", "--no-pdf", "--out"]


def _environment(scratch: Path) -> dict:
    return {
        **os.environ,
        "TMPDIR": str(scratch),
        "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""),
    }


def interpreter_startup(runs: int = 5) -> float:
    """Seconds the interpreter takes to start and to run a module with ``-m`` (``python -m this``: ``site``, its
    ``.pth`` files and ``runpy``, none of it contactsym's code), the longest of ``runs``: no signal comes sooner."""
    times = []
    for _ in range(runs):
        started = time.perf_counter()
        environment = _environment(Path(tempfile.gettempdir()))
        subprocess.run([sys.executable, "-m", "this"], env=environment, check=True, stdout=subprocess.DEVNULL)
        times.append(time.perf_counter() - started)
    return 1.2 * max(times)


def leftovers(out: Path, scratch: Path) -> list[str]:
    """Temporary files and folders of a run: hidden siblings in ``out``, figure folders in ``scratch``."""
    found = [p.name for p in out.iterdir() if p.name.startswith(".")] if out.exists() else []
    return found + [p.name for p in scratch.iterdir()]


def sigint_trial(folder: Path, delay: float) -> tuple[bool, str]:
    """SIGINT after ``delay`` seconds; (passed, what went wrong)."""
    out, scratch = folder / "out", folder / "tmp"
    scratch.mkdir(parents=True)
    child = subprocess.Popen(
        [*COMMAND, str(out)], env=_environment(scratch), stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True
    )
    time.sleep(delay)
    child.send_signal(signal.SIGINT)
    try:
        _, err = child.communicate(timeout=120)
    finally:
        child.kill()
    problems = []
    if child.returncode not in (130, 0):  # 0: the run had finished before the signal came
        problems.append(f"exit code {child.returncode}")
    if child.returncode == 0 and "interrupted" in err:
        problems.append("exit code 0 after 'interrupted'")
    if "Traceback" in err or "Exception ignored" in err:
        problems.append("traceback: " + err.strip().splitlines()[-1][:200])
    rest = leftovers(out, scratch)
    if rest:
        problems.append(f"left {rest}")
    return not problems, "; ".join(problems) or f"exit {child.returncode}"


def kill_trial(folder: Path, delay: float) -> tuple[bool, str]:
    """SIGKILL after ``delay`` seconds, then a clean run into the same place; (passed, what was left)."""
    out, scratch = folder / "out", folder / "tmp"
    scratch.mkdir(parents=True)
    environment = _environment(scratch)
    child = subprocess.Popen(
        [*COMMAND, str(out)], env=environment, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
    )
    time.sleep(delay)
    child.kill()
    child.wait()
    left_by_kill = leftovers(out, scratch)
    clean = subprocess.run([*COMMAND, str(out)], env=environment, capture_output=True, text=True, timeout=300)
    rest = leftovers(out, scratch)
    passed = clean.returncode == 0 and not rest and (out / "sliding-point" / "report.tex").is_file()
    return passed, f"killed run left {len(left_by_kill)}; after the clean run (exit {clean.returncode}): {rest}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks.signals", description=__doc__.splitlines()[0])
    parser.add_argument("--sigint", type=int, default=50, help="SIGINT trials")
    parser.add_argument("--kill", type=int, default=20, help="SIGKILL trials")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--longest", type=float, default=4.0, help="latest moment of a signal, in seconds")
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    startup = interpreter_startup() + 0.05
    print(f"interpreter start-up: {startup - 0.05:.2f} s; signals from {startup:.2f} s to {args.longest:.2f} s")
    rows, failed = [], 0
    with tempfile.TemporaryDirectory() as base:
        for kind, count, trial in (("SIGINT", args.sigint, sigint_trial), ("SIGKILL", args.kill, kill_trial)):
            passed, stopped = 0, 0
            for i in range(count):
                delay = rng.uniform(startup, max(startup, args.longest))
                ok, detail = trial(Path(base) / f"{kind}-{i}", delay)
                passed += ok
                stopped += detail == "exit 130"
                if not ok:
                    print(f"{kind} trial {i} at {delay:.2f} s failed: {detail}", flush=True)
            rows.append((kind, count, passed, stopped if kind == "SIGINT" else "-"))
            failed += count - passed
    print("| signal | trials | passed | stopped with 130 (the rest had finished first) |\n|---|---|---|---|")
    for kind, count, passed, stopped in rows:
        print(f"| {kind} | {count} | {passed} | {stopped} |")
    return 1 if failed else 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
