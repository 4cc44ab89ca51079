"""Running a sweep: in this process, on Dask's local scheduler, or on a ``dask.distributed`` cluster.

Every way runs the same task, :func:`_chunk`: a kernel (generated code, see
:mod:`contactsym.atlas.quantities`) on the points ``index * chunk`` to ``(index + 1) *
chunk`` of the flattened grid, returning their values and reasons. The results are
written as the chunks finish (memory or a Zarr checkpoint), on the calling machine only.
"""

from __future__ import annotations

import contextlib
import importlib
import json
import os
import threading
import uuid
from collections.abc import Mapping

import numpy as np

from ..mechanism.scene import Scene
from ..scenes import scene as scene_by_name
from ..validate import cut, flag, path_text, shorten
from .grid import REASON_LIMIT, AtlasError, Grid, as_grid, check_size
from .kernel import Kernel, Reasons, code_type
from .options import check_options
from .quantities import as_quantity
from .store import MemoryResults, ZarrResults, fingerprint

__all__ = ["reason_text", "sweep"]

#: Points per task: a vectorised kernel takes many at once (a few MiB of columns and results per task;
#: the classifier works through them in cache-sized pieces); a simulation is worth a task of its own.
VECTOR_CHUNK, POINT_CHUNK = 1 << 16, 16


def _require(module: str):
    """Import an optional dependency of the atlas (contactsym[atlas]), or say how to get it."""
    try:
        return importlib.import_module(module)
    except ImportError:
        raise AtlasError(
            f"contactsym.atlas needs {module}; install it with: python3 -m pip install 'contactsym[atlas]'"
        ) from None


def _chunk(kernel: Kernel, grid: Grid, chunk: int, index: int) -> tuple:
    """One task: the kernel on one chunk of the grid; a NaN always comes with its reason."""
    start = index * chunk
    values, reasons = kernel.run(grid, start, min(start + chunk, grid.size))
    reasons = reasons if isinstance(reasons, Reasons) else Reasons.from_texts(reasons)
    values = np.asarray(values, dtype=float).reshape(len(reasons), len(kernel.outputs))
    return index, values, _explained(kernel, values, reasons)


def _explained(kernel: Kernel, values: np.ndarray, reasons: Reasons) -> Reasons:
    """``reasons`` with a text for every NaN that has none: which outputs are NaN, and why if the kernel says."""
    with np.errstate(all="ignore"):  # a row sum is NaN where a value is (or where inf - inf: sorted out below)
        if not np.isnan(np.add.reduce(values, axis=None)):  # no NaN at all (the usual case): one pass, no lookup
            return reasons
        candidates = np.nonzero(np.isnan(values @ np.ones(values.shape[1])) & (reasons.codes == 0))[0]
    nan = np.isnan(values[candidates])
    missing = np.zeros(len(values), dtype=bool)
    missing[candidates[nan.any(axis=1)]] = True
    if not missing.any():
        return reasons
    explained = getattr(kernel, "nan_reasons", {})
    pattern = np.isnan(values[missing]) @ (1 << np.arange(values.shape[1], dtype=np.uint64))  # NaN outputs as bits
    table, codes = list(reasons.table), reasons.codes.astype(np.uint32)
    found = np.empty(len(pattern), dtype=np.uint32)
    for bits in np.unique(pattern):
        names = [name for j, name in enumerate(kernel.outputs) if int(bits) >> j & 1]
        why = "; ".join(explained.get(name, f"{name}: the quantity has no value here") for name in names)
        found[pattern == bits] = len(table)
        table.append(f"NaN: {why}"[:REASON_LIMIT])
    codes[missing] = found
    return Reasons(codes.astype(code_type(len(table))), table)


def _chunk_size(chunks, size: int, kernel: Kernel) -> int:
    if chunks is None:
        return min(size, VECTOR_CHUNK) if kernel.vectorised else max(1, min(POINT_CHUNK, size // 64))
    return int(chunks)


def _check_arguments(chunks, store, scheduler, workers, progress, timeout, values) -> None:
    """The keyword arguments of :func:`sweep`, before any work."""
    if chunks is not None and (isinstance(chunks, bool) or not isinstance(chunks, (int, np.integer)) or chunks < 1):
        raise AtlasError(f"chunks = {shorten(chunks)}: give the number of points per task, a positive integer.")
    if store is not None:
        path_text(store, "store", AtlasError)
    if scheduler not in ("processes", "threads", "sync"):
        raise AtlasError(f"scheduler = {shorten(scheduler)}; use 'processes', 'threads' or 'sync'.")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, (int, np.integer)) or workers < 1):
        raise AtlasError(f"workers = {shorten(workers)} must be a whole number >= 1 (or None: one per core).")
    flag(progress, "progress", AtlasError)
    ok = isinstance(timeout, (int, float, np.integer, np.floating)) and not isinstance(timeout, bool)
    if not ok or not 0 < float(timeout) < 10**6:
        raise AtlasError(f"timeout = {shorten(timeout)} must be a number of seconds between 0 and 10^6.")
    if values is not None and not isinstance(values, Mapping):
        raise AtlasError(f"values = {shorten(values)} must be a mapping {{parameter name: number}}.")


def _run_here(kernel, grid, chunk, todo, results, progress) -> None:
    for number, index in enumerate(todo, 1):
        results.write(*_chunk(kernel, grid, chunk, index))
        if progress:
            print(f"\r[atlas] {number}/{len(todo)} chunks", end="", flush=True)
    if progress:
        print()


def _run_local(kernel, grid, chunk, todo, results, scheduler, workers, progress) -> None:
    """Dask's local scheduler; each finished chunk is written by a callback in this process."""
    dask = _require("dask")
    from dask.callbacks import Callback  # dask is optional (contactsym[atlas]): imported only for a sweep
    from dask.diagnostics import ProgressBar

    class Writer(Callback):
        def _posttask(self, key, result, dsk, state, worker_id):
            if isinstance(key, str) and key.startswith("atlas-chunk-"):
                results.write(*result)

    tasks = [dask.delayed(_chunk, pure=False)(kernel, grid, chunk, i, dask_key_name=f"atlas-chunk-{i}") for i in todo]
    with Writer(), ProgressBar() if progress else contextlib.nullcontext():
        dask.compute(*tasks, scheduler=scheduler, num_workers=workers)


def connect(client, timeout: float = 10.0):
    """(a ``distributed.Client``, whether we opened it) from a Client, a cluster or an address.

    Examples
    --------
    A ``distributed.Client`` the caller opened is used as it is, and left open (``connect(client)`` is
    ``(client, False)``); a scheduler address opens a client that :func:`sweep` closes; anything else is
    refused with a clear error:

    >>> try:
    ...     connect(42)
    ... except AtlasError as error:
    ...     print(str(error).split(":")[0])
    client = 42
    """
    distributed = _require("distributed")
    ok = isinstance(timeout, (int, float)) and not isinstance(timeout, bool)
    if not ok or not 0 < float(timeout) < 10**6:
        raise AtlasError(f"timeout = {shorten(timeout)} must be a number of seconds between 0 and 10^6.")
    if isinstance(client, distributed.Client):
        return client, False
    if isinstance(client, str) or hasattr(client, "scheduler_address"):  # an address, or a cluster object
        address = getattr(client, "scheduler_address", client)
        try:
            return distributed.Client(client, timeout=timeout), True
        except (OSError, TimeoutError, ValueError) as error:
            reason = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
            raise AtlasError(f"cannot reach the Dask scheduler at {cut(str(address))}: {cut(reason, 200)}") from None
    raise AtlasError(f"client = {shorten(client)}: give a distributed.Client, a cluster or a scheduler address.")


def _run_distributed(client, kernel, grid, chunk, todo, results, progress) -> None:
    """Tasks on a cluster; a worker that dies takes no point with it: the scheduler reruns its tasks."""
    distributed = _require("distributed")
    run = uuid.uuid4().hex[:12]
    # the kernel travels once to every worker (a copy each: a dying worker takes no copy others need)
    shipped = client.scatter(kernel, broadcast=True, hash=False)
    futures = [client.submit(_chunk, shipped, grid, chunk, i, key=f"atlas-chunk-{run}-{i}") for i in todo]
    bar = None
    if progress:  # Dask's text progress bar blocks: it runs beside the loop that stores the chunks as they finish
        bar = threading.Thread(target=distributed.progress, args=(futures,), kwargs={"notebook": False}, daemon=True)
        bar.start()
    try:
        for future in distributed.as_completed(futures):
            results.write(*future.result())
        if bar is not None:
            bar.join(timeout=5)
    except distributed.KilledWorker as error:
        raise AtlasError(f"a chunk of the sweep kept killing its workers and was given up: {error}") from None
    finally:
        for future in [*futures, shipped]:
            future.release()


def sweep(
    scene,
    quantity,
    grid,
    *,
    values=None,
    client=None,
    chunks: int | None = None,
    store=None,
    scheduler: str = "processes",
    workers: int | None = None,
    progress: bool = False,
    max_points: int | None = None,
    timeout: float = 10.0,
):
    """Measure ``quantity`` at every point of ``grid``: an ``xarray.Dataset`` labelled by the grid.

    Parameters
    ----------
    scene : Scene or str
        A scene or a built-in scene's name.
    quantity : Quantity, str or callable
        ``"classification"``, ``"leading_eigenvalue"``, ``"stable_fraction"``,
        ``"equilibrium_count"``, ``"cycle"``, a :class:`~contactsym.atlas.Quantity` with
        options (``atlas.cycle(samples=512)``, ``atlas.catastrophe(eps, span, initial)``),
        or a function of a point's values ``{name: number}``.
    grid : mapping
        ``{parameter name: 1-D values}``; the sweep covers their outer product.
    values : mapping, optional
        The other parameters, fixed (as for :func:`contactsym.numerics.numeric_values`).
    client : distributed.Client, cluster or address, optional
        Run there. Without one: vectorised quantities run in this process, the others on
        Dask's local ``scheduler`` ("processes", "threads" or "sync") with ``workers``.
    chunks : int, optional
        Points per task (default 4096 for vectorised quantities, up to 16 for simulations).
    store : path, optional
        A Zarr checkpoint: chunks are written there as they finish; a sweep started again
        with the same arguments computes only the chunks not stored yet. A checkpoint is
        identified by content (the scene's equations and derived fast subsystem, the
        quantity and its options, a function's code and closure, values, grid, chunks):
        any other sweep is refused with the differing part named.
    progress : bool
        Show Dask's progress bar.
    max_points : int, optional
        Refuse larger grids (default 10^9; also refused: results beyond half the memory).
    timeout : float
        Seconds to wait for a scheduler given by its address.

    Returns
    -------
    xarray.Dataset
        One variable per output of the quantity, ``reason_code`` (why a point is NaN: a code
        into the JSON list ``attrs["reasons"]``, 0 for ``""`` where it has a value; a NaN always
        has one; :func:`reason_text` gives the texts), and attributes ``scene``, ``quantity``,
        ``fixed`` (the fixed numbers, JSON), ``points_computed``, ``points_resumed`` and
        ``chunks_recomputed`` (stored chunks that were lost or damaged, JSON).

    Examples
    --------
    >>> import numpy as np
    >>> ds = sweep("brake", "leading_eigenvalue", {"mu": [0.5, 1.5], "Phi_1": [-3.0, -1.0]},
    ...            values={"alpha": np.pi / 2, "m": 1, "Phi_2": -2, "Psi_1": -1, "Psi_2": -1})
    >>> ds.leading_eigenvalue.dims, bool((ds.leading_eigenvalue < 0).all())
    (('mu', 'Phi_1'), False)
    >>> sweep("brake", "cycle", {"mu": []})
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: the grid axis 'mu' is empty; give at least one value.
    """
    xr = _require("xarray")  # checked first: nothing starts without the container of the results

    chosen = as_quantity(quantity)
    check_options(chosen.name, chosen.options)
    _check_arguments(chunks, store, scheduler, workers, progress, timeout, values)
    grid = as_grid(grid, max_points=max_points)
    if not isinstance(scene, (str, Scene)):
        raise AtlasError(f"scene = {shorten(scene)} must be a Scene or a built-in scene's name.")
    scene = scene_by_name(scene) if isinstance(scene, str) else scene  # built after the cheap checks
    connection = connect(client, timeout) if client is not None else None  # an unreachable scheduler: before the work
    try:
        kernel = chosen.build(scene, grid, values)  # the symbolic work, once, here
        check_size(grid.size, len(kernel.outputs))  # the outputs are known now
        chunk = _chunk_size(chunks, grid.size, kernel)
        if store is not None:
            token = fingerprint(scene, chosen, values, grid, chunk)
            results = ZarrResults(store, grid.size, kernel.outputs, chunk, token)
        else:
            results = MemoryResults(grid.size, kernel.outputs, chunk)
        todo = [int(i) for i in np.nonzero(~results.done)[0]]
        resumed = int(sum(min(chunk, grid.size - i * chunk) for i in np.nonzero(results.done)[0]))
        if todo and connection is not None:
            _run_distributed(connection[0], kernel, grid, chunk, todo, results, progress)
        elif todo and (kernel.vectorised or scheduler == "sync"):
            _run_here(kernel, grid, chunk, todo, results, progress)
        elif todo:
            _run_local(kernel, grid, chunk, todo, results, scheduler, workers or os.cpu_count(), progress)
    finally:
        if connection is not None and connection[1]:
            connection[0].close()
    return _dataset(xr, scene, chosen, values, grid, kernel.outputs, results, resumed)


def _dataset(xr, scene, quantity, values, grid: Grid, outputs, results, resumed: int):
    data, reasons = results.read()
    variables = {name: (grid.names, data[:, j].reshape(grid.shape)) for j, name in enumerate(outputs)}
    codes = reasons.codes.astype(code_type(len(reasons.table)), copy=False)  # uint8 unless the table is long
    variables["reason_code"] = (grid.names, codes.reshape(grid.shape))
    attrs = {
        "reasons": json.dumps(reasons.table),  # reason_code indexes this list; 0 is "" (the point has a value)
        "scene": scene.name,
        "quantity": quantity.name,
        "fixed": json.dumps(_numbers(values)),
        "points_computed": grid.size - resumed,
        "points_resumed": resumed,
        "chunks_recomputed": json.dumps(list(results.repaired)),  # stored chunks that failed their checksum
    }
    return xr.Dataset(variables, coords=dict(zip(grid.names, grid.axes)), attrs=attrs)


def _numbers(values) -> dict:
    """The fixed values that are numbers, by name (functions such as X(x, xdot) are left out)."""
    out = {}
    for key, value in dict(values or {}).items():
        try:
            out[str(key)] = float(value)
        except (TypeError, ValueError):
            continue
    return out


def reason_text(ds):
    """Why each point of an atlas has no value: the texts of ``ds.reason_code`` (``""`` where it has one).

    The Dataset stores one small code per point and the table of texts once, in
    ``ds.attrs["reasons"]`` (JSON); this is the text per point, labelled as the atlas.

    Examples
    --------
    >>> import numpy as np
    >>> def inverse(values):
    ...     return 1 / values["mu"]
    >>> ds = sweep("brake", inverse, {"mu": [0.5, 0.0]}, scheduler="sync")
    >>> ds.reason_code.values.tolist(), reason_text(ds).values.tolist()
    ([0, 1], ['', 'ZeroDivisionError: float division by zero'])
    """
    xr = _require("xarray")
    if not isinstance(ds, xr.Dataset) or "reason_code" not in ds or "reasons" not in ds.attrs:
        raise AtlasError(f"{shorten(ds)} is not an atlas: give the Dataset that sweep returned.")
    codes = ds["reason_code"]
    try:
        table = np.asarray(json.loads(ds.attrs["reasons"]), dtype=object)
        texts = table[np.asarray(codes.values, dtype=np.int64)]
    except (TypeError, ValueError, IndexError):  # JSON that is not a list of texts, or codes beyond it
        raise AtlasError(
            "the atlas's reason codes and attrs['reasons'] do not match; the Dataset was changed."
        ) from None
    return xr.DataArray(texts, dims=codes.dims, coords=codes.coords, name="reason")
