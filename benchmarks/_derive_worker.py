"""One cold derivation in a fresh process: ``python -m benchmarks._derive_worker MODE TARGET [STAGE]``.

MODE is ours, naive or stage; TARGET a scene name, generic-K (q_i'' = sum_j a_ij N_j + b_i) or
stool-KIND (the three-legged stool of ``tests/stool.py``, KIND numbers, masses or feet). The
stage mode times one STAGE (frequency, hopf, regions, or regions-unlimited: regions with
the limits RAW_OPS and FACTOR_TERMS of :mod:`contactsym.stages.regions` lifted). Prints one JSON line, with
wall and CPU seconds.

Run as a script (``python benchmarks/_derive_worker.py ...``) with another tree's
``contactsym`` on PYTHONPATH, it times that tree on the same scenes: the stool and the
generic scenes are built here from the public API and this tree's ``tests/stool.py``.
"""

from __future__ import annotations

import json
import sys
import time
from importlib.util import module_from_spec, spec_from_file_location
from pathlib import Path

#: This tree's stool builder (loaded by path: a baseline tree may not have its options).
STOOL = Path(__file__).resolve().parent.parent / "tests" / "stool.py"


def generic_scene(k: int):
    import sympy as sp
    from sympy.physics.mechanics import dynamicsymbols

    import contactsym as cs

    q = [dynamicsymbols(f"q_{i}") for i in range(1, k + 1)]
    N = sp.symbols(f"N_1:{k + 1}", real=True)
    a = sp.Matrix(k, k, lambda i, j: sp.Symbol(f"a_{i + 1}{j + 1}", real=True))
    b = sp.symbols(f"b_1:{k + 1}", real=True)
    G = [sum(a[i, j] * N[j] for j in range(k)) + b[i] for i in range(k)]
    return cs.Scene.from_accelerations(q, G, [cs.Contact(coordinate=q[i], reaction=N[i]) for i in range(k)])


def stool_scene(kind: str):
    """The stool of ``tests/stool.py`` with ``symbolic=kind`` (numbers, masses or feet)."""
    spec = spec_from_file_location("_stool_builder", STOOL)
    module = module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.stool_scene(symbolic=kind)


def build(target: str):
    if target.startswith("generic-"):
        return generic_scene(int(target.split("-")[1]))
    if target.startswith("stool-"):
        return stool_scene(target.split("-", 1)[1])
    from importlib import import_module

    from contactsym.scenes import _MODULES

    return import_module(f"contactsym.scenes.{_MODULES[target]}").build()


def ours(scene) -> dict:
    st = scene.stability()
    stages = [
        scene.fast_subsystem().rhs,
        scene.equilibria().branches,
        scene.linearization().charpoly,
        st.hurwitz,
        st.robustly_stable,
        st.robustly_unstable,
        st.law_dependent,
        st.hopf,
        st.hopf_frequency,
    ]
    return {"conditions": len(st.hurwitz), "stages": len(stages)}


def naive(scene) -> dict:
    import sympy as sp

    lam = sp.Symbol("lambda")
    M = scene.linearization().jacobian
    p = sp.expand((lam * sp.eye(M.rows) - M).det())
    coefficients = sp.Poly(p, lam).all_coeffs()
    n = len(coefficients) - 1
    H = sp.Matrix(n, n, lambda i, j: coefficients[2 * (j + 1) - (i + 1)] if 0 <= 2 * (j + 1) - (i + 1) <= n else 0)
    minors = [sp.expand(H[:m, :m].det(method="berkowitz")) for m in range(1, n + 1)]
    return {"charpoly": p, "minors": len(minors)}


def stage(scene, name: str) -> list:
    """The expressions of one stage: the Hopf frequency, the Hopf set and frequency, or the regions."""
    stability = scene.stability()
    if name == "frequency":
        return [stability.hopf_frequency]
    if name == "hopf":  # as printed: each coefficient p_s in its shortest form (a baseline without it: as derived)
        printed = (getattr(stability, "hopf_printed", None), getattr(stability, "hopf_frequency_printed", None))
        return [stability.hopf, stability.hopf_frequency] if printed[0] is None else list(printed)
    if name == "regions-unlimited":  # every relation normalized, expanded and factored
        from contactsym.stages import regions

        regions.RAW_OPS = regions.FACTOR_TERMS = sys.maxsize  # no limit (inf is refused as an argument)
    return [region.condition for region in scene.regions().values()]


def timed_stage(target: str, name: str) -> dict:
    """Scene build and one stage, cold (import excluded): wall and CPU seconds, the size of the result."""
    import sympy as sp

    from benchmarks import load_pipeline

    load_pipeline()  # import time is not measured

    wall, cpu = time.perf_counter(), time.process_time()
    result = stage(build(target), name)
    wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    return {"seconds": wall, "cpu_s": cpu, "ops": sum(int(sp.count_ops(r)) for r in result), "parts": len(result)}


def main(argv: list[str]) -> int:
    mode, target = argv[0], argv[1]
    if mode == "stage":
        print(json.dumps(timed_stage(target, argv[2])))
        return 0
    started = time.perf_counter()
    from benchmarks import load_pipeline

    load_pipeline()
    imported = time.perf_counter()
    scene = build(target)
    if mode == "ours":
        info = ours(scene)
        seconds = time.perf_counter() - imported
    else:
        result = naive(scene)
        seconds = time.perf_counter() - imported
        import sympy as sp

        from contactsym.algebra.basic import normalize

        derived = scene.linearization().charpoly  # its variable is the pipeline's own symbol, not a user's lambda
        naive_poly = result["charpoly"].subs(sp.Symbol("lambda"), derived.gen)
        info = {"agree": normalize(naive_poly - derived.as_expr()) == 0}  # sin^2 + cos^2 = 1, s^2 = 1
    print(json.dumps({"seconds": seconds, "import_s": imported - started, **info}))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
