"""classification: region membership for >= 10^6 parameter points of the brake.

Ours: the closed-form Hurwitz conditions of the brake (4.7), factored, with factors of
known sign dropped, evaluated vectorised by ``contactsym.numerics.PointClassifier`` with
a certified error bound; points inside the band are decided exactly in rationals.
Baseline: per point, the matrix (4.5) and ``numpy.linalg.eigvals`` (timed on a subsample
and extrapolated; all points are checked against the batched eigenvalues). Times are CPU
seconds of this process (best of several runs): the bench shares its machine.
"""

from __future__ import annotations

import math
import time
from fractions import Fraction

import numpy as np
import sympy as sp

import contactsym as cs
from contactsym import numerics as nm

from . import record


def _sample(rng, n):
    return {
        "alpha": rng.uniform(0.05, math.pi - 0.05, n),
        "m": rng.uniform(0.2, 5, n),
        "mu": rng.uniform(0.05, 3, n),
        "Phi_1": -np.exp(rng.normal(0, 1.5, n)),
        "Phi_2": -np.exp(rng.normal(0, 1.5, n)),
        "Psi_1": -np.exp(rng.normal(0, 1.5, n)),
        "Psi_2": -np.exp(rng.normal(0, 1.5, n)),
    }


def _on_hopf_line(rng, n):
    """Points of the (6.4) slice placed on the Hopf line, in floats: inside the band."""
    m, mu, psi = rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n), -np.exp(rng.normal(0, 1, n))
    phi = -(1 + mu**2) * psi**2 / (m * mu**2)
    return {"alpha": np.full(n, math.pi / 2), "m": m, "mu": mu, "Phi_1": phi, "Phi_2": phi, "Psi_1": psi, "Psi_2": psi}


def _best_of(repeat, function):
    """(seconds, result): the least CPU time of this process over ``repeat`` runs. CPU time, not wall time: on
    a shared machine a run of a few milliseconds is preempted by the other jobs more often than not."""
    best, result = math.inf, None
    for _ in range(repeat):
        started = time.process_time()
        result = function()
        best = min(best, time.process_time() - started)
    return best, result


def _per_point_eigenvalues(M, values, index) -> float:
    """Seconds per point: build (4.5) for one point, then ``numpy.linalg.eigvals``."""
    started = time.process_time()
    for i in index:
        np.linalg.eigvals(np.array(M(*[v[i] for v in values]), dtype=float)).real.max()
    return (time.process_time() - started) / len(index)


def _batched_max_real_part(matrix, parameters, values) -> np.ndarray:
    """The largest real part of the eigenvalues of (4.5) at every point, batched."""
    n, size = len(values[0]), matrix.shape[0]
    matrices = np.empty((n, size, size))
    for i in range(size):
        for j in range(size):
            matrices[:, i, j] = np.broadcast_to(sp.lambdify(parameters, matrix[i, j], modules="numpy")(*values), (n,))
    return np.linalg.eigvals(matrices).real.max(axis=1)


def _against_eigenvalues(matrix, parameters, values, index, result) -> tuple[float, int]:
    """(seconds per point of the per-point baseline on ``index``, disagreements of ``result``
    outside its band with the batched eigenvalues of all points)."""
    M = sp.lambdify(parameters, matrix, modules="numpy", cse=True)
    per_point = _per_point_eigenvalues(M, values, index)
    eig_stable = _batched_max_real_part(matrix, parameters, values) < 0
    outside = ~result.in_band
    return per_point, int(np.sum((result.stable[outside] == 1) != eig_stable[outside]))


def _exact_stable(conditions, parameters, columns) -> np.ndarray:
    """All conditions > 0 at each point, in exact rationals (the binary inputs as Fractions)."""
    evaluate = sp.lambdify(parameters, conditions, modules=[])  # integer coefficients: Fractions stay exact
    out = []
    for point in zip(*columns):
        values = evaluate(*(Fraction(float(v)) for v in point))
        if not all(isinstance(v, (Fraction, int)) for v in values):
            raise ValueError("the conditions are not rational functions with rational coefficients")
        out.append(all(v > 0 for v in values))
    return np.array(out)


def run(quick: bool, out_dir) -> list[dict]:
    scene = cs.scene("brake")
    st = scene.stability()
    lin = st.linearization
    by_name = {str(s): s for s in set().union(*[c.free_symbols for c in st.hurwitz]) | lin.jacobian.free_symbols}
    names = ["alpha", "m", "mu", "Phi_1", "Phi_2", "Psi_1", "Psi_2"]
    parameters = [by_name[n] for n in names]
    rng = np.random.default_rng(2005)
    n_random, n_line = 1_000_000, 1000
    data = _sample(rng, n_random)
    line = _on_hopf_line(rng, n_line)
    values = [data[k] for k in names]
    started = time.perf_counter()
    classifier = nm.PointClassifier(st.hurwitz, parameters)
    build_s = time.perf_counter() - started
    classifier(*[v[:1000] for v in values])  # warm up the generated code
    classifier(*values)  # and compile the fused loop (numba, if installed): its compile time is in the notes
    ours_s, ours = _best_of(3, lambda: classifier(*values))
    sub = 5000 if quick else 50000
    index = rng.choice(n_random, sub, replace=False)
    per_point, disagreements = _against_eigenvalues(lin.jacobian, parameters, values, index, ours)
    notes = (
        f"brake, 7 parameters (alpha, m, mu, Phi_j, Psi_j), {n_random} random points; kept factors "
        f"{len(classifier.kept)} ({', '.join(map(str, classifier.kept[:1]))}, ...); band {ours.band:.1e} relative; "
        f"{ours.exact_points} points inside the band decided exactly; classifier built in {build_s:.2f} s "
        f"(not counted); best of 3; baseline per point {per_point * 1e6:.1f} us on {sub} points, extrapolated; "
        f"stable fraction {np.mean(ours.stable == 1):.3f}; error = disagreements outside the band with the batched "
        "eigenvalues of all points"
    )
    records = [record("classification", ours_s, per_point * n_random, disagreements, n_random, notes)]
    # the paper's slice (6.4): alpha = 90 deg, equal laws
    Phi, Psi = sp.symbols("Phi Psi", negative=True)
    m, mu, alpha = by_name["m"], by_name["mu"], by_name["alpha"]
    (P1, P2), (S1, S2) = lin.Phi, lin.Psi
    slice_6_4 = {alpha: sp.pi / 2, P1: Phi, P2: Phi, S1: Psi, S2: Psi}
    slice_parameters = [m, mu, Phi, Psi]
    conditions64 = [c.subs(slice_6_4) for c in st.hurwitz]
    # adversarial points: on the Hopf line of (6.4), in floats, so inside the band
    line_values = [line[k] for k in names]
    line_s, on_line = _best_of(1, lambda: classifier(*line_values))
    line_eig = _batched_max_real_part(lin.jacobian, parameters, line_values) < 0
    truth = _exact_stable(conditions64, slice_parameters, [line[k] for k in ("m", "mu", "Phi_1", "Psi_1")])
    wrong = int(np.sum((on_line.stable == 1) != truth))
    eig_wrong = int(np.sum(line_eig != truth))
    records.append(
        record(
            "classification/on-the-hopf-line",
            line_s,
            per_point * n_line,
            wrong,
            n_line,
            f"{n_line} points of the (6.4) slice put on the Hopf line in floats; {on_line.exact_points} decided "
            f"exactly (256-bit, then rationals); error = disagreements with the Hurwitz conditions of the slice "
            f"evaluated in exact rationals; numpy eigenvalues get {eig_wrong} of them wrong",
        )
    )
    classifier64 = nm.PointClassifier(conditions64, slice_parameters)
    slice_values = [data["m"], data["mu"], data["Phi_1"], data["Psi_1"]]
    classifier64(*[v[:1000] for v in slice_values])
    classifier64(*slice_values)
    ours64_s, ours64 = _best_of(3, lambda: classifier64(*slice_values))
    per_point64, disagree64 = _against_eigenvalues(
        lin.jacobian.subs(slice_6_4), slice_parameters, slice_values, index, ours64
    )
    notes64 = (
        f"(6.4) slice: alpha = 90 deg, Phi_1 = Phi_2, Psi_1 = Psi_2; kept condition {classifier64.kept}; "
        f"band {ours64.band:.1e}; {ours64.exact_points} points decided exactly; best of 3; baseline per point "
        f"{per_point64 * 1e6:.1f} us, extrapolated"
    )
    records.append(record("classification-6.4", ours64_s, per_point64 * n_random, disagree64, n_random, notes64))
    records += _floor_rows(classifier, values, ours_s)
    records += [
        r for r in _floor_rows(classifier64, slice_values, ours64_s, "classification-6.4") if "floor" in r["name"]
    ]
    records += _atlas_rows(quick)
    _plot(out_dir, data, ours64, slice_parameters, classifier64)
    return records


def _memory_floor(values) -> float:
    """Seconds to read every input once and write one byte per point: no classifier can do less."""
    out = np.empty(len(values[0]), dtype=np.int8)

    def touch():
        for v in values:
            np.add.reduce(v)
        out.fill(1)

    return _best_of(5, touch)[0]


def _path(classifier, n: int) -> str:
    """Which float32 pass a call of ``n`` points takes: the fused loop (numba) or the NumPy ufunc passes."""
    from contactsym.numerics import fused

    if classifier._fused_run(n, [None] * len(classifier.functions)) is None:
        return "NumPy ufunc passes" + ("" if fused.available() else " (numba not installed)")
    import numba

    return (
        f"the fused loop (numba {numba.__version__}; compiled in {classifier._fused.compile_seconds:.2f} s "
        "at the first call, not counted)"
    )


def _numpy_passes(classifier):
    """The classifier without its fused loop: the NumPy float32 pass of a shallow copy."""
    import copy

    numpy_only = copy.copy(classifier)
    numpy_only._fused_run = lambda size, given: None
    return numpy_only


def _floor_rows(classifier, values, ours_s, name: str = "classification") -> list[dict]:
    """The classifier against the memory floor (by the path a call of this size takes, and by the NumPy passes
    where that is the fused loop), and against itself with the copying input check of before (every float64
    input copied by ``astype(float)``), in one run."""
    from contactsym import validate

    n = len(values[0])
    path = _path(classifier, n)
    fused = path.startswith("the fused loop")
    numpy_only = _numpy_passes(classifier) if fused else classifier
    floor_s = _memory_floor(values)
    fresh = validate.real_array

    def copying(array, what):
        return np.array(fresh(array, what), dtype=float)

    validate.real_array = copying
    try:
        copying_s = _best_of(3, lambda: classifier(*values))[0]
    finally:
        validate.real_array = fresh
    ours_again = _best_of(3, lambda: classifier(*values))[0]
    ours = min(ours_s, ours_again)
    numpy_s = _best_of(3, lambda: numpy_only(*values))[0] if fused else ours
    floor_s = min(floor_s, _memory_floor(values))  # measured again between the two paths: the least
    ops = classifier._buffered.source.count("out=") if classifier._buffered is not None else "?"
    functions = ", ".join(f"{ufunc}({classifier.parameters[i]})" for i, ufunc in classifier.functions) or "none"
    common = (
        f"{len(values)} float64 inputs, {n} points; baseline = the memory floor (read every input once, "
        f"write one byte per point: {floor_s / n * 1e9:.2f} ns/point)"
    )
    numpy_passes = (
        "inputs rounded to float32 (one pass each, the floor's read), checked by 2 reductions over them all, "
        f"functions {functions}, {ops} ufunc passes of the generated code, the sign test and the verdicts in "
        "float32, the undecided points again in float64"
        if classifier._single
        else f"input checks (2 reductions per input), functions {functions}, {ops} ufunc passes of the "
        "generated code, the sign test and the verdicts in float64"
    )
    fused_loop = (
        f"one compiled loop per point: the inputs read, checked and rounded to float32, the {ops} operations "
        "of the generated code and the sign test in float32 (the NumPy pass's values, bit for bit), "
        + (f"functions {functions} from NumPy's float32 loops per chunk, " if classifier.functions else "")
        + "the verdicts in NumPy, the undecided points again in float64; the loop runs unchecked under the "
        "processor's floating-point status flags, and a chunk that raises one runs again with every value checked"
    )
    rows = [
        record(
            f"{name}/memory-floor",
            ours,
            floor_s,
            None,
            n,
            f"{common}; ours = {ours / floor_s:.1f}x the floor (target <= 3x), {ours / n * 1e9:.1f} ns/point, by "
            f"{path}: {fused_loop if fused else numpy_passes}; each pass over a cache-sized chunk; best of 3-5",
        ),
    ]
    if fused:
        rows.append(
            record(
                f"{name}/memory-floor-numpy",
                numpy_s,
                floor_s,
                None,
                n,
                f"{common}; ours = the same classifier by the NumPy ufunc passes (no fused loop), "
                f"{numpy_s / floor_s:.1f}x the floor, {numpy_s / n * 1e9:.1f} ns/point (the fused loop: "
                f"{ours / floor_s:.1f}x, in the same run): {numpy_passes}; best of 3",
            )
        )
    rows.append(
        record(
            "classification/no-input-copy",
            ours,
            copying_s,
            None,
            n,
            "the same classifier with float64 inputs read in place (ours) and copied by the input check as before "
            f"(baseline), by {path}; best of 3, in one run",
        )
    )
    if classifier._single:
        rows.append(_prepass_row(classifier, values, ours, floor_s))
    return rows


def _prepass_row(classifier, values, ours_s: float, floor_s: float) -> dict:
    """The float32 pass (inputs rounded, sines and cosines, generated code and sign test in float32) against
    float64 throughout, in one run: the same results."""
    import copy

    float64 = copy.copy(classifier)
    float64._single = False
    float64_s, theirs = _best_of(3, lambda: float64(*values))
    ours = classifier(*values)
    differ = int(np.sum(ours.signs != theirs.signs)) + int(np.sum(ours.in_band != theirs.in_band))
    return record(
        "classification/float32-prepass",
        ours_s,
        float64_s,
        differ,
        len(values[0]),
        f"inputs rounded to float32, sines and cosines from NumPy's float32 SIMD loops, the generated code and the "
        f"sign test in float32, certified with float32's unit; the points left undecided recomputed in float64 "
        f"(ours, {ours_s / floor_s:.1f}x the floor) against float64 throughout (baseline, {float64_s / floor_s:.1f}x "
        "the floor); error = signs or band membership that differ; best of 3, in one run",
    )


def _atlas_rows(quick: bool) -> list[dict]:
    """The atlas's classification per point against the bare classifier on the same points: in all at the larger
    grid, and per point as the slope between two grids (what a point adds; the fixed cost of a sweep apart). Both
    by the fused loop where numba is installed, and both by the NumPy passes (the fused loop off), in one run."""
    from contactsym.numerics import fused

    rows = _atlas_path_rows(quick, "")
    if fused.available():
        kept = fused.FUSED_MIN_POINTS
        fused.FUSED_MIN_POINTS = float("inf")  # both sides by the NumPy passes
        try:
            rows += _atlas_path_rows(quick, "-numpy")
        finally:
            fused.FUSED_MIN_POINTS = kept
    return rows


def _atlas_path_rows(quick: bool, suffix: str) -> list[dict]:
    from contactsym import atlas
    from contactsym.atlas import vectorised
    from contactsym.atlas.run import VECTOR_CHUNK
    from contactsym.numerics import fused

    law = {"m": 1.0, "Phi_1": -2.0, "Phi_2": -2.0, "Psi_1": -1.0, "Psi_2": -1.0}
    scene = cs.scene("brake")
    st = scene.stability()
    by_name = {str(s): s for s in set().union(*[c.free_symbols for c in st.hurwitz])}
    bare = nm.PointClassifier(st.hurwitz, [by_name[k] for k in ["alpha", "mu", *law]])
    measured = []
    for side in (300, 1000) if quick else (1000, 2000):
        grid = {"alpha": np.linspace(0.3, 2.8, side), "mu": np.linspace(0.1, 3.0, side)}
        atlas.sweep("brake", "classification", grid, values=law, scheduler="sync")  # kernel built (and compiled)
        swept_s, ds = _best_of(
            5, lambda g=grid: atlas.sweep("brake", "classification", g, values=law, scheduler="sync")
        )
        A, M = np.meshgrid(grid["alpha"], grid["mu"], indexing="ij")
        columns = [A.ravel(), M.ravel()] + [np.full(A.size, v) for v in law.values()]
        bare(*columns)  # compiled, where the fused loop runs
        bare_s, result = _best_of(5, lambda c=columns: bare(*c))
        wrong = int(np.sum(result.stable.reshape(A.shape) != ds.stable.values))
        measured.append((A.size, swept_s, bare_s, wrong))
    (n1, s1, b1, w1), (n2, s2, b2, w2) = measured
    cache = vectorised._built_classifier.cache_info()
    slope_ours, slope_bare = (s2 - s1) / (n2 - n1), (b2 - b1) / (n2 - n1)
    path = (
        "both by the NumPy passes (the fused loop off)"
        if suffix
        else (
            f"both as installed: the fused loop (numba) in calls of >= {fused.FUSED_MIN_POINTS} points, so the bare "
            f"classifier's; the atlas's tasks of {VECTOR_CHUNK} points by the "
            + ("fused loop" if VECTOR_CHUNK >= fused.FUSED_MIN_POINTS else "NumPy passes")
            if fused.available()
            else "both by the NumPy passes (numba not installed)"
        )
    )
    common = (
        "brake, grid (alpha, mu), fixed law; ours = atlas.sweep(classification, scheduler='sync') in all (robust "
        "regions, certified Hurwitz verdicts, reason codes, Dataset), baseline = the bare PointClassifier on the same "
        f"points (7 full columns); {path}; classifier cache {cache.hits} hits, {cache.misses} builds; error = "
        "verdicts that differ; best of 5"
    )
    return [
        record(
            f"classification/atlas-vs-bare{suffix}",
            s2,
            b2,
            w2,
            n2,
            f"{common}; {n2} points in all: atlas = {s2 / b2:.2f}x the bare classifier (target <= 1.5x per point)",
        ),
        record(
            f"classification/atlas-vs-bare-per-point{suffix}",
            slope_ours * 1e6,
            slope_bare * 1e6,
            w1 + w2,
            n2 - n1,
            f"{common}; seconds per 10^6 points as the slope between {n1} and {n2} points (a sweep's fixed cost, "
            f"{(s1 - slope_ours * n1) * 1e3:.1f} ms, apart): atlas = {slope_ours / slope_bare:.2f}x the bare classifier "
            "per point (target <= 1.5x)",
        ),
    ]


def _plot(out_dir, data, result, parameters, classifier):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    m, mu, Phi, Psi = parameters
    y = -data["Phi_1"] * data["m"] / data["Psi_1"] ** 2
    show = slice(0, 20000)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    stable = result.stable[show] == 1
    ax.scatter(data["mu"][show][stable], y[show][stable], s=2, c="tab:blue", label="stable (all Hurwitz > 0)")
    ax.scatter(data["mu"][show][~stable], y[show][~stable], s=2, c="tab:red", label="unstable")
    (kept,) = classifier.kept
    boundary = sp.solve(kept, Phi)[0]  # the Hopf line, derived
    grid = np.linspace(0.05, 3, 300)
    line = [float(-boundary.subs({mu: g, m: 1, Psi: -1})) for g in grid]
    ax.plot(grid, line, "k-", lw=1.5, label="Hopf line: -m mu^2 Phi = (1 + mu^2) Psi^2")
    ax.set_yscale("log")
    ax.set_xlabel("friction coefficient mu")
    ax.set_ylabel("-m Phi / Psi^2 (stiffness over damping^2)")
    ax.set_title("Brake (6.4): certified classification of 20 000 of 10^6 points")
    ax.legend(loc="upper right", markerscale=4, fontsize=8)
    fig.tight_layout()
    fig.savefig(out_dir / "classification.png", dpi=110)
    plt.close(fig)
