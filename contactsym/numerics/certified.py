"""Certified decisions: signs in floating point with a rigorous error bound, exact rationals inside the band.

:func:`certified_sign`, :func:`decide` and :func:`classify` never trust a float's luck:
a value closer to zero than its running error bound (or than ``band``) is recomputed
exactly, with the float inputs taken as the rationals they represent.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from fractions import Fraction

import sympy as sp
from sympy.core.evalf import PrecisionExhausted

from ..algebra.intervals import interval_sign
from ..algebra.reductions import SignSymbol
from ..arguments import checked
from ..errors import NumericsError
from ..parse import sympy_only
from ..stages.stability import Stability
from .values import _UNIT, NumericValues, _number, numeric_values, substitute


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
        return _bounded_pow(expr, env, memo)
    return _bounded_function(expr, env, memo)


def _bounded_pow(expr, env, memo) -> tuple[float, float, float]:
    """Integer and rational powers: the error of the base widens through the power."""
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


def _bounded_function(expr, env, memo) -> tuple[float, float, float]:
    """Elementary functions of one argument, with the error of the argument carried through."""
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


@checked(expr="sp.Expr")
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


@checked(boolean="sp.Basic")
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


@checked(nan=True)
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

    Examples
    --------
    The brake at mu = 1/2 with a damping law: every Hurwitz condition is positive, so it is stable:

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> st = cs.scene("brake").stability()
    >>> c = classify(st, {"alpha": sp.pi/2, "m": 1, "mu": 0.5, "Phi_1": -2, "Phi_2": -2, "Psi_1": -1, "Psi_2": -1})
    >>> isinstance(c, Classification), c.stable, all(s == 1 for s in c.signs), c.region
    (True, 1, True, 'law-dependent')
    """

    stable: int
    signs: tuple
    exact: tuple
    region: str | None = None


@checked(scene_or_stability="Scene | Stability")
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
    if isinstance(scene_or_stability, Stability):
        st = scene_or_stability
        scene = st.linearization.scene
        if signs is not None:
            raise NumericsError(
                "signs= chooses the pattern of a scene; a Stability has its own: pass scene.stability(signs) "
                "or classify(scene, values, signs=signs)."
            )
    else:
        scene = scene_or_stability
        st = scene.stability(signs)
    vals = numeric_values(scene, values)
    numbers = vals.numbers
    _inside_the_domain(scene, numbers)
    pattern = sorted((s for s in st.linearization.A.free_symbols if isinstance(s, SignSymbol)), key=str)
    if pattern:
        raise NumericsError(
            f"this stability is symbolic in the sign pattern {[str(s) for s in pattern]}; choose one: "
            f"classify(scene, values, signs=(1, ...)) or classify(scene.stability(signs), values)."
        )
    results = [certified_sign(substitute(c, NumericValues({}, vals.functions)), numbers, band=band) for c in st.hurwitz]
    condition_signs = tuple(s for s, _ in results)
    stable = 1 if all(s > 0 for s in condition_signs) else (-1 if any(s < 0 for s in condition_signs) else 0)
    region = None
    try:
        # None: neither proved nor disproved at a numeric A (three-valued), so it proves nothing here
        if st.robustly_stable is not None and decide(st.robustly_stable, numbers):
            region = "robustly stable"
        elif st.robustly_unstable is not None and decide(st.robustly_unstable, numbers):
            region = "robustly unstable"
        elif st.law_dependent is not None and decide(st.law_dependent, numbers):
            region = "law-dependent"
        else:
            region = _decided_at_the_point(st, vals)
    except NumericsError:
        region = None
    return Classification(stable, condition_signs, tuple(x for _, x in results), region)


def _decided_at_the_point(st: Stability, vals: NumericValues) -> str:
    """The region at a point where the symbolic regions prove nothing (k >= 3): the point decision of
    :func:`contactsym.robustness.classify.decide_robustness` on A at the point (a certificate or two
    exact witness laws), as ``scene.with_values(...).stability()`` would give; else 'undecided'."""
    if st.k < 3:
        return "undecided"
    A = substitute(st.linearization.A, vals)
    if A.free_symbols:
        return "undecided"
    from ..robustness.classify import decide_robustness  # scipy.optimize: imported for k >= 3 only

    verdict = decide_robustness(A).verdict
    return {"stable": "robustly stable", "unstable": "robustly unstable"}.get(verdict, verdict)


def _inside_the_domain(scene, numbers: Mapping) -> None:
    """Refuse a point outside the scene's declared domain (its positive expressions, e.g. cos(theta) > 0
    for 0 < theta < pi/2): the regions are derived and printed for that domain (divided by such
    expressions, say), so a verdict outside it would contradict them. An expression whose symbols are
    not all given is not checked here."""
    for expr in scene.declared_positive:
        if not expr.free_symbols <= set(numbers):
            continue
        sign, _ = certified_sign(expr, numbers)
        if sign <= 0:
            given = ", ".join(f"{s} = {float(numbers[s]):.6g}" for s in sorted(expr.free_symbols, key=str))
            raise NumericsError(
                f"{given} lies outside the domain of '{scene.name}': it declares {expr} > 0 (its intervals or "
                "positive=), and its conditions are derived and stated for that domain; choose values inside it."
            )
