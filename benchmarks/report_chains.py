"""Reports of random planar chains: ``report`` must never fail where ``conditions`` succeeds (issue 26).

Each chain has 1-4 links pinned at one end, each a uniform rod (centroidal inertia m l^2/12) or
a point mass at its far end, and 1-2 unilateral contacts with Coulomb friction: the tip on a
floor and, for two, a joint on a second floor. Masses and lengths are symbols up to two links,
random rationals beyond (the symbolic 3- and 4-link determinants are another issue's subject).

``python -m benchmarks.report_chains [COUNT] [SEED] [--pdf] [--limit=SECONDS]`` builds COUNT chains, runs
``conditions`` and then the report on each (``--pdf``: the whole directory with pdflatex), each
step with a time limit, and prints one line per chain and a table of the outcomes. A chain whose
``conditions`` fails or runs out of time does not count; a report that fails where
``conditions`` succeeded is a failure. The suite's test runs a few chains through the same code.
"""

from __future__ import annotations

import random
import signal
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import sympy as sp
from sympy.physics.mechanics import Lagrangian, Particle, Point, ReferenceFrame, RigidBody, dynamicsymbols, inertia

from contactsym import Contact, Coulomb, Scene
from contactsym.report import conditions, report_tex, write_report

__all__ = ["Chain", "build_chain", "random_chain", "check_chain"]


@dataclass(frozen=True)
class Chain:
    """What a random chain is made of."""

    links: int
    rods: tuple  # per link: True for a rod, False for a point mass at its far end
    contacts: int  # 1: the tip; 2: the tip and the joint ``joint``
    joint: int
    directions: tuple  # +1 or -1 per contact: the sliding direction along the floor
    symbolic: bool
    masses: tuple = ()
    lengths: tuple = ()

    def __str__(self) -> str:
        bodies = "".join("R" if rod else "P" for rod in self.rods)
        where = "tip" if self.contacts == 1 else f"tip+joint{self.joint}"
        return f"{self.links} links {bodies}, {where}, {'symbolic' if self.symbolic else 'numeric'}"


def random_chain(rng: random.Random, max_links: int = 4, max_contacts: int = 2, symbolic: bool | None = None) -> Chain:
    """A random chain; masses and lengths are symbols up to two links unless ``symbolic`` says otherwise."""
    links = rng.randint(1, max_links)
    contacts = 1 if links == 1 else rng.randint(1, max_contacts)
    symbolic = links <= 2 if symbolic is None else symbolic
    return Chain(
        links,
        tuple(rng.random() < 0.5 for _ in range(links)),
        contacts,
        rng.randint(1, links - 1) if contacts == 2 else 0,
        tuple(rng.choice((1, -1)) for _ in range(contacts)),
        symbolic,
        tuple(sp.Rational(rng.randint(1, 9), rng.randint(1, 4)) for _ in range(links)),
        tuple(sp.Rational(rng.randint(1, 9), rng.randint(1, 4)) for _ in range(links)),
    )


def build_chain(chain: Chain) -> Scene:
    """The chain as a Lagrangian scene (``sympy.physics.mechanics``), contacts unilateral."""
    n = chain.links
    q = [dynamicsymbols(f"q{i + 1}") for i in range(n)]
    if chain.symbolic:
        m = [sp.Symbol(f"m{i + 1}", positive=True) for i in range(n)]
        l = [sp.Symbol(f"l{i + 1}", positive=True) for i in range(n)]
    else:
        m, l = list(chain.masses), list(chain.lengths)
    g, mu = sp.symbols("g mu", positive=True)
    O = ReferenceFrame("O")
    pivot = Point("O")
    pivot.set_vel(O, 0)
    bodies, joints, joint = [], [], pivot
    for i in range(n):
        axis = sp.sin(q[i]) * O.x - sp.cos(q[i]) * O.y
        end = joint.locatenew(f"P{i + 1}", l[i] * axis)
        end.set_vel(O, end.pos_from(pivot).dt(O))
        if chain.rods[i]:
            frame = O.orientnew(f"L{i + 1}", "Axis", [q[i], O.z])
            frame.set_ang_vel(O, sp.diff(q[i], dynamicsymbols._t) * O.z)
            centre = joint.locatenew(f"C{i + 1}", l[i] * axis / 2)
            centre.set_vel(O, centre.pos_from(pivot).dt(O))
            body = RigidBody(f"rod{i + 1}", centre, frame, m[i], (inertia(frame, 0, 0, m[i] * l[i] ** 2 / 12), centre))
            body.potential_energy = m[i] * g * centre.pos_from(pivot).dot(O.y)
        else:
            body = Particle(f"mass{i + 1}", end, m[i])
            body.potential_energy = m[i] * g * end.pos_from(pivot).dot(O.y)
        bodies.append(body)
        joints.append(end)
        joint = end
    touching = [joints[-1]] + ([joints[chain.joint - 1]] if chain.contacts == 2 else [])
    contacts, at = [], {}
    for j, (point, direction) in enumerate(zip(touching, chain.directions), 1):
        depth, N = sp.Symbol(f"h{j}", positive=True), sp.Symbol(f"N{j}", real=True)
        height = point.pos_from(pivot).dot(O.y)
        contacts.append(
            Contact(
                coordinate=height + depth, reaction=N, unilateral=True, friction=Coulomb(mu, direction * O.x, point)
            )
        )
        at[depth] = -height
    return Scene.from_lagrangian(
        Lagrangian(O, *bodies), q, contacts, frame=O, at=at, name="chain", solve_for=mu, description=str(chain)
    )


class _OutOfTime(BaseException):
    """Not an Exception: the report's guards (a section that fails becomes a note) must not catch it."""


def _limited(seconds: float, work):
    """``work()`` with a wall-clock limit (SIGALRM): its result, or _OutOfTime."""

    def stop(signum, frame):
        raise _OutOfTime

    previous = signal.signal(signal.SIGALRM, stop)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        return work()
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def check_chain(chain: Chain, limit: float = 120, pdf: bool = False) -> tuple[str, float, str]:
    """(outcome, seconds, detail): 'report ok', 'REPORT FAILED', or why the chain does not count."""
    started = time.perf_counter()
    try:
        scene = _limited(limit, lambda: build_chain(chain))
        _limited(limit, lambda: conditions(scene))
    except _OutOfTime:
        return "conditions out of time", time.perf_counter() - started, ""
    except Exception as error:  # conditions fails: the report need not succeed
        return "conditions failed", time.perf_counter() - started, f"{type(error).__name__}: {str(error)[:160]}"
    try:
        if pdf:
            with tempfile.TemporaryDirectory() as directory:
                result = _limited(limit, lambda: write_report(scene, Path(directory) / "chain"))
                if result.pdf is not None and not result.pdf.read_bytes().startswith(b"%PDF"):
                    return "REPORT FAILED", time.perf_counter() - started, "no PDF"
                tex = result.tex.read_text()
        else:
            tex = _limited(limit, lambda: report_tex(scene))
        if not tex.rstrip().endswith(r"\end{document}"):
            return "REPORT FAILED", time.perf_counter() - started, "incomplete document"
        if "Not derived" in tex:  # written whole, a section in a note
            return "report ok, a section noted", time.perf_counter() - started, ""
    except _OutOfTime:
        return "report out of time", time.perf_counter() - started, ""
    except Exception as error:
        return "REPORT FAILED", time.perf_counter() - started, f"{type(error).__name__}: {str(error)[:300]}"
    return "report ok", time.perf_counter() - started, ""


def main(argv: list[str]) -> int:
    numbers = [a for a in argv if not a.startswith("--")]
    count = int(numbers[0]) if numbers else 50
    seed = int(numbers[1]) if len(numbers) > 1 else 26
    pdf = "--pdf" in argv
    limit = next((float(a.split("=", 1)[1]) for a in argv if a.startswith("--limit=")), 120.0)
    rng = random.Random(seed)
    outcomes: dict[str, int] = {}
    for index in range(count):
        chain = random_chain(rng)
        outcome, seconds, detail = check_chain(chain, limit, pdf=pdf)
        outcomes[outcome] = outcomes.get(outcome, 0) + 1
        print(f"{index + 1:3d}  {str(chain):42s} {outcome:24s} {seconds:6.1f} s  {detail}", flush=True)
    print("\n| outcome | chains |\n|---|---|")
    for outcome, number in sorted(outcomes.items()):
        print(f"| {outcome} | {number} |")
    return 1 if outcomes.get("REPORT FAILED") else 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main(sys.argv[1:]))
