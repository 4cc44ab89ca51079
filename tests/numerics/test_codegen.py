"""contactsym.numerics.codegen: generated functions, cached per scene and parameter set."""

import sympy as sp

import contactsym as cs
from contactsym import numerics as nm

x, xdot = sp.symbols("x xdot", real=True)
X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)


# --- generated code: caching, Jacobians, counting ------------------------------------------


def test_generated_functions_are_cached_per_scene_and_parameter_set():
    scene = cs.scene("sliding-point")
    values = {"m": 1.0, "b": 1.0, "mu": 0.5, X: 1, Y: -1}
    assert nm.full_system(scene, values, 1e-3) is nm.full_system(scene, dict(values), 1e-3)
    assert nm.full_system(scene, values, 1e-3) is not nm.full_system(scene, {**values, "m": 2.0}, 1e-3)
    fast = scene.fast_subsystem()
    assert nm.lambdify_stage(fast, {"b": 1, "m": 1, Y: -1}) is nm.lambdify_stage(fast, {"b": 1, "m": 1, Y: -1})
