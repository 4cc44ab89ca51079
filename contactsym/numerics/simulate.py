"""Numerics: generated code, simulations of the full, reduced, fast and averaged systems,
and certified classification of parameter points.

Every symbolic claim of contactsym deserves a numerical witness. This module turns the
stages of a scene into NumPy functions and integrates them with
:func:`scipy.integrate.solve_ivp`:

- the full compliant system (1.9) at a given ``eps``, in the original time t
  (:func:`simulate_full`), with the normal reactions ``N_j(t)`` as outputs;
- the comparison (reduced) system (2.2), the rigid-contact motion (:func:`simulate_reduced`);
- the fast subsystem (2.1) alone, in the stretched time tau = t/eps
  (:func:`simulate_fast`, :func:`fast_trajectories_data`);
- a stable cycle of the fast subsystem and the averaged system (2.7)
  (:func:`fast_cycle`, :func:`simulate_averaged`).

Compliant contacts are stiff, so the default solver is Radau with the analytic Jacobian
(LSODA has been seen to take millions of steps on them). An impact-type catastrophe
(no equilibrium of the fast subsystem: the reaction grows without bound on the fast time
scale) stops the integration through a ``solve_ivp`` event and is reported in the
result's ``status``.

:func:`decide`, :func:`classify` and :class:`PointClassifier` decide the sign of stability
conditions at parameter points in floating point with a rigorous error bound, and
recompute exactly, in rationals, the points that fall inside a band around the boundary.

Examples
--------
>>> import sympy as sp
>>> import contactsym as cs
>>> s = cs.scene("sliding-point")
>>> x, xdot = sp.symbols("x xdot", real=True)
>>> X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)
>>> values = {"m": 1, "b": 1, "mu": 0.5, X: 2, Y: -1}
>>> full = simulate_full(s, values, 1e-3, (0, 1), {x: 0, xdot: 1})
>>> reduced = simulate_reduced(s, values, (0, 1), {x: 0, xdot: 1})
>>> full.status, reduced.status
('ok', 'ok')
>>> bool(abs(full.at(1.0, "x") - reduced.at(1.0, "x")) < 1e-2)
True
"""

from __future__ import annotations

import math
import time
import weakref
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

from .. import validate
from ..errors import NumericsError
from ..intervals import interval_sign
from ..laws import Compliance, Generic, ImplicitDeformation, KelvinVoigt, Law
from ..parse import sympy_only
from ..progress import Budget, Progress
from ..scene import t as _time

__all__ = [
    "NumericsError",
    "numeric_values",
    "substitute",
    "lambdify_cse",
    "lambdify_stage",
    "NumericFunction",
    "OdeSystem",
    "Simulation",
    "full_system",
    "reduced_system",
    "fast_system",
    "integrate",
    "simulate_full",
    "simulate_reduced",
    "simulate_fast",
    "equilibrium_reactions",
    "fast_trajectories_data",
    "Cycle",
    "fast_cycle",
    "simulate_averaged",
    "decide",
    "certified_sign",
    "classify",
    "Classification",
    "PointClassifier",
]

_UNIT = 2.0**-53  # unit roundoff of IEEE double precision
_IMPLICIT = ("Radau", "BDF", "LSODA")


# --- parameter values ----------------------------------------------------------------


def _number(value, name: str) -> sp.Expr:
    """A finite real number as a SymPy number; never parses text."""
    if isinstance(value, (str, bytes)):
        raise NumericsError(
            f"{name} = {validate.shorten(value)} is text; pass a number (contactsym never parses text)."
        )
    if isinstance(value, (bool, np.bool_)):
        raise NumericsError(f"{name} = {validate.shorten(value)} is a truth value; pass a number.")
    if isinstance(value, (int, np.integer)):
        return sp.Integer(int(value))
    if isinstance(value, Fraction):
        return sp.Rational(value.numerator, value.denominator)
    if isinstance(value, (float, np.floating)):
        x = float(value)
        if not math.isfinite(x):
            raise NumericsError(f"{name} = {x} is not finite; pass a finite number.")
        return sp.Float(x)
    if isinstance(value, sp.Basic):
        if value.free_symbols:
            raise NumericsError(
                f"{name} = {validate.shorten(value)} still contains the symbols {sorted(map(str, value.free_symbols))}; pass a number."
            )
        if value.has(sp.nan, sp.zoo, sp.oo, -sp.oo) or value.is_finite is False:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not finite; pass a finite number.")
        if value.is_real is False:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not real; pass a real number.")
        if not value.is_number:
            raise NumericsError(f"{name} = {validate.shorten(value)} is not a number.")
        if not math.isfinite(float(value)):
            raise NumericsError(f"{name} = {validate.shorten(value)} is not finite; pass a finite number.")
        return value
    raise NumericsError(f"{name} = {validate.shorten(value)} of type {type(value).__name__} is not a number.")


def _positive(value, name: str, why: str) -> float:
    x = float(_number(value, name))
    if not x > 0:
        raise NumericsError(f"{name} = {x} must be > 0: {why}.")
    return x


def _plain_expr(scene, expr) -> sp.Expr:
    return scene._plain(expr)


@dataclass(frozen=True)
class _Values:
    """Numeric parameter values (Symbol -> number) and function substitutions."""

    numbers: dict
    functions: dict  # UndefinedFunction -> Lambda

    def key(self) -> tuple:
        return (frozenset(self.numbers.items()), frozenset(self.functions.items()))


def _scene_symbols(scene) -> dict[str, sp.Basic]:
    """Names of the symbols and undefined functions a scene uses, for string keys."""
    exprs = [_plain_expr(scene, g) for g in scene.accelerations.values()]
    exprs += [_plain_expr(scene, c.coordinate) for c in scene.contacts]
    fast = scene.fast_subsystem()
    exprs += list(fast.Phi) + list(fast.Psi)
    for contact in scene.contacts:
        law = contact.compliance
        if isinstance(law, KelvinVoigt):
            exprs += [law.stiffness, law.damping]
        elif isinstance(law, Law):
            exprs.append(sp.Tuple(*(law.expr.free_symbols - {law.q, law.qdot, law.eps})))
    names: dict[str, sp.Basic] = {}
    for expr in exprs:
        expr = sp.sympify(expr)
        for symbol in expr.free_symbols:
            names.setdefault(str(symbol), symbol)
        for applied in expr.atoms(sp.core.function.AppliedUndef):
            names.setdefault(str(applied.func), applied.func)
    return names


def numeric_values(scene, values: Mapping | None) -> _Values:
    """Validate parameter values for a scene: finite numbers, and functions for X(x, xdot).

    Keys are the scene's SymPy symbols or their names (strings are looked up among the
    scene's symbols, never parsed). An undefined function such as the sliding point's
    ``X(x, xdot)`` is given either applied, ``{X(x, xdot): expression in x, xdot}``, or as
    the function with a ``sympy.Lambda``.

    Examples
    --------
    >>> import contactsym as cs
    >>> v = numeric_values(cs.scene("brake"), {"m": 2, "mu": 0.5})
    >>> sorted(map(str, v.numbers))
    ['m', 'mu']
    >>> numeric_values(cs.scene("brake"), {"m": float("nan")})
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: m = nan is not finite; pass a finite number.
    >>> numeric_values(cs.scene("brake"), {"m": "2"})
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: m = '2' is text; pass a number (contactsym never parses text).
    """
    numbers: dict = {}
    functions: dict = {}
    if values is None:
        return _Values(numbers, functions)
    if isinstance(values, _Values):
        return values
    if not isinstance(values, Mapping):
        raise NumericsError(f"values must be a mapping {{symbol: number}}, not {type(values).__name__}.")
    known = None
    for key, value in values.items():
        if isinstance(key, str):
            known = known if known is not None else _scene_symbols(scene)
            if key not in known:
                raise NumericsError(f"unknown parameter name {key!r}; the scene's names are {sorted(known)}.")
            key = known[key]
        if isinstance(key, sp.core.function.UndefinedFunction):
            if isinstance(value, sp.Lambda):
                functions[key] = value
                continue
            raise NumericsError(f"give the function {key} as sympy.Lambda((x, xdot), expression) or applied.")
        if not isinstance(key, sp.Basic):
            raise NumericsError(f"parameter key {key!r} is neither a SymPy symbol nor a name.")
        if isinstance(key, sp.core.function.AppliedUndef):
            key = _plain_expr(scene, key)
            arguments = key.args
            if not all(isinstance(a, sp.Symbol) for a in arguments):
                raise NumericsError(f"the function {key} must be applied to plain symbols, e.g. X(x, xdot).")
            body = _number(value, str(key)) if not isinstance(value, sp.Basic) else sp.sympify(value)
            if isinstance(body, sp.Basic) and body.free_symbols - set(arguments):
                extra = sorted(map(str, body.free_symbols - set(arguments)))
                raise NumericsError(f"the value of {key} uses {extra}, which are not its arguments {list(arguments)}.")
            functions[key.func] = sp.Lambda(arguments, body)
            continue
        if not isinstance(key, sp.Symbol):
            raise NumericsError(f"parameter key {key} is not a symbol.")
        number = _number(value, str(key))
        _check_assumptions(key, number)
        numbers[key] = number
    return _Values(numbers, functions)


def _merge(scene, values, state) -> _Values:
    """Parameter values with a (frozen) state merged in."""
    vals = numeric_values(scene, values)
    extra = numeric_values(scene, state)
    return _Values({**vals.numbers, **extra.numbers}, {**vals.functions, **extra.functions})


def _check_assumptions(symbol: sp.Symbol, number: sp.Expr) -> None:
    x = float(number)
    if symbol.is_positive and not x > 0:
        raise NumericsError(f"{symbol} = {x} must be > 0 (the symbol is declared positive).")
    if symbol.is_negative and not x < 0:
        raise NumericsError(f"{symbol} = {x} must be < 0 (the symbol is declared negative, as (1.5) requires).")
    if symbol.is_nonnegative and not x >= 0:
        raise NumericsError(f"{symbol} = {x} must be >= 0.")


def substitute(expr, values: _Values) -> sp.Expr:
    """Plain numeric substitution: functions first, then numbers (``xreplace``).

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> s = cs.scene("sliding-point")
    >>> x, xdot = sp.symbols("x xdot", real=True)
    >>> v = numeric_values(s, {"m": 2, sp.Function("X")(x, xdot): 3*x})
    >>> substitute(s.reduced_system().accelerations[x], v)
    -mu*Abs(Y(x, xdot))/2 + 3*x/2
    """
    expr = sympy_only(expr, "the expression")
    for function, body in values.functions.items():
        expr = expr.replace(function, body)
    if isinstance(expr, sp.MatrixBase):
        return expr.xreplace(values.numbers)
    return expr.xreplace(values.numbers)


# --- generated code ---------------------------------------------------------------------

#: generated functions, per scene and parameter set
_cache: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def _cached(scene, key, build):
    store = _cache.setdefault(scene, {})
    if key not in store:
        store[key] = build()
    return store[key]


def lambdify_cse(args: Sequence, exprs) -> Callable:
    """``sympy.lambdify`` to NumPy with common-subexpression elimination.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> f = lambdify_cse([x, y], [x**2*y + 1, x**2*y*sp.sin(x)])
    >>> [round(float(v), 6) for v in f(2.0, 3.0)]
    [13.0, 10.911569]
    """
    return sp.lambdify(list(args), exprs, modules="numpy", cse=True)


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
    from ..fast import FastSubsystem
    from ..linear import Linearization
    from ..regularize import ReducedSystem, Regularized
    from ..stability import Stability

    if isinstance(stage, FastSubsystem):
        return stage.scene, stage.rhs, tuple(stage.state)
    if isinstance(stage, Linearization):
        return stage.scene, stage.matrix, ()
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


# --- systems ----------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class OdeSystem:
    """A generated first-order system ``z' = fun(t, z)`` with its Jacobian and reactions.

    Attributes
    ----------
    names : tuple of str
        State components.
    fun, jac : callable
        ``fun(t, z)`` and its Jacobian ``jac(t, z)`` (analytic).
    reactions : callable
        ``reactions(t, z)``: the normal reactions N_j (u_j for the fast subsystem).
    reaction_names : tuple of str
    time : str
        ``"t"`` (original time) or ``"tau"`` (stretched time t/eps).
    description : str
    """

    names: tuple
    fun: Callable
    jac: Callable
    reactions: Callable
    reaction_names: tuple
    time: str
    description: str
    extra: dict = field(default_factory=dict)


def _second_order(
    time_symbol, positions, rates, accelerations, reaction_symbols, laws, gaps, clamp, *, names, time, description
) -> OdeSystem:
    """z = (positions, rates), positions' = rates, rates' = G(t, z, N), N = law(z), clamped.

    ``clamp[j]``: contact j only pushes; N_j = 0 where the gap opens (g_j > 0) or the law
    would pull (N_j < 0).
    """
    n, k = len(positions), len(reaction_symbols)
    z = list(positions) + list(rates)
    args = [time_symbol, *z]
    N = list(reaction_symbols)
    law_matrix = sp.Matrix(laws)
    law_value = lambdify_cse(args, [*laws, *gaps])
    law_jac = lambdify_cse(args, law_matrix.jacobian(z))
    G = sp.Matrix(accelerations)
    acc_value = lambdify_cse(args + N, list(G))
    acc_jac = lambdify_cse(args + N, [G.jacobian(z), G.jacobian(N)])
    clamp = np.asarray(clamp, dtype=bool)
    any_clamp = bool(clamp.any())

    def reactions_and_active(t, y):
        out = np.asarray(law_value(t, *y), dtype=float)
        raw, g = out[:k], out[k:]
        if not any_clamp:
            return raw, None
        active = ~clamp | ((g <= 0) & (raw >= 0))
        return np.where(active, raw, 0.0), active

    def fun(t, y):
        Nv, _ = reactions_and_active(t, y)
        acc = np.asarray(acc_value(t, *y, *Nv), dtype=float)
        return np.concatenate([y[n:], acc])

    def jac(t, y):
        Nv, active = reactions_and_active(t, y)
        dNdz = np.asarray(law_jac(t, *y), dtype=float).reshape(k, 2 * n)
        if active is not None:
            dNdz = dNdz * active[:, None]
        dGdz, dGdN = acc_jac(t, *y, *Nv)
        dGdz = np.asarray(dGdz, dtype=float).reshape(n, 2 * n)
        dGdN = np.asarray(dGdN, dtype=float).reshape(n, k)
        J = np.zeros((2 * n, 2 * n))
        J[:n, n:] = np.eye(n)
        J[n:, :] = dGdz + dGdN @ dNdz
        return J

    def reactions(t, y):
        return reactions_and_active(t, y)[0]

    extra = {"law_value": law_value, "law_jac": law_jac, "acc_value": acc_value, "acc_jac": acc_jac, "n": n, "k": k}
    return OdeSystem(tuple(names), fun, jac, reactions, tuple(str(s) for s in N), time, description, extra)


def _first_order(time_symbol, state, rhs, reaction_exprs, *, names, reaction_names, time, description) -> OdeSystem:
    args = [time_symbol, *state]
    rhs = sp.Matrix(rhs)
    value = lambdify_cse(args, list(rhs))
    jacobian = lambdify_cse(args, rhs.jacobian(list(state)))
    reaction_value = lambdify_cse(args, list(reaction_exprs))
    m = len(state)

    def fun(t, y):
        return np.asarray(value(t, *y), dtype=float)

    def jac(t, y):
        return np.asarray(jacobian(t, *y), dtype=float).reshape(m, m)

    def reactions(t, y):
        return np.asarray(reaction_value(t, *y), dtype=float)

    return OdeSystem(tuple(names), fun, jac, reactions, tuple(reaction_names), time, description)


def _coordinates(scene) -> tuple[list, list]:
    """Plain symbols of the coordinates and their rates, in the scene's order."""
    positions = [scene._plain(q) for q in scene.coordinates]
    rates = [scene._plain(sp.diff(q, _time)) for q in scene.coordinates]
    return positions, rates


def _contact_law(scene, j: int, laws: Mapping | None):
    contact = scene.contacts[j]
    if laws:
        for key in (j, contact.reaction, str(contact.reaction)):
            if key in laws:
                law = laws[key]
                if not isinstance(law, Compliance):
                    raise NumericsError(f"laws[{key!r}] = {law!r} is not a compliance law (KelvinVoigt, Law, ...).")
                return law
    return contact.compliance


def _generic_phi_psi(scene, j: int, vals: _Values) -> tuple[sp.Expr, sp.Expr]:
    fast = scene.fast_subsystem()
    Phi, Psi = fast.Phi[j], fast.Psi[j]
    if Phi in vals.numbers and Psi in vals.numbers:
        return vals.numbers[Phi], vals.numbers[Psi]
    reaction = scene.contacts[j].reaction
    raise NumericsError(
        f"contact {j + 1} ({reaction}) has a generic compliance law; give numeric values for {Phi} and {Psi} "
        f"(both < 0; the law is then N = {Phi} q/eps**2 + {Psi} q'/eps), or pass laws={{{j}: cs.KelvinVoigt(k, d)}}."
    )


def _law_in_gap(scene, j, law, vals: _Values, eps: float, g: sp.Expr, gd: sp.Expr) -> sp.Expr:
    """N_j at deformation g and rate gd, at the numeric eps (original time)."""
    e = sp.Float(eps)
    if isinstance(law, Generic):
        Phi, Psi = _generic_phi_psi(scene, j, vals)
        return Phi * g / e**2 + Psi * gd / e
    if isinstance(law, KelvinVoigt):
        return substitute(-law.stiffness * g / e**2 - law.damping * gd / e, vals)
    if isinstance(law, Law):
        at = {law.q: g, law.qdot: gd, law.eps: e}
        return substitute(_in_domain(law.expr.xreplace(at), [w.xreplace(at) for w in law.where]), vals)
    raise NumericsError(f"unsupported compliance law {law!r}; use Generic, KelvinVoigt or Law.")


def _law_scaled(scene, j, law, vals: _Values, Q: sp.Symbol, V: sp.Symbol) -> sp.Expr:
    """N_j(Q, V) in the scaled deformation Q = q/eps**2 and rate V = q'/eps (1.8)."""
    if isinstance(law, Generic):
        Phi, Psi = _generic_phi_psi(scene, j, vals)
        return Phi * Q + Psi * V
    if isinstance(law, KelvinVoigt):
        return substitute(-law.stiffness * Q - law.damping * V, vals)
    if isinstance(law, Law):
        at = {law.Q: Q, law.V: V}
        return substitute(_in_domain(law.scaled.xreplace(at), [w.xreplace(at) for w in law.domain]), vals)
    raise NumericsError(f"unsupported compliance law {law!r}; use Generic, KelvinVoigt or Law.")


def _in_domain(N: sp.Expr, conditions) -> sp.Expr:
    """A law defined only where its conditions are positive (Hertz: in compression) gives N = 0 elsewhere."""
    if not conditions:
        return N
    # NumPy evaluates both branches: keep fractional powers real where the law is not used
    real = {p: sp.Pow(sp.Max(p.base, 0), p.exp) for p in N.atoms(sp.Pow) if not p.exp.is_integer}
    return sp.Piecewise((N.xreplace(real), sp.And(*[sp.Gt(w, 0) for w in conditions])), (0, True))


def _clamps(scene, unilateral) -> list[bool]:
    if unilateral is None:
        return [bool(c.unilateral) for c in scene.contacts]
    return [bool(unilateral)] * scene.k


def _check_free(expr_list, allowed: set, what: str) -> None:
    free = set()
    for e in expr_list:
        free |= sp.sympify(e).free_symbols
    missing = free - allowed
    if missing:
        raise NumericsError(f"{what} needs values for {sorted(map(str, missing))}; add them to values.")
    functions = set()
    for e in expr_list:
        functions |= {a.func for a in sp.sympify(e).atoms(sp.core.function.AppliedUndef)}
    if functions:
        raise NumericsError(
            f"{what} still contains the undefined functions {sorted(map(str, functions))}; "
            "give them in values, e.g. {X(x, xdot): expression}."
        )


def _manifold_parameters(scene) -> dict:
    """Parameters that the contact manifold fixes (e.g. h = l sin(phi)), with their expressions."""
    positions, rates = _coordinates(scene)
    state = set(positions) | set(rates)
    return {key: value for key, value in scene.manifold.items() if key not in state}


def full_system(scene, values: Mapping | None, eps, *, laws: Mapping | None = None, unilateral=None) -> OdeSystem:
    """The full compliant system (1.9) at a numeric ``eps``, in the original time t.

    The state is the scene's coordinates and their rates; each reaction is given by its
    contact's compliance law at the contact's gap g_j and its rate: Kelvin–Voigt
    ``N = -k g/eps**2 - d g'/eps``, a ``Law`` as written, and a generic law with the
    numeric ``Phi_j``, ``Psi_j`` of ``values`` (``N = Phi g/eps**2 + Psi g'/eps``).
    Unilateral contacts (the scene's, or all with ``unilateral=True``) only push:
    ``N_j = 0`` where the gap opens.

    Examples
    --------
    >>> import contactsym as cs
    >>> sys = full_system(cs.scene("painleve-klein-rod"), {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0,
    ...     "X_2": 1, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}, 1e-3)
    >>> sys.names, sys.reaction_names
    (('x_1', 'delta', 'xdot_1', 'deltadot'), ('R',))
    >>> full_system(cs.scene("brake"), {}, 0)
    Traceback (most recent call last):
    ...
    contactsym.numerics.NumericsError: eps = 0.0 must be > 0: it is the time scale of the contact deformations (1.6).
    """
    eps = _positive(eps, "eps", "it is the time scale of the contact deformations (1.6)")
    vals = numeric_values(scene, values)
    key = ("full", vals.key(), eps, _laws_key(laws), unilateral)
    return _cached(scene, key, lambda: _build_full(scene, vals, eps, laws, unilateral))


def _laws_key(laws) -> tuple | None:
    return None if not laws else tuple(sorted((str(k), repr(v)) for k, v in laws.items()))


def _build_full(scene, vals: _Values, eps: float, laws, unilateral) -> OdeSystem:
    positions, rates = _coordinates(scene)
    missing = [p for p in _manifold_parameters(scene) if p not in vals.numbers]
    if missing:
        raise NumericsError(
            f"the full system needs values for {sorted(map(str, missing))} (fixed by the contact manifold); "
            "give them, or call simulate_full, which takes them from the initial state."
        )
    reactions = list(scene.reactions)
    G = [substitute(_plain_expr(scene, scene.accelerations[q]), vals) for q in scene.coordinates]
    gaps, law_exprs = [], []
    for j, contact in enumerate(scene.contacts):
        g = substitute(_plain_expr(scene, contact.coordinate), vals)
        gd = substitute(_plain_expr(scene, sp.diff(contact.coordinate, _time)), vals)
        law = _contact_law(scene, j, laws)
        gaps.append(g)
        law_exprs.append(_law_in_gap(scene, j, law, vals, eps, g, gd))
    allowed = set(positions) | set(rates) | set(reactions) | {_time}
    _check_free(G + gaps + law_exprs, allowed, f"the full system of scene '{scene.name}'")
    names = [str(s) for s in positions + rates]
    return _second_order(
        _time,
        positions,
        rates,
        G,
        reactions,
        law_exprs,
        gaps,
        _clamps(scene, unilateral),
        names=names,
        time="t",
        description=f"full system (1.9) of '{scene.name}' at eps = {eps:g}",
    )


def _free_coordinates(scene) -> list[tuple[sp.Symbol, sp.Symbol]]:
    """(coordinate, rate) plain symbols that the contacts leave free to move."""
    fixed = set(scene.manifold)
    positions, rates = _coordinates(scene)
    return [(q, r) for q, r in zip(positions, rates) if q not in fixed and r not in fixed]


def _branch_at(scene, vals: _Values, signs=None):
    """The equilibrium branch to use at frozen values: the given pattern or the unique consistent one."""
    if signs is not None:
        return scene.equilibria(signs).branches[0]
    branches = [b for b in scene.equilibria() if decide(substitute(b.condition, vals), {}) is True]
    if len(branches) == 1:
        return branches[0]
    if not branches:
        raise NumericsError(
            "no equilibrium of the fast subsystem is consistent at these values: an impact-type catastrophe "
            "(no reduced system exists); simulate the full or fast system to see the reaction grow."
        )
    raise NumericsError(
        f"{len(branches)} equilibria are consistent at these values (signs {[b.signs for b in branches]}); "
        "choose one with signs=..."
    )


def equilibrium_reactions(scene, values: Mapping | None, state: Mapping | None = None) -> list[tuple]:
    """Consistent equilibria (sign pattern, u*) of the fast subsystem at numeric values.

    ``state`` gives the frozen slow state (plain symbols or names), merged into values.
    Consistency of each branch is decided with :func:`decide` (exact near the boundary).

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> [(s, [round(u, 6) for u in us]) for s, us in equilibrium_reactions(cs.scene("painleve-klein-rod"), values)]
    [((-1, -1), [-0.682472])]
    """
    vals = _merge(scene, values, state)
    found = []
    for branch in scene.equilibria():
        if decide(substitute(branch.condition, vals), {}) is True:
            found.append((branch.signs, [float(substitute(u, vals)) for u in branch.u_star]))
    return found


def reduced_system(scene, values: Mapping | None, *, signs=None, state: Mapping | None = None) -> OdeSystem:
    """The comparison system (2.2) on one equilibrium branch, as generated code.

    The branch is ``signs`` or, with ``signs=None``, the unique branch consistent at
    ``state`` (the initial state). Coordinates fixed by the contacts (e.g. the angle of
    the Painlevé–Klein rod) are constants taken from ``state``.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> reduced_system(cs.scene("painleve-klein-rod"), values).names
    ('x_1', 'xdot_1')
    """
    merged = _merge(scene, values, state)
    free = _free_coordinates(scene)
    free_symbols = {s for pair in free for s in pair}
    frozen = _Values({k: v for k, v in merged.numbers.items() if k not in free_symbols}, merged.functions)
    branch = _branch_at(scene, frozen, signs)
    key = ("reduced", frozen.key(), branch.signs)

    def build():
        reduced = scene.reduced_system(branch.signs)
        positions = [q for q, _ in free]
        rates = [r for _, r in free]
        accelerations = [substitute(reduced.accelerations[q], frozen) for q in positions]
        outputs = [substitute(u, frozen) for u in branch.u_star]
        _check_free(accelerations + outputs, set(positions) | set(rates) | {_time}, "the reduced system")
        return _first_order(
            _time,
            positions + rates,
            rates + accelerations,
            outputs,
            names=[str(s) for s in positions + rates],
            reaction_names=[str(r) for r in scene.reactions],
            time="t",
            description=f"reduced system (2.2) of '{scene.name}', signs {branch.signs}",
        )

    return _cached(scene, key, build)


def _fast_form(scene, unilateral, form) -> str:
    if form is not None:
        if form not in ("uv", "deformation"):
            raise NumericsError(f"form = {form!r}; use 'uv' (the paper's (2.1)) or 'deformation' (Q, V).")
        return form
    implicit = any(x.atoms(ImplicitDeformation) for x in scene.fast_subsystem().Phi + scene.fast_subsystem().Psi)
    return "deformation" if implicit or any(_clamps(scene, unilateral)) else "uv"


def fast_system(
    scene, values: Mapping | None, *, laws: Mapping | None = None, unilateral=None, form: str | None = None
) -> OdeSystem:
    """The fast subsystem (2.1) in the stretched time tau with the slow state frozen.

    ``form="uv"`` integrates (2.1) as printed, ``u' = Phi v + Psi f(u)``, ``v' = f(u)``.
    ``form="deformation"`` integrates the scaled deformations ``Q' = V``,
    ``V' = f(N(Q, V))``, the same system where the contact is closed, which also
    covers a unilateral contact that opens (N = 0 there); it is the default when a
    contact is unilateral. The frozen slow state and the parameters come from values.

    Examples
    --------
    >>> import contactsym as cs
    >>> fs = fast_system(cs.scene("brake"), {"m": 1, "mu": 1, "alpha": 1.5, "F_x": 0, "F_y": -2,
    ...     "Phi_1": -1, "Phi_2": -1, "Psi_1": -1, "Psi_2": -1})
    >>> fs.names, fs.time
    (('Q_1', 'Q_2', 'V_1', 'V_2'), 'tau')
    """
    vals = numeric_values(scene, values)
    chosen = _fast_form(scene, unilateral, form)
    key = ("fast", vals.key(), _laws_key(laws), unilateral, chosen)
    return _cached(scene, key, lambda: _build_fast(scene, vals, laws, unilateral, chosen))


def _build_fast(scene, vals: _Values, laws, unilateral, form: str) -> OdeSystem:
    fast = scene.fast_subsystem()
    tau = sp.Symbol("tau", real=True)
    f = [substitute(fj, vals) for fj in fast.f]
    description = f"fast subsystem (2.1) of '{scene.name}' ({form} form)"
    if form == "uv":
        Phi, Psi = [], []
        for j in range(scene.k):
            law = _contact_law(scene, j, laws)
            if isinstance(law, Generic):
                phi, psi = _generic_phi_psi(scene, j, vals)
            else:
                phi, psi = law.phi_psi(fast.u[j], fast.v[j], None if scene.k == 1 else j + 1)
            if sp.Tuple(phi, psi).atoms(ImplicitDeformation):
                raise NumericsError(
                    f"the law {law!r} of contact {j + 1} has no closed-form inverse Q(u, v), so (2.1) cannot be "
                    "integrated in (u, v); use form='deformation' (the same system in Q, V)."
                )
            Phi.append(substitute(phi, vals))
            Psi.append(substitute(psi, vals))
        rhs = [Phi[j] * fast.v[j] + Psi[j] * f[j] for j in range(scene.k)] + f
        _check_free(rhs, set(fast.u) | set(fast.v), f"the fast subsystem of '{scene.name}'")
        names = [str(s) for s in (*fast.u, *fast.v)]
        return _first_order(
            tau,
            [*fast.u, *fast.v],
            rhs,
            list(fast.u),
            names=names,
            reaction_names=names[: scene.k],
            time="tau",
            description=description,
        )
    suffix = [""] if scene.k == 1 else [f"_{j}" for j in range(1, scene.k + 1)]
    Q = [sp.Symbol(f"Q{s}", real=True) for s in suffix]
    V = [sp.Symbol(f"V{s}", real=True) for s in suffix]
    laws_QV = [_law_scaled(scene, j, _contact_law(scene, j, laws), vals, Q[j], V[j]) for j in range(scene.k)]
    accelerations = [fj.xreplace(dict(zip(fast.u, scene.reactions))) for fj in f]
    _check_free(accelerations, set(scene.reactions), f"the fast subsystem of '{scene.name}'")
    _check_free(laws_QV, set(Q) | set(V), f"the compliance laws of '{scene.name}'")
    names = [str(s) for s in Q + V]
    system = _second_order(
        tau,
        Q,
        V,
        accelerations,
        list(scene.reactions),
        laws_QV,
        Q,
        _clamps(scene, unilateral),
        names=names,
        time="tau",
        description=description,
    )
    return OdeSystem(
        system.names,
        system.fun,
        system.jac,
        system.reactions,
        tuple(str(u) for u in fast.u),
        "tau",
        description,
        system.extra,
    )


# --- integration ----------------------------------------------------------------------


class _Budget(Exception):
    pass


class _NotFinite(Exception):
    pass


@dataclass(frozen=True, eq=False)
class Simulation:
    """The result of a simulation.

    Attributes
    ----------
    t : ndarray
        Output times (t, or tau for the fast subsystem).
    y : ndarray
        States, one row per component of ``names``.
    reactions : ndarray
        Normal reactions N_j at the output times, one row per contact.
    status : str
        ``"ok"``; ``"impact"`` when the reaction grew past ``reaction_bound`` (impact-type
        catastrophe, no equilibrium of the fast subsystem); ``"failed"`` otherwise.
    message : str
        What happened, in words.
    nfev : int
        Right-hand-side evaluations, including those of finite-difference Jacobians.
    njev, nlu : int
        Jacobian evaluations and LU decompositions reported by the solver.
    cpu_s, wall_s : float
        Process (CPU) time and wall time of the integration.
    sol : OdeSolution or None
        Dense output when requested.
    """

    t: np.ndarray
    y: np.ndarray
    names: tuple
    reactions: np.ndarray
    reaction_names: tuple
    status: str
    message: str
    method: str
    analytic_jacobian: bool
    nfev: int
    njev: int
    nlu: int
    cpu_s: float
    wall_s: float
    time: str = "t"
    sol: object = None
    extra: dict = field(default_factory=dict)

    def __getitem__(self, name: str) -> np.ndarray:
        if name in self.names:
            return self.y[self.names.index(name)]
        if name in self.reaction_names:
            return self.reactions[self.reaction_names.index(name)]
        raise KeyError(f"{name!r} is none of {self.names + self.reaction_names}")

    def at(self, time_value: float, name: str) -> float:
        """One component at one time (dense output, else linear interpolation)."""
        if self.sol is not None and name in self.names:
            return float(self.sol(time_value)[self.names.index(name)])
        return float(np.interp(time_value, self.t, self[name]))

    @property
    def ok(self) -> bool:
        return self.status == "ok"


def _check_span(span, name: str) -> tuple[float, float]:
    if not isinstance(span, (tuple, list)) or len(span) != 2:
        raise NumericsError(f"{name} = {validate.shorten(span)} must be a pair (start, end).")
    start, end = (float(_number(v, name)) for v in span)
    if not end > start:
        raise NumericsError(f"{name} = ({start}, {end}): the end must come after the start.")
    return start, end


def _budget_message(method: str, analytic: bool, counter: dict, max_rhs: int, budget, span, time_name) -> str:
    """What ran out, how far the run got, and advice that is not what was already done."""
    start, end = span
    spent = (
        f"{budget.elapsed:.0f} s (max_seconds = {budget.max_seconds:g})"
        if counter["n"] <= max_rhs
        else f"{max_rhs} right-hand-side evaluations (max_rhs)"
    )
    reached = (
        f"it reached {time_name} = {counter['t']:.6g}, {100 * (counter['t'] - start) / (end - start):.3g}% of the span"
    )
    if analytic:  # the stiff solver with the exact Jacobian was already in use: the work itself is large
        advice = (
            f"{method} already had the analytic Jacobian, so the cost is the number of fast time scales in the "
            "span: shorten the span, take a larger eps, or use the reduced system (simulate_reduced) for the "
            "slow motion; raise the limit only if the whole run is needed"
        )
    elif method in _IMPLICIT:
        advice = "pass jacobian=True so that the solver gets the analytic Jacobian"
    else:
        advice = f"{method} is explicit and contacts are stiff: use method='Radau' or 'BDF' with the analytic Jacobian"
    return f"{method} used up its budget of {spent}; {reached}. {advice}."


def integrate(
    system: OdeSystem,
    span,
    z0,
    *,
    method: str = "Radau",
    jacobian: bool = True,
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = False,
    max_rhs: int = 2_000_000,
    reaction_bound: float | None = None,
    events: Sequence = (),
    progress: Progress | None = None,
    max_seconds: float | None = None,
) -> Simulation:
    """Integrate a generated system with ``scipy.integrate.solve_ivp``.

    Parameters
    ----------
    method : str
        Any ``solve_ivp`` method; Radau (default) and BDF are robust for stiff contacts.
    jacobian : bool
        Give the implicit methods the analytic Jacobian (True) or let SciPy use finite
        differences (False).
    atol : float or array, optional
        Default ``rtol`` times the magnitude of the initial state (at least 1e-12 of it).
    max_rhs : int
        Stop with status ``"failed"`` after this many right-hand-side evaluations.
    reaction_bound : float, optional
        Stop with status ``"impact"`` when some |N_j| exceeds it.
    progress : callable, optional
        ``progress(fraction of the span done, message)``, a few times per second.
    max_seconds : float, optional
        Stop with status ``"failed"`` after this much wall time, saying how far the run got.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -1}
    >>> fs = fast_system(cs.scene("painleve-klein-rod"), values)
    >>> run = integrate(fs, (0, 40), [0.0, 0.0], rtol=1e-10, atol=1e-12)
    >>> run.status, round(float(run.reactions[0, -1]), 5)
    ('ok', -0.68247)
    """
    start, end = _check_span(span, "span")
    method = validate.solver_method(method)
    t_eval = validate.output_times(t_eval, (start, end))
    z0 = validate.real_array(z0, "the initial state").ravel()
    if z0.shape != (len(system.names),):
        raise NumericsError(
            f"the initial state has {z0.size} components; {system.description} has {len(system.names)}."
        )
    if not np.all(np.isfinite(z0)):
        raise NumericsError(f"the initial state {z0.tolist()} is not finite.")
    rtol = _positive(rtol, "rtol", "it is the relative tolerance")
    if atol is None:
        magnitude = np.abs(z0)
        atol = rtol * np.maximum(magnitude, max(1e-12 * float(magnitude.max(initial=0.0)), 1e-300))
        if not magnitude.any():
            atol = np.full_like(z0, rtol)
    counter = {"n": 0, "t": start}  # t: the furthest time evaluated, for progress and for a spent budget
    budget = Budget(progress, max_seconds)

    def fun(t, y):
        counter["n"] += 1
        counter["t"] = max(counter["t"], t)
        if counter["n"] > max_rhs:
            raise _Budget
        if counter["n"] % 64 == 0 and budget.report((counter["t"] - start) / (end - start), f"{system.time} = {t:.4g}"):
            raise _Budget
        out = system.fun(t, y)
        if not np.all(np.isfinite(out)):
            raise _NotFinite(t)
        return out

    solver_events = list(events)
    if reaction_bound is not None:

        def impact(t, y):
            return reaction_bound - float(np.max(np.abs(system.reactions(t, y))))

        impact.terminal = True
        impact.direction = -1
        solver_events.append(impact)
    options = {}
    analytic = bool(jacobian) and method in _IMPLICIT
    if analytic:
        options["jac"] = system.jac
    started, cpu = time.perf_counter(), time.process_time()
    status, message, result = "ok", "integrated to the end", None
    try:
        result = solve_ivp(
            fun,
            (start, end),
            z0,
            method=method,
            t_eval=t_eval,
            dense_output=dense_output,
            events=solver_events or None,
            rtol=rtol,
            atol=atol,
            **options,
        )
        if result.status == -1:
            status, message = "failed", f"{method} failed: {result.message}"
        elif reaction_bound is not None and result.t_events[-1].size:
            status = "impact"
            message = (
                f"impact-type catastrophe: |N| passed {reaction_bound:.3g} at {system.time} = "
                f"{result.t_events[-1][0]:.6g}; the fast subsystem has no stable equilibrium to settle on "
                "and the reaction grows without bound on the fast time scale."
            )
    except _Budget:
        status = "failed"
        message = _budget_message(method, analytic, counter, max_rhs, budget, (start, end), system.time)
    except _NotFinite as stop:
        status = "failed"
        message = f"the right-hand side is not finite at {system.time} = {stop.args[0]:.6g}; check the parameters."
    wall, cpu = time.perf_counter() - started, time.process_time() - cpu
    if status == "ok":
        budget.report(1.0, f"{system.time} = {end:.4g}")
    if result is None:
        empty = np.empty((len(system.names), 0))
        return Simulation(
            np.empty(0),
            empty,
            system.names,
            np.empty((len(system.reaction_names), 0)),
            system.reaction_names,
            status,
            message,
            method,
            analytic,
            counter["n"],
            0,
            0,
            cpu,
            wall,
            system.time,
        )
    if status == "impact" and (t_eval is not None):
        # keep the state where the catastrophe was detected
        times = np.append(result.t, result.t_events[-1][0])
        states = np.column_stack([result.y, result.y_events[-1][0]])
    else:
        times, states = result.t, result.y
    reactions = (
        np.column_stack([system.reactions(ti, states[:, i]) for i, ti in enumerate(times)])
        if times.size
        else (np.empty((len(system.reaction_names), 0)))
    )
    if status == "ok" and not (np.all(np.isfinite(states)) and np.all(np.isfinite(reactions))):
        status, message = "failed", "the solution is not finite; check the parameters."
    return Simulation(
        times,
        states,
        system.names,
        reactions,
        system.reaction_names,
        status,
        message,
        method,
        analytic,
        counter["n"],
        int(result.njev),
        int(result.nlu),
        cpu,
        wall,
        system.time,
        result.sol,
        {"t_events": result.t_events, "y_events": result.y_events},
    )


# --- the full, reduced and fast systems, simulated --------------------------------------


def _state_values(names: Sequence[str], symbols: Sequence[sp.Symbol], initial, what: str) -> dict:
    """Initial values keyed by symbol, from a mapping keyed by symbols or names."""
    if initial is None:
        return {}
    if not isinstance(initial, Mapping):
        raise NumericsError(f"the initial state of the {what} must be a mapping {{symbol or name: number}}.")
    by_name = dict(zip(names, symbols))
    out = {}
    for key, value in initial.items():
        name = key if isinstance(key, str) else str(key)
        if name not in by_name:
            raise NumericsError(f"{name!r} is not a state variable of the {what}; its state is {list(names)}.")
        out[by_name[name]] = float(_number(value, name))
    return out


def _with(vals: _Values, extra: Mapping) -> _Values:
    numbers = dict(vals.numbers)
    numbers.update({k: sp.Float(v) if isinstance(v, float) else v for k, v in extra.items()})
    return _Values(numbers, vals.functions)


def _evaluate(expr, vals: _Values, what: str) -> float:
    value = substitute(expr, vals)
    if value.free_symbols:
        raise NumericsError(f"{what} needs values for {sorted(map(str, value.free_symbols))}.")
    return float(value)


def _reaction_scale(scene, frozen: _Values, branch) -> float:
    """A typical magnitude of the reactions: |u*|, or |f_j(0) / a_jj| without an equilibrium."""
    if branch is not None:
        scale = max((abs(float(substitute(u, frozen))) for u in branch.u_star), default=0.0)
        if scale > 0 and math.isfinite(scale):
            return scale
    fast = scene.fast_subsystem()
    zero = dict.fromkeys(fast.u, 0)
    estimates = []
    for j, fj in enumerate(fast.f):
        f0 = substitute(fj.xreplace(zero), frozen)
        slope = substitute(sp.diff(fj, fast.u[j]).xreplace(zero), frozen)
        if not f0.free_symbols and not slope.free_symbols and float(slope) != 0:
            estimates.append(abs(float(f0) / float(slope)))
    scale = max(estimates, default=0.0)
    return scale if scale > 0 and math.isfinite(scale) else 1.0


def _try_branch(scene, frozen: _Values, signs):
    try:
        return _branch_at(scene, frozen, signs)
    except NumericsError:
        return None


def _invert_law(N_of_Q: Callable[[float], float], target: float, scale: float) -> float:
    """Q with N(Q, 0) = target (N decreasing in Q, (1.5)), by bracketing and brentq."""
    from scipy.optimize import brentq

    def residual(Q):
        return N_of_Q(Q) - target

    width = max(scale, 1e-300)
    for _ in range(200):
        if residual(-width) * residual(width) <= 0:
            return float(brentq(residual, -width, width, xtol=1e-300, rtol=1e-15))
        width *= 4
    raise NumericsError(f"cannot invert the compliance law for the deformation at N = {target:g}.")


def simulate_full(
    scene,
    values: Mapping | None,
    eps,
    span,
    initial: Mapping,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    start: str = "rigid",
    signs=None,
    method: str = "Radau",
    jacobian: bool = True,
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = True,
    reaction_bound: float | None = None,
    bound_factor: float = 1e6,
    max_rhs: int = 2_000_000,
    progress: Progress | None = None,
    max_seconds: float | None = None,
) -> Simulation:
    """Simulate the full compliant system (1.9) at ``eps`` in the original time t.

    Parameters
    ----------
    initial : mapping
        Initial coordinates and rates (plain symbols or names, e.g. ``x``, ``xdot``).
        Coordinates fixed by the contacts may be left out: ``start="rigid"`` puts them
        on the contact manifold (g = 0, g' = 0; the reactions start from 0 and pass an
        initial layer), ``start="slow"`` deforms the contacts so that the reactions start
        at the equilibrium u* (to leading order on the slow manifold).
    laws, unilateral
        See :func:`full_system`.
    progress, max_seconds
        Progress reports and a wall-time limit; see :func:`integrate`.
    reaction_bound : float, optional
        |N_j| beyond which the run stops as an impact-type catastrophe; default
        ``bound_factor`` times the scale of the reactions (|u*|, or the loads'
        |f_j(0) / a_jj| when no equilibrium exists).
    atol : optional
        Default: ``rtol`` times a typical magnitude of each component (the contact
        deformations are O(eps**2), their rates O(eps)), but not below what the rounding
        of the gap expressions allows (a gap such as h - l sin(phi) - y is a difference
        of O(1) numbers). Where the deformations themselves are below that rounding, a
        :class:`NumericsError` says so instead of letting the solver's steps collapse.

    Examples
    --------
    >>> import contactsym as cs
    >>> rod = cs.scene("painleve-klein-rod")
    >>> values = {"phi": 0.785, "mu_1": 3, "mu_2": 0.5, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -1}
    >>> equilibrium_reactions(rod, values)
    []
    >>> run = simulate_full(rod, values, 1e-3, (0, 1), {"x_1": 0, "xdot_1": 1})
    >>> run.status
    'impact'
    >>> bool(run.t[-1] < 0.1)
    True
    """
    eps = _positive(eps, "eps", "it is the time scale of the contact deformations (1.6)")
    span = _check_span(span, "span")
    if start not in ("rigid", "slow"):
        raise NumericsError(f"start = {start!r}; use 'rigid' (on the contact manifold) or 'slow' (N = u*).")
    vals = numeric_values(scene, values)
    positions, rates = _coordinates(scene)
    state = positions + rates
    names = [str(s) for s in state]
    given = _state_values(names, state, initial, f"full system of '{scene.name}'")
    for symbol in vals.numbers:
        if symbol in state:
            raise NumericsError(f"{symbol} is a state variable of the full system; give it in initial, not in values.")
    with_state = _with(vals, given)
    # parameters fixed by the contact manifold (h = l sin(phi) for the guides), from the initial state
    fixed = {}
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in vals.numbers:
            fixed[parameter] = _evaluate(expr, with_state, f"the parameter {parameter} (fixed by the contacts)")
    vals = _with(vals, fixed)
    with_state = _with(with_state, fixed)
    z0 = []
    for symbol in state:
        if symbol in given:
            z0.append(given[symbol])
        elif symbol in scene.manifold:
            z0.append(_evaluate(scene.manifold[symbol], with_state, f"the initial value of {symbol}"))
        else:
            raise NumericsError(f"give the initial value of {symbol} in initial.")
    z0 = np.array(z0, dtype=float)
    system = full_system(scene, vals, eps, laws=laws, unilateral=unilateral)
    frozen = _with(vals, dict(zip(state, z0)))
    branch = _try_branch(scene, frozen, signs)
    if start == "slow" and branch is None:
        raise NumericsError("start='slow' needs a consistent equilibrium u* at the initial state; none was found.")
    N_scale = _reaction_scale(scene, frozen, branch)
    determined = [i for i, (q, r) in enumerate(zip(positions, rates)) if q in scene.manifold or r in scene.manifold]
    gap_exprs = [substitute(_plain_expr(scene, c.coordinate), vals) for c in scene.contacts]
    gap_function = lambdify_cse(positions, gap_exprs)
    gap_jacobian = lambdify_cse(positions, sp.Matrix(gap_exprs).jacobian(positions))
    n, k = len(positions), scene.k
    law_jac = system.extra["law_jac"]
    stiffness = np.abs(np.asarray(law_jac(span[0], *z0), dtype=float).reshape(k, 2 * n)[:, :n])
    Dg = np.asarray(gap_jacobian(*z0[:n]), dtype=float).reshape(k, n)
    S = np.array([max(float(np.max(np.abs(stiffness[j]) / np.maximum(np.abs(Dg[j]), 1e-300))), 0.0) for j in range(k)])
    S = np.where(S > 0, S, 1.0 / eps**2)
    if start == "slow":
        u_star = [float(substitute(u, frozen)) for u in branch.u_star]
        Qv = sp.Symbol("Q", real=True)
        targets = []
        for j in range(k):
            law = _contact_law(scene, j, laws)
            N_of_Q = lambdify_cse([Qv], _law_scaled(scene, j, law, vals, Qv, sp.S.Zero))
            targets.append(
                eps**2 * _invert_law(lambda Q, f=N_of_Q: float(f(Q)), u_star[j], abs(u_star[j]) / (S[j] * eps**2))
            )
        z0 = _place_gaps(z0, n, determined, gap_function, gap_jacobian, np.array(targets))
    acc_jac = system.extra["acc_jac"]
    _, dGdN = acc_jac(span[0], *z0, *system.reactions(span[0], z0))
    a = np.abs(np.diag(Dg @ np.asarray(dGdN, dtype=float).reshape(n, k)))
    gap_scale = N_scale / S
    rate_scale = gap_scale * np.sqrt(S * np.where(a > 0, a, 1.0))
    scale = np.abs(z0).copy()
    if determined:
        inverse = np.abs(np.linalg.pinv(Dg[:, determined]))
        for row, i in enumerate(determined):
            scale[i] = max(scale[i], float(inverse[row] @ gap_scale))
            scale[n + i] = max(scale[n + i], float(inverse[row] @ rate_scale))
    duration = span[1] - span[0]
    acceleration = (
        np.abs(system.fun(span[0], z0)[n:])
        if branch is None
        else np.abs(
            np.asarray(system.extra["acc_value"](span[0], *z0, *[float(substitute(u, frozen)) for u in branch.u_star]))
        )
    )
    for i in range(n):
        if i not in determined:
            scale[i] = max(scale[i], abs(z0[n + i]) * duration, acceleration[i] * duration**2 / 2)
            scale[n + i] = max(scale[n + i], acceleration[i] * duration)
    top = float(scale.max(initial=0.0))
    scale = np.maximum(scale, 1e-12 * top if top > 0 else 1.0)
    gap_noise = _gap_noise(gap_exprs, positions, z0)
    if np.any(gap_noise > gap_scale):
        j = int(np.argmax(gap_noise / gap_scale))
        raise NumericsError(
            f"at eps = {eps:g} the deformation of contact {j + 1} (about {gap_scale[j]:.1e}) is lost in the "
            f"rounding of its gap {gap_exprs[j]} (about {gap_noise[j]:.1e} with a safety margin) in these "
            "coordinates; use a larger eps (the reduced system is then the answer to this accuracy) or "
            "write the scene with the gap as a coordinate."
        )
    if atol is None:
        atol = np.maximum(rtol * scale, _roundoff_floor(gap_noise, n, determined, Dg, S * a))
    bound = reaction_bound if reaction_bound is not None else bound_factor * N_scale
    run = integrate(
        system,
        span,
        z0,
        method=method,
        jacobian=jacobian,
        rtol=rtol,
        atol=atol,
        t_eval=t_eval,
        dense_output=dense_output,
        max_rhs=max_rhs,
        reaction_bound=bound,
        progress=progress,
        max_seconds=max_seconds,
    )
    extra = {
        "eps": eps,
        "reaction_scale": N_scale,
        "reaction_bound": bound,
        "atol": atol,
        "equilibrium": None if branch is None else branch.signs,
    }
    if branch is None and run.status == "impact":
        extra["no_equilibrium"] = True
    return _replace(run, extra={**run.extra, **extra})


def _gap_noise(gap_exprs, positions, z0) -> np.ndarray:
    """Rounding error of each gap in floating point, with a margin of 10^4.

    A gap such as h - l sin(phi) - y is a difference of O(1) numbers: evaluated in floating
    point it carries an error of about u (|h| + |l sin(phi)| + |y|), which the law divides
    by eps^2.
    """
    magnitude = lambdify_cse(positions, [sp.Add(*[sp.Abs(t) for t in sp.Add.make_args(g)]) for g in gap_exprs])
    return 1e4 * _UNIT * np.abs(np.asarray(magnitude(*z0[: len(positions)]), dtype=float)).reshape(-1)


def _roundoff_floor(gap_noise, n: int, determined, Dg, fast_squared) -> np.ndarray:
    """The least absolute tolerance of each state component that the gaps' rounding allows:
    asking the solver for more in the coordinates fixed by the contacts makes its steps
    collapse."""
    floor = np.zeros(2 * n)
    if not determined:
        return floor
    rate_noise = gap_noise * np.sqrt(np.where(fast_squared > 0, fast_squared, 1.0))
    inverse = np.abs(np.linalg.pinv(Dg[:, determined]))
    for row, i in enumerate(determined):
        floor[i], floor[n + i] = inverse[row] @ gap_noise, inverse[row] @ rate_noise
    return floor


def _replace(run: Simulation, **changes) -> Simulation:
    from dataclasses import replace

    return replace(run, **changes)


def _place_gaps(z0, n, determined, gap_function, gap_jacobian, targets) -> np.ndarray:
    """Move the determined coordinates so that the gaps equal ``targets`` and their rates vanish."""
    z = np.array(z0, dtype=float)
    if len(determined) != len(targets):
        raise NumericsError("start='slow' needs as many contact-determined coordinates as contacts.")
    for _ in range(50):
        g = np.asarray(gap_function(*z[:n]), dtype=float) - targets
        D = np.asarray(gap_jacobian(*z[:n]), dtype=float).reshape(len(targets), n)
        step = np.linalg.solve(D[:, determined], g)
        z[determined] -= step
        if np.all(np.abs(step) <= 4 * _UNIT * np.maximum(np.abs(z[determined]), np.abs(targets).max(initial=0))):
            break
    D = np.asarray(gap_jacobian(*z[:n]), dtype=float).reshape(len(targets), n)
    free = [i for i in range(n) if i not in determined]
    rhs = -D[:, free] @ z[n:][free] if free else np.zeros(len(targets))
    z[[n + i for i in determined]] = np.linalg.solve(D[:, determined], rhs)
    return z


def simulate_reduced(
    scene,
    values: Mapping | None,
    span,
    initial: Mapping,
    *,
    signs=None,
    method: str = "DOP853",
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    dense_output: bool = True,
    max_rhs: int = 2_000_000,
) -> Simulation:
    """Simulate the comparison system (2.2): the classical rigid-contact motion.

    ``initial`` gives the free coordinates and rates, and any coordinate the contacts
    fix that the accelerations still need (e.g. the rod's angle phi for the guides).
    The reactions output is u* along the motion.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0}
    >>> run = simulate_reduced(cs.scene("painleve-klein-rod"), values, (0, 1), {"x_1": 0, "xdot_1": 1})
    >>> round(run.at(1.0, "xdot_1"), 6)
    1.390085
    """
    span = _check_span(span, "span")
    vals = numeric_values(scene, values)
    positions, rates = _coordinates(scene)
    state = positions + rates
    given = _state_values([str(s) for s in state], state, initial, f"reduced system of '{scene.name}'")
    frozen_given = {s: v for s, v in given.items()}
    with_state = _with(vals, frozen_given)
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in vals.numbers:
            with_state = _with(with_state, {parameter: _evaluate(expr, with_state, f"the parameter {parameter}")})
    free = _free_coordinates(scene)
    free_state = [q for q, _ in free] + [r for _, r in free]
    missing = [str(s) for s in free_state if s not in given]
    if missing:
        raise NumericsError(f"give the initial values of {missing} for the reduced system.")
    fixed_values = {s: v for s, v in given.items() if s not in free_state}
    system = reduced_system(
        scene,
        _Values(dict(with_state.numbers), vals.functions),
        signs=signs,
        state={**fixed_values, **{s: given[s] for s in free_state}},
    )
    z0 = np.array([given[s] for s in free_state], dtype=float)
    if atol is None:
        duration = span[1] - span[0]
        rhs = np.abs(system.fun(span[0], z0))
        m = len(free)
        scale = np.abs(z0).copy()
        scale[:m] = np.maximum(scale[:m], np.maximum(np.abs(z0[m:]) * duration, rhs[m:] * duration**2 / 2))
        scale[m:] = np.maximum(scale[m:], rhs[m:] * duration)
        top = float(scale.max(initial=0.0))
        atol = rtol * np.maximum(scale, 1e-12 * top if top > 0 else 1.0)
    return integrate(
        system, span, z0, method=method, rtol=rtol, atol=atol, t_eval=t_eval, dense_output=dense_output, max_rhs=max_rhs
    )


def _fast_scales(scene, system: OdeSystem, z_ref, N_scale: float, form: str) -> np.ndarray:
    k = scene.k
    J = system.jac(0.0, np.asarray(z_ref, dtype=float))
    scale = np.empty(2 * k)
    for j in range(k):
        if form == "uv":
            phi, a = abs(J[j, k + j]), abs(J[k + j, j])
            scale[j] = N_scale
            scale[k + j] = N_scale * math.sqrt(a / phi) if phi > 0 and a > 0 else N_scale
        else:
            dN = np.asarray(system.extra["law_jac"](0.0, *z_ref), dtype=float).reshape(k, 2 * k)
            phi = abs(dN[j, j])
            a_phi = abs(J[k + j, j])
            scale[j] = N_scale / phi if phi > 0 else N_scale
            scale[k + j] = scale[j] * math.sqrt(a_phi) if a_phi > 0 else scale[j]
    return scale


def _equilibrium_state(scene, system: OdeSystem, form: str, u_star, vals: _Values, laws) -> np.ndarray:
    k = scene.k
    if form == "uv":
        return np.concatenate([np.asarray(u_star, dtype=float), np.zeros(k)])
    Qv = sp.Symbol("Q", real=True)
    Q = []
    for j in range(k):
        N_of_Q = lambdify_cse([Qv], _law_scaled(scene, j, _contact_law(scene, j, laws), vals, Qv, sp.S.Zero))
        Q.append(_invert_law(lambda x, f=N_of_Q: float(f(x)), float(u_star[j]), abs(float(u_star[j])) + 1.0))
    return np.concatenate([Q, np.zeros(k)])


def simulate_fast(
    scene,
    values: Mapping | None,
    span,
    initial=None,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    method: str = "Radau",
    rtol: float = 1e-9,
    atol=None,
    t_eval=None,
    dense_output: bool = True,
    reaction_bound: float | None = None,
    bound_factor: float = 1e6,
    max_rhs: int = 2_000_000,
) -> Simulation:
    """Simulate the fast subsystem (2.1) over ``span`` in the stretched time tau.

    ``initial`` is a sequence in the order of ``fast_system(...).names`` or a mapping by
    name; default: the rigid state, all zero (N = 0). The slow state is frozen at the
    values given for its plain symbols (e.g. ``x``, ``xdot``).

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.785, "mu_1": 3, "mu_2": 0.5, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -1}
    >>> simulate_fast(cs.scene("painleve-klein-rod"), values, (0, 1000)).status
    'impact'
    """
    span = _check_span(span, "span")
    vals = numeric_values(scene, values)
    chosen = _fast_form(scene, unilateral, form)
    system = fast_system(scene, vals, laws=laws, unilateral=unilateral, form=chosen)
    if initial is None:
        z0 = np.zeros(2 * scene.k)
    elif isinstance(initial, Mapping):
        given = _state_values(system.names, list(system.names), initial, "fast subsystem")
        z0 = np.array([given.get(name, 0.0) for name in system.names], dtype=float)
    else:
        z0 = np.asarray([float(_number(v, "initial")) for v in np.ravel(initial)], dtype=float)
    branch = _try_branch(scene, vals, None)
    N_scale = _reaction_scale(scene, vals, branch)
    if atol is None:
        reference = z0
        if branch is not None:
            reference = _equilibrium_state(
                scene, system, chosen, [float(substitute(u, vals)) for u in branch.u_star], vals, laws
            )
        scale = np.maximum(np.abs(z0), _fast_scales(scene, system, reference, N_scale, chosen))
        atol = rtol * scale
    bound = reaction_bound if reaction_bound is not None else bound_factor * N_scale
    run = integrate(
        system,
        span,
        z0,
        method=method,
        rtol=rtol,
        atol=atol,
        t_eval=t_eval,
        dense_output=dense_output,
        max_rhs=max_rhs,
        reaction_bound=bound,
    )
    return _replace(
        run,
        extra={
            **run.extra,
            "reaction_scale": N_scale,
            "reaction_bound": bound,
            "form": chosen,
            "equilibrium": None if branch is None else branch.signs,
        },
    )


# --- certified decisions: floats with an error bound, rationals inside the band ----------


class _Unbounded(Exception):
    pass


def _gamma(n: int) -> float:
    nu = n * _UNIT
    return nu / (1 - nu)


def _exact_float(x: float, value) -> bool:
    try:
        return Fraction(x) == Fraction(value)
    except (TypeError, ValueError):
        return False


def _bounded(expr: sp.Expr, env: dict, memo: dict) -> tuple[float, float, float]:
    """(value, bound on its floating-point error, magnitude) by running error analysis.

    The magnitude is the value the expression would have with every sum replaced by the
    sum of absolute values: the scale against which cancellation is measured.
    """
    if expr in memo:
        return memo[expr]
    result = _bounded_node(expr, env, memo)
    memo[expr] = result
    return result


def _bounded_node(expr, env, memo) -> tuple[float, float, float]:
    if expr.is_Symbol:
        if expr not in env:
            raise NumericsError(f"no value for {expr}; add it to values.")
        v, e = env[expr]
        return v, e, abs(v)
    if expr.is_Integer or expr.is_Rational:
        v = float(expr)
        return v, 0.0 if _exact_float(v, Fraction(int(expr.p), int(expr.q))) else _UNIT * abs(v), abs(v)
    if expr.is_Float:
        v = float(expr)
        return v, 0.0 if expr._prec <= 53 else _UNIT * abs(v), abs(v)
    if expr.is_NumberSymbol:
        v = float(expr)
        return v, _UNIT * abs(v), abs(v)
    if expr.is_Add:
        parts = [_bounded(a, env, memo) for a in expr.args]
        v = math.fsum(p[0] for p in parts)  # correctly rounded sum
        return v, math.fsum(p[1] for p in parts) + _UNIT * abs(v), math.fsum(p[2] for p in parts)
    if expr.is_Mul:
        parts = [_bounded(a, env, memo) for a in expr.args]
        v, exact, widened, magnitude = 1.0, 1.0, 1.0, 1.0
        for value, error, size in parts:
            v *= value
            exact *= abs(value)
            widened *= abs(value) + error
            magnitude *= size
        return v, (widened - exact) * (1 + 4 * _UNIT * len(parts)) + _gamma(len(parts)) * abs(v), magnitude
    if expr.is_Pow:
        base, exponent = expr.args
        b, eb, mb = _bounded(base, env, memo)
        if exponent.is_Integer:
            n = int(exponent)
            v = b**n
            if n >= 0:
                spread = (abs(b) + eb) ** n - abs(b) ** n
                magnitude = mb**n
            else:
                if abs(b) <= eb:
                    raise _Unbounded
                spread = (abs(b) - eb) ** n - abs(b) ** n
                magnitude = abs(v)
            return v, spread * (1 + 8 * _UNIT * abs(n)) + 2 * _gamma(abs(n) + 1) * abs(v), magnitude
        if exponent.is_Rational:
            r = float(exponent)
            if b - eb <= 0:
                raise _Unbounded
            v = b**r
            spread = max(abs((b + eb) ** r - v), abs((b - eb) ** r - v))
            return v, spread * (1 + 8 * _UNIT) + 4 * _UNIT * abs(v), abs(v)
        raise _Unbounded
    if isinstance(expr, (sp.sin, sp.cos)):
        x, ex, _ = _bounded(expr.args[0], env, memo)
        v = math.sin(x) if isinstance(expr, sp.sin) else math.cos(x)
        return v, ex + 2 * _UNIT * abs(v) + _UNIT * 1e-3, abs(v)
    if isinstance(expr, sp.exp):
        x, ex, _ = _bounded(expr.args[0], env, memo)
        v = math.exp(x)
        return v, (math.exp(x + ex) - v) * (1 + 8 * _UNIT) + 2 * _UNIT * v, v
    if isinstance(expr, sp.log):
        x, ex, _ = _bounded(expr.args[0], env, memo)
        if x - ex <= 0:
            raise _Unbounded
        v = math.log(x)
        return v, (v - math.log(x - ex)) * (1 + 8 * _UNIT) + 2 * _UNIT * abs(v), abs(v)
    if isinstance(expr, sp.Abs):
        x, ex, mx = _bounded(expr.args[0], env, memo)
        return abs(x), ex, mx
    if isinstance(expr, sp.sign):
        x, ex, _ = _bounded(expr.args[0], env, memo)
        if abs(x) <= ex:
            raise _Unbounded
        return math.copysign(1.0, x) if x else 0.0, 0.0, 1.0
    raise _Unbounded


def _environment(values: Mapping) -> tuple[dict, dict]:
    """Float environment (value, input error) and exact rational substitution."""
    env, exact = {}, {}
    for symbol, value in values.items():
        number = _number(value, str(symbol))
        v = float(number)
        if number.is_Float:
            rational = sp.Rational(number) if number._prec <= 53 else sp.Rational(str(number))
            exact[symbol] = sp.Rational(v) if number._prec <= 53 else rational
            env[symbol] = (v, 0.0 if number._prec <= 53 else _UNIT * abs(v))
        else:
            exact[symbol] = number
            env[symbol] = (
                v,
                0.0
                if number.is_Rational and _exact_float(v, Fraction(int(number.p), int(number.q)))
                else _UNIT * abs(v),
            )
    return env, exact


def _exact_sign(expr: sp.Expr) -> int:
    """The sign of a closed numeric expression, exactly."""
    from sympy.core.evalf import PrecisionExhausted

    if expr.is_Rational:
        return int(sp.sign(expr))
    if expr.free_symbols:
        raise NumericsError(
            f"cannot decide the sign of {expr}: values are missing for {sorted(map(str, expr.free_symbols))}."
        )
    found = interval_sign(expr)  # proven by outward rounding; evalf's strict mode gives up on deep cancellation
    if found is not None:
        return found
    for precision in (30, 100, 300):
        try:
            value = expr.evalf(precision, strict=True)
        except PrecisionExhausted:
            value = sp.S.Zero
        if value != 0 and value.is_Number:
            return 1 if value > 0 else -1
        if expr.equals(0):
            return 0
    raise NumericsError(f"cannot decide the sign of {expr} exactly (it agrees with 0 to 300 digits).")


def certified_sign(expr, values: Mapping | None = None, *, band: float = 0.0) -> tuple[int, bool]:
    """The sign of ``expr`` at ``values``: (sign, whether the exact rational path was used).

    The expression is evaluated in floating point with a rigorous running error bound;
    when the value is not clearly outside ``max(band * magnitude, 2 * error bound)`` it
    is recomputed exactly, with the float inputs converted to the rationals they
    represent. The magnitude is the expression's value with every sum replaced by the
    sum of the absolute values of its terms, so ``band`` is relative to the size of the
    terms that cancel at a boundary.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> certified_sign(x - y, {x: 0.1, y: 0.2})
    (-1, False)
    >>> certified_sign(x*x - 2*x*y + y*y, {x: 0.1, y: 0.1})
    (0, True)
    >>> certified_sign((x + y)**2 - x**2 - 2*x*y - y**2 - 1e-30, {x: 1e8, y: 1e-8})
    (-1, True)
    """
    expr = sympy_only(expr, "the expression")
    env, exact = _environment(values or {})
    try:
        v, e, magnitude = _bounded(expr, env, {})
        if math.isfinite(v) and math.isfinite(e) and abs(v) > max(2 * e, band * magnitude):
            return (1 if v > 0 else -1), False
    except _Unbounded:
        pass
    except (OverflowError, ZeroDivisionError):
        pass
    floats = {f: sp.Rational(f) for f in expr.atoms(sp.Float)}  # the binary value each Float holds, exactly
    return _exact_sign(expr.xreplace(floats).xreplace(exact)), True


def decide(boolean, values: Mapping | None = None, *, band: float = 0.0) -> bool:
    """Truth of a SymPy Boolean of relationals at numeric values, never by float luck.

    ``boolean`` is a SymPy object; text is refused, never evaluated.

    Examples
    --------
    >>> import sympy as sp
    >>> x = sp.Symbol("x")
    >>> decide(sp.And(x > 0, x**2 < 2), {x: 1.4142135623730951})
    False
    >>> decide(sp.And(x > 0, x**2 < 2), {x: 1.414213562373095})
    True
    """
    boolean = sympy_only(boolean, "the condition")
    if boolean in (sp.true, True):
        return True
    if boolean in (sp.false, False):
        return False
    if isinstance(boolean, sp.And):
        return all(decide(a, values, band=band) for a in boolean.args)
    if isinstance(boolean, sp.Or):
        return any(decide(a, values, band=band) for a in boolean.args)
    if isinstance(boolean, sp.Not):
        return not decide(boolean.args[0], values, band=band)
    if isinstance(boolean, sp.core.relational.Relational):
        s, _ = certified_sign(boolean.lhs - boolean.rhs, values, band=band)
        return {
            sp.StrictGreaterThan: s > 0,
            sp.GreaterThan: s >= 0,
            sp.StrictLessThan: s < 0,
            sp.LessThan: s <= 0,
            sp.Equality: s == 0,
            sp.Unequality: s != 0,
        }[type(boolean)]
    raise NumericsError(f"cannot decide {boolean!r}: expected relationals joined by And, Or, Not.")


@dataclass(frozen=True)
class Classification:
    """The stability of one parameter point.

    Attributes
    ----------
    stable : int
        +1 asymptotically stable (all Hurwitz conditions > 0), -1 some condition < 0,
        0 on the boundary (a condition is exactly 0, none negative).
    signs : tuple of int
        The sign of each Hurwitz condition.
    exact : tuple of bool
        Which conditions needed the exact rational recomputation.
    region : str or None
        ``"robustly stable"``, ``"robustly unstable"``, ``"law-dependent"`` or
        ``"undecided"`` (Propositions 3-8), when the robustness conditions could be decided.
    """

    stable: int
    signs: tuple
    exact: tuple
    region: str | None = None


def classify(scene_or_stability, values: Mapping, *, signs=None, band: float = 1e-12) -> Classification:
    """Classify one parameter point by a scene's stability conditions, certified.

    Each Hurwitz condition is evaluated in floats with an error bound; points within
    ``band`` (relative) of a boundary, or whose sign the bound does not certify, are
    recomputed exactly in rationals.

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> st = cs.scene("brake").stability()
    >>> values = {"alpha": sp.pi/2, "m": 1, "mu": 1, "Phi_1": -2, "Phi_2": -2, "Psi_1": -1, "Psi_2": -1}
    >>> classify(st, values)          # on the Hopf line -m mu^2 Phi = (1 + mu^2) Psi^2
    Classification(stable=0, signs=(1, 1, 1, 1, 0), exact=(False, False, False, False, True), region='law-dependent')
    """
    from ..stability import Stability

    if isinstance(scene_or_stability, Stability):
        st = scene_or_stability
        scene = st.linearization.scene
    else:
        scene = scene_or_stability
        st = scene.stability(signs)
    vals = numeric_values(scene, values)
    numbers = vals.numbers
    results = [certified_sign(substitute(c, _Values({}, vals.functions)), numbers, band=band) for c in st.hurwitz]
    condition_signs = tuple(s for s, _ in results)
    stable = 1 if all(s > 0 for s in condition_signs) else (-1 if any(s < 0 for s in condition_signs) else 0)
    region = None
    try:
        if decide(st.robustly_stable, numbers):
            region = "robustly stable"
        elif decide(st.robustly_unstable, numbers):
            region = "robustly unstable"
        elif st.law_dependent is not None and decide(st.law_dependent, numbers):
            region = "law-dependent"
        else:
            region = "undecided"
    except NumericsError:
        region = None
    return Classification(stable, condition_signs, tuple(x for _, x in results), region)


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
    Those points and the points inside ``max(band, 2 gamma)`` relative are decided
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
        code = [tuple(_through_tan(g) for g in p) for p in self.parts]
        self.gammas = [_gamma(max(_roundings(g) for g in p) + 3) for p in code]
        self._function = lambdify_cse(self.parameters, [g for p in code for g in p])
        self._mp_function = self._mp_functions()

    def _mp_functions(self) -> list:
        return [sp.lambdify(self.parameters, list(p), modules="mpmath") for p in self.parts]

    def __getstate__(self) -> dict:
        # code generated for mpmath holds mpmath's context, which does not pickle (a Dask
        # worker receives the classifier by value): it is generated again when first needed
        return {k: v for k, v in self.__dict__.items() if k != "_mp_function"}

    def __setstate__(self, state: dict) -> None:
        self.__dict__.update(state)
        self._mp_function = None

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
        return [validate.real_array(array, f"the values of {symbol}") for symbol, array in zip(self.parameters, arrays)]

    def _check_values(self, arrays) -> None:
        for symbol, a in zip(self.parameters, arrays):
            if a.size == 0:
                continue
            low, high = a.min(), a.max()  # NaN propagates; +-inf shows in the extremes
            if not (math.isfinite(low) and math.isfinite(high)):
                raise NumericsError(f"the values of {symbol} are not all finite.")
            if symbol.is_positive and not low > 0:
                raise NumericsError(f"{symbol} is declared positive; some values are <= 0.")
            if symbol.is_negative and not high < 0:
                raise NumericsError(f"{symbol} is declared negative; some values are >= 0.")

    def _float_stage(self, arrays, size: int) -> np.ndarray:
        """Per kept factor: its sign where certain (+1/-1) and 0 where not (int8).

        An overflow, underflow or invalid operation would void the relative error bounds:
        a chunk where one occurs is halved until the points that cause it are found, and
        those are left to the exact path.
        """
        try:
            with np.errstate(all="raise"):
                return self._signs(arrays, size)
        except FloatingPointError:
            if size == 1:
                return np.zeros((len(self.kept), 1), dtype=np.int8)
            half = size // 2
            return np.concatenate(
                [
                    self._float_stage([a[:half] for a in arrays], half),
                    self._float_stage([a[half:] for a in arrays], size - half),
                ],
                axis=1,
            )

    def _signs(self, arrays, size: int) -> np.ndarray:
        values = iter(self._function(*arrays))
        out = np.empty((len(self.kept), size), dtype=np.int8)
        for position, part in enumerate(self.parts):
            groups = [_as_array(next(values), size) for _ in part]
            out[position] = _certain_sign(groups, max(self.band, 2 * self.gammas[position]), part)
        return out

    def _high_precision_sign(self, position: int, point: list[float]) -> int | None:
        """Sign of a kept factor in 256-bit arithmetic from the exact binary inputs, or None."""
        import mpmath

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
        self, *arrays, chunk: int = 1 << 15, progress: Progress | None = None, max_seconds: float | None = None
    ) -> _PointsResult:
        """Classify the points; ``progress(fraction, message)`` follows the exact path, which
        ``max_seconds`` bounds (a NumericsError then says how many points were decided)."""
        chunk = validate.chunk_size(chunk)
        budget = Budget(progress, max_seconds)
        arrays = self._check(arrays)
        shape = np.broadcast(*arrays).shape if arrays else ()
        arrays = [np.ascontiguousarray(np.broadcast_to(a, shape)).ravel() for a in arrays]
        size = int(np.prod(shape))
        factor_signs = np.empty((len(self.kept), size), dtype=np.int8)
        signs = np.empty((len(self.conditions), size), dtype=np.int8)
        stable = np.empty(size, dtype=np.int8)
        for start in range(0, size, chunk):  # chunks that stay in the cache
            stop = min(start + chunk, size)
            part = factor_signs[:, start:stop]
            self._check_values([a[start:stop] for a in arrays])
            part[...] = self._float_stage([a[start:stop] for a in arrays], stop - start)
            self._combine(part, signs[:, start:stop], stable[start:stop])
        in_band = np.zeros(size, dtype=bool)
        for position in range(len(self.kept)):
            in_band |= factor_signs[position] == 0
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
            self._combine(factor_signs[:, i : i + 1], signs[:, i : i + 1], stable[i : i + 1])
        budget.report(1.0, f"{size} points, {len(points)} decided exactly")
        bands = [max(self.band, 2 * g) for g in self.gammas]
        return _PointsResult(
            stable.reshape(shape),
            signs.reshape((len(self.conditions), *shape)),
            in_band.reshape(shape),
            len(points),
            max(bands, default=self.band),
        )

    def _combine(self, factor_signs, signs, stable) -> None:
        """Signs of the conditions from those of their factors; stable = the least of them."""
        signs[...] = 1
        for index, sign, position in self.uses:
            signs[index] *= factor_signs[position]
            if sign < 0:
                np.negative(signs[index], out=signs[index])
        signs[self.always_false] = 0
        if len(signs):
            np.min(signs, axis=0, out=stable)
        else:
            stable[...] = 1

    def _exact_factor_sign(self, position: int, point: list[float]) -> int:
        """The exact sign of one kept factor at one point: 256-bit first, then rationals."""
        found = self._high_precision_sign(position, point)
        if found is not None:
            return found
        return certified_sign(self.kept[position], dict(zip(self.parameters, point)), band=0.0)[0]


def _as_array(value, size: int) -> np.ndarray:
    """Generated code returns plain numbers for constant parts (0 for an empty M)."""
    return value if isinstance(value, np.ndarray) else np.full(size, float(value))


def _certain_sign(groups, width: float, part) -> np.ndarray:
    """+1/-1 where the sign of P - M (+ U) is certain, 0 elsewhere (int8 array); valid for
    values computed without overflow, underflow or invalid operations."""
    P, M, *rest = groups
    if rest:  # terms of unknown sign: |F^ - F| <= gamma (P + M + |U|)
        value = P - M + rest[0]
        certain = np.abs(value) > width * (P + M + rest[1])
        return np.where(certain, np.where(value > 0, 1, -1), 0).astype(np.int8)
    if part[1] == 0:  # F = P, nonnegative terms: P^ > 0 iff P > 0
        return (P > 0).view(np.int8)
    if part[0] == 0:
        return -(M > 0).view(np.int8)
    # P - M > width (P + M) iff P (1 - width) > M (1 + width): no cancellation in the test
    positive = (P * (1 - width) > M * (1 + width)).view(np.int8)
    negative = (M * (1 - width) > P * (1 + width)).view(np.int8)
    return positive - negative


def _through_tan(expr: sp.Expr) -> sp.Expr:
    """Even powers of sin and cos written with t = tan: sin^2 = t^2/(1 + t^2), cos^2 = 1/(1 + t^2).

    NumPy vectorises float64 tan (within 4 units in the last place) but not sin and cos,
    which cost several times more; the new sums have terms of one sign, so the relative
    error bound holds.
    """

    def rewrite(node):
        if node.is_Pow and node.exp.is_Integer and node.exp % 2 == 0 and isinstance(node.base, (sp.sin, sp.cos)):
            t2 = sp.tan(node.base.args[0]) ** 2
            square = t2 / (1 + t2) if isinstance(node.base, sp.sin) else 1 / (1 + t2)
            return square ** (node.exp // 2)
        return node

    return sp.bottom_up(expr, rewrite)


def _one_signed_form(total: sp.Expr) -> sp.Expr:
    """A cheap form of ``total``, a sum of terms of one sign, in which every sum still has
    terms of one sign (so floating point keeps a relative error bound): the sum or its
    factored form, with shared powers pulled out of sums."""
    if total.is_Number or len(sp.Add.make_args(total)) < 2:
        return total
    candidates = [_pulled_out(total), sp.Mul(*[_pulled_out(f) for f in sp.Mul.make_args(sp.factor(total))])]
    valid = [c for c in candidates if _one_signed_sums(c)]
    return min(valid, key=sp.count_ops) if valid else total


def _pulled_out(expr: sp.Expr) -> sp.Expr:
    """``expr`` with, recursively, the power shared by most terms pulled out of each sum:
    a + b x + c x y becomes a + x (b + c y), and a + b + x (a + b) becomes (x + 1)(a + b)."""
    if expr.is_Pow and expr.exp.is_Integer:
        return _pulled_out(expr.base) ** expr.exp
    terms = sp.Add.make_args(expr)
    if len(terms) < 2:
        return expr
    counts: dict = {}
    for term in terms:
        for base, exponent in term.as_powers_dict().items():
            if not base.is_Number and exponent.is_Integer and exponent > 0:
                counts.setdefault(base, []).append(int(exponent))
    shared = [(len(e), b) for b, e in counts.items() if len(e) > 1]
    if not shared:
        return expr
    _, base = max(shared, key=lambda item: (item[0], sp.default_sort_key(item[1])))
    power = base ** min(counts[base])
    inside = [t for t in terms if base in t.as_powers_dict()]
    outside = [t for t in terms if base not in t.as_powers_dict()]
    inner, rest = _pulled_out(sp.Add(*[t / power for t in inside])), _pulled_out(sp.Add(*outside))
    return (power + 1) * inner if inner == rest else power * inner + rest


def _one_signed_sums(expr: sp.Expr) -> bool:
    for node in sp.preorder_traversal(expr):
        if node.is_Add and not (all(a.is_nonnegative for a in node.args) or all(a.is_nonpositive for a in node.args)):
            return False
    return True


def _roundings(expr: sp.Expr) -> int:
    """Roundings along the longest path of the evaluation of ``expr`` in floating point:
    its computed value is within gamma_r relative of the exact one when every sum of
    ``expr`` has terms of one sign."""
    if expr.is_Symbol:
        return 0
    if expr.is_Number or expr.is_NumberSymbol:
        if expr.is_Rational and _exact_float(float(expr), Fraction(int(expr.p), int(expr.q))):
            return 0
        return 1
    if expr.is_Add:
        return max(_roundings(a) for a in expr.args) + len(expr.args) - 1
    if expr.is_Mul:  # a product of k factors: k - 1 roundings, none for a power of two
        exact = sum(1 for f in expr.args if f.is_Integer and f != 0 and abs(int(f)).bit_count() == 1)
        return sum(_roundings(f) for f in expr.args) + len(expr.args) - 1 - exact
    if expr.is_Pow:
        base, exponent = expr.args
        if exponent.is_Integer:
            n = abs(int(exponent))
            return n * _roundings(base) + n + (1 if exponent < 0 else 0)
        if exponent.is_Rational:
            return _roundings(base) + 2
    if isinstance(expr, sp.Abs):
        return _roundings(expr.args[0])
    if isinstance(expr, sp.Function) and len(expr.args) == 1:
        if _roundings(expr.args[0]) == 0:
            return 4  # NumPy's elementary functions: at most 4 units in the last place (its SIMD ones)
        raise NumericsError(
            f"cannot bound the rounding of {expr}: its argument is rounded; introduce a parameter for the argument."
        )
    raise NumericsError(f"cannot bound the rounding of {expr}; rewrite it with +, *, powers and functions.")


@dataclass(frozen=True, eq=False)
class _PointsResult:
    """Result of :class:`PointClassifier`: ``stable`` (+1, -1, 0 per point), per-condition
    ``signs``, the mask ``in_band`` of points decided exactly, their number, and the
    relative band half-width used."""

    stable: np.ndarray
    signs: np.ndarray
    in_band: np.ndarray
    exact_points: int
    band: float


# --- cycles of the fast subsystem and the averaged system (2.7) --------------------------


@dataclass(frozen=True, eq=False)
class Cycle:
    """A stable periodic solution of the fast subsystem (Proposition 2).

    Attributes
    ----------
    converged : bool
        True when successive returns to the Poincaré section agreed to ``tol``.
    period, omega : float
        Period and angular frequency in the stretched time tau (omega/eps in t).
    tau, states, reactions : ndarray
        One period, uniformly sampled (``samples`` points, endpoint excluded).
    mean_reactions : ndarray
        The reactions averaged over the period: the reactions of the averaged system (2.7).
    contact_loss : bool
        Some reaction vanishes on part of the cycle (a unilateral contact opens).
    message : str
    """

    converged: bool
    period: float
    omega: float
    tau: np.ndarray
    states: np.ndarray
    reactions: np.ndarray
    mean_reactions: np.ndarray
    names: tuple
    reaction_names: tuple
    contact_loss: bool
    message: str


def _no_cycle(system: OdeSystem, message: str) -> Cycle:
    empty = np.empty((len(system.names), 0))
    return Cycle(
        False,
        math.nan,
        math.nan,
        np.empty(0),
        empty,
        np.empty((len(system.reaction_names), 0)),
        np.full(len(system.reaction_names), math.nan),
        system.names,
        system.reaction_names,
        False,
        message,
    )


def fast_cycle(
    scene,
    values: Mapping | None,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    initial=None,
    periods: int = 3000,
    tol: float = 1e-7,
    rtol: float = 1e-10,
    samples: int = 4096,
    method: str = "DOP853",
) -> Cycle:
    """Find a stable cycle of the fast subsystem by integration to a Poincaré section.

    Starting near the equilibrium (or at ``initial``), the fast subsystem is integrated
    (DOP853 by default: in tau the fast subsystem is not stiff, and a contact that opens
    and closes makes the force discontinuous, which implicit methods pass only with tiny
    steps) until successive upward crossings of ``v_1 = 0`` (``V_1 = 0``) agree to ``tol``
    (relative to the typical magnitudes); the last period is then sampled and the
    reactions averaged over it.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> equilibrium_reactions(cs.scene("brake"), values)
    [((1, 1), [1.0000000000000002, 3.0])]
    >>> cycle = fast_cycle(cs.scene("brake"), values, samples=512, tol=1e-6)
    >>> cycle.converged, cycle.contact_loss, round(cycle.period, 3)
    (True, True, 4.901)
    """
    vals = numeric_values(scene, values)
    chosen = _fast_form(scene, unilateral, form)
    system = fast_system(scene, vals, laws=laws, unilateral=unilateral, form=chosen)
    k = scene.k
    branch = _try_branch(scene, vals, None)
    N_scale = _reaction_scale(scene, vals, branch)
    if branch is None:
        return _no_cycle(system, "no consistent equilibrium: an impact-type catastrophe, not a cycle.")
    u_star = [float(substitute(u, vals)) for u in branch.u_star]
    z_eq = _equilibrium_state(scene, system, chosen, u_star, vals, laws)
    scale = _fast_scales(scene, system, z_eq, N_scale, chosen)
    eigenvalues = np.linalg.eigvals(system.jac(0.0, z_eq))
    omega0 = float(np.max(np.abs(eigenvalues.imag)))
    if omega0 == 0:
        return _no_cycle(system, "the linearization has no oscillatory mode; no cycle is born here.")
    T0 = 2 * math.pi / omega0
    if initial is None:
        z = z_eq.copy()
        z[0] += 1e-2 * scale[0]
    else:
        z = np.asarray(initial, dtype=float)

    def section(t, y):
        return y[k]

    section.direction = 1
    atol = rtol * scale
    hits: list[np.ndarray] = []
    times: list[float] = []
    elapsed = 0.0
    while elapsed < periods * T0:
        block = 50 * T0
        run = integrate(
            system,
            (elapsed, elapsed + block),
            z,
            method=method,
            rtol=rtol,
            atol=atol,
            reaction_bound=1e6 * N_scale,
            events=[section],
        )
        if run.status == "impact":
            return _no_cycle(system, "the fast motion escapes: " + run.message)
        if run.status != "ok":
            return _no_cycle(system, run.message)
        for t_hit, y_hit in zip(run.extra["t_events"][0], run.extra["y_events"][0]):
            times.append(float(t_hit))
            hits.append(np.asarray(y_hit))
        z = run.y[:, -1]
        elapsed += block
        if len(hits) >= 3:
            change = np.max(np.abs(hits[-1] - hits[-2]) / scale)
            if np.max(np.abs(hits[-1] - z_eq) / scale) < tol:
                return _no_cycle(system, "the fast motion settles on the equilibrium: it is stable, no cycle.")
            if change < tol and abs((times[-1] - times[-2]) - (times[-2] - times[-3])) < 1e2 * tol * T0:
                break
    else:
        return _no_cycle(system, f"no convergence to a cycle within {periods} linear periods.")
    period = times[-1] - times[-2]
    final = integrate(
        system, (0.0, 1.25 * period), hits[-1], method=method, rtol=rtol, atol=atol, dense_output=True, events=[section]
    )
    crossings = [t for t in final.extra["t_events"][0] if t > 0.5 * period]
    if crossings:
        period = float(crossings[0])
    tau = np.linspace(0.0, period, samples, endpoint=False)
    states = final.sol(tau)
    reactions = np.column_stack([system.reactions(ti, states[:, i]) for i, ti in enumerate(tau)])
    loss = bool(np.any(np.abs(reactions) <= 1e-12 * N_scale))
    return Cycle(
        True,
        period,
        2 * math.pi / period,
        tau,
        states,
        reactions,
        reactions.mean(axis=1),
        system.names,
        system.reaction_names,
        loss,
        f"cycle of period {period:.6g} in tau",
    )


def simulate_averaged(
    scene,
    values: Mapping | None,
    span,
    initial: Mapping,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    method: str = "DOP853",
    rtol: float = 1e-8,
    atol=None,
    t_eval=None,
    cycle_options: Mapping | None = None,
) -> Simulation:
    """Simulate the averaged system (2.7): slow motion driven by cycle-averaged forces.

    Where the fast subsystem has a stable cycle (Proposition 2), the slow coordinates
    follow their accelerations averaged over the cycle at the frozen slow state,
    ``<G(x, N(tau))>``, not G at the averaged reactions. When the fast subsystem does
    not depend on the slow state (the brake), the cycle is computed once. The output
    reactions are the cycle means.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4, "J": 1, "r": 1,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> run = simulate_averaged(cs.scene("brake"), values, (0, 1), {"theta": 0, "thetadot": -5},
    ...                         cycle_options={"samples": 512, "tol": 1e-6})
    >>> run.names, run.status
    (('theta', 'thetadot'), 'ok')
    """
    span = _check_span(span, "span")
    vals = numeric_values(scene, values)
    free = _free_coordinates(scene)
    positions, rates = [q for q, _ in free], [r for _, r in free]
    free_state = positions + rates
    positions_all, rates_all = _coordinates(scene)
    state_all = positions_all + rates_all
    given = _state_values([str(s) for s in state_all], state_all, initial, f"averaged system of '{scene.name}'")
    missing = [str(s) for s in free_state if s not in given]
    if missing:
        raise NumericsError(f"give the initial values of {missing} for the averaged system.")
    fixed_state = {s: v for s, v in given.items() if s not in free_state}
    base = _with(vals, fixed_state)
    for parameter, expr in _manifold_parameters(scene).items():
        if parameter not in base.numbers:
            base = _with(base, {parameter: _evaluate(expr, base, f"the parameter {parameter}")})
    by_plain = {scene._plain(q): q for q in scene.coordinates}
    G = [substitute(scene.freeze(scene.accelerations[by_plain[q]]), base) for q in positions]
    reactions = list(scene.reactions)
    _check_free(G, set(free_state) | set(reactions) | {_time}, "the averaged system")
    G_function = lambdify_cse([_time, *free_state, *reactions], G)
    fast_f = [substitute(f, base) for f in scene.fast_subsystem().f]
    depends = any(f.free_symbols & set(free_state) for f in fast_f)
    options = dict(cycle_options or {})
    cache: dict = {}

    def cycle_at(y) -> Cycle:
        key = tuple(np.round(y, 12)) if depends else ()
        if key not in cache:
            frozen = _with(base, dict(zip(free_state, y))) if depends else base
            found = fast_cycle(scene, frozen, laws=laws, unilateral=unilateral, form=form, **options)
            if not found.converged:
                raise NumericsError(
                    f"no stable cycle of the fast subsystem at the slow state {list(y)}: {found.message}"
                )
            cache[key] = found
        return cache[key]

    m = len(positions)

    def averaged(t, y):
        cycle = cycle_at(y)
        values_G = G_function(t, *y, *cycle.reactions)
        mean = [float(np.mean(np.broadcast_to(np.asarray(g, dtype=float), cycle.tau.shape))) for g in values_G]
        return np.concatenate([y[m:], mean])

    def reactions_out(t, y):
        return cycle_at(y).mean_reactions

    z0 = np.array([given[s] for s in free_state], dtype=float)
    system = OdeSystem(
        tuple(str(s) for s in free_state),
        averaged,
        lambda t, y: None,
        reactions_out,
        tuple(str(r) for r in reactions),
        "t",
        f"averaged system (2.7) of '{scene.name}'",
    )
    run = integrate(
        system, span, z0, method=method, jacobian=False, rtol=rtol, atol=atol, t_eval=t_eval, dense_output=True
    )
    return _replace(run, extra={**run.extra, "cycle": cache.get(()) if not depends else None})


# --- trajectories of the fast subsystem (drawn by contactsym.plotting) --------------------


def fast_trajectories_data(
    scene,
    values: Mapping | None,
    *,
    laws: Mapping | None = None,
    unilateral=None,
    form: str | None = None,
    starts=None,
    span=(0.0, 30.0),
    grid: int = 21,
) -> dict:
    """Simulated trajectories of the fast subsystem (2.1) and its vector field.

    Draw them with :func:`contactsym.plotting.fast_trajectories_plot`.

    For one contact the plane is (u, v) (or (Q, V)) with the vector field on a
    ``grid x grid`` mesh; for more contacts the trajectories are drawn in the plane of
    the first two reactions. The consistent equilibria are included.

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0,
    ...           "Phi": -1, "Psi": -0.3}
    >>> data = fast_trajectories_data(cs.scene("painleve-klein-rod"), values, grid=5)
    >>> data["labels"], len(data["trajectories"]), data["field"][0].shape
    (('u', 'v'), 6, (5, 5))
    """
    vals = numeric_values(scene, values)
    chosen = _fast_form(scene, unilateral, form)
    system = fast_system(scene, vals, laws=laws, unilateral=unilateral, form=chosen)
    k = scene.k
    branch = _try_branch(scene, vals, None)
    N_scale = _reaction_scale(scene, vals, branch)
    equilibria = []
    for _signs, u_star in equilibrium_reactions(scene, vals):
        equilibria.append(_equilibrium_state(scene, system, chosen, u_star, vals, laws))
    centre = equilibria[0] if equilibria else np.zeros(2 * k)
    scale = _fast_scales(scene, system, centre, N_scale, chosen)
    if starts is None:
        angles = np.linspace(0, 2 * np.pi, 6, endpoint=False)
        starts = []
        for a in angles:
            z = centre.copy()
            z[0] += 1.5 * scale[0] * np.cos(a)
            z[k] += 1.5 * scale[k] * np.sin(a)
            starts.append(z)
    trajectories, impacts = [], []
    samples = np.linspace(span[0], span[1], 600)
    for z0 in starts:
        run = simulate_fast(
            scene,
            vals,
            span,
            np.asarray(z0, dtype=float),
            laws=laws,
            unilateral=unilateral,
            form=chosen,
            t_eval=samples,
            reaction_bound=50 * N_scale,
            dense_output=False,
        )
        if k == 1:
            trajectories.append(run.y[[0, 1]])
        else:
            trajectories.append(run.reactions[[0, 1]])
        impacts.append(run.status == "impact")
    field_data = None
    if k == 1:
        xs = np.linspace(centre[0] - 2 * scale[0], centre[0] + 2 * scale[0], grid)
        ys = np.linspace(centre[1] - 2 * scale[1], centre[1] + 2 * scale[1], grid)
        X, Y = np.meshgrid(xs, ys)
        U, V = np.empty_like(X), np.empty_like(X)
        for index in np.ndindex(X.shape):
            d = system.fun(0.0, np.array([X[index], Y[index]]))
            U[index], V[index] = d
        field_data = (X, Y, U, V)
        labels = (system.names[0], system.names[1])
        points = [(e[0], e[1]) for e in equilibria]
    else:
        labels = system.reaction_names[:2]
        points = [tuple(system.reactions(0.0, e)[:2]) for e in equilibria]
    return {
        "labels": labels,
        "trajectories": trajectories,
        "impact": impacts,
        "field": field_data,
        "equilibria": points,
        "title": system.description,
    }


# --- the Hopf bifurcation of the fast subsystem (contactsym.hopf) -------------------------


def first_lyapunov(scene, values: Mapping, **options):
    """l1 of the fast subsystem at a point on its Hopf set; see :func:`contactsym.hopf.first_lyapunov`."""
    from ..hopf import first_lyapunov as compute

    return compute(scene, values, **options)


def hopf_point(scene, values: Mapping, parameter, **options):
    """The Hopf crossing along ``parameter`` and l1 there; see :func:`contactsym.hopf.hopf_point`."""
    from ..hopf import hopf_point as compute

    return compute(scene, values, parameter, **options)
