"""Import time: ``import contactsym`` against ``import sympy``, each in a fresh interpreter.

The package loads its parts on first use; the second row times the first use of the core
(``contactsym.Scene``: the mechanism, the stages and SymPy's mechanics), the third the report.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

from . import record

ROOT = Path(__file__).resolve().parent.parent
CASES = {
    "import contactsym": "import contactsym",
    "import contactsym; contactsym.Scene": "import contactsym; contactsym.Scene",
    "import contactsym; contactsym.write_report": "import contactsym; contactsym.write_report",
}
HEAVY = ("contactsym.report", "contactsym.plotting", "contactsym.numerics", "scipy.ndimage", "matplotlib")


def _seconds(code: str) -> tuple[float, list[str]]:
    """Wall seconds of ``code`` in a fresh interpreter (its start-up excluded) and the heavy modules it loaded."""
    probe = (
        "import sys, time, json\nstart = time.perf_counter()\n"
        f"{code}\nseconds = time.perf_counter() - start\n"
        f"print(json.dumps([seconds, [m for m in {HEAVY!r} if m in sys.modules]]))"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    done = subprocess.run(
        [sys.executable, "-c", probe], capture_output=True, text=True, env=env, timeout=120, check=True
    )
    seconds, loaded = json.loads(done.stdout.strip().splitlines()[-1])
    return seconds, loaded


def run(quick: bool, out: Path) -> list[dict]:
    rounds = 3 if quick else 11
    times: dict[str, list[float]] = {"import sympy": [], **{name: [] for name in CASES}}
    loaded: dict[str, list[str]] = {}
    for _ in range(rounds):  # interleaved, so a load change on the machine hits every row alike
        times["import sympy"].append(_seconds("import sympy")[0])
        for name, code in CASES.items():
            seconds, loaded[name] = _seconds(code)
            times[name].append(seconds)
    sympy_s = statistics.median(times["import sympy"])
    records = []
    for name in CASES:
        ours = statistics.median(times[name])
        notes = (
            f"fresh interpreter, start-up excluded; median of {rounds} interleaved rounds; "
            f"ratio = sympy / ours (target for the bare import: ours <= 1.3x sympy, ratio >= 0.77); "
            f"loaded of {', '.join(HEAVY)}: {', '.join(loaded[name]) or 'none'}"
        )
        records.append(record(f"import/{name}", ours, sympy_s, None, rounds, notes))
    return records
