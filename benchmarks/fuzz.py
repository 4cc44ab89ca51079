"""Fuzz the public API and the command line with bad inputs: ``python -m benchmarks.fuzz [--n 20000]``.

The probe is generated (:mod:`benchmarks.boundary`): every public callable of
``contactsym.__all__`` and of each subpackage's ``__all__``, the public methods of the
public classes and the command line's subcommands and options, each parameter fed wrong
types, shapes and values. Each call runs in a worker process under a time limit (a
worker that overruns it is killed and replaced) and is sorted into one outcome:

- ``clear error``: a ContactsymError with a one-line message of bounded length;
- ``accepted``: no argument of a type its hint rules out, and a result;
- ``raw traceback``: any other exception;
- ``silent acceptance``: an argument of a type its hint rules out, and a result;
- ``evaluated text``: a string argument was executed as Python (a sentinel notices);
- ``hang``: the time limit passed.

The hand-written cases below (``CASES``) add valid calls with known answers. Each case takes a valid call of an entry point and, most of the time, replaces one
argument by a bad value (nan, infinities, complex numbers, wrong types and shapes,
text, huge text, out-of-range numbers). Every call runs under a time limit and is
sorted into one outcome:

- ``clear error``: a ContactsymError with a one-line message of bounded length;
- ``accepted``: a valid input that gave a result with no nan/inf in it;
- ``raw traceback``: any other exception;
- ``silent acceptance``: a bad input that gave a result instead of an error;
- ``bad result``: a valid input whose result holds nan/inf, or an "ok" with nan in it;
- ``evaluated text``: a string argument was executed as Python (a sentinel notices);
- ``hang``: the time limit passed.

``--out FILE`` writes the table as Markdown (the repository keeps it in
``docs/robustness.md``). The tests in ``tests/test_fuzz.py`` run a seeded sample of both.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import random
import signal
import tempfile
import time
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from benchmarks import boundary
from contactsym import numerics as nm
from contactsym.cli import main as cli_main

#: Set by the sentinel text when some entry point executes it as Python.
FLAG = "CONTACTSYM_FUZZ_EVALUATED"
SENTINEL = f"__import__('os').environ.__setitem__('{FLAG}', '1') or 1"
OUTCOMES = ("clear error", "accepted", "raw traceback", "silent acceptance", "bad result", "evaluated text", "hang")

x, y = dynamicsymbols("x y")
N, N2, X, Y = sp.symbols("N N2 X Y", real=True)
MU = sp.Symbol("mu", positive=True)


@dataclass
class Case:
    """One call: ``bad`` says whether a clear error is the right answer."""

    target: str
    call: Callable[[], object]
    bad: bool
    check: Callable[[object], bool] = lambda result: True  # for results: True when sound


class _Hang(BaseException):
    """Raised by the alarm; a BaseException so that no ``except Exception`` in the library swallows it."""


# --- bad values ---------------------------------------------------------------------------------

NOT_FINITE = [float("nan"), float("inf"), -float("inf"), np.nan, sp.nan, sp.oo, -sp.oo, sp.zoo]
WRONG_TYPE = [None, [], {}, (), object(), b"bytes", "x" * 100_000, SENTINEL, 1j, np.complex128(1 + 1j), True]
NUMBERS_BAD = NOT_FINITE + WRONG_TYPE


def _one_of(rng: random.Random, values):
    return values[rng.randrange(len(values))]


def _corrupt(rng: random.Random, slots: dict, bad: dict) -> tuple[dict, bool]:
    """The valid slots, with one replaced by a bad value four times in five."""
    arguments = dict(slots)
    if rng.random() < 0.2:
        return arguments, False
    name = _one_of(rng, sorted(bad))
    arguments[name] = _one_of(rng, bad[name])
    return arguments, True


def _finite(values) -> bool:
    array = np.asarray(values, dtype=float)
    return bool(np.all(np.isfinite(array)))


# --- cases ---------------------------------------------------------------------------------------


def scene_case(rng: random.Random) -> Case:
    contact = cs.Contact(coordinate=y, reaction=N)
    slots = {"coordinates": [x, y], "accelerations": [X - MU * sp.Abs(N), N + Y], "contacts": [contact], "eps": None}
    slots |= {"name": "user", "at": None, "parameters": None, "positive": ()}
    bad = {
        "coordinates": [None, 5, "xy", [], [x], [x, 3], [x, x], [x, y, y], [SENTINEL, y]],
        "accelerations": [None, [X], [X, N + Y, 7], [X, sp.nan * N + Y], [X, sp.oo * N + Y], [X, sp.zoo + N]]
        + [[X, [N]], [X, None], [X, N * float("nan")], [X, float("inf")], [X, SENTINEL]],
        "contacts": [None, [(y, N)], [], [contact, cs.Contact(coordinate=x, reaction=N2)], "contact", [None]],
        "eps": [*NOT_FINITE, -1, 0, -1e-3, 1j, [], object(), SENTINEL, "x" * 100_000],
        "name": [None, 3, b"user", ["user"]],
        "at": [5, "h", {X: sp.nan}, {X: None}, [X]],
        "parameters": [5, ["X"], "X", [X, None]],
        "positive": [None, 5, [sp.nan], [None]],
    }
    arguments, is_bad = _corrupt(rng, slots, bad)
    eps = arguments.pop("eps")

    def call():
        s = cs.Scene.from_accelerations(**arguments, eps=eps)
        return s.stability().hurwitz

    return Case("Scene.from_accelerations", call, is_bad, lambda h: all(not c.has(sp.nan, sp.zoo, sp.oo) for c in h))


def contact_case(rng: random.Random) -> Case:
    slots = {"coordinate": y, "reaction": N, "compliance": None, "friction": None, "unilateral": False}
    bad = {
        "coordinate": [None, 3, "y", sp.nan, sp.oo + y, [y]],
        "reaction": [None, "N", 3, N + 1, [N]],
        "compliance": [3, "KelvinVoigt", object(), cs.Coulomb(MU, {x: 1})],
        "friction": [0.3, "Coulomb", object(), cs.KelvinVoigt(1, 1)],
        "unilateral": ["yes", None, 1.5, []],
    }
    arguments, is_bad = _corrupt(rng, slots, bad)
    return Case("Contact", lambda: cs.Contact(**arguments), is_bad)


def law_case(rng: random.Random) -> Case:
    law = _one_of(rng, ["Coulomb", "Viscous", "KelvinVoigt"])
    if law == "KelvinVoigt":
        slots = {"stiffness": 2, "damping": sp.Rational(1, 2)}
        bad = {name: [*NUMBERS_BAD, -1, 0, -0.5] for name in slots}
        arguments, is_bad = _corrupt(rng, slots, bad)
        return Case(law, lambda: cs.KelvinVoigt(**arguments), is_bad)
    name = "mu" if law == "Coulomb" else "c"
    arguments, is_bad = _corrupt(rng, {name: 0.3}, {name: [*NUMBERS_BAD, -0.5, -1, "0.3"]})
    make = cs.Coulomb if law == "Coulomb" else cs.Viscous
    return Case(law, lambda: make(*arguments.values(), {x: 1}), is_bad)


def signs_case(rng: random.Random) -> Case:
    stage = _one_of(rng, ["stability", "regions", "equilibria", "linearization", "reduced_system"])
    bad = [[], [1], [1, 0], [1, 1, 1], [1, -1], np.array([1, -1]), "+-", "+1,+1", 5, [True, 1], [1.0, 1]]
    bad += [[sp.nan, 1], [1j, 1], [SENTINEL, 1], {1: 1, 2: 1}, [None, None]]
    signs, is_bad = (_one_of(rng, [(1, 1), np.array([1, 1]), None]), False) if rng.random() < 0.2 else (None, True)
    if is_bad:
        signs = _one_of(rng, bad)
    return Case(f"Scene.{stage}(signs)", lambda: getattr(cs.scene("brake"), stage)(signs), is_bad)


def scene_name_case(rng: random.Random) -> Case:
    bad = [None, 3, "", "x" * 100_000, "brake ", "BRAKE", SENTINEL, b"brake", ["brake"], "../brake", "\x00"]
    if rng.random() < 0.2:
        return Case("scene(name)", lambda: cs.scene(_one_of(rng, cs.scene_names())), False)
    name = _one_of(rng, bad)
    return Case("scene(name)", lambda: cs.scene(name), True)


BRAKE_POINT = {"alpha": 1.0, "m": 1.0, "mu": 0.7, "Phi_1": -2.0, "Phi_2": -3.0, "Psi_1": -1.0, "Psi_2": -0.5}


def classify_case(rng: random.Random) -> Case:
    slots = {k: v * (0.5 + rng.random()) for k, v in BRAKE_POINT.items()}
    bad = {k: NUMBERS_BAD + ["1", [1.0, 2.0], np.array([1.0])] for k in slots}
    bad["m"] = bad["m"] + [-1.0, 0]
    bad["Phi_1"] = bad["Phi_1"] + [2.0, 0]
    arguments, is_bad = _corrupt(rng, slots, bad)
    st = cs.scene("brake").stability()
    return Case("classify", lambda: nm.classify(st, arguments), is_bad, lambda c: set(c.signs) <= {-1, 0, 1})


_ROD = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}


def integrate_case(rng: random.Random) -> Case:
    slots = {"span": (0.0, 1.0), "z0": [0.1, 0.0], "method": "Radau", "t_eval": None, "rtol": 1e-6}
    bad = {
        "span": [(1.0, 0.0), (0.0, float("nan")), (0.0, float("inf")), None, "0 1", (0, 1, 2), (0, 1j)],
        "z0": [[float("nan"), 0.0], [1j, 0.0], [0.0], None, "00", [[0.0], [0.0, 1.0]], [SENTINEL, 0]],
        "method": ["Nope", None, 3, SENTINEL, "radau"],
        "t_eval": [[float("nan")], [0.0, 2.0], [0.5, 0.2], [1j], "x", [-1.0, 0.5], [[0.1], [0.2, 0.3]]],
        "rtol": [0, -1, *NOT_FINITE, None, "1e-6"],
    }
    arguments, is_bad = _corrupt(rng, slots, bad)
    system = nm.fast_system(cs.scene("painleve-klein-rod"), _ROD)

    def sound(run) -> bool:
        return not run.ok or (_finite(run.y) and _finite(run.reactions) and _finite(run.t))

    return Case("integrate", lambda: nm.integrate(system, **arguments), is_bad, sound)


_CLASSIFIER: list = []


def point_classifier_case(rng: random.Random) -> Case:
    if not _CLASSIFIER:
        m, mu = sp.symbols("m mu", positive=True)
        Phi = sp.Symbol("Phi", negative=True)
        _CLASSIFIER.append(nm.PointClassifier([m * mu**2 + Phi, mu - m], [m, mu, Phi]))
    pc = _CLASSIFIER[0]
    size = rng.randrange(1, 50)
    slots = {
        "m": np.array([rng.uniform(0.1, 3) for _ in range(size)]),
        "mu": np.array([rng.uniform(0.1, 3) for _ in range(size)]),
        "Phi": -np.array([rng.uniform(0.1, 3) for _ in range(size)]),
        "chunk": rng.randrange(1, 64),
    }
    arrays = [np.array([v]) for v in (np.nan, np.inf, -np.inf)] + [np.array([1 + 1j]), "1", None, [[1, 2], [3]]]
    bad = {"m": [*arrays, np.array([-1.0])], "mu": arrays, "Phi": [*arrays, np.array([1.0])]}
    bad["chunk"] = [0, -5, 1.5, "8", None, True, np.nan]
    arguments, is_bad = _corrupt(rng, slots, bad)
    chunk = arguments.pop("chunk")
    return Case(
        "PointClassifier",
        lambda: pc(*arguments.values(), chunk=chunk),
        is_bad,
        lambda r: set(r.stable.ravel()) <= {-1, 0, 1},
    )


def cli_case(rng: random.Random) -> Case:
    junk = ["", "x" * 5000, SENTINEL, "-", "nope", "+1,x", "1,1,1", "+,0", "\x00", "--format", "--signs"]
    valid = [["list"], ["conditions", "brake", "--signs", "+1,+1"], ["conditions", "sliding-point", "--format", "json"]]
    bad = [
        ["show", _one_of(rng, junk)],
        ["conditions", "brake", "--signs", _one_of(rng, junk)],
        ["conditions", _one_of(rng, junk), "--format", "text"],
        ["conditions", "brake", "--format", _one_of(rng, junk)],
        ["report", "--out", ""],
        ["report", _one_of(rng, junk), "--out", "/nonexistent/dir", "--no-pdf"],
        ["bench", "--json", "/nonexistent/dir/x.json"],
        ["bench", "--out", ""],
        [_one_of(rng, junk)],
        ["list", _one_of(rng, junk)],
    ]
    is_bad = rng.random() >= 0.2
    argv = _one_of(rng, bad if is_bad else valid)
    command = argv[0] if argv[0] in ("show", "list", "conditions", "report", "bench") else "(no command)"
    case = cli_case_of(argv, is_bad)
    case.target = f"cli {command}"
    return case


def cli_case_of(argv: list[str], is_bad: bool) -> Case:
    """The command line on ``argv``: an exit code 1 or 2 with one short line is a clear error."""

    def call():
        err = io.StringIO()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
            code = cli_main(argv)
        lines = err.getvalue().strip().splitlines()
        if code not in (0, 1, 2) or "Traceback" in err.getvalue():
            raise RuntimeError(f"exit code {code}: {err.getvalue()[:300]}")
        if code:  # the command line turns errors into exit codes: give them back as errors here
            if len(lines) != 1 or len(lines[0]) > 400:
                raise RuntimeError(f"the error is not one short line: {err.getvalue()[:300]}")
            raise cs.ContactsymError(lines[0])
        return code

    return Case("cli", call, is_bad)


def lagrangian_case(rng: random.Random) -> Case:
    from sympy.physics.vector import Point, ReferenceFrame

    frame = ReferenceFrame("O")
    slots = {"lagrangian": x.diff() ** 2 / 2 + y.diff() ** 2 / 2 - y, "loads": [], "frame": None}
    bad = {
        "lagrangian": [None, [x], sp.nan * x, sp.oo * x.diff() ** 2, x.diff() ** 2 / 2, "x" * 100_000, object()],
        "loads": [None, [1, 2], [(Point("P"),)], [(frame, 3)], "loads"],
        "frame": [3, "O", Point("P")],
    }
    arguments, is_bad = _corrupt(rng, slots, bad)
    contact = cs.Contact(coordinate=y, reaction=N)
    return Case(
        "Scene.from_lagrangian",
        lambda: cs.Scene.from_lagrangian(**arguments, coordinates=[x, y], contacts=[contact]),
        is_bad,
    )


CASES = [
    scene_case,
    lagrangian_case,
    contact_case,
    law_case,
    signs_case,
    scene_name_case,
    classify_case,
    integrate_case,
    point_classifier_case,
    cli_case,
]


# --- running -------------------------------------------------------------------------------------


@contextlib.contextmanager
def _time_limit(seconds: float):
    def alarm(signum, frame):
        raise _Hang

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def outcome(case: Case, seconds: float = 30.0) -> tuple[str, str]:
    """(outcome, detail) of one case; see the module docstring."""
    os.environ.pop(FLAG, None)
    try:
        with _time_limit(seconds):
            result = case.call()
    except _Hang:
        return "hang", f"more than {seconds:g} s"
    except cs.ContactsymError as error:
        if os.environ.pop(FLAG, None):
            return "evaluated text", str(error)[:200]
        message = str(error)
        if "\n" in message.strip() or len(message) > 400:
            return "raw traceback", f"a long or multi-line message ({len(message)} characters)"
        return "clear error", message[:200]
    except Exception as error:  # anything else is what the fuzz hunts for
        os.environ.pop(FLAG, None)
        return "raw traceback", f"{type(error).__name__}: {str(error)[:200]}"
    if os.environ.pop(FLAG, None):
        return "evaluated text", repr(result)[:200]
    if case.bad:
        return "silent acceptance", repr(result)[:200]
    if not case.check(result):
        return "bad result", repr(result)[:200]
    return "accepted", ""


def run(n: int, seed: int = 0, seconds: float = 30.0) -> tuple[Counter, Counter, list]:
    """Run n cases drawn in turn from :data:`CASES`: totals, totals by target, and the failures."""
    rng = random.Random(seed)
    totals, by_target, failures = Counter(), Counter(), []
    for i in range(n):
        case = CASES[i % len(CASES)](rng)
        kind, detail = outcome(case, seconds)
        totals[kind] += 1
        totals["bad inputs"] += case.bad
        by_target[case.target, kind] += 1
        if kind not in ("clear error", "accepted"):
            failures.append((case.target, kind, detail))
    return totals, by_target, failures


def table(totals: Counter, by_target: Counter, seconds: float, n: int, seed: int) -> str:
    targets = sorted({t for t, _ in by_target})
    lines = [
        "## Hand-written cases",
        "",
        f"`python -m benchmarks.fuzz --cases {n} --seed {seed}`: {n} generated inputs, {totals['bad inputs']} of them "
        f"bad (one argument of a valid call replaced by a bad value), in {seconds:.0f} s on one core. "
        "Outcomes are defined in `benchmarks/fuzz.py`; a clear error is a ContactsymError with a one-line message.",
        "",
        "| outcome | count |",
        "|---|---|",
    ]
    lines += [f"| {kind} | {totals[kind]} |" for kind in OUTCOMES]
    lines += ["", "| entry point | " + " | ".join(OUTCOMES) + " |", "|---" * (len(OUTCOMES) + 1) + "|"]
    for target in targets:
        lines.append(f"| `{target}` | " + " | ".join(str(by_target[target, k]) for k in OUTCOMES) + " |")
    executed = [t for t in targets if by_target[t, "evaluated text"]]
    if executed:
        lines += [
            "",
            f"Text was executed as Python by {', '.join(f'`{t}`' for t in executed)}: these entry points hand "
            "strings to `sympify`, which evaluates them.",
        ]
    return "\n".join(lines) + "\n"


# --- the generated probe, in worker processes ----------------------------------------------------------


#: Calls with right-typed arguments of these callables do real work longer than the probe's limit:
#: ``paper_figures`` derives and draws the four paper scenes (42 s of CPU at resolution 8 and 20 dpi,
#: measured 2026-11-27 on a loaded 2-core machine). A valid call gets this many seconds before it counts
#: as a hang; a call with a wrong argument keeps the probe's limit (it must be refused at once).
SLOW_VALID = {"contactsym.plotting.paper_figures": 300.0}


def call_limit(target: str, wrong: list, seconds: float) -> float:
    """The time limit of one probe call: :data:`SLOW_VALID` for a call of a slow callable whose arguments all
    have the right types (a right-typed value out of range is refused at once, so the limit does not matter)."""
    return seconds if wrong else max(seconds, SLOW_VALID.get(target, seconds))


def _probe_call(index: int, seed: int, seconds: float) -> tuple[str, str, str]:
    """(target, outcome, detail) of probe call ``index`` (runs in a worker)."""
    rng = random.Random(seed)
    if index < len(_PROBE["targets"]):
        call = boundary.make_call(_PROBE["targets"][index], rng, _PROBE["wrong"])
        case = Case(call.target, lambda: call.function(*call.args, **call.kwargs), bool(call.wrong))
        kind, detail = outcome(case, call_limit(call.target, call.wrong, seconds))
        if kind in ("clear error", "raw traceback", "silent acceptance"):
            detail = f"{detail} [wrong: {', '.join(call.mutated)}]"
        return call.target, kind, detail
    command, argv = boundary.cli_argv(rng, _PROBE["cli"], _PROBE["labels"][index][len("cli ") :])
    case = cli_case_of(argv, is_bad=True)
    case.target = f"cli {command}"
    kind, detail = outcome(case, seconds)
    if kind == "silent acceptance":  # the junk may have been a usable path or name: no claim about it
        kind = "accepted"
    return case.target, kind, f"{detail} {argv!r}"[:300]


_PROBE: dict = {}


def _worker(connection, seconds: float) -> None:
    import resource

    os.chdir(tempfile.mkdtemp(prefix="contactsym-fuzz-"))  # files the calls write land here
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1), os.dup2(devnull, 2)
    with contextlib.suppress(ValueError, OSError):
        resource.setrlimit(resource.RLIMIT_AS, (6 << 30, 6 << 30))  # a memory bomb is a MemoryError, not a crash
    while True:
        job = connection.recv()
        if job is None:
            return
        try:
            connection.send(_probe_call(*job, seconds))
        except BaseException as error:  # noqa: BLE001 - the harness itself must answer
            connection.send(("harness", "raw traceback", f"{type(error).__name__}: {str(error)[:200]}"))


class _Workers:
    """One forked worker; killed and replaced when a call overruns the hard limit."""

    def __init__(self, seconds: float):
        import multiprocessing

        self.context, self.seconds = multiprocessing.get_context("fork"), seconds
        self._start()

    def _start(self):
        self.parent, child = self.context.Pipe()
        self.process = self.context.Process(target=_worker, args=(child, self.seconds), daemon=True)
        self.process.start()

    def run(self, index: int, seed: int, label: str) -> tuple[str, str, str]:
        self.parent.send((index, seed))
        if self.parent.poll(max([self.seconds, *SLOW_VALID.values()]) + 15):
            try:
                return self.parent.recv()
            except EOFError:
                answer = (label, "raw traceback", "the worker died (a crash in compiled code)")
        else:
            answer = (label, "hang", f"more than {self.seconds + 15:g} s (the worker was killed)")
        self.process.kill()
        self.process.join()
        self._start()
        return answer

    def close(self):
        with contextlib.suppress(OSError, BrokenPipeError):
            self.parent.send(None)
        self.process.join(timeout=5)
        if self.process.is_alive():
            self.process.kill()


def probe_targets() -> list[str]:
    """Build the probe (in this process, before any worker forks); returns the labels, CLI commands last."""
    if not _PROBE:
        _PROBE["targets"] = boundary.targets()
        _PROBE["wrong"] = boundary.wrong_values()
        _PROBE["cli"] = boundary.cli_options()
        _PROBE["labels"] = [t.label for t in _PROBE["targets"]] + [f"cli {c}" for c in sorted(_PROBE["cli"])]
    return [t.label for t in _PROBE["targets"]] + [f"cli {c}" for c in sorted(_PROBE["cli"])]


def probe(
    n: int,
    seed: int = 0,
    seconds: float = 30.0,
    progress: bool = False,
    only: tuple[str, ...] = (),
    workers: int = 1,
) -> tuple[Counter, Counter, list]:
    """``n`` generated calls, round-robin over every target (or those whose label starts with one of
    ``only``), in ``workers`` worker processes: totals, totals by target, and the failures."""
    from concurrent.futures import ThreadPoolExecutor

    everything = probe_targets()
    chosen = [i for i, label in enumerate(everything) if not only or label.startswith(only)]
    rng = random.Random(seed)
    jobs = [(chosen[i % len(chosen)], rng.randrange(2**32)) for i in range(n)]  # the calls do not depend on timing
    pool = [_Workers(seconds) for _ in range(workers)]
    totals, by_target, failures = Counter(), Counter(), []

    def share(number: int) -> list:
        return [pool[number].run(index, job_seed, everything[index]) for index, job_seed in jobs[number::workers]]

    try:
        with ThreadPoolExecutor(workers) as threads:
            answers = list(threads.map(share, range(workers)))
    finally:
        for worker in pool:
            worker.close()
    for number, answered in enumerate(answers):
        for (index, _), (_, kind, detail) in zip(jobs[number::workers], answered):
            label = everything[index]
            totals[kind] += 1
            by_target[label, kind] += 1
            if kind not in ("clear error", "accepted"):
                failures.append((label, kind, detail))
    if progress:
        print(f"[fuzz] {n} calls: {dict(totals)}", flush=True)
    return totals, by_target, failures


PROBE_OUTCOMES = ("clear error", "accepted", "raw traceback", "silent acceptance", "evaluated text", "hang")


def _group(label: str) -> str:
    """The table's row for a target: its package (a method counts with its class's package)."""
    if label.startswith("cli "):
        return "command line"
    head = label.rsplit(".", 1)[0]
    return head if head.startswith("contactsym") else f"methods of {head}"


def probe_table(
    totals: Counter, by_target: Counter, seconds: float, n: int, seed: int, where: str, workers: int = 1
) -> str:
    labels = sorted({t for t, _ in by_target})
    groups: dict = {}
    for label in labels:
        groups.setdefault(_group(label), []).append(label)
    lines = [
        "## The generated probe",
        "",
        f"`python -m benchmarks.fuzz --n {n} --seed {seed}`: {n} calls over {len(labels)} public callables "
        f"(every name in `contactsym.__all__` and the subpackages' `__all__`, the public methods of the public "
        f"classes, the command line's subcommands and options), in {seconds:.0f} s with {workers} worker process(es); "
        f"{where}.",
        "",
        "| outcome | count |",
        "|---|---|",
    ]
    lines += [f"| {kind} | {totals[kind]} |" for kind in PROBE_OUTCOMES]
    lines += ["", "| callables of | callables | " + " | ".join(PROBE_OUTCOMES) + " |"]
    lines.append("|---" * (len(PROBE_OUTCOMES) + 2) + "|")
    for group in sorted(groups):
        counts = [sum(by_target[t, k] for t in groups[group]) for k in PROBE_OUTCOMES]
        lines.append(f"| `{group}` | {len(groups[group])} | " + " | ".join(map(str, counts)) + " |")
    bad = [t for t in labels if any(by_target[t, k] for k in PROBE_OUTCOMES[2:])]
    lines += ["", f"Callables with a raw traceback, a silent acceptance or a hang ({len(bad)} of {len(labels)}):", ""]
    lines += [", ".join(f"`{t}`" for t in bad) or "none."]
    return "\n".join(lines) + "\n"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m benchmarks.fuzz", description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=20_000, help="number of generated calls of the probe")
    parser.add_argument("--cases", type=int, default=0, help="hand-written cases to run as well")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--seconds", type=float, default=30.0, help="time limit per call")
    parser.add_argument("--only", default="", help="comma-separated label prefixes: probe only these targets")
    parser.add_argument("--workers", type=int, default=1, help="worker processes")
    parser.add_argument("--where", default="on this machine", help="where and when, for the table")
    parser.add_argument("--out", help="write the Markdown table to this file")
    parser.add_argument("--failures", help="write every failing call to this file")
    args = parser.parse_args(argv)
    started = time.perf_counter()
    only = tuple(p for p in args.only.split(",") if p)
    totals, by_target, failures = probe(args.n, args.seed, args.seconds, True, only, args.workers)
    elapsed = time.perf_counter() - started
    text = probe_table(totals, by_target, elapsed, args.n, args.seed, args.where, args.workers)
    bad = sum(totals[k] for k in PROBE_OUTCOMES[2:])
    if args.cases:
        started = time.perf_counter()
        totals, by_target, more = run(args.cases, args.seed, args.seconds)
        text += "\n" + table(totals, by_target, time.perf_counter() - started, args.cases, args.seed)
        failures += more
        bad += sum(totals[k] for k in OUTCOMES if k not in ("clear error", "accepted"))
    print(text)
    if args.failures:
        Path(args.failures).write_text("\n".join(f"{k} | {t} | {d}" for t, k, d in failures) + "\n")
    if args.out:
        Path(args.out).write_text(text)
    return 0 if bad == 0 else 1


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
