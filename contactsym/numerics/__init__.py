"""Numerics: generated code, simulations of the full, reduced, fast and averaged systems,
and certified classification of parameter points.

Every symbolic claim of contactsym deserves a numerical witness. This package turns the
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

The modules, each one job, from the bottom up:

- :mod:`~contactsym.numerics.values`: parameter values, checked, and their substitution;
- :mod:`~contactsym.numerics.codegen`: generated NumPy code, cached per scene;
- :mod:`~contactsym.numerics.systems`: ODE assembly, and the full system (1.9);
- :mod:`~contactsym.numerics.certified`: certified signs, :func:`decide`, :func:`classify`;
- :mod:`~contactsym.numerics.integration`: :func:`integrate` and the :class:`Simulation` result;
- :mod:`~contactsym.numerics.reduced`: equilibrium branches and the reduced system (2.2);
- :mod:`~contactsym.numerics.fastsystem`: the fast subsystem (2.1), generated and simulated; :class:`FastProblem`;
- :mod:`~contactsym.numerics.simulate`: the full system (1.9) simulated;
- :mod:`~contactsym.numerics.cycles`: cycles of (2.1) and the averaged system (2.7);
- :mod:`~contactsym.numerics.trajectories`: trajectories of (2.1) for a phase portrait;
- :mod:`~contactsym.numerics.classifier`: :class:`PointClassifier`, many points at once.

The Hopf bifurcation of the fast subsystem is :mod:`contactsym.numerics.hopf`, which builds on
these modules; :func:`first_lyapunov_at` and :func:`hopf_point` are its functions.

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

from ..errors import NumericsError
from .certified import Classification, certified_sign, classify, decide
from .classifier import PointClassifier
from .codegen import NumericFunction, lambdify_cse, lambdify_stage
from .cycles import Cycle, fast_cycle, simulate_averaged
from .fastsystem import FastProblem, fast_system, simulate_fast
from .hopf import first_lyapunov as first_lyapunov  # the name of 0.1, deprecated
from .hopf import first_lyapunov_at, hopf_point
from .integration import Simulation, integrate
from .reduced import equilibrium_reactions, reduced_system, simulate_reduced
from .simulate import simulate_full
from .systems import OdeSystem, full_system
from .trajectories import fast_trajectories_data
from .values import NumericValues, numeric_values, substitute

__all__ = [
    "NumericsError",
    "NumericValues",
    "numeric_values",
    "substitute",
    "lambdify_cse",
    "lambdify_stage",
    "NumericFunction",
    "OdeSystem",
    "Simulation",
    "full_system",
    "reduced_system",
    "FastProblem",
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
    "first_lyapunov_at",
    "hopf_point",
]
