"""The classifier's verdicts from the signs of its kept factors: per point the least sign of the conditions
(``stable``), computed chunk by chunk, and per condition its sign, computed only when asked for.

A verdict costs a pass or two over bytes, not one per condition: conditions that are the same product of
factors are one row, a condition that is one factor is that factor's row, and no row of condition signs
is written unless :attr:`PointsResult.signs` is read.
"""

from __future__ import annotations

from collections.abc import Sequence
from functools import cached_property

import numpy as np

__all__ = ["PointsResult", "Verdicts"]


class Verdicts:
    """How the signs of the conditions follow from those of the kept factors (int8 rows of +1, -1, 0).

    Parameters
    ----------
    uses : sequence of (condition index, sign, factor position)
        Condition ``index`` has the factor at ``position``, with ``sign`` (-1: a dropped factor of negative sign).
    conditions : int
        The number of conditions; one without uses is positive.
    always_false : sequence of int
        Conditions that are never > 0 (their sign is 0 everywhere).

    Examples
    --------
    >>> import numpy as np
    >>> v = Verdicts([(0, 1, 0), (1, -1, 0), (1, 1, 1)], 3, [])
    >>> factors = np.array([[1, 1, -1, 0], [1, -1, -1, 1]], dtype=np.int8)
    >>> stable = np.empty(4, dtype=np.int8)
    >>> v.stable(factors, stable, np.empty((1, 4), dtype=np.int8))
    >>> stable.tolist(), v.signs(factors).tolist()
    ([-1, 1, -1, 0], [[1, 1, -1, 0], [-1, 1, -1, 0], [1, 1, 1, 1]])
    """

    def __init__(self, uses: Sequence[tuple[int, int, int]], conditions: int, always_false: Sequence[int]):
        self.uses, self.conditions, self.always_false = list(uses), int(conditions), list(always_false)
        products: dict[int, tuple[int, list[int]]] = {}
        for index, sign, position in self.uses:
            total, positions = products.get(index, (1, []))
            products[index] = (total * sign, [*positions, position])
        # conditions that are the same product are one row of the least
        self.products = sorted({(sign, tuple(sorted(p))) for sign, p in products.values()}, key=lambda s: len(s[1]))

    def stable(self, factor_signs: np.ndarray, out: np.ndarray, scratch: np.ndarray) -> None:
        """Into ``out``: per point the least sign of the conditions (1 stable, -1 unstable, 0 undecided).

        ``scratch``: an int8 row at least as long, overwritten."""
        least = None  # the row of the least so far: a factor's own row, or out
        for sign, positions in self.products:
            if sign > 0 and len(positions) == 1:
                row = factor_signs[positions[0]]
            else:  # a product of factors, or a factor of changed sign: into out (the first) or scratch
                row = out if least is None else scratch[0, : len(out)]
                second = sign if len(positions) == 1 else factor_signs[positions[1]]
                np.multiply(factor_signs[positions[0]], second, out=row)
                for position in positions[2:]:
                    np.multiply(row, factor_signs[position], out=row)
                if sign < 0 and len(positions) > 1:
                    np.negative(row, out=row)
            if least is None:
                least = row
            else:  # one pass: the least of two rows straight into out
                np.minimum(least, row, out=out)
                least = out
        if least is None:  # no condition depends on the point
            out[...] = 1
        elif least is not out:  # a single condition, one factor
            np.copyto(out, least)
        if self.always_false:
            np.minimum(out, 0, out=out)

    def signs(self, factor_signs: np.ndarray) -> np.ndarray:
        """Per condition its sign at each point: a new int8 array of shape (conditions, points)."""
        signs = np.ones((self.conditions, factor_signs.shape[1]), dtype=np.int8)
        for index, sign, position in self.uses:
            signs[index] *= factor_signs[position]
            if sign < 0:
                np.negative(signs[index], out=signs[index])
        signs[self.always_false] = 0
        return signs


class PointsResult:
    """Result of :class:`~contactsym.numerics.PointClassifier`: ``stable`` (+1, -1, 0 per point), per-condition
    ``signs`` (computed when first read from ``factor_signs``, shape (kept factors, points)), the mask ``in_band`` of points decided exactly, their number
    ``exact_points``, and the relative band half-width ``band`` used.

    Examples
    --------
    >>> import numpy as np
    >>> factors = np.array([[1, -1, 1]], dtype=np.int8)
    >>> r = PointsResult(np.array([1, -1, 1], dtype=np.int8), factors, Verdicts([(0, 1, 0)], 2, []),
    ...                  np.zeros(3, dtype=bool), 0, 1e-12)
    >>> r.stable.tolist(), r.signs.tolist(), r.exact_points
    ([1, -1, 1], [[1, -1, 1], [1, 1, 1]], 0)
    """

    def __init__(
        self,
        stable: np.ndarray,
        factor_signs: np.ndarray,
        verdicts: Verdicts,
        in_band: np.ndarray,
        exact_points: int,
        band: float,
    ):
        self.stable, self.in_band, self.exact_points, self.band = stable, in_band, exact_points, band
        self._factor_signs, self._verdicts = factor_signs, verdicts

    @cached_property
    def signs(self) -> np.ndarray:
        """Per condition, its sign at each point (shape: conditions, then the points' shape)."""
        flat = self._verdicts.signs(self._factor_signs)  # (kept factors, points), flat
        return flat.reshape((self._verdicts.conditions, *self.stable.shape))
