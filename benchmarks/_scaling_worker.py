"""One cold derivation of a mechanism in a fresh process: ``python benchmarks/_scaling_worker.py MODE TARGET``.

MODE is ``ours`` (the contact-space derivation of the contactsym on the path) or ``naive``
(the way before it: the accelerations by LU solve of the symbolic mass matrix, each expanded,
then the same stages with expand-based normalization). Run with another contactsym first on
``PYTHONPATH`` (an older checkout), ``ours`` measures that one: the benchmark's baseline.
TARGET is ``chain-N`` (point masses, one tip contact, the built-in chain), ``stepladder``, a
built-in scene, ``arm`` (examples/four-link-arm.toml) or ``links-N-C-KIND`` (a scene file
written here: N links of KIND ``rods`` or ``points``, C = 1..3 contacts); a suffix ``-fixed``
fixes every mass and length at 1 (``Scene.with_values`` where it exists, else the numbers
written into the file). Prints one JSON line: seconds from scene to Hurwitz conditions and
robust classification, and operation counts; with a third argument LIMIT, ``null`` when that is not done LIMIT
seconds after the imports.
"""

from __future__ import annotations

import json
import re
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _expand_normalize(expr):
    """The normalization of earlier versions: expand, then sin^2 = 1 - cos^2 and s^2 = 1."""
    import sympy as sp

    from contactsym.algebra.basic import reduce_signs, reduce_trig

    return reduce_signs(reduce_trig(sp.expand(expr)))


def _use_the_naive_way() -> None:
    """Accelerations by LU solve + expand, and expand-based normalization in every stage."""
    import contactsym as cs
    from contactsym.mechanism import contact_space as mechanics
    from contactsym.mechanism.scene import Contact, Scene
    from contactsym.stages import equilibria, fast, linear, regions, regularize, stability

    for module in (fast, linear, stability, equilibria, regions, regularize):
        module.normalize = _expand_normalize

    def from_lagrangian(cls, lagrangian, coordinates, contacts, loads=(), frame=None, **options):
        space = mechanics.contact_space(lagrangian, coordinates, contacts, loads, frame)
        accelerations = [_expand_normalize(a) for a in space.M.LUsolve(space.forcing)]
        plain = [Contact(c.coordinate, c.reaction, c.compliance, None, c.unilateral) for c in contacts]
        return cls(coordinates, accelerations, plain, **options)

    Scene.from_lagrangian = classmethod(from_lagrangian)
    assert cs.Scene is Scene


def chain_file(n: int, contacts: int, kind: str) -> str:
    """A scene file: n links pinned at the origin at angles q_i from the downward vertical, as
    uniform rods or as point masses at the joints; the tip slides in +x on a rough floor, and
    for contacts 2 and 3 the joints ceil(n/2) and 1 (or 2) slide up rough walls x = w_2, w_3."""
    if not 1 <= contacts <= min(3, n):
        raise ValueError(f"{contacts} contacts on {n} links")
    rods = kind == "rods"
    q = [f"q{i}" for i in range(1, n + 1)]

    def joint(j, half=False):  # the joint at the end of link j (or the middle of link j)
        x = " + ".join(f"l{i}*sin(q{i})" + ("/2" if half and i == j else "") for i in range(1, j + 1))
        y = " - ".join(f"l{i}*cos(q{i})" + ("/2" if half and i == j else "") for i in range(1, j + 1))
        return x, "-" + y

    lines = ["[scene]", f'name = "links-{n}-{contacts}-{kind}"', f"coordinates = {json.dumps(q)}", "[parameters]"]
    names = [f"m{i}" for i in range(1, n + 1)] + [f"l{i}" for i in range(1, n + 1)] + ["g", "h"]
    names += [f"w{c}" for c in range(2, contacts + 1)] + [f"mu_{c}" for c in range(1, contacts + 1)]
    lines += [f'{name} = "positive"' for name in names]
    lines.append("[points]")
    for j in range(1, n + 1):
        x, y = joint(j)
        lines.append(f'P{j} = ["{x}", "{y}"]')
        if rods:
            x, y = joint(j, half=True)
            lines.append(f'C{j} = ["{x}", "{y}"]')
    for j in range(1, n + 1):
        if rods:
            lines += [
                "[[bodies]]",
                f'point = "C{j}"',
                f'angle = "q{j}"',
                f'mass = "m{j}"',
                f'inertia = "m{j}*l{j}^2/12"',
            ]
        else:
            lines += ["[[masses]]", f'point = "P{j}"', f'mass = "m{j}"']
    height = [f"m{j}*g*({joint(j, half=rods)[1]})" for j in range(1, n + 1)]
    lines += ["[energy]", f'potential = "{" + ".join(height)}"']
    tip_y = joint(n)[1]
    lines += ["[[contacts]]", f'gap = "h + ({tip_y})"', 'reaction = "N_1"', "unilateral = true"]
    lines.append(f'friction = {{ mu = "mu_1", point = "P{n}", direction = ["1", "0"] }}')
    at = [f'h = "-({tip_y})"']
    for c, j in zip(range(2, contacts + 1), [(n + 1) // 2, 1 if (n + 1) // 2 != 1 else 2]):
        x = joint(j)[0]
        lines += ["[[contacts]]", f'gap = "w{c} - ({x})"', f'reaction = "N_{c}"', "unilateral = true"]
        lines.append(f'friction = {{ mu = "mu_{c}", point = "P{j}", direction = ["0", "1"] }}')
        at.append(f'w{c} = "{x}"')
    return "\n".join(lines + ["[at]", *at]) + "\n"


def _numbers_written_in(text: str, names: list[str]) -> str:
    """The file with each name replaced by 1 in its formulas and dropped from [parameters]."""
    head, rest = text.split("[points]", 1)
    for name in names:
        head = re.sub(rf'^{name} = "positive"\n', "", head, flags=re.M)
        rest = re.sub(rf"\b{name}\b", "1", rest)
    return head + "[points]" + rest


def build(target: str):
    fixed = target.endswith("-fixed")
    target = target.removesuffix("-fixed")
    if target == "arm" or target.startswith("links-"):
        from contactsym.mechanism.files import read_scene

        if target == "arm":
            text, n = (ROOT / "examples" / "four-link-arm.toml").read_text(), 4
        else:
            _, n, contacts, kind = target.split("-")
            n = int(n)
            text = chain_file(n, int(contacts), kind)
        names = [f"{p}{i}" for p in "ml" for i in range(1, n + 1)]
        if not fixed:
            return read_scene(text, f"{target}.toml")
        if "[values]" in (ROOT / "contactsym" / "mechanism" / "files" / "spec.py").read_text() and hasattr(
            __import__("contactsym").Scene, "with_values"
        ):
            return read_scene(text, f"{target}.toml").with_values(dict.fromkeys(names, 1))
        return read_scene(_numbers_written_in(text, names), f"{target}.toml")
    if target.startswith("chain-"):
        from contactsym.scenes.link_chain import build_chain

        return build_chain(int(target.split("-")[1]))
    if target == "stepladder":
        from contactsym.scenes.stepladder import build as build_stepladder

        return build_stepladder()
    from importlib import import_module

    from contactsym.scenes import _MODULES

    return import_module(f"contactsym.scenes.{_MODULES[target]}").build()


def _limit(seconds: float) -> None:
    """After ``seconds`` (wall time) print ``null`` (not finished) and end the process; 0 cancels it."""
    import os
    import signal

    def out_of_time(signum, frame):
        print("null", flush=True)
        os._exit(0)

    signal.signal(signal.SIGALRM, out_of_time)
    signal.setitimer(signal.ITIMER_REAL, seconds)


def main(argv: list[str]) -> int:
    import sympy as sp

    mode, target = argv[0], argv[1]
    from benchmarks import load_pipeline

    load_pipeline()  # import time is not measured

    if mode == "naive":
        _use_the_naive_way()
    if len(argv) > 2:  # a time limit from here, the imports done (on a loaded machine they alone take seconds)
        _limit(float(argv[2]))
    started, cpu = time.perf_counter(), time.process_time()
    scene = build(target)
    if mode == "report":  # the whole report, the PDF too where pdflatex is installed
        import tempfile

        from contactsym.report import write_report

        with tempfile.TemporaryDirectory() as directory:
            pdf = write_report(scene, Path(directory) / "report").pdf is not None
        seconds, cpu_s = time.perf_counter() - started, time.process_time() - cpu
        print(json.dumps({"seconds": seconds, "cpu_s": cpu_s, "pdf": pdf}))
        return 0
    lin = scene.linearization()
    st = scene.stability()
    conditions = st.hurwitz
    hurwitz_s, hurwitz_cpu = time.perf_counter() - started, time.process_time() - cpu
    claims = (st.robustly_stable, st.robustly_unstable)
    seconds, cpu_s = time.perf_counter() - started, time.process_time() - cpu
    if len(argv) > 2:  # done in time: the counts below are not timed
        _limit(0)
    # the times first (stderr): the operation counts below need A's entries, minutes on a six-link chain
    print(json.dumps({"seconds": seconds, "cpu_s": cpu_s, "hurwitz_cpu_s": hurwitz_cpu}), file=sys.stderr, flush=True)
    info = {
        "seconds": seconds,
        "hurwitz_s": hurwitz_s,
        "cpu_s": cpu_s,
        "hurwitz_cpu_s": hurwitz_cpu,
        "ops_f": int(sp.count_ops(scene.fast_subsystem().f)) if not target.startswith(("arm", "links")) else None,
        "ops_A": int(sp.count_ops(lin.A)),
        "ops_hurwitz": int(sum(sp.count_ops(c) for c in conditions)),
        "claims": len(claims),
    }
    print(json.dumps(info))
    return 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path.cwd()))  # run as a file: the contactsym of the working directory first
    sys.exit(main(sys.argv[1:]))
