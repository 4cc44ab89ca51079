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
from .grid import AtlasError, Grid
from .kernel import Kernel, setup_for

__all__ = ["PointFailure", "build_catastrophe", "build_cycle", "build_function"]


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
