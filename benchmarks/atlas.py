"""atlas: throughput of ``contactsym.atlas.sweep`` in points/s, in this process and on Dask.

The squeal atlas of the brake (``atlas.cycle``: one fast-subsystem cycle per point) is
swept in this process (the baseline), on Dask's local process scheduler and on a
``LocalCluster`` of 1 and 2 worker processes (``--quick``: the 2-worker cluster alone, one
point per worker), each warmed first by a cycle cut at 5 periods per process (``WARM``), this process
too; error = the largest difference from the
in-process result (0: bit for bit). A vectorised quantity (``stable_fraction``) is swept
in this process and on the 2-worker cluster. Dask's per-task overhead is measured with a
function that does nothing; with the measured per-point cost it gives the estimate of a
10^6-point squeal atlas on a 100-node cluster (printed, and in the last record's notes).
"""

from __future__ import annotations

import time

import numpy as np

from contactsym import atlas

from . import record

SQUEAL = {"m": 1, "alpha": np.pi / 2, "F_x": 2, "F_y": -4, "Phi_2": -2.5, "Psi_1": -1, "Psi_2": -1}
CYCLE = atlas.cycle(samples=256, tol=1e-6)
#: The warm-up of each process: the same quantity cut at 5 periods (no cycle: NaN). It loads what a cycle needs
#: (imports, the scene, the generated code, the integrator) for ~1.2 CPU s a worker, not a whole cycle (~3-4.5
#: CPU s); measured 2026-11-28 on the 2-worker cluster after it: two cycles 5.7 CPU s, the same two again 5.5.
WARM = atlas.cycle(samples=256, tol=1e-6, periods=5)
#: The cluster of the estimate: nodes, worker processes per node, points per task.
NODES, CORES_PER_NODE, CHUNK = 100, 32, 16


def _timed(**sweep_options):
    t0 = time.perf_counter()
    ds = atlas.sweep("brake", **sweep_options)
    return time.perf_counter() - t0, ds


def _difference(a, b, name: str) -> float:
    x, y = a[name].values, b[name].values
    same_nan = np.array_equal(np.isnan(x), np.isnan(y))
    return float(np.nanmax(np.abs(x - y), initial=0.0)) if same_nan else float("inf")


def _nothing():
    """A quantity that does nothing (made inside a function: it travels to the workers by value)."""

    def nothing(values):
        return 0.0

    return nothing


def run(quick: bool, out) -> list[dict]:
    from distributed import Client, LocalCluster

    count = 2 if quick else 16  # one point per worker in --quick: a cycle costs seconds
    grid = {"mu": np.linspace(1.2, 1.8, count), "Phi_1": [-2.5]}  # past the Hopf line (mu = 0.82 here)
    squeal = {"quantity": CYCLE, "grid": grid, "values": SQUEAL, "chunks": 1}
    warm = {"mu": [1.3, 1.5], "Phi_1": [-2.5]}  # a point per worker first: imports, code, caches
    atlas.sweep("brake", WARM, warm, values=SQUEAL, chunks=1, scheduler="sync")  # this process too: the scene's
    cpu = time.process_time()  # derivation and code are not in the baseline, as they are not in the cluster's time
    here_s, here = _timed(scheduler="sync", **squeal)
    per_point = (time.process_time() - cpu) / count  # CPU time: on a shared machine wall time also counts the others
    records = []
    if not quick:  # --quick: the 2-worker cluster alone (each pool and cluster costs seconds of start-up and cycles)
        local_s, local = _timed(scheduler="processes", workers=2, **squeal)
        records.append(
            record(
                "atlas/squeal/dask-local-processes-2",
                local_s,
                here_s,
                _difference(local, here, "amplitude"),
                count,
                f"{count / local_s:.3g} points/s against {count / here_s:.3g} in this process (ratio: speed-up); "
                "includes starting the process pool",
            )
        )
    throughput = {}
    for workers in (2,) if quick else (1, 2):
        with LocalCluster(n_workers=workers, threads_per_worker=1, dashboard_address=None, silence_logs=50) as c:
            with Client(c) as client:
                atlas.sweep("brake", WARM, warm, values=SQUEAL, chunks=1, client=client)
                seconds, ds = _timed(client=client, **squeal)
                throughput[workers] = count / seconds
                records.append(
                    record(
                        f"atlas/squeal/cluster-{workers}-workers",
                        seconds,
                        here_s,
                        _difference(ds, here, "amplitude"),
                        count,
                        f"{throughput[workers]:.3g} points/s (in this process, warm too: {count / here_s:.3g}); "
                        f"LocalCluster of {workers} worker process(es), warm (a cycle cut at 5 periods on each first)",
                    )
                )
                if workers == 2:
                    records += _vectorised_and_overhead(client, per_point)
    _plot(out, count / here_s, throughput)
    return records


def _vectorised_and_overhead(client, per_point: float) -> list[dict]:
    grid = {"alpha": np.linspace(0.05, 3.09, 100), "mu": np.linspace(0.05, 3.0, 100)}
    options = {"quantity": atlas.stable_fraction(laws=64), "grid": grid, "values": {"m": 1}, "chunks": 1000}
    here_s, here = _timed(**options)
    cluster_s, remote = _timed(client=client, **options)
    records = [
        record(
            "atlas/stable-fraction/cluster-2-workers",
            cluster_s,
            here_s,
            _difference(remote, here, "stable_fraction"),
            10_000,
            f"vectorised, 64 laws per point: {10_000 / cluster_s:.3g} points/s on 2 workers, "
            f"{10_000 / here_s:.3g} in this process",
        )
    ]
    tasks = 200
    seconds, _ = _timed(quantity=_nothing(), grid={"mu": np.arange(1.0, tasks + 1)}, chunks=1, client=client)
    overhead = seconds * 2 / tasks  # worker-seconds per task that does nothing
    points, workers = 10**6, NODES * CORES_PER_NODE
    compute = points * per_point / workers
    scheduling = points / CHUNK * seconds / tasks  # the one scheduler hands out the tasks one after another
    estimate = (
        f"10^6-point squeal atlas: {points * per_point / 3600:.0f} CPU-hours at {per_point:.2f} CPU s/point (measured "
        f"here); on {NODES} nodes x {CORES_PER_NODE} workers with {CHUNK} points/task: compute "
        f"{compute / 60:.1f} min, Dask overhead {overhead * 1e3:.1f} ms/task -> "
        f"{points / CHUNK * overhead / workers:.2f} s per worker, scheduler {scheduling:.0f} s in all "
        f"(hidden behind the compute when below it): about {max(compute, scheduling) / 60:.1f} min; "
        f"chunks of {int(np.ceil(CHUNK * scheduling / compute))} points or more keep the scheduler below the compute"
    )
    print("  " + estimate, flush=True)
    records.append(record("atlas/dask-task-overhead", seconds, None, None, tasks, estimate))
    return records


def _plot(out, here: float, throughput: dict) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(5, 3.5))
    workers = sorted(throughput)
    ax.plot(workers, [throughput[w] for w in workers], "o-", label="LocalCluster")
    ax.plot(workers, [here * w for w in workers], "k--", lw=1, label="ideal (in-process rate x workers)")
    ax.axhline(here, color="0.5", lw=1, label="in this process")
    ax.set_xticks(workers)
    ax.set_xlabel("worker processes")
    ax.set_ylabel("squeal atlas points/s")
    ax.set_title("contactsym.atlas: scaling with the workers", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "atlas.png", dpi=100)
    plt.close(fig)
