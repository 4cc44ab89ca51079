"""The classifier's float32 pass: a chunk's inputs rounded to float32, then the generated code and the sign
test in float32, certified as the float64 stage is.

NumPy's float32 loops take twice the values per SIMD instruction, and a chunk is half the bytes. The
rounding-error bound is the float64 one (:mod:`.one_signed`) with the float32 unit, each input's own
rounding to float32 counted as one more rounding at its leaf, and a sine or cosine from NumPy's float32
loops counted by its checked error. The sign test's width is chosen so that a point certain in float32
is certain, with the same sign, in float64: :class:`~contactsym.numerics.classifier.PointClassifier`
evaluates only the points it leaves uncertain again in float64, and its result is the float64 one.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import sympy as sp

from .certified import _gamma
from .float_stage import _CHEAP_ABSOLUTE, _CHEAP_ERROR, _CHEAP_RANGE
from .one_signed import _roundings

__all__ = ["SINE_ROUNDINGS", "SINGLE_UNITS", "single_functions", "single_widths", "to_single"]

#: A float32 rounding in float64 units (u32 = 2^-24 = 2^29 u64): the unit ``_gamma`` counts in.
SINGLE_UNITS = 2**29

#: The float32 roundings a sine or cosine of :func:`single_functions` counts for (its relative error, checked
#: per chunk, is at most ``_CHEAP_ERROR``; gamma_k >= k u).
SINE_ROUNDINGS = math.ceil(_CHEAP_ERROR / 2.0**-24)

_ULP_BELOW = 1 + 2.0**-22  # a float64 value is within this factor of its float32 rounding (normal range)


def single_widths(
    code: Sequence[tuple], functions: Sequence[sp.Symbol], computed: bool, widths: Sequence[float], gammas
) -> list[float]:
    """Per kept factor, the relative width of the float32 sign test: certain there means certain, with the
    same sign, in float64 at ``widths`` (the float64 test's widths, ``gammas`` its error bounds).

    ``code``: per factor, its generated expressions (P, M[, U, |U|]) with each function of a parameter
    replaced by its symbol in ``functions``; those count as :data:`SINE_ROUNDINGS` roundings if
    ``computed`` (:func:`single_functions`) and as one (a float64 value rounded to float32) if given.
    The width is 2 gamma32 + 2 width + 2 gamma64, gamma32 over the roundings of the longest path plus the
    sign test's three: certain with it, |F| > (2 width + gamma64) (P + M + |U|), so float64 is certain too. Raises ``NumericsError`` for code without a float32
    bound (a function computed inside the code, a fractional power).

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y", positive=True)
    >>> [w] = single_widths([(x * y, sp.Integer(1))], [], True, [1e-12], [2e-16])
    >>> round(w / 2.0**-24, 3)  # 2 gamma_6 (x, y rounded, one product, three in the test), in float32 units
    12.0
    """
    leaves = dict.fromkeys(functions, SINE_ROUNDINGS if computed else 1)
    return [
        2 * _gamma((max(_roundings(g, leaves=leaves) for g in part) + 3) * SINGLE_UNITS) + 2 * w + 2 * gamma
        for part, w, gamma in zip(code, widths, gammas)
    ]


def to_single(arrays: Sequence[np.ndarray], rows: np.ndarray) -> list[np.ndarray]:
    """Each float64 array rounded to float32 into a row of ``rows`` (float32, at least as long), the first rows
    in order; an array of one value for every point (stride 0) is rounded once and stays one value.

    Run under ``np.errstate(all="raise")``: a value that overflows or underflows float32 raises
    ``FloatingPointError`` (its rounding error would not be relative). NaN and infinities pass through,
    for the caller's checks.

    Examples
    --------
    >>> import numpy as np
    >>> rows = np.empty((2, 3), dtype=np.float32)
    >>> a, b = to_single([np.array([0.1, 2.0, -3.5]), np.broadcast_to(0.5, (3,))], rows)
    >>> a.dtype.name, a.tolist() == [np.float32(0.1), 2.0, -3.5], b.strides, b.tolist()
    ('float32', True, (0,), [0.5, 0.5, 0.5])
    """
    out, used = [], 0
    for array in arrays:
        n = len(array)
        if array.strides == (0,) and n > 1:
            one = np.empty(1, dtype=np.float32)
            np.copyto(one, array[:1], casting="same_kind")
            out.append(np.ndarray((n,), dtype=np.float32, buffer=one, strides=(0,)))
        else:  # the arrays of the points fill the first rows, in order: one reduction can check them all
            np.copyto(rows[used, :n], array, casting="same_kind")
            out.append(rows[used, :n])
            used += 1
    return out


def single_functions(functions, arrays: Sequence[np.ndarray], reach: Sequence[float], rows: np.ndarray) -> list | None:
    """Per ``(index, ufunc)`` of ``functions`` (sine or cosine), its values at the float32 arguments
    ``arrays[index]`` from NumPy's float32 SIMD loops, into a row of ``rows``; None where the error bound
    does not hold (then the chunk is evaluated in float64).

    With x32 the float32 rounding of the float64 argument x and NumPy's float32 function within
    ``_CHEAP_ABSOLUTE`` of the exact one at x32, a value v is within e = 2^-24 |x| + ``_CHEAP_ABSOLUTE`` of
    sin(x) (or cos(x)); relative to the function at x, at most ``_CHEAP_ERROR`` where the least |v| over the
    chunk makes it so. ``reach``: per parameter the largest |x32|.

    Examples
    --------
    >>> import numpy as np
    >>> x = np.array([0.5, 1.0, 1.5], dtype=np.float32)
    >>> [s] = single_functions([(0, "sin")], [x], [1.5], np.empty((1, 3), dtype=np.float32))
    >>> bool(np.allclose(s, np.sin([0.5, 1.0, 1.5]), rtol=1e-6))
    True
    >>> single_functions([(0, "sin")], [np.array([0.0, 1.0], dtype=np.float32)], [1.0], np.empty((1, 2), np.float32))
    """
    values = []
    with np.errstate(all="ignore"):
        for number, (index, ufunc) in enumerate(functions):
            argument, n = arrays[index], len(arrays[index])
            if not reach[index] <= _CHEAP_RANGE:
                return None
            one = argument.strides == (0,) and n > 1
            row = np.empty(1, dtype=np.float32) if one else rows[number, :n]
            getattr(np, ufunc)(argument[:1] if one else argument, out=row)
            error = reach[index] * _ULP_BELOW * 2.0**-24 + _CHEAP_ABSOLUTE
            low, high = float(np.minimum.reduce(row)), float(np.maximum.reduce(row))
            smallest = low if low > 0 else -high if high < 0 else 0.0  # NaN: 0.0, refused below
            if not (smallest > error and error / (smallest - error) <= _CHEAP_ERROR):
                return None
            values.append(np.ndarray((n,), dtype=np.float32, buffer=row, strides=(0,)) if one else row)
    return values
