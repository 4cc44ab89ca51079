"""contactsym.numerics.values: ill-posed numeric input gets a clear error."""

import pytest
import sympy as sp

import contactsym as cs
from contactsym import numerics as nm

x, xdot = sp.symbols("x xdot", real=True)
X, Y = sp.Function("X")(x, xdot), sp.Function("Y")(x, xdot)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        ({"eps": 0.0}, "eps = 0.0 must be > 0"),
        ({"eps": -1e-3}, "must be > 0"),
        ({"eps": float("inf")}, "not finite"),
        ({"m": float("nan")}, "m = nan is not finite"),
        ({"m": -1.0}, "must be > 0"),
        ({"m": "1"}, "is text"),
        ({"b": None}, "needs values for \\['b'\\]"),
    ],
)
def test_ill_posed_input_gets_a_clear_error(change, message):
    scene = cs.scene("sliding-point")
    values = {"m": 1.0, "b": 1.0, "mu": 0.5, X: 1, Y: -1}
    eps = change.pop("eps", 1e-3)
    for key, value in change.items():
        if value is None:
            values.pop(key)
        else:
            values[key] = value
    with pytest.raises(nm.NumericsError, match=message):
        nm.simulate_full(scene, values, eps, (0, 1), {x: 0, xdot: 1})
