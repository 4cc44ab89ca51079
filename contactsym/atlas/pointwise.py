"""Quantities measured point by point: simulations (a fast cycle, a run to the catastrophe) and
the user's own functions. Dask's scheduler spreads the points over processes or a cluster.

The scene travels with its derivation already done (fast subsystem, equilibria); a point
costs its integration, plus substituting the point's numbers into the derived system and
generating its code (1.7 % of a brake cycle, 98.3 % is the integration, measured with cProfile).
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from .. import numerics
from ..errors import ComplianceError, HopfError
from ..numerics.normal_form import NormalForm, normal_form
from .grid import AtlasError, Grid
from .kernel import Kernel, setup_for

__all__ = ["PointFailure", "SQUEAL_METHODS", "build_catastrophe", "build_cycle", "build_function", "build_squeal"]


class PointFailure(Exception):
    """A quantity has no value at a point (no cycle found, a failed integration)."""


class _PerPoint(Kernel):
    def __init__(self, scene, grid: Grid, values, options: dict):
        self.scene, self.names, self.values, self.options = scene, grid.names, dict(values or {}), options

    def at(self, row) -> dict:
        return {**self.values, **{name: float(x) for name, x in zip(self.names, row)}}

    def evaluate(self, points):
        return np.array([self.point(self.at(row)) for row in points], dtype=float)


class _Cycle(_PerPoint):
    outputs = ("amplitude", "omega")

    def point(self, values):
        found = numerics.fast_cycle(self.scene, values, **self.options)
        if not found.converged:
            raise PointFailure(found.message)
        return [float(np.max(np.ptp(found.reactions, axis=1)) / 2), found.omega]


def _prepared(scene, grid, values):
    setup_for(scene, grid, values)  # names and values checked before any work
    scene.fast_subsystem(), scene.equilibria()  # derived once, here; the workers get them with the scene
    return scene


def build_cycle(scene, grid, values, **options):
    return _Cycle(_prepared(scene, grid, values), grid, values, options)


class _Catastrophe(_PerPoint):
    outputs = ("time_to_catastrophe",)

    def point(self, values):
        run = numerics.simulate_full(self.scene, values, *self.options["args"], **self.options["keywords"])
        if run.status == "impact":
            return [float(run.t[-1])]
        if run.status == "ok":
            return [np.inf]  # none within the span
        raise PointFailure(run.message)


def build_catastrophe(scene, grid, values, eps=None, span=None, initial=None, **options):
    if eps is None or span is None or initial is None:
        raise AtlasError("the catastrophe quantity needs eps, span and initial: catastrophe(eps, span, initial).")
    return _Catastrophe(
        _prepared(scene, grid, values), grid, values, {"args": (eps, span, initial), "keywords": options}
    )


class _Function(_PerPoint):
    def __init__(self, grid, values, fn, outputs):
        super().__init__(None, grid, values, {})
        self.fn, self.outputs = fn, tuple(outputs)

    def point(self, values):
        result = self.fn({str(k): v for k, v in values.items()})
        if isinstance(result, Mapping):
            return [float(result[name]) for name in self.outputs]
        return [float(x) for x in np.atleast_1d(result)]


def build_function(scene, grid, values, fn=None, outputs=None):
    return _Function(grid, values, fn, outputs)


#: The ``method`` codes of the squeal quantity.
SQUEAL_METHODS = {
    0: "no cycle: the equilibrium is stable here (omega: the linear frequency of the decay)",
    1: "Hopf normal form (l1 and the crossing speed at the line)",
    2: "simulation to a Poincaré section (numerics.fast_cycle)",
}


class _Squeal(Kernel):
    """The squeal's amplitude and frequency: the normal form near the Hopf line, a simulation farther out.

    Points are grouped by their values other than ``parameter``: one Hopf point per group
    (cached), then the normal form at every value of the parameter in one array operation.
    """

    outputs = ("amplitude", "omega", "method", "error", "contact_loss")

    def __init__(self, scene, grid: Grid, values, parameter: str, laws, tol: float, simulate: bool, options: dict):
        self.scene, self.names, self.values = scene, grid.names, dict(values or {})
        self.parameter, self.laws, self.tol, self.simulate, self.options = parameter, laws, tol, simulate, options
        self.forms: dict = {}

    def _form(self, key, values):
        """The normal form of one grid line, warm-started from the last line's crossing (cached)."""
        if key in self.forms:
            return self.forms[key]
        known = [f.hopf.value for f in self.forms.values() if isinstance(f, NormalForm)]
        brackets = [(0.98 * known[-1], 1.02 * known[-1]), None] if known else [None]
        found = None
        for bracket in brackets:  # the neighbouring line's crossing first, then a search from the point
            try:
                found = normal_form(self.scene, values, self.parameter, laws=self.laws, bracket=bracket)
                break
            except (numerics.NumericsError, HopfError, ComplianceError, ValueError) as error:
                found = error  # ValueError: no sign change in the bracket
        self.forms[key] = found
        return found

    def __call__(self, points: np.ndarray) -> tuple[np.ndarray, list[str]]:
        n = len(points)
        out = np.full((n, len(self.outputs)), np.nan)
        reasons = [""] * n
        rows = [{**self.values, **{name: float(x) for name, x in zip(self.names, row)}} for row in points]
        groups: dict = {}
        for i, row in enumerate(rows):
            key = tuple(sorted((str(k), v) for k, v in row.items() if str(k) != self.parameter))
            groups.setdefault(key, []).append(i)
        for key, index in groups.items():
            form = self._form(key, rows[index[0]])
            if isinstance(form, Exception):
                for i in index:
                    self._simulated(rows[i], out, reasons, i, f"no Hopf point nearby ({_first_line(form)})")
                continue
            with np.errstate(all="ignore"):
                self._from_form(form, index, rows, out, reasons)
        return out, reasons

    def _from_form(self, form, index, rows, out, reasons) -> None:
        p = np.array([float(rows[i][self.parameter]) for i in index])
        r2, amplitude = form.radius_squared(p), form.amplitude(p)
        lost = np.any(amplitude >= form.hopf.u_star, axis=-1)  # a reaction would reach 0: the pads lose contact
        error, omega = form.error(p), form.omega(p)
        unstable = form.hopf.dalpha * (p - form.hopf.value) > 0
        for position, i in enumerate(index):
            if not unstable[position]:  # the equilibrium is stable (for l1 > 0 a large cycle may coexist)
                out[i] = [0.0, omega[position], 0, 0.0, 0]
            elif form.stable() and r2[position] > 0 and error[position] <= self.tol and not lost[position]:
                out[i] = [np.max(amplitude[position]), omega[position], 1, error[position], 0]
            else:
                why = (
                    "contact loss" if lost[position] else ("subcritical" if not form.stable() else "far from the line")
                )
                self._simulated(rows[i], out, reasons, i, why)

    def _simulated(self, values, out, reasons, i, why: str) -> None:
        if not self.simulate:
            reasons[i] = f"{why}; the normal form does not apply and simulate=False"
            return
        try:
            found = numerics.fast_cycle(self.scene, values, laws=self.laws, **self.options)
        except Exception as error:  # noqa: BLE001 - a failing point is NaN with its reason, never a crash
            reasons[i] = f"{why}; simulation failed: {type(error).__name__}: {_first_line(error)}"
            return
        if not found.converged or found.reactions.size == 0:
            reasons[i] = f"{why}; simulation: {found.message}"[:300]
            return
        amplitude = float(np.max(np.ptp(found.reactions, axis=1)) / 2)
        out[i] = [amplitude, found.omega, 2, self.options.get("tol", 1e-7), float(found.contact_loss)]


def _first_line(error: BaseException) -> str:
    return (str(error).strip().splitlines() or [""])[0][:200]


def build_squeal(scene, grid, values, parameter=None, laws=None, tol=0.002, simulate=True, **options):
    if parameter is None:
        raise AtlasError("the squeal quantity needs the bifurcation parameter: squeal(parameter='mu').")
    if not 0 < float(tol) < 1:
        raise AtlasError(f"tol = {tol!r} must be a relative error in (0, 1).")
    return _Squeal(_prepared(scene, grid, values), grid, values, str(parameter), laws, float(tol), simulate, options)
