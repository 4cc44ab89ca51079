"""The classifier's float stage, piece by piece: functions of a parameter as arguments of the generated
code and the certified sign test (the float32 pass: :mod:`.single`)."""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from .. import validate
from ..errors import NumericsError
from .buffered import NUMPY_FUNCTIONS

__all__: list[str] = []  # helpers of contactsym.numerics.classifier

#: The float32 pass (:mod:`.single`): the relative error it allows a sine or cosine (checked per chunk), the largest |argument|,
#: and the absolute error of NumPy's float32 sin and cos there (its SIMD loops claim 1.49 units in the last place,
#: under 2^-23; tests/numerics/test_classifier.py checks 2^-21 on a dense sample).
_CHEAP_ERROR, _CHEAP_RANGE, _CHEAP_ABSOLUTE = 2.0**-14, 2.0**10, 2.0**-21


def _functions_as_arguments(flat: list, parameters: tuple) -> tuple[tuple, tuple]:
    """((new symbols, ``flat`` with them), per new symbol (index of its parameter, NumPy ufunc name)): each
    function of one parameter (``sin(alpha)``) becomes an argument of the generated code, computed once per
    chunk or given by the caller (an atlas computes it once per value of a grid axis)."""
    found = sorted(
        {f for e in flat for f in e.atoms(sp.Function) if len(f.args) == 1 and f.args[0] in parameters},
        key=sp.default_sort_key,
    )
    found = [f for f in found if type(f) in NUMPY_FUNCTIONS]
    names = tuple(sp.Dummy(f"f{i}") for i in range(len(found)))
    replaced = [e.xreplace(dict(zip(found, names))) for e in flat]
    return (names, replaced), tuple((parameters.index(f.args[0]), NUMPY_FUNCTIONS[type(f)]) for f in found)


def _function_values(argument: np.ndarray, ufunc: str, row: np.ndarray) -> np.ndarray:
    """``ufunc`` of a chunk's argument into ``row``; of one value for every point (stride 0), once."""
    if argument.strides == (0,) and len(argument) > 1:
        one = getattr(np, ufunc)(argument[:1])
        return np.ndarray(argument.shape, dtype=np.float64, buffer=one, strides=(0,))
    return getattr(np, ufunc)(argument, out=row)


def _as_array(value, size: int) -> np.ndarray:
    """Generated code returns plain numbers for constant parts (0 for an empty M)."""
    return value if isinstance(value, np.ndarray) else np.full(size, float(value))


def _certain_sign(groups, width: float, zeros: tuple[bool, bool], out: np.ndarray, scratch) -> None:
    """Into ``out`` (int8): +1/-1 where the sign of P - M (+ U) is certain, 0 elsewhere; valid for
    values computed without overflow, underflow or invalid operations. ``zeros``: whether
    P and M are identically 0; ``scratch``: two float64 and two int8 rows of ``out``'s length."""
    P, M, *rest = groups
    f0, f1, i0, i1 = scratch
    b0, b1 = i0.view(np.bool_), i1.view(np.bool_)
    if rest:  # terms of unknown sign: |F^ - F| <= gamma (P + M + |U|); certain where |F^| > width (P + M + |U|)
        np.subtract(P, M, out=f0)
        np.add(f0, rest[0], out=f0)
        np.add(P, M, out=f1)
        np.add(f1, rest[1], out=f1)
        np.multiply(f1, width, out=f1)
        np.greater(f0, f1, out=b0)
        np.negative(f1, out=f1)
        np.less(f0, f1, out=b1)
        np.subtract(i0, i1, out=out)
    elif zeros[1]:  # F = P, nonnegative terms: P^ > 0 iff P > 0
        np.greater(P, 0.0, out=out.view(np.bool_))
    elif zeros[0]:
        np.greater(M, 0.0, out=out.view(np.bool_))
        np.negative(out, out=out)
    else:  # P - M > width (P + M) iff P (1 - width)/(1 + width) > M: no cancellation in the test; the
        # few roundings of the ratio and the product are far inside width >= 2 gamma_(r+3)
        shrink = (1 - width) / (1 + width)
        np.multiply(P, shrink, out=f0)
        np.greater(f0, M, out=b0)
        np.multiply(M, shrink, out=f0)
        np.greater(f0, P, out=b1)
        np.subtract(i0, i1, out=out)


def _undecided(factor_signs: np.ndarray, out: np.ndarray) -> np.ndarray:
    """Into ``out`` (bool): where some factor's sign (int8 rows of +1, -1, 0) is 0, i.e. their product is 0."""
    if not len(factor_signs):
        out[...] = False
        return out
    product = factor_signs[0]
    if len(factor_signs) > 1:
        product = np.multiply(factor_signs[0], factor_signs[1])
        for row in factor_signs[2:]:
            np.multiply(product, row, out=product)
    return np.equal(product, 0, out=out)


def _given(function_values, functions: tuple, arrays) -> list:
    """The caller's values of the classifier's ``functions`` (None: computed per chunk), flat, checked."""
    if function_values is None:
        return [None] * len(functions)
    if len(function_values) != len(functions):
        raise NumericsError(f"give {len(functions)} function_values (or None), one per {functions}.")
    size = math.prod(np.broadcast(*arrays).shape) if arrays else 0
    given = [None if v is None else validate.real_array(v, "function_values").reshape(-1) for v in function_values]
    if any(g is not None and len(g) != size for g in given):
        raise NumericsError(f"each of function_values needs one value per point ({size}).")
    return given
