"""The fast subsystem (2.1) as generated code, in (u, v) or in the scaled deformations (Q, V), and simulated.

:class:`FastProblem` is a point's numeric fast subsystem, set up once (values, form, generated
system, equilibrium branch, reaction scale) for :func:`simulate_fast`,
:func:`~contactsym.numerics.fast_trajectories_data`, :func:`~contactsym.numerics.fast_cycle` and
:mod:`contactsym.numerics.hopf`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
import sympy as sp

from ..arguments import checked
from ..errors import NumericsError
from ..laws import ImplicitDeformation
from ..validate import shorten
from .codegen import _cached, lambdify_cse
from .integration import Simulation, integrate_with_impact_bound
from .reduced import _branch_at, _reaction_scale, _try_branch, _why_no_branch
from .systems import (
    OdeSystem,
    _clamps,
    _contact_law,
    _first_order,
    _index,
    _invert_law,
    _law_scaled,
    _laws_key,
    _require_coefficients,
    _second_order,
)
from .values import NumericValues, _check_free, _check_span, _number, _state_values, numeric_values, substitute

_TAU = sp.Symbol("tau", real=True)  # the stretched time t/eps


def _fast_form(scene, unilateral, form) -> str:
    if form is not None:
        if form not in ("uv", "deformation"):
            raise NumericsError(f"form = {shorten(form)}; use 'uv' (the paper's (2.1)) or 'deformation' (Q, V).")
        return form
    implicit = any(x.atoms(ImplicitDeformation) for x in scene.fast_subsystem().Phi + scene.fast_subsystem().Psi)
    return "deformation" if implicit or any(_clamps(scene, unilateral)) else "uv"


@checked(scene="Scene", unilateral="bool | None")
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


def _build_fast(scene, vals: NumericValues, laws, unilateral, form: str) -> OdeSystem:
    fast = scene.fast_subsystem()
    f = [substitute(fj, vals) for fj in fast.f]
    description = f"fast subsystem (2.1) of '{scene.name}' ({form} form)"
    if form == "uv":
        return _build_fast_uv(scene, vals, laws, f, description)
    return _build_fast_deformation(scene, vals, laws, unilateral, f, description)


def _build_fast_uv(scene, vals: NumericValues, laws, f: list, description: str) -> OdeSystem:
    """(2.1) as printed: u' = Phi v + Psi f(u), v' = f(u), with each law's Phi, Psi."""
    fast = scene.fast_subsystem()
    Phi, Psi = [], []
    for j in range(scene.k):
        law = _contact_law(scene, j, laws)
        _require_coefficients(scene, j, law, vals)
        phi, psi = law.phi_psi(fast.u[j], fast.v[j], _index(scene, j))
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
        _TAU,
        [*fast.u, *fast.v],
        rhs,
        list(fast.u),
        names=names,
        reaction_names=names[: scene.k],
        time="tau",
        description=description,
    )


def _build_fast_deformation(scene, vals: NumericValues, laws, unilateral, f: list, description: str) -> OdeSystem:
    """The same system in the scaled deformations: Q' = V, V' = f(N(Q, V)), N = 0 where a contact opens."""
    fast = scene.fast_subsystem()
    suffix = [""] if scene.k == 1 else [f"_{j}" for j in range(1, scene.k + 1)]
    Q = [sp.Symbol(f"Q{s}", real=True) for s in suffix]
    V = [sp.Symbol(f"V{s}", real=True) for s in suffix]
    laws_QV = [_law_scaled(scene, j, _contact_law(scene, j, laws), vals, Q[j], V[j]) for j in range(scene.k)]
    accelerations = [fj.xreplace(dict(zip(fast.u, scene.reactions))) for fj in f]
    _check_free(accelerations, set(scene.reactions), f"the fast subsystem of '{scene.name}'")
    _check_free(laws_QV, set(Q) | set(V), f"the compliance laws of '{scene.name}'")
    names = [str(s) for s in Q + V]
    system = _second_order(
        _TAU,
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
    # the reactions are those of the contacts, named by the fast variables u_j they stand for
    reaction_names = tuple(str(u) for u in fast.u)
    return replace(system, reaction_names=reaction_names)


@checked
@dataclass(frozen=True, eq=False)
class FastProblem:
    """A point's numeric fast subsystem (2.1): the values, the form, the generated system, the
    equilibrium branch and the reaction scale, each computed once (and only when asked for).

    Build it with :meth:`at`. ``signs`` chooses the equilibrium branch; by default the unique
    branch consistent at the values (``branch`` is None when there is none or several).

    Examples
    --------
    >>> import contactsym as cs
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4,
    ...           "Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}
    >>> problem = FastProblem.at(cs.scene("brake"), values)
    >>> problem.form, problem.branch.signs, problem.u_star, problem.reaction_scale
    ('deformation', (1, 1), [1.0000000000000002, 3.0], 3.0)
    >>> problem.system.names
    ('Q_1', 'Q_2', 'V_1', 'V_2')
    """

    scene: object
    values: NumericValues
    laws: Mapping | None = None
    unilateral: object = None
    requested_form: str | None = None
    signs: tuple | None = None

    @classmethod
    def at(
        cls,
        scene,
        values: Mapping | None,
        *,
        laws: Mapping | None = None,
        unilateral=None,
        form: str | None = None,
        signs=None,
    ) -> FastProblem:
        """The fast subsystem of ``scene`` at ``values`` (checked with :func:`numeric_values`)."""
        return cls(scene, numeric_values(scene, values), laws, unilateral, form, signs)

    @cached_property
    def form(self) -> str:
        """'uv' (the paper's (2.1)) or 'deformation' (Q, V): as requested, else as the laws need."""
        return _fast_form(self.scene, self.unilateral, self.requested_form)

    @cached_property
    def system(self) -> OdeSystem:
        """The generated system in the stretched time tau (:func:`fast_system`)."""
        return fast_system(self.scene, self.values, laws=self.laws, unilateral=self.unilateral, form=self.form)

    @cached_property
    def branch(self):
        """The equilibrium branch used at the values, or None."""
        return _try_branch(self.scene, self.values, self.signs)

    def why_no_branch(self) -> str:
        """Why :attr:`branch` is None: several equilibria, contacts lifting off, or none at all."""
        return _why_no_branch(self.scene, self.values)

    def require_branch(self):
        """The equilibrium branch, or a NumericsError saying why there is none to use."""
        return self.branch if self.branch is not None else _branch_at(self.scene, self.values, self.signs)

    @cached_property
    def reaction_scale(self) -> float:
        """A typical magnitude of the reactions: |u*|, or |f_j(0) / a_jj| without an equilibrium."""
        return _reaction_scale(self.scene, self.values, self.branch)

    @cached_property
    def u_star(self) -> list[float] | None:
        """The equilibrium reactions of :attr:`branch` at the values, or None."""
        if self.branch is None:
            return None
        return [float(substitute(u, self.values)) for u in self.branch.u_star]

    def state_at(self, u_star) -> np.ndarray:
        """The state of :attr:`system` at rest with the reactions ``u_star``: (u*, 0), or (Q*, 0)."""
        k = self.scene.k
        if self.form == "uv":
            return np.concatenate([np.asarray(u_star, dtype=float), np.zeros(k)])
        Qv = sp.Symbol("Q", real=True)
        Q = []
        for j in range(k):
            law = _contact_law(self.scene, j, self.laws)
            N_of_Q = lambdify_cse([Qv], _law_scaled(self.scene, j, law, self.values, Qv, sp.S.Zero))
            Q.append(_invert_law(lambda x, f=N_of_Q: float(f(x)), float(u_star[j]), abs(float(u_star[j])) + 1.0))
        return np.concatenate([Q, np.zeros(k)])

    def scales(self, reference) -> np.ndarray:
        """Typical magnitudes of the state components near the state ``reference``, from the reaction
        scale and the linearization there (deformations N/|dN/dQ|, rates times the fast frequency)."""
        k, system, N_scale = self.scene.k, self.system, self.reaction_scale
        J = system.jac(0.0, np.asarray(reference, dtype=float))
        scale = np.empty(2 * k)
        for j in range(k):
            if self.form == "uv":
                phi, a = abs(J[j, k + j]), abs(J[k + j, j])
                scale[j] = N_scale
                scale[k + j] = N_scale * math.sqrt(a / phi) if phi > 0 and a > 0 else N_scale
            else:
                dN = np.asarray(system.extra["law_jac"](0.0, *reference), dtype=float).reshape(k, 2 * k)
                phi = abs(dN[j, j])
                a_phi = abs(J[k + j, j])
                scale[j] = N_scale / phi if phi > 0 else N_scale
                scale[k + j] = scale[j] * math.sqrt(a_phi) if a_phi > 0 else scale[j]
        return scale


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
    # long by its keyword options and docstring
    span = _check_span(span, "span")
    problem = FastProblem.at(scene, values, laws=laws, unilateral=unilateral, form=form)
    system = problem.system
    if initial is None:
        z0 = np.zeros(2 * scene.k)
    elif isinstance(initial, Mapping):
        given = _state_values(system.names, list(system.names), initial, "fast subsystem")
        z0 = np.array([given.get(name, 0.0) for name in system.names], dtype=float)
    else:
        z0 = np.asarray([float(_number(v, "initial")) for v in np.ravel(initial)], dtype=float)
        if z0.size != len(system.names):
            raise NumericsError(
                f"initial has {z0.size} values; the fast subsystem's state is {list(system.names)} "
                f"({len(system.names)} values, in this order), or give a mapping by name."
            )
    if atol is None:
        reference = z0 if problem.u_star is None else problem.state_at(problem.u_star)
        atol = rtol * np.maximum(np.abs(z0), problem.scales(reference))
    return integrate_with_impact_bound(
        system,
        span,
        z0,
        reaction_scale=problem.reaction_scale,
        reaction_bound=reaction_bound,
        bound_factor=bound_factor,
        equilibrium=None if problem.branch is None else problem.branch.signs,
        extra={"form": problem.form},
        method=method,
        rtol=rtol,
        atol=atol,
        t_eval=t_eval,
        dense_output=dense_output,
        max_rhs=max_rhs,
    )
