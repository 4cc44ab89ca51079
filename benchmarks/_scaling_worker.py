"""One cold derivation of a mechanism in a fresh process: ``python -m benchmarks._scaling_worker MODE TARGET``.

MODE is ``ours`` (the contact-space derivation) or ``naive`` (today's way before it: the
accelerations by LU solve of the symbolic mass matrix, each expanded, then the same stages
with expand-based normalization). TARGET is ``chain-N``, ``stepladder`` or a built-in scene.
Prints one JSON line: seconds from scene to stability, and operation counts.
"""

from __future__ import annotations

import json
import sys
import time


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


def build(target: str):
    if target.startswith("chain-"):
        from contactsym.scenes.link_chain import build_chain

        return build_chain(int(target.split("-")[1]))
    if target == "stepladder":
        from contactsym.scenes.stepladder import build as build_stepladder

        return build_stepladder()
    from importlib import import_module

    from contactsym.scenes import _MODULES

    return import_module(f"contactsym.scenes.{_MODULES[target]}").build()


def main(argv: list[str]) -> int:
    import sympy as sp

    mode, target = argv[0], argv[1]
    import contactsym  # noqa: F401

    if mode == "naive":
        _use_the_naive_way()
    started = time.perf_counter()
    scene = build(target)
    lin = scene.linearization()
    st = scene.stability()
    conditions = st.hurwitz
    claims = (st.robustly_stable, st.robustly_unstable)
    seconds = time.perf_counter() - started
    info = {
        "seconds": seconds,
        "ops_f": int(sp.count_ops(scene.fast_subsystem().f)),
        "ops_A": int(sp.count_ops(lin.A)),
        "ops_hurwitz": int(sum(sp.count_ops(c) for c in conditions)),
        "claims": len(claims),
    }
    print(json.dumps(info))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
