"""The Hopf bifurcation of the fast subsystem (2.1) at numeric parameter values.

(2.1) is only piecewise smooth (Abs/sign of the switching functions), but near an
equilibrium whose u* lies off the switching surfaces it is smooth: the sign pattern of
the equilibrium fixes the piece. l1 is computed on that piece, in the scaled
deformations ``Q_j = q_j/eps**2`` and their rates ``V_j = q_j'/eps``,

    Q_j' = V_j,    V_j' = f_j(N_1(Q_1, V_1), ..., N_k(Q_k, V_k)),

which is (2.1) in other coordinates (``u_j = N_j(Q_j, V_j)``, ``v_j = V_j``): it needs no
inverse of the law. The sign of l1 does not depend on the coordinates, and neither does
the predicted cycle, whose reaction amplitudes are reported. l1 itself is given in the
normalization ``<q, q> = 1`` of the state (Q, V) (see :mod:`contactsym.lyapunov.coefficient`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..arguments import checked
from ..deprecation import deprecated_alias
from ..errors import ComplianceError, HopfError, NumericsError
from ..lyapunov.coefficient import HopfVectors, first_lyapunov_from_derivatives
from ..validate import shorten
from .codegen import _cached, lambdify_cse
from .fastsystem import FastProblem
from .systems import _contact_law, _index, _laws_key
from .values import NumericValues, numeric_values, substitute

__all__ = ["HopfCoefficient", "first_lyapunov_at", "full_cycle_start", "hopf_point"]


@checked(nan=True)
@dataclass(frozen=True, eq=False)
class HopfCoefficient:
    """l1 of the fast subsystem at a Hopf point, and the cycle it predicts.

    Attributes
    ----------
    l1 : float
        The first Lyapunov coefficient, normalization ``<q, q> = <p, q> = 1`` in (Q, V).
    omega : float
        The frequency of the critical pair in tau (``omega/eps`` in t).
    direction : str
        'supercritical' (l1 < 0: soft onset of a stable cycle), 'subcritical' (l1 > 0:
        a jump to a large cycle, hysteresis) or 'degenerate' (l1 = 0 to rounding).
    u_star : ndarray
        The equilibrium reactions.
    reaction_vector : ndarray
        ``dN_j . q``, the reactions' part of the critical eigenvector; ``2 |dN_j . q|`` are the
        reaction amplitudes per unit radius |z| of the normal form.
    vectors : HopfVectors
        l1, c1, q and p in the state (Q_1..Q_k, V_1..V_k).
    state : ndarray
        The equilibrium (Q*, 0).
    parameter, value, dalpha : optional
        The bifurcation parameter, its value on the line and d Re(lambda)/d parameter there
        (from :func:`hopf_point`).
    """

    l1: float
    omega: float
    direction: str
    u_star: np.ndarray
    reaction_vector: np.ndarray
    vectors: HopfVectors
    state: np.ndarray
    parameter: object = None
    value: float | None = None
    dalpha: float | None = None

    def amplitude(self, value: float) -> np.ndarray | None:
        """Predicted reaction amplitudes (half peak-to-peak) of the small cycle at ``parameter = value``.

        To leading order ``2 |q_N| sqrt(-alpha / Re c1)`` with ``alpha = dalpha (value - value*)``:
        proportional to ``sqrt(distance / |l1|)``. The same in tau and in t. None on the side
        of the line where no small cycle exists (stable side for l1 < 0, unstable for l1 > 0).
        """
        if self.dalpha is None:
            raise HopfError("amplitude(value) needs the bifurcation parameter: compute the point with hopf_point().")
        radius = self.vectors.radius(self.dalpha * (value - self.value))
        return None if radius is None else 2 * radius * np.abs(self.reaction_vector)

    def cycle_start(self, value: float, factor: float = 1.0) -> np.ndarray | None:
        """A state on the predicted cycle at ``parameter = value`` (radius times ``factor``)."""
        radius = self.vectors.radius(self.dalpha * (value - self.value))
        return None if radius is None else self.state + 2 * factor * radius * self.vectors.q.real

    def in_time(self, eps: float) -> dict:
        """The cycle's frequency and period in tau and in the physical time t = eps tau."""
        return {
            "omega_tau": self.omega,
            "period_tau": 2 * math.pi / self.omega,
            "omega_t": self.omega / eps,
            "period_t": 2 * math.pi * eps / self.omega,
        }


def _field(scene, signs: tuple, laws, functions: dict) -> dict:
    """The (Q, V) field of one piece and its derivative tensors as generated code (cached)."""

    def build():
        k = scene.k
        fast = scene.fast_subsystem()
        Q = [sp.Symbol(f"Q_{j + 1}", real=True) for j in range(k)]
        V = [sp.Symbol(f"V_{j + 1}", real=True) for j in range(k)]
        z = Q + V
        only_functions = NumericValues({}, functions)
        law = [_contact_law(scene, j, laws) for j in range(k)]
        N = [substitute(law[j].smooth_scaled(Q[j], V[j], _index(scene, j)), only_functions) for j in range(k)]
        # N_j cut to 0 outside the law's domain, for the inversion at the equilibrium
        N_cut = [substitute(law[j].reaction_scaled(Q[j], V[j], _index(scene, j)), only_functions) for j in range(k)]
        f = [substitute(e, only_functions).xreplace(dict(zip(fast.u, N))) for e in fast.piece(signs)]
        F = sp.Matrix(V + f)
        params = sorted(F.free_symbols - set(z), key=str)
        n = 2 * k
        J = F.jacobian(z)
        H = [[[J[i, j].diff(z[m]) for m in range(n)] for j in range(n)] for i in range(n)]
        T = [[[[H[i][j][m].diff(z[l]) for l in range(n)] for m in range(n)] for j in range(n)] for i in range(n)]
        dN = [[sp.diff(N[j], x) for x in z] for j in range(k)]
        args = z + params
        return {
            "params": params,
            "tensors": lambdify_cse(args, [J.tolist(), H, T, dN]),
            "N_rest": [lambdify_cse([Q[j], *params], N_cut[j].subs(V[j], 0), point=True) for j in range(k)],
            "N_QV": [
                lambdify_cse([Q[j], *params], [N[j].diff(x).subs(V[j], 0) for x in (Q[j], V[j])]) for j in range(k)
            ],
            "k": k,
        }

    return _cached(scene, ("hopf-field", signs, _laws_key(laws), frozenset(functions.items())), build)


def _parameter_values(data: dict, vals: NumericValues) -> list[float]:
    missing = [str(p) for p in data["params"] if p not in vals.numbers]
    if missing:
        raise NumericsError(f"l1 needs numeric values for {missing}.")
    return [float(vals.numbers[p]) for p in data["params"]]


def _invert_on_branch(data: dict, j: int, target: float, params: list[float]) -> float:
    """Q with N_j(Q, 0) = target on the monotone branch through Q = 0, walking out from 0.

    Raises ComplianceError naming the interval of N that branch covers when the law stops
    decreasing (or leaves its domain) before it reaches the target."""
    from scipy.optimize import brentq

    def N(x):
        return float(data["N_rest"][j](x, *params))

    direction = -1.0 if target > N(0.0) else 1.0
    step, here, value = 1e-3 * (abs(target) + 1.0), 0.0, N(0.0)
    for _ in range(400):
        there = here + direction * step
        new = N(there)
        if (target - value) * (target - new) <= 0:
            return float(brentq(lambda x: N(x) - target, min(here, there), max(here, there), xtol=1e-15, rtol=1e-15))

        def slope(x):
            return float(data["N_QV"][j](x, *params)[0])

        if not (slope(there) < 0 and (new - value) * direction < 0):
            if slope(there) >= 0 > slope(here):  # the exact turning point: the end of the monotone branch
                here = brentq(slope, min(here, there), max(here, there), xtol=1e-14)
                value = N(here)
            low, high = sorted((N(0.0), value))
            raise ComplianceError(
                f"contact {j + 1}: the law is not monotone where it is used: along Q = q/eps^2 from 0 it stops "
                f"decreasing at Q = {here:.4g}, so it covers only N in [{low:.4g}, {high:.4g}] there, and the "
                f"equilibrium needs N = {target:.4g}; (1.5) fails. Choose loads inside that interval or a law "
                "monotone up to that load."
            )
        here, value, step = there, new, step * 1.5
    raise ComplianceError(f"contact {j + 1}: the law does not reach N = {target:g}; it is bounded.")


def _check_damping(data: dict, j: int, Q_star: float, u_star: float, params: list[float]) -> None:
    N_V = float(data["N_QV"][j](Q_star, *params)[1])
    if not N_V < 0:
        raise ComplianceError(
            f"contact {j + 1}: eps dN/dq' = {N_V:g} >= 0 at the equilibrium N = {u_star:g}; (1.5) needs damping."
        )


def _at_point(problem: FastProblem):
    """(u*, J, H, T, dN, (Q*, 0)) of the smooth piece of the equilibrium's branch at the problem's point."""
    branch = problem.require_branch()
    data = _field(problem.scene, tuple(branch.signs), problem.laws, problem.values.functions)
    params = _parameter_values(data, problem.values)
    u_star = np.array(problem.u_star)
    Q_star = []
    for j in range(problem.scene.k):
        Q_j = _invert_on_branch(data, j, u_star[j], params)
        _check_damping(data, j, Q_j, u_star[j], params)
        Q_star.append(Q_j)
    z = [*Q_star, *([0.0] * problem.scene.k)]
    J, H, T, dN = (np.asarray(x, dtype=float) for x in data["tensors"](*z, *params))
    return u_star, J, H, T, dN, np.array(z)


@checked(scene="Scene")
def first_lyapunov_at(
    scene, values: Mapping, *, laws: Mapping | None = None, signs=None, tol: float = 1e-6
) -> HopfCoefficient:
    """l1 of the fast subsystem at a numeric point on its Hopf set, with the cycle it predicts.

    The numeric variant of the first Lyapunov coefficient (the symbolic one is
    :attr:`Stability.first_lyapunov`; see :mod:`contactsym.lyapunov`); ``first_lyapunov`` is its
    deprecated name.

    Raises HopfError off the Hopf set, saying how far (``Re lambda / omega``), and
    ComplianceError when a law is not monotone at the equilibrium.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> values = {"m": 1, "mu": 1.2, "alpha": 1.5707963267948966, "F_x": 0, "F_y": -4}
    >>> first_lyapunov_at(cs.scene("brake"), values, laws={0: Hertz(), 1: Hertz()})
    Traceback (most recent call last):
    ...
    contactsym.errors.HopfError: the point is off the Hopf set: the critical eigenvalues are 0.033063 +- 2.08966 i, so Re(lambda)/omega = 0.0158 (tolerance 1e-06); l1 is defined where Re(lambda) = 0: move the point onto the line (e.g. with contactsym.numerics.hopf_point).
    """
    u_star, J, H, T, dN, z = _at_point(FastProblem.at(scene, values, laws=laws, signs=signs))
    vectors = first_lyapunov_from_derivatives(J, H, T, tol=tol)
    return _coefficient(vectors, u_star, dN, state=z)


# the name of 0.1, kept: it warns
first_lyapunov = deprecated_alias(first_lyapunov_at, "first_lyapunov")


def _coefficient(vectors: HopfVectors, u_star, dN, state, **extra) -> HopfCoefficient:
    scale = np.max(np.abs(vectors.c1)) if vectors.c1 else 0.0
    degenerate = abs(vectors.c1.real) <= 1e-10 * max(scale, vectors.omega * np.max(np.abs(vectors.q)) ** 2)
    direction = "degenerate" if degenerate else ("supercritical" if vectors.l1 < 0 else "subcritical")
    return HopfCoefficient(vectors.l1, vectors.omega, direction, u_star, dN @ vectors.q, vectors, state, **extra)


@checked(scene="Scene", parameter="sp.Symbol | str", signs="Sequence[int] | None")
def hopf_point(
    scene,
    values: Mapping,
    parameter,
    *,
    laws: Mapping | None = None,
    signs=None,
    bracket: tuple[float, float] | None = None,
) -> HopfCoefficient:
    """Move ``parameter`` from its value in ``values`` onto the Hopf set and compute l1 there.

    The crossing is found by root finding of ``alpha(p) = Re lambda`` of the critical
    pair (in ``bracket``, or widening around the given value); ``dalpha`` is its slope.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 0, "F_y": -4}
    >>> h = hopf_point(cs.scene("brake"), values, "mu", laws={0: Hertz(), 1: Hertz()})
    >>> h.direction, round(h.value, 6)
    ('supercritical', 1.074858)
    """
    from scipy.optimize import brentq

    vals = numeric_values(scene, values)
    key = next((p for p in vals.numbers if p == parameter or str(p) == str(parameter)), None)
    if key is None:
        known = sorted(str(p) for p in scene.parameters)
        if str(parameter) not in known:
            raise NumericsError(f"{shorten(parameter)} is not a parameter of '{scene.name}'; its parameters: {known}.")
        raise NumericsError(f"give a starting value for the parameter {shorten(parameter)} in values.")
    start = float(vals.numbers[key])

    def alpha(p):
        point = NumericValues({**vals.numbers, key: sp.Float(p)}, vals.functions)
        J = _at_point(FastProblem(scene, point, laws, signs=signs))[1]
        eigenvalues = np.linalg.eigvals(J)
        complex_pairs = eigenvalues[eigenvalues.imag > 1e-12]
        if complex_pairs.size == 0:
            raise HopfError(f"at {key} = {p:g} the fast subsystem has no oscillatory pair.")
        return float(complex_pairs.real.max())

    bracket = _widen(alpha, start) if bracket is None else _bracket(alpha, bracket, key)
    p_star = brentq(alpha, *bracket, xtol=1e-15 * max(abs(start), 1.0), rtol=1e-15)
    h = 1e-6 * max(abs(p_star), 1e-8)
    slope = (alpha(p_star + h) - alpha(p_star - h)) / (2 * h)
    point = NumericValues({**vals.numbers, key: sp.Float(p_star)}, vals.functions)
    u_star, J, H, T, dN, z = _at_point(FastProblem(scene, point, laws, signs=signs))
    vectors = first_lyapunov_from_derivatives(J, H, T, tol=1e-6)
    return _coefficient(vectors, u_star, dN, state=z, parameter=key, value=p_star, dalpha=slope)


def _bracket(alpha, bracket, key) -> tuple[float, float]:
    """A given bracket, checked: two finite numbers, low < high, Re lambda of the critical pair changing sign."""
    try:
        low, high = (float(b) for b in bracket)
    except (TypeError, ValueError):
        raise NumericsError(f"bracket = {shorten(bracket)}; give two numbers (low, high).") from None
    if not (np.isfinite(low) and np.isfinite(high) and low < high):
        raise NumericsError(f"bracket = {shorten(bracket)}; give two finite numbers with low < high.")
    at_low, at_high = alpha(low), alpha(high)
    if at_low * at_high > 0:
        raise HopfError(
            f"Re lambda of the critical pair is {at_low:.3g} at {key} = {low:g} and {at_high:.3g} at {key} = {high:g}: "
            "the same sign, so no Hopf crossing is bracketed; widen the bracket or leave it out (the start value "
            "is widened around)."
        )
    return low, high


def _widen(alpha, start: float) -> tuple[float, float]:
    a0 = alpha(start)
    for width in (1e-3, 1e-2, 0.1, 0.3, 0.6, 0.9):
        for other in (start * (1 + width), start * (1 - width)):
            try:
                if alpha(other) * a0 <= 0:
                    return (min(start, other), max(start, other))
            except (HopfError, NumericsError, ComplianceError):
                continue
    raise HopfError(
        f"Re lambda of the critical pair keeps the sign of {a0:.3g} within 90% of the start value: no Hopf "
        "crossing nearby; give bracket=(low, high)."
    )


@checked(scene="Scene", base="Mapping | None")
def full_cycle_start(
    scene, hopf: HopfCoefficient, values: Mapping, eps: float, value: float, *, factor: float = 1.0, base=None
) -> dict:
    """Initial coordinates and rates of the full system (1.9) on the predicted cycle at ``parameter = value``.

    The fast state (Q, V) of :meth:`HopfCoefficient.cycle_start` becomes gaps ``g_j = eps**2 Q_j``
    and gap rates ``g_j' = eps V_j`` (the scaling (1.8)); the coordinates move from ``base``
    (names to numbers, default 0, on the contact manifold) by the smallest change that gives
    those gaps (Newton steps with the pseudo-inverse of the gaps' Jacobian), the rates likewise.
    The result is a mapping by name for :func:`contactsym.numerics.simulate_full`.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 0, "F_y": -4}
    >>> brake, laws = cs.scene("brake"), {0: Hertz(), 1: Hertz()}
    >>> h = hopf_point(brake, values, "mu", laws=laws)
    >>> start = full_cycle_start(brake, h, values, 1e-3, 1.01 * h.value, base={"thetadot": -1})
    >>> Q_1, Q_2, V_1, V_2 = h.cycle_start(1.01 * h.value)  # here g_1 = y and g_2 = -x
    >>> [round(abs(float(x)), 9) for x in (start["y"] / 1e-6 - Q_1, start["x"] / 1e-6 + Q_2, start["ydot"] / 1e-3 - V_1)]
    [0.0, 0.0, 0.0]
    >>> start["thetadot"]
    -1.0
    """
    fast = hopf.cycle_start(value, factor)
    if fast is None:
        raise HopfError(f"no small cycle at {hopf.parameter} = {value:g}: it lives on the other side of the line.")
    k = scene.k
    Q, V = fast[:k], fast[k:]
    numbers = numeric_values(scene, values).numbers
    coordinates = list(scene.coordinates)
    names = [q.func.__name__ for q in coordinates]
    plain = [sp.Symbol(f"_{name}", real=True) for name in names]
    gaps = sp.Matrix([c.coordinate.subs(dict(zip(coordinates, plain))) for c in scene.contacts]).xreplace(numbers)
    gap_value = sp.lambdify(plain, list(gaps))
    gap_jacobian = sp.lambdify(plain, gaps.jacobian(plain))
    base = dict(base or {})
    position = np.array([float(base.get(name, 0.0)) for name in names])
    target = eps**2 * np.asarray(Q, dtype=float)
    for _ in range(20):  # Newton's method towards the gaps eps^2 Q (one step for linear gaps)
        residual = np.asarray(gap_value(*position), dtype=float) - target
        if np.max(np.abs(residual)) <= 1e-13 * max(np.max(np.abs(target)), 1e-300):
            break
        position -= np.linalg.pinv(np.asarray(gap_jacobian(*position), dtype=float)) @ residual
    rate = np.array([float(base.get(f"{name}dot", 0.0)) for name in names])
    Dg = np.asarray(gap_jacobian(*position), dtype=float)
    rate += np.linalg.pinv(Dg) @ (eps * np.asarray(V, dtype=float) - Dg @ rate)
    return {
        **{name: float(x) for name, x in zip(names, position)},
        **{f"{n}dot": float(r) for n, r in zip(names, rate)},
    }
