"""One cold derivation in a fresh process: ``python -m benchmarks._derive_worker MODE TARGET``.

MODE is ours or naive; TARGET a scene name or generic-K. Prints one JSON line.
"""

from __future__ import annotations

import json
import sys
import time


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


def build(target: str):
    if target.startswith("generic-"):
        return generic_scene(int(target.split("-")[1]))
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


def main(argv: list[str]) -> int:
    mode, target = argv[0], argv[1]
    started = time.perf_counter()
    import contactsym  # noqa: F401

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
