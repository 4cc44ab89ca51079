"""robustness: undecided fraction and time per point of ``robustness.decide_robustness`` against Props 7/8.

Ours: :func:`contactsym.robustness.classify.decide_robustness` (certificates and exact witness laws), per point.
Baseline: what contactsym had for k >= 3: Proposition 7 (A symmetric positive definite:
stable for every law) and Proposition 8 (det A < 0 or all a_ss < 0: unstable for every
law), the rest undecided. Cases: random A with entries uniform in [-2, 2] (k = 3 and 4,
two decimals) and a three-legged stool (k = 3, derived by the pipeline from its
accelerations, ``tests/stool.py``) over random (sign pattern, mu, h). error = claims
(ours and the baseline's) contradicted by the eigenvalues of (4.5) at sampled laws.
"""

from __future__ import annotations

import itertools
import time

import numpy as np
import sympy as sp

from contactsym.robustness.classify import decide_robustness, nested_sequences
from contactsym.robustness.law_polynomials import LawPolynomials, fast_spectral_abscissa

from . import record

VERDICTS = ("stable", "unstable", "law-dependent", "undecided")


def _random_matrices(k, n, seed):
    rng = np.random.default_rng(seed)
    return [sp.Matrix(k, k, [sp.Rational(int(x), 100) for x in rng.integers(-200, 201, k * k)]) for _ in range(n)]


def _stool_matrices(n, seed):
    from tests.stool import h, mu, stool_scene

    scene = stool_scene()
    patterns = list(itertools.product([1, -1], repeat=3))
    symbolic = {p: scene.linearization(signs=p).A for p in patterns}
    rng = np.random.default_rng(seed)
    points = []
    for _ in range(n):
        signs = patterns[rng.integers(len(patterns))]
        mu_value = sp.Rational(int(rng.integers(0, 201)), 100)
        h_value = sp.Rational(int(rng.integers(20, 301)), 100)
        points.append(symbolic[signs].xreplace({mu: mu_value, h: h_value}))
    return points


def baseline(A: np.ndarray) -> str:
    """Propositions 7 and 8 (the k >= 3 classification before the certificates)."""
    if np.linalg.det(A) < 0 or (np.diag(A) < 0).all():
        return "unstable"
    if np.array_equal(A, A.T) and (np.linalg.eigvalsh(A) > 0).all():
        return "stable"
    return "undecided"


def _contradicted(verdict: str, A: np.ndarray, laws: int, seed: int) -> bool:
    if verdict not in ("stable", "unstable"):
        return False
    rng = np.random.default_rng(seed)
    k = A.shape[0]
    c, d = 10.0 ** rng.uniform(-3, 3, (laws, k)), 10.0 ** rng.uniform(-3, 3, (laws, k))
    top = fast_spectral_abscissa(A, c, d)
    tol = 1e-9 * np.maximum(1.0, np.abs(A).sum() * (c.max(axis=1) + d.max(axis=1)))
    return bool((top >= tol).any()) if verdict == "stable" else bool((top <= -tol).any())


def _nested_conjecture(A, Af: np.ndarray, laws: int, seed: int) -> int:
    """1 if A has no nested sequence of positive principal minors, det A > 0, and a sampled law is
    stable: P6's converse fails there (rare; such points are why the unstable side needs P5)."""
    lp = LawPolynomials(A)
    if lp.minors[tuple(range(lp.k))] <= 0 or nested_sequences(lp.minors):
        return 0
    return int(_contradicted("unstable", Af, laws, seed))


def _case(matrices, laws):
    ours, base, errors, seconds, base_seconds = [], [], 0, [], 0.0
    counterexamples = 0
    for i, A in enumerate(matrices):
        t0 = time.process_time()  # CPU seconds: the machine may be shared
        result = decide_robustness(A)
        seconds.append(time.process_time() - t0)
        Af = np.array(A.tolist(), dtype=float)
        t0 = time.process_time()
        base.append(baseline(Af))
        base_seconds += time.process_time() - t0
        ours.append(result.verdict)
        errors += _contradicted(result.verdict, Af, laws, i) + _contradicted(base[-1], Af, laws, i)
        counterexamples += _nested_conjecture(A, Af, laws, i)
    return ours, base, errors, np.array(seconds), base_seconds / len(matrices), counterexamples


def _fractions(verdicts) -> dict:
    return {v: verdicts.count(v) / len(verdicts) for v in VERDICTS}


def robustness_plot(rows, ax=None):
    """Stacked verdict fractions, ours and baseline side by side, per case; returns the bars."""
    import matplotlib.pyplot as plt

    if ax is None:
        ax = plt.figure(figsize=(8, 4)).add_subplot()
    labels, bottoms, artists = [], None, []
    fractions = []
    for name, ours, base in rows:
        labels += [f"{name}\nours", f"{name}\nProps 7/8"]
        fractions += [ours, base]
    bottoms = np.zeros(len(fractions))
    colors = {"stable": "tab:green", "unstable": "tab:red", "law-dependent": "tab:orange", "undecided": "0.7"}
    for verdict in VERDICTS:
        heights = np.array([f[verdict] for f in fractions])
        artists.append(ax.bar(labels, heights, bottom=bottoms, color=colors[verdict], label=verdict))
        bottoms += heights
    ax.set_ylabel("fraction of points")
    ax.set_title("robustness to the contact law (k >= 3): certificates and witness laws vs Props 7/8", fontsize=9)
    ax.legend(fontsize=8, loc="upper right")
    ax.tick_params(axis="x", labelsize=7)
    return artists


def run(quick: bool, out) -> list[dict]:
    sizes = (
        # --quick: ~25-90 ms a point plus the checks of the sampled laws, part of a 3-minute bench (half the points of
        # 80, 20, 60 before: ~22 CPU s for the module on 2026-11-28)
        {"random-3x3": 40, "random-4x4": 10, "stool": 30}
        if quick
        else {"random-3x3": 1000, "random-4x4": 100, "stool": 500}
    )
    laws = 2000 if quick else 10_000
    cases = {
        "random-3x3": _random_matrices(3, sizes["random-3x3"], 11),
        "random-4x4": _random_matrices(4, sizes["random-4x4"], 12),
        "stool": _stool_matrices(sizes["stool"], 13),
    }
    decide_robustness(cases["random-3x3"][0])  # caches the generic Hurwitz minors (not timed)
    decide_robustness(cases["random-4x4"][0])
    records, rows = [], []
    print(f"{'case':<12} {'undecided ours':>15} {'Props 7/8':>10} {'ms/point':>9} {'max ms':>8} {'false claims':>12}")
    for name, matrices in cases.items():
        ours, base, errors, seconds, base_seconds, counterexamples = _case(matrices, laws)
        fo, fb = _fractions(ours), _fractions(base)
        rows.append((name, fo, fb))
        print(
            f"{name:<12} {fo['undecided']:>15.3f} {fb['undecided']:>10.3f} {1e3 * seconds.mean():>9.1f} "
            f"{1e3 * seconds.max():>8.0f} {errors:>12d}"
        )
        notes = (
            f"{len(matrices)} points; undecided {fo['undecided']:.3f} (Props 7/8: {fb['undecided']:.3f}); ours "
            + ", ".join(f"{v} {fo[v]:.3f}" for v in VERDICTS[:3])
            + f"; per point mean {1e3 * seconds.mean():.1f} ms, max {1e3 * seconds.max():.0f} ms (CPU); "
            f"claims checked against {laws} sampled laws per point; points without a nested sequence of positive "
            f"principal minors (det A > 0) where a sampled law is stable: {counterexamples}; ratio = baseline time / ours (< 1: ours is slower, "
            "and decides more)"
        )
        records.append(record(f"robustness/{name}", float(seconds.mean()), base_seconds, errors, len(matrices), notes))
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4))
    robustness_plot(rows, ax=ax)
    fig.tight_layout()
    fig.savefig(out / "robustness.png", dpi=120)
    plt.close(fig)
    return records
