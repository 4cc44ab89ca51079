"""closed forms k=3/4: cold time of the Hopf frequency, the Hopf set and ``Scene.regions()``.

Scenes: a three-legged stool sliding and spinning on a rough floor (k = 3, as in
``tests/stool.py``) with its feet at fixed, unequal positions (4-digit rationals) and

- ``stool-numbers``: mass and inertias numbers, mu, h and the sign symbols symbolic;
- ``stool-fixed``: mass m and inertias I_1..I_3 symbolic too;
- ``stool-symbolic``: feet (x_j, y_j) and slip directions (c_j, d_j) symbolic as well;

and the generic scenes q_i'' = sum_j a_ij N_j + b_i for k = 3 and k = 4.

Ours is this source tree; the baseline is the main branch (``/work/main``, or
``$CONTACTSYM_BASELINE``) run by the same worker, both measured side by side in one run.
Each measurement is a fresh process (scene build included, import excluded) with a time
limit, ours and the baseline alternating, best of two (one with ``--quick``); a baseline
that does not finish counts as the limit (the ratio is then a lower bound).
The worker runs as a script, so it imports whichever ``contactsym`` its PYTHONPATH holds.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BASELINE = Path(os.environ.get("CONTACTSYM_BASELINE", "/work/main"))

#: (scene, stage, target seconds or None): the rows, in order.
CASES = (
    ("stool-numbers", "frequency", 5.0),
    ("stool-numbers", "regions", 5.0),
    ("stool-fixed", "frequency", 5.0),
    ("stool-fixed", "regions", 5.0),
    ("stool-symbolic", "frequency", None),
    ("generic-3", "hopf", 10.0),
    ("generic-4", "hopf", 60.0),
)


def _worker(source: Path, scene: str, stage: str, timeout: float) -> dict | None:
    env = dict(os.environ)
    env["PYTHONPATH"] = str(source)
    command = [sys.executable, str(Path(__file__).resolve()), scene, stage]
    try:
        done = subprocess.run(command, cwd=source, env=env, capture_output=True, text=True, timeout=timeout, check=True)
    except subprocess.TimeoutExpired:
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def run(quick: bool, out_dir) -> list[dict]:
    from . import record

    limit = 120 if quick else 600
    cases = [c for c in CASES if not (quick and c[0] in ("stool-symbolic", "generic-4"))]
    rows = []
    repeats = 1 if quick else 2
    for scene, stage, target in cases:
        ours, old = [], []
        for _ in range(repeats):  # alternating, best of each: the load of a shared machine drifts
            ours.append(_worker(ROOT, scene, stage, limit))
            old.append(_worker(BASELINE, scene, stage, limit) if BASELINE.is_dir() else None)
        ours, old = _best(ours), _best(old)
        ours_s = ours["seconds"] if ours else float(limit)
        old_s = old["seconds"] if old else float(limit)
        notes = (
            f"cold, fresh process, scene build included, best of {repeats}; time limit {limit} s; baseline {BASELINE}"
        )
        if target is not None:
            notes += f"; target < {target:.0f} s; within target: {ours is not None and ours_s < target}"
        if ours:
            notes += f"; ops ours {ours['ops']}" + (f", baseline {old['ops']}" if old else "")
        if old is None:
            notes += "; the baseline timed out: baseline_s is the limit and the ratio a lower bound"
        rows.append(record(f"closed forms/{scene} {stage}", ours_s, old_s, None, 1, notes))
    return rows


def _best(results: list) -> dict | None:
    finished = [r for r in results if r is not None]
    return min(finished, key=lambda r: r["seconds"]) if finished else None


# --- the worker (runs as a script in a fresh process) ---------------------------------------


def _rational(x: float):
    import sympy as sp

    return sp.nsimplify(round(x, 4))


def stool(kind: str):
    """The stool of the module docstring: ``numbers``, ``fixed`` or ``symbolic``."""
    import numpy as np
    import sympy as sp
    from sympy.physics.mechanics import dynamicsymbols

    import contactsym as cs

    mu, h = sp.symbols("mu h", positive=True)
    if kind == "numbers":
        Minv = sp.diag(1, 1, 1, sp.Rational(5, 2), 2, sp.Rational(10, 7))
    else:
        m, *inertia = sp.symbols("m I_1:4", positive=True)
        Minv = sp.diag(*[1 / m] * 3, *[1 / x for x in inertia])
    angles = 2 * np.pi * np.arange(3) / 3
    velocity, spin = np.array([np.cos(0.3), np.sin(0.3), 0.0]), 0.8
    ez = sp.Matrix([0, 0, 1])
    wrenches, frictions = [], []
    for j, angle in enumerate(angles, 1):
        foot = np.array([np.cos(angle) - 0.15, np.sin(angle) + 0.1, 0.0])
        slip = velocity + spin * np.cross([0, 0, 1.0], foot)
        slip /= np.linalg.norm(slip)
        if kind == "symbolic":
            x, y, c, d = sp.symbols(f"x_{j} y_{j} c_{j} d_{j}", real=True)
        else:
            x, y, c, d = (_rational(v) for v in (foot[0], foot[1], slip[0], slip[1]))
        r, t = sp.Matrix([x, y, -h]), sp.Matrix([c, d, 0])
        wrenches.append(sp.Matrix.vstack(ez, r.cross(ez)))
        frictions.append(sp.Matrix.vstack(t, r.cross(t)))
    q = dynamicsymbols("q_1:4")
    N = sp.symbols("N_1:4", real=True)
    b = sp.symbols("b_1:4", real=True)
    force = sum((wrenches[i] * N[i] - mu * sp.Abs(N[i]) * frictions[i] for i in range(3)), sp.zeros(6, 1))
    accelerations = [(wrenches[j].T * Minv * force)[0] + b[j] for j in range(3)]
    contacts = [cs.Contact(coordinate=q[j], reaction=N[j]) for j in range(3)]
    return cs.Scene.from_accelerations(q, accelerations, contacts, name=f"stool-{kind}")


def generic_scene(k: int):
    """q_i'' = sum_j a_ij N_j + b_i (as ``benchmarks._derive_worker.generic_scene``)."""
    import sympy as sp
    from sympy.physics.mechanics import dynamicsymbols

    import contactsym as cs

    q = [dynamicsymbols(f"q_{i}") for i in range(1, k + 1)]
    N = sp.symbols(f"N_1:{k + 1}", real=True)
    a = sp.Matrix(k, k, lambda i, j: sp.Symbol(f"a_{i + 1}{j + 1}", real=True))
    b = sp.symbols(f"b_1:{k + 1}", real=True)
    G = [sum(a[i, j] * N[j] for j in range(k)) + b[i] for i in range(k)]
    return cs.Scene.from_accelerations(q, G, [cs.Contact(coordinate=q[i], reaction=N[i]) for i in range(k)])


def _main(scene_name: str, stage: str) -> None:
    import sympy as sp

    import contactsym  # noqa: F401  (import time is not measured)

    started = time.perf_counter()
    if scene_name.startswith("generic-"):
        scene = generic_scene(int(scene_name.split("-")[1]))
    else:
        scene = stool(scene_name.split("-")[1])
    stability = scene.stability()
    if stage == "frequency":
        result = [stability.hopf_frequency]
    elif stage == "hopf":
        result = [stability.hopf, stability.hopf_frequency]
    else:
        result = [region.condition for region in scene.regions().values()]
    seconds = time.perf_counter() - started
    print(json.dumps({"seconds": seconds, "ops": sum(int(sp.count_ops(r)) for r in result)}))


if __name__ == "__main__":  # pragma: no cover
    _main(sys.argv[1], sys.argv[2])
