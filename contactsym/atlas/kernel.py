"""The kernel of a quantity: generated code and plain numbers, evaluated on a chunk of grid points."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp

from .. import numerics
from .grid import AtlasError, Grid

__all__ = ["Kernel", "Setup", "setup_for"]


def _reason(error: BaseException) -> str:
    text = str(error).strip().splitlines()[0] if str(error).strip() else ""
    return f"{type(error).__name__}: {text}"[:300]


class Kernel:
    """Generated code for one quantity: ``kernel(points) -> (values, reasons)``.

    ``points`` has one row per point and one column per grid axis; ``values`` one row per
    point and one column per name in ``outputs``. A vectorised kernel evaluates a whole
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

    def evaluate(self, points: np.ndarray) -> np.ndarray:
        raise NotImplementedError

    def __call__(self, points: np.ndarray) -> tuple[np.ndarray, list[str]]:
        n = len(points)
        if self.vectorised:
            try:
                with np.errstate(all="ignore"):
                    return np.asarray(self.evaluate(points), dtype=float).reshape(n, len(self.outputs)), [""] * n
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

    def columns(self, points: np.ndarray) -> list[np.ndarray]:
        n = len(points)
        return [points[:, i] for i in range(points.shape[1])] + [np.full(n, v) for v in self.fixed]

    def prepare(self, expr, what: str, extra=()) -> sp.Expr:
        """The expression with the user's functions substituted; every other symbol is an argument."""
        expr = numerics.substitute(expr, self.functions)
        missing = sorted(map(str, expr.free_symbols - set(self.symbols) - set(extra)))
        if missing:
            raise AtlasError(f"{what} needs values for {missing}; give them in values= or in the grid.")
        return expr


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
