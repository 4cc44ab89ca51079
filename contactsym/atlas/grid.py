"""The parameter grid of an atlas: named 1-D axes, their outer product, validated up front."""

from __future__ import annotations

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..errors import AtlasError

__all__ = ["AtlasError", "Grid", "MAX_POINTS", "MAX_REASONS", "REASON_LIMIT", "as_grid", "check_size", "result_bytes"]

#: The largest grid :func:`as_grid` accepts unless told otherwise.
MAX_POINTS = 10**9
#: The longest reason kept for a point without a value (characters).
REASON_LIMIT = 300
#: The most distinct reasons a sweep keeps; beyond, a point's reason says that the table is full.
MAX_REASONS = 2**16 - 1
#: Bytes per point and output: the float64 value in the results and again in the Dataset.
_BYTES_PER_VALUE = 16
#: Bytes per point for its reason: a code (at most 2 bytes, see MAX_REASONS) in the results and in the Dataset.
_BYTES_PER_REASON = 2 * 2
#: Bytes of the reason table at its fullest: per entry a str of REASON_LIMIT ASCII characters (49 + REASON_LIMIT
#: bytes), a pointer, and a dictionary entry (about 100 bytes) to find it.
_REASON_TABLE_BYTES = (MAX_REASONS + 1) * (49 + REASON_LIMIT + 8 + 100)


@dataclass(frozen=True, eq=False)
class Grid:
    """Named axes; the grid is their outer product, points in C order (the last axis fastest).

    Examples
    --------
    >>> g = as_grid({"mu": [0.5, 1.0, 1.5], "alpha": [1.0, 2.0]})
    >>> g.shape, g.size
    ((3, 2), 6)
    >>> g.points(2, 5).tolist()
    [[1.0, 1.0], [1.0, 2.0], [1.5, 1.0]]
    """

    names: tuple
    axes: tuple

    def __post_init__(self):
        named = isinstance(self.names, tuple) and all(isinstance(n, str) for n in self.names)
        arrays = isinstance(self.axes, tuple) and all(isinstance(a, np.ndarray) and a.ndim == 1 for a in self.axes)
        if not (named and arrays and len(self.names) == len(self.axes)):
            raise AtlasError("a Grid holds a tuple of names and a tuple of 1-D arrays, one per name; use as_grid().")

    @property
    def shape(self) -> tuple:
        return tuple(len(a) for a in self.axes)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def points(self, start: int, stop: int) -> np.ndarray:
        """Points ``start:stop`` of the flattened grid, one row each: computed, never stored whole.

        Column-major, so that each column (one parameter at every point) is contiguous."""
        out = np.empty((stop - start, len(self.axes)), order="F")
        for j, column in enumerate(self.columns(start, stop)):
            out[:, j] = column
        return out

    def columns(self, start: int, stop: int) -> list[np.ndarray]:
        """Per axis, its value at the points ``start:stop``: runs of equal values, made by ``numpy.repeat``.

        Examples
        --------
        >>> [c.tolist() for c in as_grid({"mu": [0.5, 1.0], "alpha": [1.0, 2.0, 3.0]}).columns(1, 5)]
        [[0.5, 0.5, 1.0, 1.0], [2.0, 3.0, 1.0, 2.0]]
        """
        return [self.column(j, start, stop) for j in range(len(self.axes))]

    def column(self, j: int, start: int, stop: int, along: np.ndarray | None = None) -> np.ndarray:
        """Axis ``j``'s value at the points ``start:stop``, or ``along`` (one value per value of the axis, e.g.
        a function of it computed once per value) laid out the same way.

        Examples
        --------
        >>> g = as_grid({"mu": [0.5, 1.0], "alpha": [1.0, 2.0, 3.0]})
        >>> g.column(1, 1, 5, along=np.array([10.0, 20.0, 30.0])).tolist()
        [20.0, 30.0, 10.0, 20.0]
        """
        axis = self.axes[j] if along is None else along
        inner = math.prod(self.shape[j + 1 :])  # points per step along this axis
        if stop <= start:
            return np.empty(0)
        period, count = inner * len(axis), stop - start
        offset = start % period
        if period <= count:  # whole periods, repeated: copies, no index arithmetic
            return np.tile(np.repeat(axis, inner), -(-(offset + count) // period))[offset : offset + count]
        if inner == 1:  # a window of the axis, wrapping around at most once
            return np.concatenate([axis[offset : offset + count], axis[: max(0, offset + count - period)]])
        first, last = start // inner, (stop - 1) // inner
        runs = np.full(last - first + 1, inner)
        runs[0] -= start - first * inner
        runs[-1] -= (last + 1) * inner - stop
        return np.repeat(axis[np.arange(first, last + 1) % len(axis)], runs)

    def token(self) -> bytes:
        """The grid's identity, for a checkpoint's fingerprint."""
        return repr(self.names).encode() + b"".join(a.tobytes() for a in self.axes)


def _axis(name: str, values) -> np.ndarray:
    if isinstance(values, (str, bytes)):
        raise AtlasError(f"the grid axis {name!r} is text; give a sequence of numbers (nothing is parsed).")
    try:
        axis = np.asarray(values, dtype=float)
    except (TypeError, ValueError) as error:
        raise AtlasError(f"the grid axis {name!r} is not a sequence of numbers: {error}.") from None
    if axis.ndim == 0:
        axis = axis.reshape(1)
    if axis.ndim != 1:
        raise AtlasError(f"the grid axis {name!r} has shape {axis.shape}; give a 1-D sequence of values.")
    if axis.size == 0:
        raise AtlasError(f"the grid axis {name!r} is empty; give at least one value.")
    bad = ~np.isfinite(axis)
    if bad.any():
        raise AtlasError(f"the grid axis {name!r} has non-finite values {axis[bad][:3].tolist()}; give finite numbers.")
    return axis


def _memory_bytes() -> int | None:
    try:
        return os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):
        return None


def as_grid(grid, *, max_points: int | None = None, outputs: int = 1) -> Grid:
    """Validate a grid ``{name: values}`` before any work: non-empty, finite, and small enough.

    Names are parameter names of the scene (or symbols, taken by name). The grid is too
    large when it has more than ``max_points`` points (default 10^9) or when its results
    (``outputs`` float64 arrays and the reasons) would not fit in half of this machine's
    memory.

    Examples
    --------
    >>> as_grid({})
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: the grid is empty; give {parameter name: values}, e.g. {"mu": numpy.linspace(0, 2, 50)}.
    >>> as_grid({"mu": [1.0, float("inf")]})
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: the grid axis 'mu' has non-finite values [inf]; give finite numbers.
    >>> as_grid({"mu": range(1000), "alpha": range(1000)}, max_points=10**5)
    Traceback (most recent call last):
    ...
    contactsym.errors.AtlasError: the grid has 1000000 points, more than max_points = 100000; sweep a coarser grid or raise max_points.
    """
    if isinstance(outputs, bool) or not isinstance(outputs, (int, np.integer)) or outputs < 1:
        raise AtlasError(f"outputs = {outputs!r:.60} must be a whole number >= 1.")
    if isinstance(grid, Grid):
        return grid
    if not isinstance(grid, Mapping):
        raise AtlasError(f"the grid must be a mapping {{parameter name: values}}, not {type(grid).__name__}.")
    if not grid:
        raise AtlasError('the grid is empty; give {parameter name: values}, e.g. {"mu": numpy.linspace(0, 2, 50)}.')
    for name in grid:
        if not isinstance(name, (str, sp.Symbol)) or not str(name).strip():
            raise AtlasError(f"the grid name {name!r} is not a parameter name; use text such as 'mu' (or a Symbol).")
    names = tuple(str(name) for name in grid)
    if len(set(names)) != len(names):
        raise AtlasError(f"the grid names a parameter twice: {list(names)}.")
    axes = tuple(_axis(name, values) for name, values in zip(names, grid.values()))
    result = Grid(names, axes)
    check_size(result.size, outputs, max_points)
    return result


def result_bytes(points: int, outputs: int = 1) -> int:
    """Memory a sweep's results may take: the values, twice, the reasons' codes, twice, and the reason table.

    Examples
    --------
    >>> round(result_bytes(10**6, outputs=2) / 2**20)  # MiB: 32 bytes of values and 4 of codes per point, the table
    63
    """
    return points * (outputs * _BYTES_PER_VALUE + _BYTES_PER_REASON) + min(points, MAX_REASONS + 1) * (
        _REASON_TABLE_BYTES // (MAX_REASONS + 1)
    )


def check_size(points: int, outputs: int = 1, max_points: int | None = None) -> None:
    """Refuse ``points`` above ``max_points`` (default :data:`MAX_POINTS`) or results beyond half the memory."""
    if max_points is not None and (
        isinstance(max_points, bool) or not isinstance(max_points, (int, np.integer)) or max_points < 1
    ):
        raise AtlasError(f"max_points = {max_points!r} must be a whole number >= 1 (or None).")
    limit = MAX_POINTS if max_points is None else int(max_points)
    if points > limit:
        raise AtlasError(
            f"the grid has {points} points, more than max_points = {limit}; sweep a coarser grid or raise max_points."
        )
    memory, needed = _memory_bytes(), result_bytes(points, outputs)
    if memory is not None and needed > memory // 2:
        raise AtlasError(
            f"the grid has {points} points; its results and their reasons need up to {needed / 2**30:.1f} GiB, more "
            f"than half of this machine's {memory / 2**30:.1f} GiB; sweep a coarser grid or split it."
        )
