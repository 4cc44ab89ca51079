"""contactsym.atlas: sweeps checked against independent computations, on a real 2-worker LocalCluster."""

import json
import os

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym import atlas, numerics
from contactsym.atlas import AtlasError

BRAKE_LAW = {"m": 1, "Phi_1": -2.0, "Phi_2": -2.0, "Psi_1": -1.0, "Psi_2": -1.0}
SQUEAL = {"m": 1, "alpha": np.pi / 2, "F_x": 2, "F_y": -4, "Phi_1": -2.5, "Phi_2": -2.5, "Psi_1": -1, "Psi_2": -1}
CYCLE = atlas.cycle(samples=256, tol=1e-6)
ROD = {"phi": 0.785, "mu_1": 3, "mu_2": 0.5, "X_1": 0, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}


def _eigenvalues(scene, point: dict) -> np.ndarray:
    """Eigenvalues of (4.5) by SymPy substitution: independent of the atlas's generated code."""
    by_name = {str(s): s for s in scene.linearization().jacobian.free_symbols}
    matrix = scene.linearization().jacobian.xreplace(
        {by_name[k]: sp.Float(v) for k, v in point.items() if k in by_name}
    )
    return np.linalg.eigvals(np.array(matrix.evalf(), dtype=float))


# --- bad input: clear errors before any work ----------------------------------------------------


def _never(values):
    raise AssertionError("no point may be computed")


@pytest.mark.parametrize(
    ("grid", "message"),
    [
        ({}, "the grid is empty"),
        ({"mu": []}, "is empty"),
        ({"mu": [1.0, np.nan]}, "non-finite"),
        ({"mu": "1,2"}, "is text"),
        ({"mu": [[1.0, 2.0]]}, "1-D"),
        ({"mu": np.arange(1, 1001.0), "alpha": np.linspace(0.1, 3, 1000)}, "max_points"),
    ],
)
def test_bad_grid_is_refused_before_any_work(grid, message):
    with pytest.raises(AtlasError, match=message):
        atlas.sweep("brake", _never, grid, max_points=10**5)


def test_grid_too_large_for_memory():
    with pytest.raises(AtlasError, match="half of this machine's"):
        atlas.as_grid({"a": np.arange(10**6.0), "b": np.arange(10**6.0)}, max_points=10**13)


def test_bad_names_and_values():
    with pytest.raises(AtlasError, match="unknown parameter name 'nu'"):
        atlas.sweep("brake", "leading_eigenvalue", {"nu": [1.0]}, values=BRAKE_LAW)
    with pytest.raises(AtlasError, match="mu = -1.0 must be > 0"):
        atlas.sweep("brake", "leading_eigenvalue", {"mu": [-1.0, 1.0]}, values=BRAKE_LAW)
    with pytest.raises(AtlasError, match=r"needs values for \['alpha'\]"):
        atlas.sweep("brake", "leading_eigenvalue", {"mu": [1.0]}, values=BRAKE_LAW)
    with pytest.raises(AtlasError, match="both swept"):
        atlas.sweep("brake", "leading_eigenvalue", {"m": [1.0]}, values=BRAKE_LAW)
    with pytest.raises(AtlasError, match="unknown quantity 'squeal'"):
        atlas.sweep("brake", "squeal", {"mu": [1.0]})
    with pytest.raises(AtlasError, match="chunks"):
        atlas.sweep("brake", "leading_eigenvalue", {"mu": [1.0]}, values={**BRAKE_LAW, "alpha": 1.0}, chunks=0)


def test_import_contactsym_does_not_import_dask():
    """No module of the package imports dask, distributed, xarray or zarr at import time (only inside functions)."""
    import ast
    from pathlib import Path

    optional = {"dask", "distributed", "xarray", "zarr"}
    found = []
    for path in Path(cs.__file__).parent.rglob("*.py"):
        for node in ast.parse(path.read_text()).body:  # module level only: function bodies import when they run
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else []
            names += [node.module or ""] if isinstance(node, ast.ImportFrom) and not node.level else []
            found += [f"{path.name}: {n}" for n in names if n.split(".")[0] in optional]
    assert found == []


# --- the quantities, against independent computations -------------------------------------------


@settings(max_examples=5, deadline=None)
@given(st.lists(st.floats(0.1, 3.0), min_size=2, max_size=4), st.floats(0.2, 2.9), st.floats(-5.0, -0.1))
def test_leading_eigenvalue_against_sympy_substitution(mus, alpha, phi):
    law = {"m": 1.3, "Phi_1": phi, "Phi_2": -2.0, "Psi_1": -0.7, "Psi_2": -1.1, "alpha": alpha}
    ds = atlas.sweep("brake", "leading_eigenvalue", {"mu": mus}, values=law)
    brake = cs.scene("brake")
    for mu, leading, frequency in zip(mus, ds.leading_eigenvalue.values, ds.frequency.values):
        eigenvalues = _eigenvalues(brake, {**law, "mu": mu})
        top = eigenvalues[np.argmax(eigenvalues.real)]
        assert leading == pytest.approx(top.real, abs=1e-9)
        assert frequency == pytest.approx(abs(top.imag), abs=1e-9)


@pytest.mark.parametrize("signs", [(1, -1), (-1, -1)])
def test_guides_leading_eigenvalue_against_sympy_substitution(signs):
    """Another scene (k = 2, a 4 x 4 matrix (4.5)), sign patterns, random laws on the grid."""
    guides = cs.scene("painleve-klein-guides")
    rng = np.random.default_rng(7)
    grid = {"mu_1": [0.1, 0.8, 2.5], "Phi_1": -rng.uniform(0.05, 5, 3), "Psi_2": -rng.uniform(0.05, 5, 2)}
    values = {"phi": 0.6, "mu_2": 0.7, "Phi_2": -1.3, "Psi_1": -0.4}
    ds = atlas.sweep(guides, atlas.leading_eigenvalue(signs=signs), grid, values=values)
    matrix = guides.linearization(signs).jacobian
    by_name = {str(s): s for s in matrix.free_symbols}
    for index, leading in np.ndenumerate(ds.leading_eigenvalue.values):
        point = values | {name: grid[name][i] for name, i in zip(grid, index)}
        numeric = matrix.xreplace({by_name[k]: sp.Float(v) for k, v in point.items()}).evalf()
        assert leading == pytest.approx(np.linalg.eigvals(np.array(numeric, dtype=float)).real.max(), abs=1e-9)


def test_stable_fraction_is_one_exactly_where_every_law_is_stable():
    """1 on the closed-form region mu <= |cot alpha| (6.3); elsewhere the fraction of the same
    sampled laws whose eigenvalues all have negative real parts."""
    grid = {"alpha": np.linspace(0.3, 2.8, 5), "mu": [0.2, 0.9, 2.0]}
    quantity = atlas.stable_fraction(laws=12, seed=3)
    ds = atlas.sweep("brake", quantity, grid, values={"m": 1})
    region = cs.scene("brake").regions()["stable for every law"]
    A, M = np.meshgrid(grid["alpha"], grid["mu"], indexing="ij")
    robust = region.evaluate(alpha=A, mu=M)
    assert robust.any() and (~robust).any()
    assert np.all(ds.stable_fraction.values[robust] == 1.0)
    laws = -(10.0 ** np.random.default_rng(3).uniform(-1, 1, size=(12, 4)))
    brake = cs.scene("brake")
    for (i, j), alpha in np.ndenumerate(A):
        point = {"m": 1, "alpha": alpha, "mu": M[i, j]}
        stable = [
            _eigenvalues(brake, {**point, "Phi_1": a, "Phi_2": b, "Psi_1": c, "Psi_2": d}).real.max() < 0
            for a, b, c, d in laws
        ]
        assert ds.stable_fraction.values[i, j] == pytest.approx(np.mean(stable))
    assert (ds.stable_fraction.values < 1).any()


def test_classification_against_closed_form_regions_and_eigenvalues():
    grid = {"alpha": np.linspace(0.3, 2.8, 6), "mu": [0.3, 1.2, 2.5]}
    ds = atlas.sweep("brake", "classification", grid, values=BRAKE_LAW)
    regions = cs.scene("brake").regions()
    A, M = np.meshgrid(grid["alpha"], grid["mu"], indexing="ij")
    assert np.array_equal(ds.region.values == 1, regions["stable for every law"].evaluate(alpha=A, mu=M))
    assert np.array_equal(ds.region.values == 0, regions["law-dependent"].evaluate(alpha=A, mu=M))
    brake = cs.scene("brake")
    for (i, j), alpha in np.ndenumerate(A):
        leading = _eigenvalues(brake, {**BRAKE_LAW, "alpha": alpha, "mu": M[i, j]}).real.max()
        assert ds.stable.values[i, j] == (1 if leading < 0 else -1)
    assert set(np.unique(ds.stable.values)) == {-1.0, 1.0}


def test_equilibrium_count_against_numerics():
    grid = {"alpha": np.linspace(0.3, 2.8, 5), "F_y": [-4.0, -0.5, 3.0]}
    values = {"m": 1, "mu": 0.8, "F_x": 2}
    ds = atlas.sweep("brake", "equilibrium_count", grid, values=values)
    for (i, j), count in np.ndenumerate(ds.equilibrium_count.values):
        point = {**values, "alpha": grid["alpha"][i], "F_y": grid["F_y"][j]}
        assert count == len(numerics.equilibrium_reactions(cs.scene("brake"), point))
    assert len(np.unique(ds.equilibrium_count.values)) == 2


def test_failing_points_are_nan_with_a_reason():
    def picky(values):
        if values["mu"] > 1:
            raise ValueError(f"no value at mu = {values['mu']}")
        return values["mu"] ** 2

    ds = atlas.sweep("brake", picky, {"mu": [0.5, 1.0, 1.5, 2.0]}, scheduler="sync")
    assert ds.picky.values[:2].tolist() == [0.25, 1.0]
    assert np.isnan(ds.picky.values[2:]).all()
    texts = ["", "", "ValueError: no value at mu = 1.5", "ValueError: no value at mu = 2.0"]
    assert atlas.reason_text(ds).values.tolist() == texts
    assert ds.reason_code.dtype == np.uint8 and json.loads(ds.attrs["reasons"])[0] == ""


def test_cycle_amplitude_is_born_past_the_hopf_line():
    """Stable side of the Hopf line: no cycle, NaN with the reason; beyond it: a cycle of the reactions."""
    hopf = cs.scene("brake").regions()["Hopf line"].condition
    by_name = {str(s): s for s in hopf.free_symbols}
    mus = [0.6, 1.2]
    sides = [
        float((hopf.lhs - hopf.rhs).xreplace({by_name[k]: v for k, v in {**SQUEAL, "mu": mu}.items() if k in by_name}))
        for mu in mus
    ]
    assert sides[0] * sides[1] < 0  # the closed-form Hopf line passes between the two points
    ds = atlas.sweep("brake", CYCLE, {"mu": mus}, values=SQUEAL, scheduler="sync")
    assert np.isnan(ds.amplitude.values[0]) and "settles on the equilibrium" in atlas.reason_text(ds).values[0]
    assert ds.amplitude.values[1] > 0.1 and ds.omega.values[1] > 0 and ds.reason_code.values[1] == 0


def test_plot_the_closed_form_hopf_line_falls_where_the_atlas_changes_sign():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    values = {k: v for k, v in SQUEAL.items() if not k.startswith("F_") and k != "alpha"}
    grid = {"mu": np.linspace(0.3, 1.6, 27), "alpha": [np.pi / 2, 2.0]}
    ds = atlas.sweep("brake", "leading_eigenvalue", grid, values=values).sel(alpha=np.pi / 2)  # a cut
    data = atlas.atlas_data(ds, "leading_eigenvalue", resolution=2001)
    (field,) = data.boundaries["Hopf line"][1]
    xs, le = data.fine[0], ds.leading_eigenvalue.values
    line = xs[np.nonzero(np.diff(np.sign(field)))[0]]
    change = ds.mu.values[np.nonzero(np.diff(np.sign(le)))[0]]
    assert len(line) == len(change) == 1 and change[0] <= line[0] <= change[0] + 0.05
    fig, ax = plt.subplots()
    artists = atlas.atlas_plot(data, ax=ax)
    assert len(ax.lines) == 1 + 1 + 1  # the atlas, the Hopf line at the sign change, its legend entry
    assert artists and ax.get_legend() is not None
    plt.close(fig)


# --- checkpoint and resume ------------------------------------------------------------------------


def _counting(log_dir, stop_at=None):
    """A user quantity that records each call in a file (calls happen in other processes); it dies at
    ``mu == stop_at`` while the file ``stop`` exists beside the log (its code and closure stay the same)."""

    def counted(values):
        (log_dir / f"{values['mu']!r}.{os.getpid()}.{os.urandom(4).hex()}").touch()
        if values["mu"] == stop_at and (log_dir.parent / "stop").exists():
            raise KeyboardInterrupt  # the sweep dies here, as on a restart
        return 10 * values["mu"]

    return counted


def test_a_resumed_sweep_recomputes_nothing_stored(tmp_path):
    store, log = tmp_path / "atlas.zarr", tmp_path / "calls"
    log.mkdir()
    grid = {"mu": np.arange(1.0, 13.0)}
    first = atlas.function(_counting(log, stop_at=9.0), outputs=["counted"])
    (tmp_path / "stop").touch()
    with pytest.raises(KeyboardInterrupt):
        atlas.sweep("brake", first, grid, chunks=4, store=store, scheduler="sync")
    assert len(list(log.iterdir())) == 9  # two chunks stored, the third died at its first point
    (tmp_path / "stop").unlink()
    done = atlas.sweep("brake", first, grid, chunks=4, store=store, scheduler="sync")
    assert (done.points_resumed, done.points_computed) == (8, 4)
    assert sorted(float(p.name.split(".")[0] + "." + p.name.split(".")[1]) for p in log.iterdir()) == sorted(
        list(range(1, 10)) + [9, 10, 11, 12]
    )
    assert done.counted.values.tolist() == (10 * grid["mu"]).tolist()
    again = atlas.sweep("brake", first, grid, chunks=4, store=store, scheduler="sync")
    assert (again.points_resumed, again.points_computed) == (12, 0) and len(list(log.iterdir())) == 13
    with pytest.raises(AtlasError, match="holds a different sweep: the grid differ"):
        atlas.sweep("brake", first, {"mu": np.arange(1.0, 14.0)}, chunks=4, store=store, scheduler="sync")


def _brake_named(name: str, factor) -> cs.Scene:
    """A brake-like scene built in Python: same name, equations scaled by ``factor``."""
    from sympy.physics.mechanics import dynamicsymbols

    x, y = dynamicsymbols("x y")
    N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    return cs.Scene.from_accelerations([x, y], [-mu * sp.Abs(N), factor * N - 1], [cs.Contact(y, N)], name=name)


def test_a_checkpoint_is_identified_by_content_not_by_names(tmp_path):
    store, grid = tmp_path / "atlas.zarr", {"mu": [0.5, 1.0]}
    values = {"Phi": -1.0, "Psi": -1.0}
    atlas.sweep(_brake_named("mine", 1), "leading_eigenvalue", grid, values=values, store=store)
    with pytest.raises(AtlasError, match="different sweep: the scene .* differ"):
        atlas.sweep(_brake_named("mine", 2), "leading_eigenvalue", grid, values=values, store=store)
    same = atlas.sweep(_brake_named("mine", 1), "leading_eigenvalue", grid, values=values, store=store)
    assert same.points_resumed == 2
    with pytest.raises(AtlasError, match="the quantity or its options"):
        atlas.sweep(_brake_named("mine", 1), "classification", grid, values=values, store=store)

    lambdas = tmp_path / "lambdas.zarr"
    atlas.sweep("brake", lambda v: v["mu"], grid, store=lambdas)
    for other in (lambda v: 2 * v["mu"], _scaled(3), _scaled(4)):
        with pytest.raises(AtlasError, match="the quantity or its options"):
            atlas.sweep("brake", other, grid, store=lambdas)
    store_of_3 = tmp_path / "three.zarr"
    assert atlas.sweep("brake", _scaled(3), grid, store=store_of_3).points_computed == 2
    assert atlas.sweep("brake", _scaled(3), grid, store=store_of_3).points_resumed == 2  # same code, same closure


def _scaled(k):
    def value(v):
        return k * v["mu"]

    return value


def test_a_lost_or_damaged_chunk_is_recomputed_and_named(tmp_path):
    import zarr

    store, grid = tmp_path / "atlas.zarr", {"mu": np.arange(1.0, 9.0)}
    quantity = atlas.function(_scaled(10), outputs=["value"])
    first = atlas.sweep("brake", quantity, grid, chunks=2, store=store, scheduler="sync")
    group = zarr.open_group(str(store), mode="r+")
    group["value_value"][2:4] = np.nan  # chunk 1 lost its values, its flag still says done
    group["reason_code"][6:7] = 7  # chunk 3 damaged
    again = atlas.sweep("brake", quantity, grid, chunks=2, store=store, scheduler="sync")
    assert again.chunks_recomputed == "[1, 3]" and (again.points_resumed, again.points_computed) == (4, 4)
    assert np.array_equal(again.value.values, first.value.values) and (again.reason_code.values == 0).all()


def test_a_nan_always_has_a_reason():
    ds = atlas.sweep("brake", lambda v: float("nan") if v["mu"] > 1 else v["mu"], {"mu": [0.5, 1.5]})
    value = ds[next(iter(ds.data_vars))]
    texts = atlas.reason_text(ds).values
    assert not np.isnan(value.values[0]) and texts[0] == ""
    assert np.isnan(value.values[1]) and texts[1].startswith("NaN: ")


@pytest.mark.parametrize(
    ("make", "words"),
    [
        (lambda: atlas.stable_fraction(laws=0), "laws = 0"),
        (lambda: atlas.stable_fraction(laws="256"), "laws = '256'"),
        (lambda: atlas.stable_fraction(magnitudes=(10.0, 0.1)), "low must be below high"),
        (lambda: atlas.stable_fraction(magnitudes=(0, 1)), "magnitudes = 0"),
        (lambda: atlas.stable_fraction(seed=-1), "seed = -1"),
        (lambda: atlas.classification(signs=(1, 0)), "signs"),
        (lambda: atlas.leading_eigenvalue(signs="+-"), "signs"),
        (lambda: atlas.cycle(sampels=256), "no option 'sampels'"),
        (lambda: atlas.cycle(tol=float("nan")), "tol = nan"),
        (lambda: atlas.cycle(method="Euler"), "not a solver"),
        (lambda: atlas.cycle(periods=2.5), "periods = 2.5"),
        (lambda: atlas.catastrophe(-1, (0, 1), {}), "eps = -1"),
        (lambda: atlas.catastrophe(0.01, (1, 0), {}), "start must come before"),
        (lambda: atlas.catastrophe(0.01, (0, 1), None), "initial = None"),
        (lambda: atlas.catastrophe(0.01, (0, 1), {}, start="fast"), "'rigid', 'slow'"),
        (lambda: atlas.function(len, outputs="ab"), "outputs = 'ab'"),
        (lambda: atlas.function(len, outputs=["a", "a"]), "distinct"),
    ],
)
def test_every_option_of_every_quantity_is_checked(make, words):
    with pytest.raises(AtlasError) as error:
        make()
    assert words in str(error.value)


def test_the_memory_estimate_counts_the_reasons():
    from contactsym.atlas.grid import MAX_REASONS, REASON_LIMIT, result_bytes

    # values twice and codes twice per point, and a table of distinct reasons, each up to REASON_LIMIT characters
    assert result_bytes(1000, 2) >= 1000 * (2 * 2 * 8 + 2 * 2) + 1000 * (49 + REASON_LIMIT)
    assert result_bytes(10**8, 1) >= 10**8 * (2 * 8 + 2 * 2) + (MAX_REASONS + 1) * (49 + REASON_LIMIT)


def test_reason_codes_round_trip_to_the_same_texts():
    from contactsym.atlas.kernel import Reasons
    from contactsym.atlas.store import MemoryResults

    rng = np.random.default_rng(5)
    pool = ["", "ValueError: a", "NaN: b", "x" * 400, "é ü"]
    texts = [pool[i] for i in rng.integers(0, len(pool), 60)]
    reasons = Reasons.from_texts(texts)
    assert reasons.texts().tolist() == [t[:300] for t in texts] and reasons.codes.dtype == np.uint8
    results = MemoryResults(60, ("v",), 20)  # three chunks, each with its own table, merged into one
    for index in range(3):
        results.write(index, np.zeros((20, 1)), Reasons.from_texts(texts[20 * index : 20 * index + 20]))
    assert results.read()[1].texts().tolist() == [t[:300] for t in texts]
    many = [f"ValueError: point {i}" for i in range(300)]  # more than 255 distinct reasons: wider codes
    wide = MemoryResults(300, ("v",), 300)
    wide.write(0, np.zeros((300, 1)), Reasons.from_texts(many))
    assert wide.read()[1].codes.dtype == np.uint16 and wide.read()[1].texts().tolist() == many


def test_reason_codes_round_trip_through_a_checkpoint(tmp_path):
    def odd(values):
        if values["mu"] % 2:
            raise ValueError(f"odd mu = {values['mu']:g}")
        return values["mu"]

    grid = {"mu": np.arange(1.0, 9.0)}
    first = atlas.sweep("brake", odd, grid, chunks=3, store=tmp_path / "a.zarr", scheduler="sync")
    again = atlas.sweep("brake", odd, grid, chunks=3, store=tmp_path / "a.zarr", scheduler="sync")
    here = atlas.sweep("brake", odd, grid, chunks=3, scheduler="sync")
    expected = [
        "ValueError: odd mu = 1",
        "",
        "ValueError: odd mu = 3",
        "",
        "ValueError: odd mu = 5",
        "",
        "ValueError: odd mu = 7",
        "",
    ]
    for ds in (first, again, here):
        assert atlas.reason_text(ds).values.tolist() == expected
    assert again.points_resumed == 8 and here.reason_code.dtype == np.uint8


def test_the_cli_checks_the_grid_size_before_it_allocates(capsys):
    from contactsym.cli import main

    code = main(["atlas", "brake", "classification", "--grid", "mu=0.1:2:1000000000000", "--set", "m=1"])
    assert code == 2 and "more than max_points" in capsys.readouterr().err


# --- a real LocalCluster with 2 worker processes ----------------------------------------------------


@pytest.fixture(scope="module", autouse=True)
def cluster():
    """Started with the module: its workers import contactsym while the local tests above run."""
    import importlib

    import distributed  # in the test extra: this test runs in CI, it is never skipped

    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=50
        ) as local,
        distributed.Client(local) as client,
    ):
        for address in client.scheduler_info()["workers"]:
            warm = client.submit(importlib.import_module, "contactsym.atlas", workers=[address], pure=False)
            distributed.fire_and_forget(warm)
        yield client


def test_distributed_equals_local_bit_for_bit(cluster):
    grid = {"alpha": np.linspace(0.3, 2.8, 5), "mu": np.linspace(0.2, 2.4, 5)}
    quantity = atlas.stable_fraction(laws=16)
    local = atlas.sweep("brake", quantity, grid, values={"m": 1}, chunks=7)
    remote = atlas.sweep("brake", quantity, grid, values={"m": 1}, chunks=7, client=cluster)
    assert remote.identical(local)
    # a stiff full simulation per point (Radau): the rod pushed until the impact-type catastrophe
    quantity = atlas.catastrophe(1e-3, (0, 1), {"x_1": 0, "xdot_1": 1})
    grid = {"X_2": [-1.0, 2.0]}
    local = atlas.sweep("painleve-klein-rod", quantity, grid, values=ROD, chunks=1, scheduler="sync")
    remote = atlas.sweep("painleve-klein-rod", quantity, grid, values=ROD, chunks=1, client=cluster)
    assert remote.identical(local)
    count = atlas.sweep("painleve-klein-rod", "equilibrium_count", grid, values=ROD)
    # no catastrophe (inf) exactly where an equilibrium exists: two quantities, two derivations
    assert np.array_equal(np.isinf(remote.time_to_catastrophe.values), count.equilibrium_count.values > 0)
    assert np.isfinite(remote.time_to_catastrophe.values).any() and np.isinf(remote.time_to_catastrophe.values).any()


def test_resume_on_the_cluster(cluster, tmp_path):
    import zarr

    store, log = tmp_path / "atlas.zarr", tmp_path / "calls"
    log.mkdir()
    quantity = atlas.function(_counting(log), outputs=["counted"])
    grid = {"mu": np.arange(1.0, 9.0)}
    first = atlas.sweep("brake", quantity, grid, chunks=2, store=store, client=cluster, progress=True)
    zarr.open_group(str(store), mode="r+")["done"][1:2] = False  # as if the sweep stopped before chunk 1 was written
    again = atlas.sweep("brake", quantity, grid, chunks=2, store=store, client=cluster)
    assert (again.points_resumed, again.points_computed) == (6, 2)
    assert len(list(log.iterdir())) == 8 + 2
    assert again.identical(first.assign_attrs(points_resumed=6, points_computed=2))


def test_a_killed_worker_loses_no_point(cluster, tmp_path):
    # last on the cluster: the worker that dies comes back cold (its imports again)
    marker = tmp_path / "killed"

    def fragile(values):
        import time

        time.sleep(0.02)
        if values["mu"] == 5.0 and not marker.exists():
            marker.touch()
            os._exit(1)  # the worker process dies in the middle of its task
        return values["mu"] ** 2

    ds = atlas.sweep("brake", fragile, {"mu": np.arange(1.0, 21.0)}, chunks=2, client=cluster)
    assert marker.exists()
    assert ds.fragile.values.tolist() == (np.arange(1.0, 21.0) ** 2).tolist()
    assert (ds.reason_code.values == 0).all()


def test_unreachable_scheduler_is_one_line():
    with pytest.raises(AtlasError) as error:
        atlas.sweep("brake", _never, {"mu": [1.0]}, client="tcp://127.0.0.1:9", timeout=0.5)
    assert str(error.value).startswith("cannot reach the Dask scheduler at tcp://127.0.0.1:9")
    assert "\n" not in str(error.value)


# --- the command line -------------------------------------------------------------------------------


def test_cli_writes_the_atlas_all_or_nothing(tmp_path, capsys):
    import xarray as xr

    from contactsym.cli import main

    out = tmp_path / "atlas.nc"
    grid = ["--grid", "alpha=0.3:2.8:4", "--grid", "mu=0.5,1.5"]
    assert main(["atlas", "brake", "classification", *grid, "--set", "m=1", "--out", str(out)]) == 0
    assert "wrote" in capsys.readouterr().out
    written = xr.open_dataset(out, engine="scipy")
    direct = atlas.sweep(
        "brake", "classification", {"alpha": np.linspace(0.3, 2.8, 4), "mu": [0.5, 1.5]}, values={"m": 1}
    )
    assert np.array_equal(written.region.values, direct.region.values)
    assert [p.name for p in tmp_path.iterdir()] == ["atlas.nc"]  # no temporary file left
    assert main(["atlas", "brake", "cycle", "--grid", "mu=0:1"]) == 2
    assert main(["atlas", "brake", "cycle", "--grid", "mu=1", "--out", str(tmp_path / "a.txt")]) == 2
    assert main(["atlas", "brake", "classification", "--grid", "mu=-1,1", "--set", "alpha=1"]) == 1
    errors = capsys.readouterr().err.splitlines()
    assert errors == [
        "contactsym: error: --grid mu=0:1: write NAME=START:STOP:COUNT or NAME=V1,V2,...",
        f"contactsym: error: --out {tmp_path / 'a.txt'}: the atlas is written as NetCDF; give a file name ending in .nc.",
        "contactsym: error: grid axis 'mu': mu = -1.0 must be > 0 (the symbol is declared positive).",
    ]


def test_the_classifier_is_built_once_per_scene_and_quantity(monkeypatch):
    """A second sweep of the same scene and quantity reuses the classifier (building one factors
    every Hurwitz condition), also with other fixed values (they are arguments of its code);
    the verdicts agree with the first sweep's; another quantity builds its own."""
    from contactsym.atlas import vectorised

    vectorised._built_classifier.cache_clear()
    built = []
    original = numerics.PointClassifier.__init__

    def counted(self, *args, **kwargs):
        built.append(args[1])
        original(self, *args, **kwargs)

    monkeypatch.setattr(numerics.PointClassifier, "__init__", counted)
    grid = {"alpha": np.linspace(0.3, 2.8, 4), "mu": [0.3, 2.5]}
    first = atlas.sweep("brake", "classification", grid, values=BRAKE_LAW, scheduler="sync")
    again = atlas.sweep(
        "brake", "classification", {"alpha": grid["alpha"], "mu": [2.5]}, values=BRAKE_LAW, scheduler="sync"
    )
    assert len(built) == 1
    assert np.array_equal(first.stable.values[:, 1], again.stable.values[:, 0])
    other_law = atlas.sweep("brake", "classification", grid, values={**BRAKE_LAW, "Phi_1": -3.0}, scheduler="sync")
    assert len(built) == 1 and set(np.unique(other_law.stable.values)) <= {-1.0, 1.0}
    atlas.sweep("brake", "equilibrium_count", {"alpha": grid["alpha"]}, values={"m": 1, "mu": 0.8, "F_x": 2, "F_y": -4})
    assert len(built) > 1


def test_squeal_from_the_normal_form_near_the_line_and_by_continuation_farther_out():
    """Hertz pads: before the line the equilibrium is stable (amplitude 0); at 0.1-0.3% past it the
    normal form gives the value (where a simulation to a Poincare section does not converge), with
    its error calibrated by one shot cycle of the line; farther out, cycles continued by shooting
    (stable: multiplier < 1), the one at 1.5% within 2% of a long simulation of the fast subsystem
    (runs from inside and outside the cycle bracket it); at 5% a pad opens: NaN, labelled."""
    from contactsym.atlas.quantities import SQUEAL_METHODS, squeal
    from contactsym.laws.library import Hertz

    laws = {0: Hertz(), 1: Hertz()}
    disc = {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
    h = numerics.hopf_point(cs.scene("brake"), {**disc, "mu": 1.0}, "mu", laws=laws)
    distances = np.array([-0.01, 0.001, 0.003, 0.005, 0.015, 0.05])
    grid = {"mu": h.value * (1 + distances)}
    ds = atlas.sweep("brake", squeal("mu", laws=laws, tol=0.01, simulate=False), grid, values=disc, scheduler="sync")
    assert ds.method.values.tolist()[:5] == [0.0, 1.0, 1.0, 3.0, 3.0] and set(SQUEAL_METHODS) == {0, 1, 2, 3}
    assert ds.amplitude.values[0] == 0 and np.all(np.diff(ds.amplitude.values[:5]) > 0)
    assert np.all(ds.error.values[1:3] < 0.01) and np.all(ds.error.values[3:5] < 1e-3)
    assert np.all(ds.multiplier.values[:5] < 1) and np.all(ds.contact_loss.values[:5] == 0)
    assert np.isnan(ds.amplitude.values[5]) and "contact loss" in str(atlas.reason_text(ds).values[5])
    assert ds.contact_loss.values[5] == 1
    mu = grid["mu"][4]  # 1.5% past the line: the long runs last 1.5/alpha
    duration, period = 1.5 / (h.dalpha * (mu - h.value)), 2 * np.pi / h.omega
    simulated = []
    for factor in (0.8, 1.2):
        run = numerics.simulate_fast(
            cs.scene("brake"), {**disc, "mu": mu}, (0, duration), initial=h.cycle_start(mu, factor), laws=laws,
            method="DOP853", rtol=1e-6, t_eval=np.linspace(duration - 2 * period, duration, 1000),
        )  # fmt: skip
        simulated.append(float(np.max(np.ptp(run.reactions, axis=1)) / 2))
    assert min(simulated) < ds.amplitude.values[4] < max(simulated)
    assert abs(ds.amplitude.values[4] - np.mean(simulated)) / np.mean(simulated) < 0.02, (
        ds.amplitude.values[4],
        simulated,
    )
