"""The renamed names of 0.1 still work, give what their successors give, and warn."""

import importlib

import numpy as np
import pytest
import sympy as sp

import contactsym as cs

#: (module, old name, new name): module attributes renamed.
RENAMED = [
    ("contactsym.algebra.canonical_form", "Fraction", "TrigFraction"),
    ("contactsym.canonical", "Fraction", "TrigFraction"),  # the 0.1 path
    ("contactsym.robustness", "Law", "WitnessLaw"),
    ("contactsym.robustness.classify", "Law", "WitnessLaw"),
]

#: (module, old function, new function): functions renamed, called through the old name.
FUNCTIONS = [
    ("contactsym.robustness", "decide", "decide_robustness"),
    ("contactsym.lyapunov", "lyapunov_numeric", "first_lyapunov_from_derivatives"),
    ("contactsym.lyapunov.coefficient", "fast_first_lyapunov", "first_lyapunov_symbolic"),
    ("contactsym.numerics", "first_lyapunov", "first_lyapunov_at"),
    ("contactsym.hopf", "first_lyapunov", "first_lyapunov_at"),  # the 0.1 path
]


@pytest.mark.parametrize(("module", "old", "new"), RENAMED)
def test_a_renamed_class_is_the_new_one_and_warns(module, old, new):
    namespace = importlib.import_module(module)
    with pytest.warns(DeprecationWarning, match=f"{old} is deprecated; use .*{new}"):
        value = getattr(namespace, old)
    assert value is getattr(namespace, new)


def test_an_unknown_name_is_still_an_attribute_error():
    with pytest.raises(AttributeError, match="no attribute 'Fractions'"):
        importlib.import_module("contactsym.algebra.canonical_form").Fractions  # noqa: B018


@pytest.mark.parametrize(("module", "old", "new"), FUNCTIONS)
def test_a_renamed_function_warns_and_calls_the_new_one(module, old, new):
    namespace = importlib.import_module(module)
    alias, function = getattr(namespace, old), getattr(namespace, new)
    assert alias.__wrapped__ is function and alias.__name__ == old


def test_the_old_names_give_what_the_new_ones_give():
    A = sp.Matrix([[1, 0, 0], [0, -1, 0], [0, 0, 1]])
    with pytest.warns(DeprecationWarning, match="decide is deprecated"):
        old = cs.robustness.decide(A)
    assert old.verdict == cs.robustness.decide_robustness(A).verdict == "unstable"
    J = np.array([[0.0, -1.0], [1.0, 0.0]])
    H, T = np.zeros((2, 2, 2)), np.zeros((2, 2, 2, 2))
    T[0, 0, 0, 0] = T[1, 1, 1, 1] = -6.0  # x' = -y - x^3, y' = x - y^3: l1 < 0
    with pytest.warns(DeprecationWarning, match="lyapunov_numeric is deprecated"):
        numeric = cs.lyapunov.lyapunov_numeric(J, H, T)
    assert numeric.l1 == cs.lyapunov.first_lyapunov_from_derivatives(J, H, T).l1 < 0


@pytest.mark.parametrize(
    ("stage", "old", "new"), [("linearization", "matrix", "jacobian"), ("stability", "poly", "routh_hurwitz")]
)
def test_a_renamed_stage_attribute_is_the_new_one_and_warns(stage, old, new):
    obj = getattr(cs.scene("brake"), stage)()
    with pytest.warns(DeprecationWarning, match=f"{type(obj).__name__}.{old} is deprecated"):
        value = getattr(obj, old)
    assert value is getattr(obj, new)
