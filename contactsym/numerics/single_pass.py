"""The classifier's float32 pass over one chunk (:mod:`.single`), with as little Python per chunk as NumPy allows.

A chunk of 2^16 points costs some fifty ufunc calls of about a microsecond each, on top of the arithmetic;
the Python around them once cost as much again (0.5 ns a point, a sixth of the memory floor). Here
everything that depends only on the chunk's layout (its length, which arrays hold one value for every
point, whether function values are given) is set up once and kept: the float32 rows and views of the
workspace, the generated code's compiled variant and its buffers, the sign test's scratch rows. A chunk
then costs its ufunc calls and a few list operations: rounding, two reductions that check every array
of the points, the sines or cosines, the generated code and the sign test.

The arithmetic, the checks and the results are those of the pass as first written: the same roundings,
the same bound, the same refusals (a value that breaks a check sends the chunk to the classifier's own
check, which raises the same error as for the float64 inputs).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Sequence

import numpy as np

from .buffered import BufferedCode
from .float_stage import _certain_sign
from .single import single_functions

__all__ = ["SinglePass"]


class _Layout:
    """Rows and views for chunks of one layout (length, arrays of one value, given functions)."""

    __slots__ = ("block", "buffers", "code", "copies", "inputs", "lone", "rows", "scratch")

    def __init__(self, code: BufferedCode, flags: tuple, functions: tuple, parameters: int, workspace: tuple):
        arrays, (floats, small) = sum(not lone for lone in flags), workspace
        rows = floats[: arrays + len(functions) + code.buffers + 2]
        n = rows.shape[1]
        self.inputs, self.copies, self.lone, used = [], [], [], 0
        for index, lone in enumerate(flags):
            if lone:  # one value for every point: rounded once, read through a view of stride 0
                one = np.empty(1, dtype=np.float32)
                self.inputs.append(np.ndarray((n,), dtype=np.float32, buffer=one, strides=(0,)))
                self.copies.append((one, True))
                if index < parameters:
                    self.lone.append((index, one))
            else:  # the arrays of the points fill the first rows, in order: one reduction checks them all
                self.inputs.append(rows[used])
                self.copies.append((rows[used], False))
                used += 1
        self.block = rows[: sum(not lone for lone in flags[:parameters])]
        self.rows = rows[arrays : arrays + len(functions)]  # sines and cosines computed here
        if functions:  # computed: a function of a parameter of one value is one value (:func:`.single_functions`)
            flags = flags + tuple(flags[index] for index in functions)
        self.code = code.function(frozenset(i for i, lone in enumerate(flags) if lone))
        self.buffers = list(rows[arrays + len(functions) : arrays + len(functions) + code.buffers])
        self.scratch = (rows[-2], rows[-1], small[0], small[1])


class SinglePass:
    """``run(pieces, known, out)``: the float32 pass of :class:`~contactsym.numerics.classifier.PointClassifier`
    over one chunk.

    Parameters
    ----------
    code : BufferedCode
        The kept factors' parts (P, M[, U, |U|]) over the parameters, then one argument per function.
    functions : tuple of (int, str)
        Per function argument, the index of its parameter and its NumPy ufunc (sine or cosine if computed).
    declared : sequence of (bool, bool)
        Per parameter, whether it is declared positive, negative.
    widths : (list or None, list)
        The float32 sign test's widths (:func:`.single.single_widths`) with the functions computed (None: not
        available) and given.
    parts : sequence of (int, (bool, bool))
        Per kept factor, the number of its parts and whether P and M are identically 0.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> from contactsym.numerics.buffered import BufferedCode
    >>> x, y = sp.symbols("x y", positive=True)
    >>> code = BufferedCode([x, y], [x * y, sp.Integer(2)])  # the factor x*y - 2: P = x*y, M = 2
    >>> run = SinglePass(code, (), [(True, False)] * 2, (None, [1e-6]), [(2, (False, False))])
    >>> out = np.empty((1, 3), dtype=np.int8)
    >>> run.run([np.array([1.0, 2.0, 4.0]), np.array([1.0, 1.0, 1.0])], [], out), out.tolist()
    (True, [[-1, 0, 1]])
    """

    def __init__(self, code: BufferedCode, functions: tuple, declared: Sequence, widths: tuple, parts: Sequence):
        self.code, self.functions, self.widths, self.parts = code, tuple(functions), widths, list(parts)
        self.parameters = len(declared)
        self.positive = [i for i, (positive, _) in enumerate(declared) if positive]
        self.negative = [i for i, (_, negative) in enumerate(declared) if negative]
        self._local = threading.local()

    def __getstate__(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "_local"}  # rows are made again where needed

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._local = threading.local()

    def _layout(self, pieces, known, n: int) -> _Layout:
        """The layout of a chunk of ``n`` points, made once (views into one workspace per thread)."""
        flags = tuple(n > 1 and a.strides == (0,) for a in (*pieces, *[k for k in known if k is not None]))
        local = self._local
        found = getattr(local, "layouts", {}).get((n, flags))
        if found is None:
            if getattr(local, "size", 0) < n:  # the rows of the largest layout, for the longest chunk so far
                rows = self.parameters + len(self.functions) + self.code.buffers + 2
                local.workspace = (np.empty((rows, n), dtype=np.float32), np.empty((2, n), dtype=np.int8))
                local.size, local.layouts = n, {}
            if len(local.layouts) >= 16:  # a few lengths and layouts per call
                local.layouts.clear()
            computed = tuple(index for index, _ in self.functions) if not any(k is not None for k in known) else ()
            workspace = tuple(w[:, :n] for w in local.workspace)
            found = local.layouts[(n, flags)] = _Layout(self.code, flags, computed, self.parameters, workspace)
        return found

    def run(self, pieces: Sequence[np.ndarray], known: Sequence, out: np.ndarray) -> bool | None:
        """Into ``out`` (int8, one row per kept factor): the float32 signs (+1/-1 certain, 0 not) and True; or
        False (the chunk's values are checked, evaluate it in float64) or None (not even checked: check, then
        evaluate in float64). ``known``: per function, None or its given float64 values."""
        given = [k for k in known if k is not None]
        if given and len(given) < len(known):  # some given, some not: no float32 bound counts both
            return None
        layout = self._layout(pieces, known, len(pieces[0]))
        checked = False
        try:
            with np.errstate(all="raise"):  # a value outside float32's normal range: float64 for this chunk
                for (row, lone), array in zip(layout.copies, (*pieces, *given)):
                    np.copyto(row, array[:1] if lone else array, casting="same_kind")
                reach = self._checked(layout)
                if reach is None:
                    return None
                checked = True
                widths = self.widths[1] if given or not self.functions else self.widths[0]
                if given:
                    functions = layout.inputs[self.parameters :]
                elif widths is None:
                    return False
                else:
                    functions = single_functions(self.functions, layout.inputs, reach, layout.rows)
                    if functions is None:
                        return False
                values = iter(layout.code(*layout.inputs[: self.parameters], *functions, *layout.buffers))
                for position, (count, zeros) in enumerate(self.parts):
                    groups = [next(values) for _ in range(count)]  # a constant part is a number: ufuncs take it
                    _certain_sign(groups, widths[position], zeros, out[position], layout.scratch)
                return True
        except FloatingPointError:
            return False if checked else None

    def _checked(self, layout: _Layout) -> list[float] | None:
        """Per parameter the largest |value| of the chunk (float32, as rounded), or None where a value is not
        finite or breaks its declared sign (rounding to float32 keeps both properties)."""
        lows = np.minimum.reduce(layout.block, axis=1).tolist() if len(layout.block) else []
        highs = np.maximum.reduce(layout.block, axis=1).tolist() if len(layout.block) else []
        for index, one in layout.lone:  # one value for every point, in parameter order among the rows
            value = float(one[0])
            lows.insert(index, value)
            highs.insert(index, value)
        if not math.isfinite(sum(lows) + sum(highs)):  # NaN or an infinity somewhere (float32 values: no overflow)
            return None
        if any(not lows[i] > 0 for i in self.positive) or any(not highs[i] < 0 for i in self.negative):
            return None
        return [max(-low, high) for low, high in zip(lows, highs)]
