"""The classifier's float32 pass as one compiled loop over the points (numba, optional: ``contactsym[fast]``).

The NumPy pass (:mod:`.single_pass`) makes some fifty passes over a chunk: the rounding to float32, the
checks, each operation of the generated code, the sign test. Each pass reads and writes the cache; together
they cost about three times reading the inputs once (the memory floor). Here one loop, compiled
by numba, does all of it per point: it reads the float64 inputs once, rounds them to float32, evaluates the
generated code's operations in the same order in float32, and applies the same sign test with the same widths
(:func:`.single.single_widths`), writing one int8 sign per kept factor. The values are those of the NumPy
pass, bit for bit (no fastmath, no contraction into fused multiply-adds, constants rounded to float32 as
NumPy rounds a Python float against a float32 array). Sines and cosines still come from NumPy's float32
loops, once per chunk, with the same error bound, checked per point.

The NumPy pass evaluates a chunk under ``np.errstate(all="raise")`` and sends a chunk that traps to float64.
Here a chunk runs first without checks under the processor's floating-point status flags, cleared before and
read after through the C library (as NumPy reads them): a chunk without an overflow, underflow, invalid
operation or division by zero is done. A chunk that raised one (or every chunk, where the flags cannot be read)
runs again in a checked loop, where each point checks its own values: one (an input rounded, a result) that
is not a normal float32 number, with a margin (so also an exact 0 or a zero input), leaves the point undecided
(0), and the classifier evaluates it again in float64 as it does every point the float32 pass leaves
undecided. The results are therefore the float64 stage's, exactly. An input that is not finite or breaks
its declared sign makes :meth:`FusedPass.run` return None: the classifier's own check then raises its usual
error.

Compiling takes about a second per loop and layout of the inputs (arrays, or one value for every point;
functions computed or given);
:class:`~contactsym.numerics.classifier.PointClassifier` compiles once, and only for calls of at least
:data:`FUSED_MIN_POINTS` points.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import functools
import math
import platform
import sys
import threading
import time
from collections.abc import Sequence

import numpy as np

from .buffered import BufferedCode
from .float_stage import _CHEAP_ABSOLUTE, _CHEAP_ERROR, _CHEAP_RANGE
from .single import _ULP_BELOW

__all__ = ["FUSED_MIN_POINTS", "FusedPass", "available"]

#: Calls of at least this many points (an atlas task's size) take the fused loop when numba is installed;
#: smaller calls (the many small ones of tests and of interactive work) never pay its compile time.
FUSED_MIN_POINTS = 1 << 16

_OPERATIONS = {"add": "{} + {}", "subtract": "{} - {}", "multiply": "{} * {}", "divide": "{} / {}"}
_UNARY = {"square": "{0} * {0}", "negative": "-{}", "absolute": "abs({})", "sqrt": "np.sqrt({})"}
_TINY = 2.0 * float(np.finfo(np.float32).tiny)  # a margin above float32's least normal number
_HUGE = float(np.finfo(np.float32).max)


def _sine_bound() -> tuple[float, float]:
    """(slope, least): a float32 sine or cosine v of the rounded argument x32 is within ``_CHEAP_ERROR`` relative
    of the function at x where ``|v| >= slope |x32| + least`` holds in float32 (both rounded up, with a margin).

    :func:`.single.single_functions` asks e / (|v| - e) <= ``_CHEAP_ERROR`` for e = |x32| ``_ULP_BELOW`` 2^-24 +
    ``_CHEAP_ABSOLUTE``, i.e. |v| >= e (1 + 1/``_CHEAP_ERROR``); the factor 1 + 2^-10 covers the three float32
    roundings of the test."""
    scale = (1 + 1 / _CHEAP_ERROR) * (1 + 2.0**-10)
    up = [np.nextafter(np.float32(k * scale), np.float32(np.inf)) for k in (_ULP_BELOW * 2.0**-24, _CHEAP_ABSOLUTE)]
    return float(up[0]), float(up[1])


_SINE = _sine_bound()


@functools.cache
def available() -> bool:
    """Whether numba imports here (then large calls of the classifier take the fused loop)."""
    try:
        import numba  # noqa: F401 - optional (contactsym[fast]), imported where first needed
    except ImportError:
        return False
    return True


def _source(
    code: BufferedCode, functions, declared: Sequence, widths, parts: Sequence, given: bool, checked: bool, constant=()
):
    """The kernel's Python source, or None where an operation has no float32 form here.

    ``checked``: every float32 value of a point (inputs rounded, results of operations) must be a normal number,
    with a margin: the least and the largest magnitude are kept (``lo``, ``hi``). A NaN changes neither; but every
    value computed from a NaN is NaN, and a sign test that meets one is false both ways (0), so a factor whose
    sign is decided was computed from values that ``lo`` and ``hi`` saw. Else no value is checked: the chunk
    runs under the status flags (:func:`_status_flags`). ``constant``: per argument, whether it is one value for
    every point (passed as one element and read once: a stride-0 array in the loop would keep it from SIMD)."""
    p, f = len(declared), len(functions)

    def at(i: int) -> str:
        return f"a{i}[0]" if i < len(constant) and constant[i] else f"a{i}[i]"

    names = [f"a{i}" for i in range(p + f)]
    outs = [f"out{k}" for k in range(len(parts))]
    body = ["    n = len(out0)", "    bad = False", "    for i in range(n):"]
    body += ["        ok = True"] + (["        lo = HUGE", "        hi = TINY"] if checked else [])
    value: dict[str, str] = {}

    def seen(name: str) -> None:
        if not checked:
            return
        body.append(f"        m = abs({name})")
        body.append("        lo = m if m < lo else lo")
        body.append("        hi = m if m > hi else hi")

    for i, (positive, negative) in enumerate(declared):
        body.append(f"        x{i} = {at(i)}")
        test = f"(x{i} > 0.0) & (x{i} <= MAX64)" if positive else f"(x{i} < 0.0) & (x{i} >= -MAX64)"
        body.append(f"        bad = bad | ~({test if positive or negative else f'abs(x{i}) <= MAX64'})")
        body.append(f"        y{i} = np.float32(x{i})")
        seen(f"y{i}")
        value[f"a{i}"] = f"y{i}"
    for number, (index, _) in enumerate(functions):
        i = p + number
        body.append(f"        y{i} = np.float32({at(i)})")
        if given:  # a float64 value rounded, one rounding as for an input
            seen(f"y{i}")
        else:  # NumPy's float32 sine or cosine of the rounded argument within its bound (:data:`_SINE`)
            body.append(f"        r{i} = abs(y{index})")
            body.append(f"        ok = ok & (r{i} <= CHEAP_RANGE) & (abs(y{i}) >= r{i} * SINE_SLOPE + SINE_LEAST)")
        value[f"a{i}"] = f"y{i}"

    def shown(operand: str) -> str:
        return value.get(operand) or f"np.float32({operand})"

    def emit(ufunc: str, operands: Sequence[str], result: str) -> None:
        form = _OPERATIONS.get(ufunc) or _UNARY[ufunc]
        body.append(f"        {result} = {form.format(*[shown(o) for o in operands])}")
        seen(result)
        if ufunc == "sqrt" and checked:  # of a negative number: NaN
            body.append(f"        ok = ok & (abs({result}) <= HUGE)")
        value[result] = result

    for ufunc, operands, result in code._code:
        if ufunc not in _OPERATIONS and ufunc not in _UNARY:
            return None
        emit(ufunc, operands, result)
    results = iter(code._results)
    for k, ((count, (zero_p, zero_m)), width) in enumerate(zip(parts, widths)):
        P, M, *rest = [next(results) for _ in range(count)]
        if rest:  # |F| > width (P + M + |U|), as _certain_sign
            emit("subtract", (P, M), f"g{k}")
            emit("add", (f"g{k}", rest[0]), f"g{k}_")
            emit("add", (P, M), f"h{k}")
            emit("add", (f"h{k}", rest[1]), f"h{k}_")
            emit("multiply", (f"h{k}_", repr(float(width))), f"w{k}")
            sign = f"np.int8(g{k}_ > w{k}) - np.int8(g{k}_ < -w{k})"
        elif zero_m:
            sign = f"np.int8({shown(P)} > 0.0)"
        elif zero_p:
            sign = f"-np.int8({shown(M)} > 0.0)"
        else:
            shrink = repr((1 - width) / (1 + width))
            emit("multiply", (P, shrink), f"g{k}")
            emit("multiply", (M, shrink), f"h{k}")
            sign = f"np.int8(g{k} > {shown(M)}) - np.int8(h{k} > {shown(P)})"
        body.append(f"        s{k} = {sign}")
    if checked:
        body.append("        ok = ok & (lo >= TINY) & (hi <= HUGE)")
    for k in range(len(parts)):
        body.append(f"        out{k}[i] = s{k} * np.int8(ok)")
    body.append("    return bad")
    return "\n".join([f"def _fused({', '.join(names + outs)}):", *body])


class FusedPass:
    """``run(pieces, known, out)``: the float32 pass of :class:`~contactsym.numerics.classifier.PointClassifier`
    over one chunk, as one compiled loop (numba); the same arguments and results as
    :meth:`.single_pass.SinglePass.run`, and the same parameters as :class:`.single_pass.SinglePass`.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> from contactsym.numerics.buffered import BufferedCode
    >>> x, y = sp.symbols("x y", positive=True)
    >>> code = BufferedCode([x, y], [x * y, sp.Integer(2)])  # the factor x*y - 2: P = x*y, M = 2
    >>> run = FusedPass(code, (), [(True, False)] * 2, ([1e-6], [1e-6]), [(2, (False, False))])
    >>> out = np.empty((1, 3), dtype=np.int8)
    >>> if available():
    ...     assert run.run([np.array([1.0, 2.0, 4.0]), np.array([1.0, 1.0, 1.0])], [], out)
    ...     assert out.tolist() == [[-1, 0, 1]]
    """

    def __init__(self, code: BufferedCode, functions: tuple, declared: Sequence, widths: tuple, parts: Sequence):
        self.code, self.functions, self.declared = code, tuple(functions), list(declared)
        self.widths, self.parts = widths, list(parts)
        self.compile_seconds = 0.0  # numba's compile time so far (the first call of each layout)
        self._kernels: dict = {}
        self._local = threading.local()

    def __getstate__(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k not in ("_kernels", "_local")}  # compiled again

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._kernels, self._local = {}, threading.local()

    def applies(self, given: Sequence) -> bool:
        """Whether the loop applies with the functions ``given`` (per function, None or its values): all given
        or none, and a float32 bound for them; a generated code of +, -, *, / and square roots only."""
        some = [g is not None for g in given]
        if any(some) and not all(some):
            return False
        mode = bool(some) and all(some)
        return self.widths[mode] is not None and self.kernel(mode) is not None

    def kernel(self, given: bool, constant: tuple = ()):
        """The compiled loops, unchecked and checked (:func:`_source`), with the functions ``given`` or computed
        and the arguments ``constant`` (one value for every point) read once (None: no float32 form), made once
        per such layout; numba compiles each at its first call with new array types."""
        key = (given, constant)
        if key not in self._kernels:
            sources = [
                _source(
                    self.code, self.functions, self.declared, self.widths[given], self.parts, given, checked, constant
                )
                for checked in (False, True)
            ]
            self._kernels[key] = None if sources[0] is None else tuple(map(_compiled, sources))
        return self._kernels[key]

    def run(self, pieces: Sequence[np.ndarray], known: Sequence, out: np.ndarray) -> bool | None:
        """Into ``out`` (int8, one row per kept factor): the float32 signs (+1/-1 certain, 0 not) and True; or
        None where a value is not finite or breaks its declared sign (the classifier's check says which).

        The unchecked loop runs first, under the status flags; where it raised one (or the flags cannot be
        read here), the checked loop runs again over the chunk."""
        given = bool(known) and known[0] is not None
        n = len(pieces[0])
        inputs = (*pieces, *(known if given else self._functions(pieces, n)))
        constant = tuple(a.strides == (0,) and n > 1 for a in inputs)
        arguments = (*(a[:1] if one else a for a, one in zip(inputs, constant)), *out)
        unchecked, checked = self.kernel(given, constant)
        flags = _status_flags()
        if flags is not None:
            compiled, started = len(unchecked.signatures), time.perf_counter()
            flags[0]()
            bad = unchecked(*arguments)
            raised = flags[1]()
            self._compiled(unchecked, compiled, started)
            if not raised:
                return None if bad else True
        compiled, started = len(checked.signatures), time.perf_counter()
        bad = checked(*arguments)
        self._compiled(checked, compiled, started)
        return None if bad else True

    def _compiled(self, kernel, compiled: int, started: float) -> None:
        if len(kernel.signatures) > compiled:  # this call compiled a new layout: count its time
            self.compile_seconds += time.perf_counter() - started

    def _functions(self, pieces, n: int) -> list[np.ndarray]:
        """NumPy's float32 sines and cosines of the chunk's arguments rounded to float32 (one value for an
        argument of one value), as :func:`.single.single_functions` computes them."""
        local = self._local
        if getattr(local, "size", 0) < n:
            local.rows, local.size = np.empty((len(self.functions), n), dtype=np.float32), n
        values = []
        with np.errstate(all="ignore"):  # the loop checks each value's range and bound
            for number, (index, ufunc) in enumerate(self.functions):
                argument = pieces[index]
                one = argument.strides == (0,) and n > 1
                row = np.empty(1, dtype=np.float32) if one else local.rows[number, :n]
                np.copyto(row, argument[:1] if one else argument, casting="same_kind")
                getattr(np, ufunc)(row, out=row)
                values.append(np.ndarray((n,), dtype=np.float32, buffer=row, strides=(0,)) if one else row)
        return values


@functools.cache
def _status_flags():
    """(clear, raised): clear this thread's floating-point status flags, and whether an overflow, underflow,
    invalid operation or division by zero has raised one since, through the C library's ``feclearexcept`` and
    ``fetestexcept`` (what NumPy reads for ``np.errstate``); None where these or their bits are not known here
    (then every chunk runs the checked loop). The bits are checked once: each exception, raised by NumPy, must
    set its own."""
    bits = {"x86_64": (1, 4, 8, 16), "amd64": (1, 4, 8, 16), "aarch64": (1, 2, 4, 8), "arm64": (1, 2, 4, 8)}
    found = bits.get(platform.machine().lower())
    if found is None or sys.platform not in ("linux", "darwin"):
        return None
    try:
        library = ctypes.CDLL(ctypes.util.find_library("m") or ctypes.util.find_library("c"))
        clear, test = library.feclearexcept, library.fetestexcept
    except (OSError, AttributeError, TypeError):
        return None
    clear.argtypes, test.argtypes, clear.restype, test.restype = (
        [ctypes.c_int],
        [ctypes.c_int],
        ctypes.c_int,
        ctypes.c_int,
    )
    mask = sum(found)
    one, zero, big, small = np.float32(1), np.float32(0), np.float32(3e38), np.float32(1e-30)
    raising = (lambda: np.sqrt(-one), lambda: one / zero, lambda: big * big, lambda: small * small)
    with np.errstate(all="ignore"):
        for bit, operation in zip(found, raising):
            clear(mask)
            operation()
            if test(mask) != bit:
                return None
        clear(mask)
        one * one
        if test(mask):
            return None
    return (lambda: clear(mask)), (lambda: test(mask) != 0)


def _compiled(source: str):
    import numba  # optional (contactsym[fast]): only a caller that found it available gets here

    namespace = {
        "np": np,
        "math": math,
        "HUGE": np.float32(_HUGE),
        "TINY": np.float32(_TINY),
        "MAX64": float(np.finfo(np.float64).max),
        "SINE_SLOPE": np.float32(_SINE[0]),
        "SINE_LEAST": np.float32(_SINE[1]),
        "CHEAP_RANGE": np.float32(_CHEAP_RANGE),
    }
    exec(compile(source, "<fused kernel>", "exec"), namespace)  # noqa: S102 - our own generated source
    # error_model="numpy": a division by zero gives inf (then the point is left undecided), as in NumPy
    return numba.njit(cache=False, fastmath=False, error_model="numpy", nogil=True)(namespace["_fused"])
