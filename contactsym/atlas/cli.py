"""The atlas command: ``contactsym atlas SCENE QUANTITY --grid NAME=START:STOP:COUNT``, one ``--grid`` per axis.

Options: ``--scheduler ADDRESS``, ``--store DIR``, ``--out FILE``.

Numbers on the command line are read with ``float``; nothing is evaluated. The output
file (NetCDF, ``.nc``) is written all-or-nothing: to a temporary file beside it, then
renamed.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
from pathlib import Path

import numpy as np

from ..atomic import process_tag, remove_leftovers, umask_bits
from ..errors import AtlasError, ContactsymError, UsageError
from ..validate import cut, named_once
from .grid import check_size
from .run import sweep

__all__ = ["add_atlas_command", "parse_axis", "run_atlas"]

_CLI_QUANTITIES = ("classification", "leading-eigenvalue", "stable-fraction", "equilibrium-count", "cycle")


def _number(text: str, what: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise UsageError(f"{what}: {text!r} is not a number.") from None
    if not np.isfinite(value):
        raise UsageError(f"{what}: {text!r} is not finite.")
    return value


def _axis_spec(text: str) -> tuple[str, float, float, int] | tuple[str, list]:
    """``(name, start, stop, count)`` or ``(name, values)``: nothing allocated yet."""
    name, _, spec = text.partition("=")
    name = name.strip()
    if not name or not spec:
        raise UsageError(f"--grid {cut(text)}: write NAME=START:STOP:COUNT or NAME=V1,V2,...")
    what = f"--grid {cut(text)}"
    if ":" in spec:
        parts = spec.split(":")
        if len(parts) != 3:
            raise UsageError(f"{what}: write NAME=START:STOP:COUNT or NAME=V1,V2,...")
        count = _number(parts[2], what)
        if count != int(count) or count < 1:
            raise UsageError(f"{what}: COUNT = {parts[2]} must be a positive integer.")
        return name, _number(parts[0], what), _number(parts[1], what), int(count)
    return name, [_number(v, what) for v in spec.split(",")]


def _count(spec: tuple) -> int:
    return spec[3] if len(spec) == 4 else len(spec[1])


def _values(spec: tuple) -> np.ndarray:
    return np.linspace(spec[1], spec[2], spec[3]) if len(spec) == 4 else np.array(spec[1])


def parse_axis(text: str) -> tuple[str, np.ndarray]:
    """``NAME=START:STOP:COUNT`` (evenly spaced, ends included) or ``NAME=V1,V2,...``.

    Examples
    --------
    >>> name, values = parse_axis("mu=0.5:1.5:3")
    >>> name, values.tolist()
    ('mu', [0.5, 1.0, 1.5])
    >>> parse_axis("alpha=1,2.5")[1].tolist()
    [1.0, 2.5]
    >>> parse_axis("mu=0:1")
    Traceback (most recent call last):
    ...
    contactsym.errors.UsageError: --grid mu=0:1: write NAME=START:STOP:COUNT or NAME=V1,V2,...
    """
    spec = _axis_spec(text)
    check_size(_count(spec))
    return spec[0], _values(spec)


def _parse_set(text: str) -> tuple[str, float]:
    name, _, value = text.partition("=")
    if not name.strip() or not value:
        raise UsageError(f"--set {text}: write NAME=NUMBER.")
    return name.strip(), _number(value, f"--set {text}")


def add_atlas_command(sub) -> None:
    """Add the ``atlas`` subcommand to the ``contactsym`` parser's subparsers."""
    atlas = sub.add_parser("atlas", help="sweep a quantity over a parameter grid (contactsym[atlas]: Dask, xarray)")
    atlas.add_argument("scene", help="a built-in scene")
    atlas.add_argument("quantity", choices=_CLI_QUANTITIES, help="what to measure at each point")
    atlas.add_argument(
        "--grid", action="append", required=True, metavar="NAME=START:STOP:COUNT", help="an axis (repeat for more)"
    )
    atlas.add_argument("--set", action="append", default=[], metavar="NAME=NUMBER", help="a fixed parameter")
    atlas.add_argument("--scheduler", metavar="ADDRESS", help="a dask.distributed scheduler, e.g. tcp://host:8786")
    atlas.add_argument("--chunks", type=int, help="points per task")
    atlas.add_argument("--store", metavar="DIR", help="a Zarr checkpoint; a sweep run again resumes from it")
    atlas.add_argument("--out", metavar="FILE.nc", help="write the atlas as NetCDF (else print it)")
    atlas.add_argument("--progress", action="store_true", help="show Dask's progress bar")
    atlas.add_argument("--force", action="store_true", help="replace an existing --out file")


def _write(ds, out: Path) -> None:
    """NetCDF (SciPy's writer, no further dependency), to a temporary file that is then renamed.

    The temporary file carries this run's host and process id; a killed run's is removed by the next run.
    """
    if out.suffix != ".nc":
        raise UsageError(f"--out {out}: the atlas is written as NetCDF; give a file name ending in .nc.")
    folder = out.parent if str(out.parent) else Path(".")
    remove_leftovers(folder, f".{out.name}.new-")
    handle, temporary = tempfile.mkstemp(prefix=f".{out.name}.new-{process_tag()}", suffix=".tmp", dir=folder)
    os.close(handle)
    try:
        ds.to_netcdf(temporary, engine="scipy")
        os.chmod(temporary, 0o666 & ~umask_bits())  # mkstemp makes 0600; a new file follows the umask
        os.replace(temporary, out)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def run_atlas(args) -> int:
    """Run ``contactsym atlas``; returns the exit code."""
    try:
        specs = [_axis_spec(text) for text in args.grid]
        names = [spec[0] for spec in specs]
        if len(set(names)) != len(names):
            raise UsageError(f"--grid names a parameter twice: {names}; give each axis once.")
        check_size(math.prod(_count(spec) for spec in specs))  # before any axis is allocated
        grid = {spec[0]: _values(spec) for spec in specs}
        try:
            values = named_once(_parse_set(text) for text in args.set)
        except ContactsymError as error:
            raise UsageError(str(error)) from None
        out = Path(args.out) if args.out else None
        if out is not None and out.suffix != ".nc":
            raise UsageError(f"--out {out}: the atlas is written as NetCDF; give a file name ending in .nc.")
        if out is not None and os.path.lexists(out) and not args.force:
            raise UsageError(f"--out {out} exists; choose another file, or replace it with --force.")
    except AtlasError as error:  # a usage error, or a grid too large for this machine
        print(f"contactsym: error: {error}", file=sys.stderr)
        return 2
    ds = sweep(
        args.scene,
        args.quantity,
        grid,
        values=values,
        client=args.scheduler,
        chunks=args.chunks,
        store=args.store,
        progress=args.progress,
    )
    if out is None:
        print(ds)
    else:
        _write(ds, out)
        failed = int((ds["reason_code"] != 0).sum())
        points = int(np.prod(list(ds.sizes.values())))
        print(
            f"wrote {out}: {ds.attrs['quantity']} at {points} points ({failed} without a value: see reason_code and attrs['reasons'])"
        )
    return 0
