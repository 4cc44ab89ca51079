"""Certified, vectorised classification of many parameter points (:class:`PointClassifier`)."""

from __future__ import annotations

import math
import threading
from collections.abc import Sequence

import mpmath
import numpy as np
import sympy as sp

from .. import validate
from ..arguments import checked
from ..errors import NumericsError
from ..parse import sympy_only
from ..progress import Budget, Progress
from . import fused
from .buffered import BufferedCode, cheapest_trig
from .certified import _gamma, certified_sign
from .codegen import lambdify_cse
from .float_stage import _as_array, _certain_sign, _function_values, _functions_as_arguments, _given, _undecided
from .one_signed import _one_signed_form, _roundings
from .single import single_widths
from .single_pass import SinglePass
from .verdicts import PointsResult, Verdicts


@checked(conditions="list | tuple | sp.MatrixBase")
class PointClassifier:
    """Certified, vectorised classification of many parameter points.

    Each condition (stable iff all > 0) is factored, and factors of known sign (masses,
    Phi < 0, Psi < 0) are dropped; equal factors of different conditions are evaluated
    once. Each remaining factor is split into its terms of known sign, F = P - M + U with
    P, M sums of nonnegative terms and U the terms of unknown sign. P and M are
    factored again where every sum of the factored form has terms of one sign: such a
    form is cheaper and keeps a relative error bound, |P^ - P| <= gamma_r P with r the
    roundings along its longest path. Hence |F^ - F| <= gamma (P + M + |U|), and the sign
    is certain where |F^| > 2 gamma (P + M + |U|). A factor without negative part is
    certain wherever P^ > 0. The bounds assume no overflow, underflow or invalid
    operation: the float stage runs with these trapped, in chunks that stay in the
    cache, and a chunk that traps is halved until the points that cause it are found.
    A function of one parameter (``sin(alpha)``) is computed once per chunk (or given:
    ``function_values``). Where it applies (:mod:`.single`), a chunk is first evaluated in
    float32: inputs rounded, sines and cosines from float32 loops with their own bound, with
    a width that makes its certain points certain in float64 too; the points it leaves
    undecided are evaluated again in float64, so the result is the float64 one. With numba installed
    (``contactsym[fast]``), a call of at least :data:`.fused.FUSED_MIN_POINTS` points runs that float32 pass
    as one compiled loop over the points (:mod:`.fused`): the same values, the same results.
    Points that trap and the points inside ``max(band, 2 gamma)`` relative are decided
    exactly: the binary inputs are exact rationals, F is evaluated in 256-bit
    arithmetic, and where even that leaves |F| < 2^-200 (P + M + |U|) the point is
    recomputed in SymPy rationals.

    Parameters
    ----------
    conditions : sequence of sympy expressions
        Stable exactly when all are > 0 (e.g. ``Stability.hurwitz``); SymPy objects, not text.
    parameters : sequence of Symbol
        The order of the parameter arrays passed to :meth:`__call__`. Functions such as
        ``sin`` must act on expressions that are exact in floating point (a parameter,
        or twice a parameter); otherwise introduce a parameter for the argument.
    band : float
        Relative half-width of the band decided exactly.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> import contactsym as cs
    >>> st = cs.scene("brake").stability()
    >>> Phi, Psi = sp.symbols("Phi Psi", negative=True)
    >>> m, mu, alpha = sp.symbols("m mu alpha", positive=True)
    >>> (P1, P2), (S1, S2) = st.linearization.Phi, st.linearization.Psi
    >>> slice_6_4 = {alpha: sp.pi/2, P1: Phi, P2: Phi, S1: Psi, S2: Psi}
    >>> pc = PointClassifier([c.subs(slice_6_4) for c in st.hurwitz], [m, mu, Phi, Psi])
    >>> pc.kept
    [Phi*m*mu**2 + Psi**2*mu**2 + Psi**2]
    >>> pc.parts[0]  # P and M of the kept factor
    (Psi**2*(mu**2 + 1), -Phi*m*mu**2)
    >>> out = pc(np.array([1.0, 1.0]), np.array([1.0, 1.0]), np.array([-2.0, -1.0]), np.array([-1.0, -1.0]))
    >>> out.stable.tolist(), out.exact_points
    ([0, 1], 1)
    """

    def __init__(self, conditions: Sequence, parameters: Sequence[sp.Symbol], *, band: float = 1e-12):
        self.parameters = tuple(parameters)
        self.band = float(band)
        self.conditions = [sympy_only(c, "a condition") for c in conditions]
        self.kept: list[sp.Expr] = []  # distinct factors of unknown sign
        self.uses: list[tuple[int, int, int]] = []  # (condition index, sign, position in kept)
        self.always_false: list[int] = []
        for index, condition in enumerate(self.conditions):
            sign, factors = self._reduce(condition)
            if sign == 0:
                self.always_false.append(index)
            for number, factor in enumerate(factors):
                if factor not in self.kept:
                    self.kept.append(factor)
                self.uses.append((index, sign if number == 0 else 1, self.kept.index(factor)))
        free = set().union(*[f.free_symbols for f in self.kept]) if self.kept else set()
        if free - set(self.parameters):
            raise NumericsError(f"the conditions also need values for {sorted(map(str, free - set(self.parameters)))}.")
        self.parts = [self._split(factor) for factor in self.kept]
        code = [tuple(cheapest_trig(g) for g in p) for p in self.parts]
        self.gammas = [_gamma(max(_roundings(g) for g in p) + 3) for p in code]
        flat = [g for p in code for g in p]
        arguments, self.functions = _functions_as_arguments(flat, self.parameters)
        try:  # every operation into a reused buffer: the chunk stays in the cache, no temporaries
            self._buffered: BufferedCode | None = BufferedCode(self.parameters + arguments[0], arguments[1])
            self._function = None
        except NumericsError:  # a part without a buffered form (e.g. a symbolic exponent)
            self._buffered, self._function = None, lambdify_cse(self.parameters, flat)
            self.functions = ()
        self._widths = [max(self.band, 2 * g) for g in self.gammas]
        self._single_widths = self._float32_widths(arguments, len(code))
        self._single = self._single_widths is not None  # False: float64 throughout (same results, slower)
        self._verdicts = Verdicts(self.uses, len(self.conditions), self.always_false)
        self._declared = [(s, bool(s.is_positive), bool(s.is_negative)) for s in self.parameters]  # looked up once
        self._names = [f"the values of {s}" for s in self.parameters]  # printed once: SymPy's printer is slow
        self._zeros = [(part[0] == 0, part[1] == 0) for part in self.parts]  # SymPy comparisons: once, not per chunk
        self._single_pass = self._fused = None
        if self._single:
            declared, parts = [d[1:] for d in self._declared], [(len(p), z) for p, z in zip(self.parts, self._zeros)]
            self._single_pass = SinglePass(self._buffered, self.functions, declared, self._single_widths, parts)
            self._fused = fused.FusedPass(self._buffered, self.functions, declared, self._single_widths, parts)
        self._mp_function = self._mp_functions()
        self._workspaces = threading.local()

    def _float32_widths(self, arguments: tuple, count: int) -> tuple | None:
        """The float32 pass's widths (:mod:`.single`), with the functions computed (if they are all sines and
        cosines, else None) and given; None where the code has no float32 bound."""
        if self._buffered is None:
            return None
        names, flat = arguments
        sizes = [len(p) for p in self.parts]
        code = [tuple(flat[sum(sizes[:k]) : sum(sizes[: k + 1])]) for k in range(count)]
        try:
            given = single_widths(code, names, False, self._widths, self.gammas)
            computed = single_widths(code, names, True, self._widths, self.gammas)
        except NumericsError:
            return None
        if max(given, default=0.0) > 1e-3:  # a pass that would decide little is not worth its cost
            return None
        sines = all(ufunc in ("sin", "cos") for _, ufunc in self.functions)
        return (computed if sines and max(computed, default=0.0) <= 1e-3 else None), given

    def _mp_functions(self) -> list:
        return [sp.lambdify(self.parameters, list(p), modules="mpmath") for p in self.parts]

    def __getstate__(self) -> dict:
        # code generated for mpmath holds mpmath's context, which does not pickle (a Dask
        # worker receives the classifier by value): it is generated again when first needed
        return {k: v for k, v in self.__dict__.items() if k not in ("_mp_function", "_workspaces")}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._mp_function = None
        self._workspaces = threading.local()

    def _workspace(self, size: int) -> tuple[np.ndarray, np.ndarray]:
        """Float buffers for the generated code (two more for the sign test) and two int8 rows, per thread."""
        rows = (self._buffered.buffers if self._buffered is not None else 0) + 2 + len(self.functions)
        found = getattr(self._workspaces, "arrays", None)
        if found is None or found[0].shape[1] < size:
            found = (np.empty((rows, size)), np.empty((2, size), dtype=np.int8))
            self._workspaces.arrays = found
        return found

    @staticmethod
    def _reduce(condition: sp.Expr) -> tuple[int, list]:
        """(sign of the dropped factors, factors of unknown sign)."""
        if condition.is_positive:
            return 1, []
        if condition.is_nonpositive:
            return 0, []
        factored = sp.factor(condition) if sp.count_ops(condition) < 400 else sp.factor_terms(condition)
        sign, kept = 1, []
        for factor in sp.Mul.make_args(factored):
            if factor.is_positive:
                continue
            if factor.is_negative:
                sign = -sign
                continue
            kept.append(factor)
        return sign, kept or [sp.S.One]

    @staticmethod
    def _split(factor: sp.Expr) -> tuple:
        """(P, M) or (P, M, U, |U|): the factor is P - M + U."""
        plus, minus, unknown = [], [], []
        for term in sp.Add.make_args(sp.expand(factor)):
            if term.is_nonnegative:
                plus.append(term)
            elif term.is_nonpositive:
                minus.append(-term)
            else:
                unknown.append(term)
        P, M = (_one_signed_form(sp.Add(*terms)) for terms in (plus, minus))
        if not unknown:
            return P, M
        return P, M, sp.Add(*unknown), sp.Add(*[sp.Abs(t) for t in unknown])

    def _check(self, arrays) -> list[np.ndarray]:
        if len(arrays) != len(self.parameters):
            raise NumericsError(
                f"give {len(self.parameters)} arrays, one per parameter {list(map(str, self.parameters))}."
            )
        return [validate.real_array(array, what) for what, array in zip(self._names, arrays)]

    def _check_values(self, arrays, extremes=None) -> list[float]:
        """Refuse values that are not finite or break a declared sign; the largest |value| of each array.
        ``extremes``: if known, (least, largest) of each array of more than one value, in order."""
        reach = []
        for (symbol, positive, negative), a in zip(self._declared, arrays):
            if a.strides == (0,) or not a.size:  # one value for every point (or none): no reductions
                low = high = float(a[0]) if a.size else 0.0
            elif extremes is not None:
                low, high = next(extremes)
            else:  # NaN propagates; +-inf shows in the extremes
                low, high = float(np.minimum.reduce(a)), float(np.maximum.reduce(a))
            if not (math.isfinite(low) and math.isfinite(high)):
                raise NumericsError(f"the values of {symbol} are not all finite.")
            if a.size and ((positive and not low > 0) or (negative and not high < 0)):
                raise NumericsError(
                    f"{symbol} is declared {'positive' if positive else 'negative'}; some values are "
                    f"{'<=' if positive else '>='} 0."
                )
            reach.append(max(-low, high))
        return reach

    def _float_stage(self, arrays, known, out: np.ndarray, widths: list) -> None:
        """Per kept factor, into ``out``: its sign where certain (+1/-1) and 0 where not (int8).

        An overflow, underflow or invalid operation would void the relative error bounds:
        a chunk where one occurs is halved until the points that cause it are found, and
        those are left to the exact path.
        """
        size = out.shape[1]
        try:
            with np.errstate(all="raise"):
                self._signs(arrays, known, out, widths)
        except FloatingPointError:
            if size == 1:
                out[...] = 0
                return
            half = size // 2
            self._float_stage([a[:half] for a in arrays], [k[:half] for k in known], out[:, :half], widths)
            self._float_stage([a[half:] for a in arrays], [k[half:] for k in known], out[:, half:], widths)

    def _signs(self, arrays, known, out: np.ndarray, widths: list, floats: np.ndarray | None = None) -> None:
        """The generated code and the sign test, in float64 or (``floats``: float32 rows) float32."""
        size = out.shape[1]
        floats64, small = self._workspace(size)
        floats = floats64 if floats is None else floats
        if self._buffered is not None:
            rows = floats[: self._buffered.buffers + len(self.functions)]
            functions = [
                k if k is not None else _function_values(arrays[index], ufunc, rows[-1 - number, :size])
                for number, ((index, ufunc), k) in enumerate(zip(self.functions, known))
            ]
            values = iter(self._buffered([*arrays, *functions], rows))
        else:
            values = iter(_as_array(v, size) for v in self._function(*arrays))
        scratch = (floats[-2, :size], floats[-1, :size], small[0, :size], small[1, :size])
        for position, part in enumerate(self.parts):
            groups = [next(values) for _ in part]
            _certain_sign(groups, widths[position], self._zeros[position], out[position], scratch)

    def _high_precision_sign(self, position: int, point: list[float]) -> int | None:
        """Sign of a kept factor in 256-bit arithmetic from the exact binary inputs, or None."""
        if self._mp_function is None:  # unpickled: see __getstate__
            self._mp_function = self._mp_functions()
        with mpmath.workprec(256):
            P, M, *rest = self._mp_function[position](*[mpmath.mpf(x) for x in point])
            U, Ua = rest or (0, 0)
            value = P - M + U
            if abs(value) > mpmath.mpf(2) ** -200 * (P + M + Ua):
                return 1 if value > 0 else -1
        return None

    def __call__(
        self,
        *arrays,
        chunk: int = 1 << 16,
        progress: Progress | None = None,
        max_seconds: float | None = None,
        function_values: Sequence | None = None,
    ) -> PointsResult:
        """Classify the points; ``progress(fraction, message)`` follows the exact path, which
        ``max_seconds`` bounds (a NumericsError then says how many points were decided).

        ``function_values``: per entry ``(index, ufunc)`` of :attr:`functions`, None or the values of
        ``ufunc`` at the points as NumPy computes them from parameter ``index`` (e.g. once per value of a
        grid axis, then laid out as the axis is); the certificate assumes exactly these numbers."""
        chunk = validate.chunk_size(chunk)
        budget = Budget(progress, max_seconds)
        arrays = self._check(arrays)
        given = _given(function_values, self.functions, arrays)
        shape = np.broadcast(*arrays).shape if arrays else ()
        # no copies: an array of the points' shape is read in place, one value stays one value (a view of
        # zero stride, checked once), and only an array broadcast along some axes is copied
        arrays = [
            a.reshape(-1)
            if a.shape == shape
            else np.broadcast_to(a.reshape(()) if a.size == 1 else a, shape).reshape(-1)
            for a in arrays
        ]
        size = math.prod(shape)
        factor_signs = np.empty((len(self.kept), size), dtype=np.int8)
        stable = np.empty(size, dtype=np.int8)
        in_band = np.empty(size, dtype=bool)
        left: list[np.ndarray] = []  # points the float32 pass leaves to float64, all chunks in one go
        fast = self._fused_run(size, given)
        for start in range(0, size, chunk):  # one pass per chunk: checks, generated code, signs, all in the cache
            stop = min(start + chunk, size)
            part = factor_signs[:, start:stop]
            pieces = [a[start:stop] for a in arrays]
            known = [None if g is None else g[start:stop] for g in given]
            single = self._chunk_signs(pieces, known, part, fast)
            self._verdicts.stable(part, stable[start:stop], self._workspace(stop - start)[1])
            undecided = _undecided(part, in_band[start:stop])
            if single:
                left.append(start + np.nonzero(undecided)[0])
        if left:
            self._in_float64(np.concatenate(left), arrays, given, chunk, (factor_signs, stable, in_band))
        points = np.nonzero(in_band)[0]
        for done, i in enumerate(points):
            if budget.report(done / len(points), f"{done} of {len(points)} points decided exactly"):
                raise NumericsError(
                    f"the exact path decided {done} of {len(points)} points near a boundary within max_seconds = "
                    f"{max_seconds:g} (the float stage decided the other {size - len(points)}); raise max_seconds, "
                    "or classify fewer points at a time."
                )
            point = [float(a[i]) for a in arrays]
            for position in np.nonzero(factor_signs[:, i] == 0)[0]:
                factor_signs[position, i] = self._exact_factor_sign(position, point)
            self._verdicts.stable(factor_signs[:, i : i + 1], stable[i : i + 1], self._workspace(1)[1])
        budget.report(1.0, f"{size} points, {len(points)} decided exactly")
        band = max(self._widths, default=self.band)
        return PointsResult(
            stable.reshape(shape), factor_signs, self._verdicts, in_band.reshape(shape), len(points), band
        )

    def _fused_run(self, size: int, given: list):
        """The fused float32 loop's ``run`` (:mod:`.fused`) for a call of ``size`` points, or None: NumPy passes."""
        if not (self._single and self.parts and size >= fused.FUSED_MIN_POINTS and fused.available()):
            return None
        return self._fused.run if self._fused.applies(given) else None

    def _chunk_signs(self, pieces, known, part, fast=None) -> bool:
        """Checks and signs of the kept factors on a chunk (0: not certain): by the float32 pass where it applies
        (``fast``: its fused loop; then True: the points it leaves undecided go to :meth:`_in_float64`), else in
        float64."""
        run = fast or (self._single_pass.run if self._single else None)
        done = run(pieces, known, part) if run is not None and len(pieces[0]) else None
        if done:
            return True
        if done is None:  # not checked (or a value the float32 check refused): the check that says why
            self._check_values(pieces)
        self._float_stage(pieces, known, part, self._widths)
        return False

    def _in_float64(self, index: np.ndarray, arrays, given, chunk: int, results: tuple) -> None:
        """The points ``index`` that the float32 pass left undecided, in float64 (a chunk at a time), into
        ``results`` (factor signs, stable, in_band): the same as float64 throughout (:mod:`.single`)."""
        factor_signs, stable, in_band = results
        for start in range(0, len(index), chunk):
            some = index[start : start + chunk]
            again = np.empty((len(self.kept), len(some)), dtype=np.int8)
            known = [None if g is None else g[some] for g in given]
            self._float_stage([a[some] for a in arrays], known, again, self._widths)
            least = np.empty(len(some), dtype=np.int8)
            self._verdicts.stable(again, least, self._workspace(len(some))[1])
            factor_signs[:, some], stable[some] = again, least
            in_band[some] = _undecided(again, np.empty(len(some), dtype=bool))

    def _exact_factor_sign(self, position: int, point: list[float]) -> int:
        """The exact sign of one kept factor at one point: 256-bit first, then rationals."""
        found = self._high_precision_sign(position, point)
        if found is not None:
            return found
        return certified_sign(self.kept[position], dict(zip(self.parameters, point)), band=0.0)[0]
