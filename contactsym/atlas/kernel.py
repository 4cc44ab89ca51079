"""The kernel of a quantity: generated code and plain numbers, evaluated on a chunk of grid points."""

from __future__ import annotations

import math
import threading
import weakref
from dataclasses import dataclass

import numpy as np
import sympy as sp

from .. import numerics
from .grid import REASON_LIMIT, AtlasError, Grid

__all__ = ["Kernel", "Reasons", "Setup", "once_per_scene", "setup_for"]


def _reason(error: BaseException) -> str:
    text = str(error).strip().splitlines()[0] if str(error).strip() else ""
    return f"{type(error).__name__}: {text}"[:300]


class Reasons:
    """Why points have no value, compactly: per point a code (``uint8`` while the table has at most
    256 entries, wider beyond) into ``table``, a list of texts whose entry 0 is ``""`` (a value).

    Examples
    --------
    >>> r = Reasons.from_texts(["", "ValueError: x", "", "ValueError: x", "NaN: y"])
    >>> r.codes.tolist(), r.table
    ([0, 1, 0, 1, 2], ['', 'ValueError: x', 'NaN: y'])
    >>> r[3], len(r), r.codes.dtype.name
    ('ValueError: x', 5, 'uint8')
    >>> r.texts().tolist() == ["", "ValueError: x", "", "ValueError: x", "NaN: y"]
    True
    """

    def __init__(self, codes: np.ndarray, table: list[str]):
        self.codes, self.table = codes, table

    @classmethod
    def none(cls, n: int) -> Reasons:
        """``n`` points, every one with a value."""
        return cls(np.zeros(n, dtype=np.uint8), [""])

    @classmethod
    def from_texts(cls, texts) -> Reasons:
        """From one text per point (``""`` where the point has a value)."""
        found: dict[str, int] = {"": 0}
        codes = [found.setdefault(str(text)[:REASON_LIMIT], len(found)) for text in texts]
        return cls(np.asarray(codes, dtype=code_type(len(found))), list(found))

    def __len__(self) -> int:
        return len(self.codes)

    def __getitem__(self, i: int) -> str:
        return self.table[int(self.codes[i])]

    def texts(self) -> np.ndarray:
        """One text per point (an object array; the texts themselves are shared)."""
        return np.asarray(self.table, dtype=object)[self.codes]


def code_type(entries: int) -> np.dtype:
    """The narrowest unsigned integer type for codes into a table of ``entries`` texts."""
    for dtype in (np.uint8, np.uint16, np.uint32):
        if entries <= np.iinfo(dtype).max + 1:
            return np.dtype(dtype)
    return np.dtype(np.uint64)


class Kernel:
    """Generated code for one quantity: ``kernel(points) -> (values, reasons)``.

    ``points`` has one row per point and one column per grid axis; ``values`` one row per
    point and one column per name in ``outputs``; ``reasons`` one text per point (``""``
    where it has a value), as a list or as :class:`Reasons`. A vectorised kernel evaluates a whole
    chunk at once; where that fails it is evaluated point by point, so that a failure costs
    only its own point: NaN, with the error as the point's reason.

    Examples
    --------
    A quantity builds its kernel once; the kernel then measures a chunk of points:

    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym import atlas
    >>> def ratio(values):
    ...     return 1 / values["mu"]
    >>> kernel = atlas.function(ratio).build(cs.scene("brake"), atlas.as_grid({"mu": [0.5, 0.0]}), {})
    >>> isinstance(kernel, atlas.Kernel), kernel.outputs
    (True, ('ratio',))
    >>> values, reasons = kernel(np.array([[0.5], [0.0]]))
    >>> float(values[0, 0]), bool(np.isnan(values[1, 0])), reasons[1]
    (2.0, True, 'ZeroDivisionError: float division by zero')
    """

    outputs: tuple = ()
    vectorised: bool = False

    def scratch(self, name: str, shape: tuple) -> np.ndarray:
        """A float64 array of ``shape`` for this thread, reused chunk after chunk: fresh memory of a few
        hundred kilobytes costs a page fault per 4 KiB each time. Never returned: the next chunk overwrites it."""
        local = self.__dict__.get("_scratch")
        if local is None:
            local = self.__dict__["_scratch"] = threading.local()
        size = math.prod(shape)
        found = getattr(local, name, None)
        if found is None or found.size < size:
            found = np.empty(size)
            setattr(local, name, found)
        return found[:size].reshape(shape)

    def __getstate__(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "_scratch"}  # per process, per thread

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)

    def evaluate(self, points: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def run(self, grid: Grid, start: int, stop: int) -> tuple[np.ndarray, Reasons | list[str]]:
        """The points ``start:stop`` of ``grid``: ``self(grid.points(start, stop))`` unless a kernel reads
        the grid's columns (and functions of its axes, once per axis value) itself."""
        return self(grid.points(start, stop))

    def __call__(self, points: np.ndarray) -> tuple[np.ndarray, Reasons | list[str]]:
        n = len(points)
        if self.vectorised:
            try:
                with np.errstate(all="ignore"):
                    values = np.asarray(self.evaluate(points), dtype=float).reshape(n, len(self.outputs))
                return values, Reasons.none(n)
            except Exception:  # noqa: BLE001 - find the failing points one by one below
                pass
        values = np.full((n, len(self.outputs)), np.nan)
        reasons = [""] * n
        for i in range(n):
            try:
                with np.errstate(all="ignore"):
                    values[i] = np.asarray(self.evaluate(points[i : i + 1]), dtype=float).reshape(-1)
            except Exception as error:  # noqa: BLE001 - a failing point is NaN with its reason, never a crash
                reasons[i] = _reason(error)
        return values, reasons


@dataclass(frozen=True)
class Setup:
    """Grid symbols then fixed symbols, the fixed numbers, and the user's function values."""

    symbols: tuple
    fixed: tuple
    functions: numerics.NumericValues

    @property
    def swept(self) -> tuple:
        """The grid's symbols."""
        return self.symbols[: len(self.symbols) - len(self.fixed)]

    def specialised(self, expr):
        """``expr`` with the fixed numbers put in, each as the exact rational its float stands for: code
        generated from it has fewer inputs and operations, and a classifier built on it stays exact."""
        fixed = self.symbols[len(self.swept) :]
        return expr.xreplace({s: sp.Rational(v) for s, v in zip(fixed, self.fixed)})

    def grid_columns(self, points: np.ndarray) -> list[np.ndarray]:
        """One contiguous array per grid axis (the arguments of code built on :meth:`specialised` expressions)."""
        return [np.ascontiguousarray(points[:, i]) for i in range(points.shape[1])]

    def fixed_columns(self, n: int) -> list[np.ndarray]:
        """Each fixed number for ``n`` points: a read-only view of one value (stride 0, no memory per point;
        generated code reads it once)."""
        return [_constant(v, n) for v in self.fixed]

    def columns(self, points: np.ndarray) -> list[np.ndarray]:
        """One array per symbol: the grid's columns (contiguous), then the fixed numbers (:meth:`fixed_columns`)."""
        return self.grid_columns(points) + self.fixed_columns(len(points))

    def prepare(self, expr, what: str, extra=()) -> sp.Expr:
        """The expression with the user's functions substituted; every other symbol is an argument."""
        expr = numerics.substitute(expr, self.functions)
        missing = sorted(map(str, expr.free_symbols - set(self.symbols) - set(extra)))
        if missing:
            raise AtlasError(f"{what} needs values for {missing}; give them in values= or in the grid.")
        return expr


def _constant(value: float, n: int) -> np.ndarray:
    """``value`` for ``n`` points: a read-only array of stride 0 (as ``numpy.broadcast_to``, at a tenth of its cost)."""
    out = np.ndarray((n,), dtype=np.float64, buffer=np.array([value], dtype=np.float64), strides=(0,))
    out.flags.writeable = False
    return out


def _grid_symbols(scene, grid: Grid) -> list:
    symbols = []
    for name, axis in zip(grid.names, grid.axes):
        for end in (axis.min(), axis.max()):  # names and sign assumptions, checked at both ends
            try:
                (symbol,) = numerics.numeric_values(scene, {name: float(end)}).numbers
            except numerics.NumericsError as error:
                raise AtlasError(f"grid axis {name!r}: {error}") from None
        symbols.append(symbol)
    return symbols


def setup_for(scene, grid: Grid, values) -> Setup:
    vals = numerics.numeric_values(scene, values)
    symbols = _grid_symbols(scene, grid)
    both = sorted(str(s) for s in set(symbols) & set(vals.numbers))
    if both:
        raise AtlasError(f"{both} are both swept (grid) and fixed (values); give each in one place.")
    fixed = [s for s in vals.numbers if s not in symbols]
    return Setup(
        tuple(symbols) + tuple(fixed),
        tuple(float(vals.numbers[s]) for s in fixed),
        numerics.NumericValues({}, vals.functions),
    )


#: Kernels of the vectorised quantities, per scene: see :func:`once_per_scene`.
_KERNELS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def once_per_scene(builder, scene, grid: Grid, values, options: dict) -> Kernel:
    """The kernel of a vectorised quantity, kept per scene, grid (names and ends), fixed numbers and options.

    The symbolic work of a kernel (conditions prepared, code generated) costs far more than a
    chunk; a sweep run again, or over another grid of the same parameters and range, takes the
    kernel built before (read-only: its scratch is per thread). Fixed values that are not
    numbers (functions) are not compared: such a kernel is built afresh.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym import atlas
    >>> from contactsym.atlas.quantities import classification
    >>> builder, grid = classification().builder, atlas.as_grid({"mu": [0.5, 1.5]})
    >>> first = once_per_scene(builder, cs.scene("brake"), grid, {"alpha": 1.0, "m": 1}, {"signs": None})
    >>> first is once_per_scene(builder, cs.scene("brake"), grid, {"alpha": 1.0, "m": 1}, {"signs": None})
    True
    """
    try:
        fixed = tuple(sorted((type(k).__name__, str(k), float(v)) for k, v in dict(values or {}).items()))
    except (TypeError, ValueError):
        return builder(scene, grid, values, **options)
    ends = tuple((float(a.min()), float(a.max())) for a in grid.axes)
    key = (builder.__name__, grid.names, ends, fixed, repr(sorted(options.items())))
    store = _KERNELS.setdefault(scene, {})
    if key not in store:
        if len(store) >= 32:  # a long session of many sweeps: keep the memory bounded
            store.clear()
        store[key] = builder(scene, grid, values, **options)
    return store[key]
