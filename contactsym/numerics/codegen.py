"""Generated NumPy code: ``lambdify`` with common subexpressions, cached per scene and parameter set."""

from __future__ import annotations

import weakref
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.printing.numpy import NumPyPrinter

from ..arguments import checked
from ..errors import NumericsError
from ..stages.fast import FastSubsystem
from ..stages.linear import Linearization
from ..stages.regularize import ReducedSystem, Regularized
from ..stages.stability import Stability
from .values import numeric_values, substitute

#: generated functions, per scene and parameter set
_cache: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _cached(scene, key, build):
    store = _cache.setdefault(scene, {})
    if key not in store:
        store[key] = build()
    return store[key]


def _has_text(exprs) -> bool:
    """Text anywhere in nested lists, tuples or dicts of expressions (lambdify would evaluate it)."""
    if isinstance(exprs, (str, bytes)):
        return True
    if isinstance(exprs, dict):
        return any(_has_text(e) for e in exprs.values())
    return isinstance(exprs, (list, tuple)) and any(_has_text(e) for e in exprs)


class _PointPrinter(NumPyPrinter):
    """NumPy code for one point at a time (the right-hand side of an ODE): a Piecewise is Python's
    conditional expression, which evaluates the one branch that applies (NumPy's ``select`` evaluates
    every branch and costs ~20 us a call on scalars: 90 % of a Hertz pad's reaction), Max and Min are
    nested ``maximum`` and ``minimum`` (NaN-propagating, as before) instead of ``reduce`` over a list."""

    def _print_Piecewise(self, expr):
        text = self._print(sp.nan)  # no condition holds: NaN, as NumPy's select(..., default=nan)
        for piece in reversed(expr.args):
            value = self._print(piece.expr)
            if piece.cond == sp.true:
                text = value
            else:
                cond = sp.simplify_logic(piece.cond) if piece.cond.has(sp.ITE) else piece.cond
                text = f"(({value}) if ({self._print(cond)}) else ({text}))"
        return text

    def _nested(self, name: str, args) -> str:
        op = self._module_format(f"{self._module}.{name}")
        text = self._print(args[-1])
        for arg in reversed(args[:-1]):
            text = f"{op}({self._print(arg)}, {text})"
        return text

    def _print_Max(self, expr):
        return self._nested("maximum", expr.args)

    def _print_Min(self, expr):
        return self._nested("minimum", expr.args)


@checked(exprs="list | tuple | sp.Basic | sp.MatrixBase", point="bool")
def lambdify_cse(args: Sequence, exprs, *, point: bool = False) -> Callable:
    """``sympy.lambdify`` to NumPy with common-subexpression elimination.

    ``point=True``: code for one point at a time (scalar arguments, as an ODE solver calls a right-hand
    side), where a Piecewise is a conditional expression; the same values, several times faster.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> f = lambdify_cse([x, y], [x**2*y + 1, x**2*y*sp.sin(x)])
    >>> [round(float(v), 6) for v in f(2.0, 3.0)]
    [13.0, 10.911569]
    >>> hertz = sp.Piecewise((sp.Max(0, -x) ** sp.Rational(3, 2) - y, x < 0), (0, True))
    >>> g = lambdify_cse([x, y], [hertz], point=True)
    >>> [float(g(-4.0, 1.0)[0]), float(g(1.0, 1.0)[0])]
    [7.0, 0.0]
    """
    if isinstance(args, (str, bytes)) or not all(isinstance(a, sp.Basic) for a in args) or _has_text(exprs):
        raise NumericsError("lambdify_cse takes SymPy symbols and SymPy expressions (text is never evaluated).")
    if not point:
        return sp.lambdify(list(args), exprs, modules="numpy", cse=True)
    settings = {"fully_qualified_modules": False, "inline": True, "allow_unknown_functions": True, "user_functions": {}}
    return sp.lambdify(list(args), exprs, modules="numpy", cse=True, printer=_PointPrinter(settings))


@checked
@dataclass(frozen=True, eq=False)
class NumericFunction:
    """A generated NumPy function of ``args`` returning ``exprs`` (shape kept).

    Attributes
    ----------
    args : tuple of Symbol
        Positional arguments, in order.
    exprs : sympy Matrix
        What the function computes (after numeric substitution).
    function : callable
        The generated code, ``function(*args)``.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> exprs = sp.Matrix([x**2*y, x + y])
    >>> F = NumericFunction((x, y), exprs, lambdify_cse([x, y], exprs))
    >>> F(2.0, 3.0).ravel().tolist()
    [12.0, 5.0]
    >>> F.jacobian()(2.0, 3.0).tolist()  # [[2 x y, x^2], [1, 1]]
    [[12.0, 4.0], [1.0, 1.0]]
    """

    args: tuple
    exprs: sp.Matrix
    function: Callable

    def __call__(self, *arguments):
        return np.asarray(self.function(*arguments), dtype=float)

    def jacobian(self) -> NumericFunction:
        """The Jacobian of the (column of) expressions with respect to ``args``."""
        J = sp.Matrix(list(self.exprs)).jacobian(list(self.args))
        return NumericFunction(self.args, J, lambdify_cse(self.args, J))


def _stage_exprs(stage) -> tuple[object, sp.Matrix, tuple]:
    """(scene, expressions, default arguments) of a stage object."""
    if isinstance(stage, FastSubsystem):
        return stage.scene, stage.rhs, tuple(stage.state)
    if isinstance(stage, Linearization):
        return stage.scene, stage.jacobian, ()
    if isinstance(stage, Stability):
        return stage.linearization.scene, sp.Matrix(stage.hurwitz), ()
    if isinstance(stage, Regularized):
        return stage.scene, sp.Matrix.vstack(stage.X, stage.Y), (*stage.x, *stage.y, stage.eps)
    if isinstance(stage, ReducedSystem):
        coordinates = list(stage.accelerations)
        return stage.scene, sp.Matrix([stage.accelerations[q] for q in coordinates]), tuple(coordinates)
    raise NumericsError(
        f"cannot generate code for {type(stage).__name__}; pass a FastSubsystem, Linearization, "
        "Stability, Regularized or ReducedSystem."
    )


@checked
def lambdify_stage(stage, values: Mapping | None = None, args: Sequence | None = None) -> NumericFunction:
    """Generated NumPy code for a stage object, cached per scene and parameter set.

    The fast subsystem gives its right-hand side in ``(u, v)``; a linearization its
    matrix (4.5); a stability stage its Hurwitz conditions; the regularized system
    ``(X, Y)`` in ``(x, y, eps)``; a reduced system its accelerations. Arguments default
    to the state variables followed by every symbol left after substituting ``values``.

    Examples
    --------
    >>> import contactsym as cs
    >>> fs = cs.scene("sliding-point").fast_subsystem()
    >>> fs.scene.parameters
    (b, m, x, xdot)
    >>> import sympy as sp
    >>> x, xdot = sp.symbols("x xdot", real=True)
    >>> f = lambdify_stage(fs, {"b": 1, "m": 1, sp.Function("Y")(x, xdot): -2})
    >>> f.args
    (u, v)
    >>> f(1.0, 0.0).ravel().tolist()
    [2.0, -1.0]
    """
    scene, exprs, default_args = _stage_exprs(stage)
    vals = numeric_values(scene, values)
    key = ("stage", type(stage).__name__, id(stage), vals.key(), None if args is None else tuple(args))

    def build():
        numeric = substitute(sp.Matrix(exprs), vals)
        chosen = tuple(args) if args is not None else default_args
        rest = sorted(numeric.free_symbols - set(chosen), key=str)
        arguments = chosen + tuple(rest)
        return NumericFunction(arguments, numeric, lambdify_cse(arguments, numeric))

    return _cached(scene, key, build)
