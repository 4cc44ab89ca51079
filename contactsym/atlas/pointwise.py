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
from ..numerics.branches import squeal_lines
from ..numerics.continuation import fast_field
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
    3: "continuation of the cycle by shooting (numerics.continuation), from the neighbouring point's cycle",
}


class _Squeal(Kernel):
    """The squeal's amplitude and frequency: the normal form near the Hopf line, continued cycles farther out.

    Points are grouped into lines by their values other than ``parameter``: one Hopf point per line
    (cached), then :func:`contactsym.numerics.branches.squeal_lines` for all supercritical lines of the
    chunk together; a simulation only where neither applies (no Hopf point, subcritical, contact loss).
    """

    outputs = ("amplitude", "omega", "method", "error", "contact_loss", "multiplier")
    vectorised = True  # a chunk is solved together (its lines in one batch): big chunks, in this process
    nan_reasons = {"multiplier": "multiplier: not computed where the simulation (method 2) gave the cycle"}

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
        supercritical = []
        for key, index in groups.items():
            form = self._form(key, rows[index[0]])
            if isinstance(form, Exception):
                for i in index:
                    self._simulated(rows[i], out, reasons, i, f"no Hopf point nearby ({_first_line(form)})")
            elif not form.stable():
                with np.errstate(all="ignore"):
                    self._subcritical(form, index, rows, out, reasons)
            else:
                supercritical.append((form, index))
        if supercritical:
            self._lines(supercritical, rows, out, reasons)
        return out, reasons

    def _lines(self, lines: list, rows: list, out, reasons) -> None:
        vals = numerics.numeric_values(self.scene, rows[lines[0][1][0]])
        field = fast_field(self.scene, laws=self.laws, functions=vals.functions)
        where = [str(s) for s in field.params].index(self.parameter)
        bases = [field.parameter_values(numerics.numeric_values(self.scene, rows[index[0]])) for _, index in lines]
        values = [np.array([rows[i][self.parameter] for i in index], dtype=float) for _, index in lines]
        with np.errstate(all="ignore"):
            results = squeal_lines(field, [f for f, _ in lines], bases, where, values, tol=self.tol)
        for (_, index), result in zip(lines, results):
            for position, i in enumerate(index):
                if np.isnan(result.method[position]):
                    self._simulated(rows[i], out, reasons, i, result.reasons[position])
                    continue
                out[i] = [
                    result.amplitude[position],
                    result.omega[position],
                    result.method[position],
                    result.error[position],
                    result.contact_loss[position],
                    result.multiplier[position],
                ]

    def _subcritical(self, form, index, rows, out, reasons) -> None:
        p = np.array([float(rows[i][self.parameter]) for i in index])
        omega = form.omega(p)
        alpha = form.hopf.dalpha * (p - form.hopf.value)
        for position, i in enumerate(index):
            if alpha[position] <= 0:  # the equilibrium is stable (for l1 > 0 a large cycle may coexist)
                out[i] = [0.0, omega[position], 0, 0.0, 0, np.exp(2 * np.pi * alpha[position] / omega[position])]
            else:
                self._simulated(rows[i], out, reasons, i, "subcritical (l1 > 0): the stable cycle is a large one")

    def _simulated(self, values, out, reasons, i, why: str) -> None:
        if not self.simulate:
            reasons[i] = f"{why}; the normal form and the continuation do not apply and simulate=False"[:300]
            if why.startswith("contact loss"):
                out[i, 4] = 1.0
            return
        try:
            found = numerics.fast_cycle(self.scene, values, laws=self.laws, **self.options)
        except Exception as error:  # noqa: BLE001 - a failing point is NaN with its reason, never a crash
            reasons[i] = f"{why}; simulation failed: {type(error).__name__}: {_first_line(error)}"[:300]
            return
        if not found.converged or found.reactions.size == 0:
            reasons[i] = f"{why}; simulation: {found.message}"[:300]
            return
        amplitude = float(np.max(np.ptp(found.reactions, axis=1)) / 2)
        # fast_cycle stops when successive returns agree to tol: the cycle is attracting, its multiplier < 1
        out[i] = [amplitude, found.omega, 2, self.options.get("tol", 1e-7), float(found.contact_loss), np.nan]
        reasons[i] = ""


def _first_line(error: BaseException) -> str:
    return (str(error).strip().splitlines() or [""])[0][:200]


def build_squeal(scene, grid, values, parameter=None, laws=None, tol=0.002, simulate=True, **options):
    if parameter is None:
        raise AtlasError("the squeal quantity needs the bifurcation parameter: squeal(parameter='mu').")
    if not 0 < float(tol) < 1:
        raise AtlasError(f"tol = {tol!r} must be a relative error in (0, 1).")
    return _Squeal(_prepared(scene, grid, values), grid, values, str(parameter), laws, float(tol), simulate, options)
