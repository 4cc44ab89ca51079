"""Generated NumPy code that evaluates into buffers given to it: one ufunc call per operation, no temporaries.

``lambdify`` writes ``x*y + z`` as Python arithmetic on arrays: every operation allocates a
new array, and arrays of a few hundred kilobytes are fresh pages for the operating system to
hand out (a page fault per 4 KiB) each time. :class:`BufferedCode` writes every operation as
a ufunc call with ``out=`` one of a few buffers that the caller allocates once and reuses
chunk after chunk, so that a chunk's data stay in the cache. The buffers are assigned by
liveness: an intermediate's buffer is reused as soon as its last reader has run.

The arithmetic is the expression's own, operation for operation, with two cheaper forms that
never round more: ``a * b**-1`` is one division (not a reciprocal and a product) and an
integer power is repeated squaring. So a rounding-error bound counted on the expression
(:func:`contactsym.numerics.classifier.PointClassifier`) holds for the generated code.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import sympy as sp

from ..errors import NumericsError

__all__ = ["NUMPY_FUNCTIONS", "BufferedCode", "cheapest_trig", "through_tan"]

#: SymPy functions of one argument and the NumPy ufunc for each.
NUMPY_FUNCTIONS = {
    sp.sin: "sin",
    sp.cos: "cos",
    sp.tan: "tan",
    sp.exp: "exp",
    sp.log: "log",
    sp.sinh: "sinh",
    sp.cosh: "cosh",
    sp.tanh: "tanh",
    sp.atan: "arctan",
    sp.asin: "arcsin",
    sp.acos: "arccos",
    sp.Abs: "absolute",
}


#: Relations and logical connectives, evaluated to 1.0 (true) and 0.0 (false).
_RELATIONS = {
    sp.StrictGreaterThan: "greater",
    sp.GreaterThan: "greater_equal",
    sp.StrictLessThan: "less",
    sp.LessThan: "less_equal",
}
_CONNECTIVES = {sp.And: "logical_and", sp.Or: "logical_or", sp.Not: "logical_not"}


def _tan_is_vectorised() -> bool:
    """Whether this NumPy runs a SIMD loop for float64 tan (SVML, on AVX-512 machines).

    Elsewhere tan, sin and cos are all scalar loops, and tan the dearest of the three (17, 12 and
    14 ns per value on an AVX2 AMD EPYC, NumPy 2.4)."""
    try:
        from numpy.lib.introspect import opt_func_info  # NumPy >= 2.0
    except ImportError:
        return False
    loop = opt_func_info(func_name="^tan$", signature="^dd$").get("tan", {}).get("dd", {}).get("current", "baseline")
    return not loop.startswith("baseline")


#: Whether :func:`cheapest_trig` writes even powers of sin and cos through tan on this machine.
TAN_IS_VECTORISED = _tan_is_vectorised()


def cheapest_trig(expr: sp.Basic) -> sp.Basic:
    """``expr`` in the form of its trigonometric functions that NumPy evaluates fastest here:
    :func:`through_tan` where float64 tan is vectorised (one SIMD tan, a square, a sum and a
    quotient per angle), else unchanged (sin or cos, then a square: one scalar call per angle).
    Both forms keep a relative error bound; the classifier's verdicts are the same either way.

    Examples
    --------
    >>> import sympy as sp
    >>> a = sp.Symbol("a")
    >>> cheapest_trig(sp.sin(a)**2) in (sp.sin(a)**2, through_tan(sp.sin(a)**2))
    True
    """
    return through_tan(expr) if TAN_IS_VECTORISED else expr


def through_tan(expr: sp.Basic) -> sp.Basic:
    """Even powers of sin and cos written with t = tan: sin^2 = t^2/(1 + t^2), cos^2 = 1/(1 + t^2).

    Where NumPy vectorises float64 tan (SVML on AVX-512, within 4 units in the last place) and not
    sin and cos, this costs several times less; the new sums have terms of one sign, so a relative
    error bound still holds. See :func:`cheapest_trig`.

    Examples
    --------
    >>> import sympy as sp
    >>> a = sp.Symbol("a")
    >>> through_tan(sp.sin(a)**2 + sp.cos(a)**4)
    tan(a)**2/(tan(a)**2 + 1) + (tan(a)**2 + 1)**(-2)
    """

    def rewrite(node):
        if node.is_Pow and node.exp.is_Integer and node.exp % 2 == 0 and isinstance(node.base, (sp.sin, sp.cos)):
            t2 = sp.tan(node.base.args[0]) ** 2
            square = t2 / (1 + t2) if isinstance(node.base, sp.sin) else 1 / (1 + t2)
            return square ** (node.exp // 2)
        return node

    return sp.bottom_up(expr, rewrite)


class _Unsupported(Exception):
    """A node without a buffered form: the caller keeps its ``lambdify`` code."""


class _Writer:
    """Instructions in static single assignment: ``(ufunc, operands, result)``; operands are
    input names (``a0``), temporaries (``t3``) or float literals."""

    def __init__(self, arguments: Sequence[sp.Symbol]):
        self.names = {symbol: f"a{i}" for i, symbol in enumerate(arguments)}
        self.code: list[tuple[str, tuple[str, ...], str]] = []
        self.count = 0

    def op(self, ufunc: str, *operands: str) -> str:
        if all(not _is_array(o) for o in operands):  # constants fold here
            with np.errstate(all="ignore"):
                return repr(float(getattr(np, ufunc)(*[float(o) for o in operands])))
        self.count += 1
        result = f"t{self.count}"
        self.code.append((ufunc, operands, result))
        return result

    def emit(self, expr: sp.Expr) -> str:
        if expr in self.names:
            return self.names[expr]
        if expr.is_Number or expr.is_NumberSymbol:
            return repr(float(expr))
        if expr.is_Add:
            return self._sum(expr)
        if expr.is_Mul:
            return self._product(expr)
        if expr.is_Pow:
            return self._power(expr)
        ufunc = NUMPY_FUNCTIONS.get(type(expr))
        if ufunc is not None and len(expr.args) == 1:
            return self.op(ufunc, self.emit(expr.args[0]))
        if expr is sp.true or expr is sp.false:
            return "1.0" if expr is sp.true else "0.0"
        ufunc = _RELATIONS.get(type(expr)) or _CONNECTIVES.get(type(expr))
        if ufunc is not None:  # truth values as 1.0 and 0.0 in the float buffers
            operands = [self.emit(a) for a in expr.args]
            result = self.op(ufunc, *operands[:2]) if len(operands) > 1 else self.op(ufunc, operands[0])
            for operand in operands[2:]:
                result = self.op(ufunc, result, operand)
            return result
        raise _Unsupported(f"{type(expr).__name__}")

    def _sum(self, expr: sp.Expr) -> str:
        plus, minus = [], []
        for term in expr.args:
            coefficient, _ = term.as_coeff_Mul()
            (minus if coefficient.is_negative else plus).append(-term if coefficient.is_negative else term)
        if not plus:  # -(a + b + ...)
            return self.op(
                "negative", self._sum(sp.Add(*minus, evaluate=False)) if len(minus) > 1 else self.emit(minus[0])
            )
        total = self.emit(plus[0])
        for term in plus[1:]:
            total = self.op("add", total, self.emit(term))
        for term in minus:
            total = self.op("subtract", total, self.emit(term))
        return total

    def _product(self, expr: sp.Expr) -> str:
        coefficient, rest = expr.as_coeff_Mul()
        if coefficient.is_negative:
            return self.op("negative", self.emit(-expr))
        numerator, denominator = [], []
        for factor in sp.Mul.make_args(rest):
            if factor.is_Pow and factor.exp.is_Integer and factor.exp < 0:
                denominator.append(factor.base ** (-factor.exp))
            else:
                numerator.append(factor)
        top = self.emit(numerator[0]) if numerator else "1.0"
        for factor in numerator[1:]:
            top = self.op("multiply", top, self.emit(factor))
        if coefficient != 1:
            top = self.op("multiply", repr(float(coefficient)), top) if numerator else repr(float(coefficient))
        if not denominator:
            return top
        bottom = self.emit(denominator[0])
        for factor in denominator[1:]:
            bottom = self.op("multiply", bottom, self.emit(factor))
        return self.op("divide", top, bottom)

    def _power(self, expr: sp.Expr) -> str:
        base, exponent = expr.args
        if exponent.is_Integer:
            n = int(exponent)
            if n < 0:
                return self.op("divide", "1.0", self._integer_power(self.emit(base), -n))
            return self._integer_power(self.emit(base), n)
        if exponent == sp.S.Half:
            return self.op("sqrt", self.emit(base))
        if exponent.is_Rational:
            return self.op("power", self.emit(base), repr(float(exponent)))
        raise _Unsupported("a power with a symbolic exponent")

    def _integer_power(self, base: str, n: int) -> str:
        """Repeated squaring: at most n - 1 roundings, as many as n - 1 products."""
        if n == 0:
            return "1.0"
        result, square = None, base
        while True:
            if n & 1:
                result = square if result is None else self.op("multiply", result, square)
            n >>= 1
            if not n:
                return result
            square = self.op("square", square)


def _is_array(operand: str) -> bool:
    return operand[0] in "at"


class BufferedCode:
    """``code(arrays, buffers)``: the values of ``expressions`` at the points of ``arrays``.

    ``arrays`` holds one 1-D float64 array per argument, all of one length n, and ``buffers``
    a float64 array of shape ``(code.buffers, N)`` with N >= n, reused from call to call.
    Each result is an array (a row of ``buffers`` or one of ``arrays``: read it before the next
    call) or a number (a constant part, or a part of arguments that hold one value for all points). Raises :class:`NumericsError` when an expression has
    a part without a buffered form (e.g. a symbolic exponent): use ``lambdify`` there.

    Examples
    --------
    >>> import numpy as np, sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> code = BufferedCode([x, y], [x**2 * y - y / (1 + x**2), sp.Integer(3)])
    >>> buffers = np.empty((code.buffers, 4))
    >>> first, constant = code([np.arange(4.0), np.full(4, 2.0)], buffers)
    >>> first.tolist(), constant
    ([-2.0, 1.0, 7.6, 17.8], 3.0)

    With ``y`` one value for all points (a view of stride 0), ``x**2 * y`` is a product per point,
    ``y / (1 + x**2)`` a division per point, and nothing is done twice:

    >>> same, _ = code([np.arange(4.0), np.broadcast_to(2.0, (4,))], buffers)
    >>> same.tolist() == first.tolist()
    True
    """

    def __init__(self, arguments: Sequence[sp.Symbol], expressions: Sequence[sp.Expr]):
        self.arguments = tuple(arguments)
        writer = _Writer(self.arguments)
        replacements, reduced = sp.cse(list(expressions), order="none")
        try:
            for symbol, value in replacements:
                writer.names[symbol] = writer.emit(value)
            results = [writer.emit(e) for e in reduced]
        except _Unsupported as error:
            raise NumericsError(f"no buffered code for {error}; use lambdify_cse.") from None
        self._code, self._results = writer.code, results
        self.buffers, lines = _assigned(self._code, self._results, len(self.arguments), frozenset())
        self.source = "\n".join(lines)
        self._variants: dict = {}

    def __call__(self, arrays: Sequence[np.ndarray], buffers: np.ndarray) -> list:
        """An argument that holds one value for every point (a view of stride 0) is read once: the
        operations on such arguments alone run once, on numbers, not once per point."""
        n = len(arrays[0]) if arrays else 0
        function = self.function(frozenset(i for i, a in enumerate(arrays) if n > 1 and a.strides == (0,)))
        return function(*arrays, *[row[:n] for row in buffers])

    def function(self, constant: frozenset):
        """The compiled code for the arguments ``constant`` (their indices) of one value, the others arrays:
        ``function(*arrays, *buffers)`` with ``buffers`` rows cut to the arrays' length (what ``code(arrays,
        buffers)`` calls; a caller that evaluates chunk after chunk of one layout looks it up once)."""
        function = self._variants.get(constant)
        if function is None:
            count, lines = _assigned(self._code, self._results, len(self.arguments), constant)
            if count > self.buffers:  # never more buffers than promised: then every argument is an array
                count, lines = _assigned(self._code, self._results, len(self.arguments), frozenset())
            function = self._variants[constant] = _compiled(lines)
        return function

    def __getstate__(self) -> dict:
        return {k: v for k, v in self.__dict__.items() if k != "_variants"}  # the code travels, not the functions

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._variants = {}


def _compiled(lines: list[str]):
    namespace: dict = {"np": np, "nan": np.nan, "inf": np.inf}
    exec(compile("\n".join(lines), "<buffered code>", "exec"), namespace)  # noqa: S102 - our own generated source
    return namespace["_buffered"]


def _assigned(code, results, arity: int, constant: frozenset) -> tuple[int, list[str]]:
    """Buffers for the temporaries (a buffer is free again after its temporary's last reader) and the source.

    ``constant``: the arguments that hold one value; operations on these (and on numbers) alone give
    numbers, computed once and kept in a variable, not in a buffer."""
    last: dict[str, int] = {}
    for index, (_, operands, _) in enumerate(code):
        for operand in operands:
            last[operand] = index
    for operand in results:
        last[operand] = len(code)  # the results live to the end
    free: list[int] = []
    where: dict[str, str] = {f"a{i}": f"c{i}" for i in constant}
    count = 0
    body = [f"    c{i} = a{i}[0]" for i in sorted(constant)]
    for index, (ufunc, operands, result) in enumerate(code):
        shown = [where.get(o, o) for o in operands]
        if all(not _is_array(o) or where.get(o, o)[0] == "c" for o in operands):  # numbers only: once
            where[result] = f"c{result}"
            body.append(f"    c{result} = np.{ufunc}({', '.join(shown)})")
            continue
        for operand in set(operands):  # an operand read here for the last time frees its buffer for the result
            if operand.startswith("t") and last[operand] == index and where[operand][0] == "b":
                free.append(int(where[operand][1:]))
        if free:
            slot = free.pop()
        else:
            slot, count = count, count + 1
        where[result] = f"b{slot}"
        body.append(f"    np.{ufunc}({', '.join(shown)}, out=b{slot})")
    arguments = [f"a{i}" for i in range(arity)]
    header = f"def _buffered({', '.join([*arguments, *[f'b{i}' for i in range(count)], '*_'])}):"  # spare buffers
    shown_results = [where.get(r, r) for r in results]
    return count, [header, *body, f"    return [{', '.join(shown_results)}]"]
