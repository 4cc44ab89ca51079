"""ODE assembly: generated first- and second-order systems, and the full compliant system (1.9).

Each contact's reaction comes from its compliance law, which the law itself writes
(:meth:`contactsym.laws.Compliance.reaction`), at the contact's gap and its rate.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import numpy as np
import sympy as sp
from scipy.optimize import brentq  # already loaded by scipy.integrate

from ..arguments import checked
from ..errors import NumericsError
from ..laws import Compliance
from ..mechanism.scene import t as _time
from .codegen import _cached, lambdify_cse
from .values import NumericValues, _check_free, _plain_expr, _positive, numeric_values, substitute


@checked
@dataclass(frozen=True, eq=False)
class OdeSystem:
    """A generated first-order system ``z' = fun(t, z)`` with its Jacobian and reactions.

    Attributes
    ----------
    names : tuple of str
        State components.
    fun, jac : callable
        ``fun(t, z)`` and its Jacobian ``jac(t, z)`` (analytic), at one state ``z`` (a 1-D array, as
        ``solve_ivp`` passes it): generated code for one point (:func:`lambdify_cse` with ``point=True``).
    reactions : callable
        ``reactions(t, z)``: the normal reactions N_j (u_j for the fast subsystem).
    reaction_names : tuple of str
    time : str
        ``"t"`` (original time) or ``"tau"`` (stretched time t/eps).
    description : str

    Examples
    --------
    The brake's fast subsystem; its analytic Jacobian agrees with central differences of ``fun``:

    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym.numerics import fast_system
    >>> ode = fast_system(cs.scene("brake"), {"m": 1, "mu": 1, "alpha": 1.5, "F_x": 0, "F_y": -2,
    ...     "Phi_1": -1, "Phi_2": -1, "Psi_1": -1, "Psi_2": -1})
    >>> isinstance(ode, OdeSystem), ode.names, ode.time
    (True, ('Q_1', 'Q_2', 'V_1', 'V_2'), 'tau')
    >>> z, h = np.array([-1.0, -2.0, 0.3, -0.2]), 1e-6
    >>> differences = np.column_stack([(ode.fun(0, z + h*e) - ode.fun(0, z - h*e)) / (2*h) for e in np.eye(4)])
    >>> bool(np.allclose(ode.jac(0, z), differences, atol=1e-6))
    True
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
    law_value = lambdify_cse(args, [*laws, *gaps], point=True)
    law_jac = lambdify_cse(args, law_matrix.jacobian(z), point=True)
    G = sp.Matrix(accelerations)
    acc_value = lambdify_cse(args + N, list(G), point=True)
    acc_jac = lambdify_cse(args + N, [G.jacobian(z), G.jacobian(N)], point=True)
    clamp = tuple(bool(c) for c in clamp)
    any_clamp = any(clamp)
    zero = np.float64(0.0)

    def reaction_list(t, y) -> list:
        """The N_j at one state, NumPy floats in a list. The solver calls this a few times per step with
        k of them: NumPy's operations on arrays that small cost several times the arithmetic, so the
        clamp is plain comparisons (a NaN reaction of a clamped contact is 0, as with ``np.where``)."""
        out = np.asarray(law_value(t, *y), dtype=float)
        if not any_clamp:
            return list(out[:k])
        return [r if not c or (g <= 0 and r >= 0) else zero for c, r, g in zip(clamp, out[:k], out[k:])]

    def reactions_and_active(t, y):
        out = np.asarray(law_value(t, *y), dtype=float)
        raw, g = out[:k], out[k:]
        if not any_clamp:
            return raw, None
        active = ~np.array(clamp) | ((g <= 0) & (raw >= 0))
        return np.where(active, raw, 0.0), active

    def fun(t, y):
        out = np.empty(2 * n)
        out[:n] = y[n:]
        out[n:] = acc_value(t, *y, *reaction_list(t, y))
        return out

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
        return np.array(reaction_list(t, y))

    extra = {"law_value": law_value, "law_jac": law_jac, "acc_value": acc_value, "acc_jac": acc_jac, "n": n, "k": k}
    return OdeSystem(tuple(names), fun, jac, reactions, tuple(str(s) for s in N), time, description, extra)


def _first_order(time_symbol, state, rhs, reaction_exprs, *, names, reaction_names, time, description) -> OdeSystem:
    args = [time_symbol, *state]
    rhs = sp.Matrix(rhs)
    value = lambdify_cse(args, list(rhs), point=True)
    jacobian = lambdify_cse(args, rhs.jacobian(list(state)), point=True)
    reaction_value = lambdify_cse(args, list(reaction_exprs), point=True)
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
    positions = [scene.plain(q) for q in scene.coordinates]
    rates = [scene.plain(sp.diff(q, _time)) for q in scene.coordinates]
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


def _index(scene, j: int) -> int | None:
    """How the symbols of contact j are numbered: none for a scene's only contact."""
    return None if scene.k == 1 else j + 1


def _require_coefficients(scene, j: int, law: Compliance, vals: NumericValues) -> None:
    """A law that leaves Phi, Psi free (a generic law) needs numbers for them before a simulation."""
    needed = law.coefficients(_index(scene, j))
    if all(symbol in vals.numbers for symbol in needed):
        return
    Phi, Psi = needed
    reaction = scene.contacts[j].reaction
    raise NumericsError(
        f"contact {j + 1} ({reaction}) has a generic compliance law; give numeric values for {Phi} and {Psi} "
        f"(both < 0; the law is then N = {Phi} q/eps**2 + {Psi} q'/eps), or pass laws={{{j}: cs.KelvinVoigt(k, d)}}."
    )


def _law_in_gap(scene, j, law: Compliance, vals: NumericValues, eps: float, g: sp.Expr, gd: sp.Expr) -> sp.Expr:
    """N_j at deformation g and rate gd, at the numeric eps (original time)."""
    _require_coefficients(scene, j, law, vals)
    return substitute(_reaction(law, "reaction", g, gd, sp.Float(eps), _index(scene, j)), vals)


def _law_scaled(scene, j, law: Compliance, vals: NumericValues, Q: sp.Symbol, V: sp.Symbol) -> sp.Expr:
    """N_j(Q, V) in the scaled deformation Q = q/eps**2 and rate V = q'/eps (1.8)."""
    _require_coefficients(scene, j, law, vals)
    return substitute(_reaction(law, "reaction_scaled", Q, V, _index(scene, j)), vals)


def _reaction(law: Compliance, method: str, *arguments) -> sp.Expr:
    try:
        return getattr(law, method)(*arguments)
    except NotImplementedError:  # a user's Compliance subclass that does not say its reaction
        raise NumericsError(f"unsupported compliance law {law!r}; use Generic, KelvinVoigt or Law.") from None


def _clamps(scene, unilateral) -> list[bool]:
    if unilateral is None:
        return [bool(c.unilateral) for c in scene.contacts]
    return [bool(unilateral)] * scene.k


def _manifold_parameters(scene) -> dict:
    """Parameters that the contact manifold fixes (e.g. h = l sin(phi)), with their expressions."""
    positions, rates = _coordinates(scene)
    state = set(positions) | set(rates)
    return {key: value for key, value in scene.manifold.items() if key not in state}


@checked(scene="Scene", unilateral="bool | None")
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


def _build_full(scene, vals: NumericValues, eps: float, laws, unilateral) -> OdeSystem:
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


def _invert_law(N_of_Q: Callable[[float], float], target: float, scale: float) -> float:
    """Q with N(Q, 0) = target (N decreasing in Q, (1.5)), by bracketing and brentq."""

    def residual(Q):
        return N_of_Q(Q) - target

    width = max(scale, 1e-300)
    for _ in range(200):
        if residual(-width) * residual(width) <= 0:
            return float(brentq(residual, -width, width, xtol=1e-300, rtol=1e-15))
        width *= 4
    raise NumericsError(f"cannot invert the compliance law for the deformation at N = {target:g}.")
