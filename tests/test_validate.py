"""The validation layer: each bad input of issue #14 gives the package's own error, short and specific."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym import numerics as nm
from contactsym import validate
from contactsym.errors import ComplianceError, ContactsymError, SceneError, SignPatternError
from contactsym.numerics import NumericsError

x, y = dynamicsymbols("x y")
N, N2, X, Y = sp.symbols("N N2 X Y", real=True)
CONTACT = cs.Contact(coordinate=y, reaction=N)


def _scene(accelerations=(X, N + Y), contacts=(CONTACT,), **options):
    return cs.Scene.from_accelerations([x, y], list(accelerations), contacts, **options)


LAGRANGIAN = x.diff() ** 2 / 2 + y.diff() ** 2 / 2 - y


def _lagrangian(lagrangian=LAGRANGIAN, **options):
    return cs.Scene.from_lagrangian(lagrangian, [x, y], [CONTACT], **options)


SCENE_CASES = [
    # (label, call, error type, words the message must contain)
    ("inf*N acceleration", lambda: _scene([X, float("inf") * N + Y]), SceneError, "not finite"),
    ("nan acceleration", lambda: _scene([X, sp.nan * N + Y]), SceneError, "not a number"),
    ("zoo acceleration", lambda: _scene([X, sp.zoo + N]), SceneError, "not finite"),
    ("accelerations=None", lambda: cs.Scene.from_accelerations([x, y], None, [CONTACT]), SceneError, "a list"),
    ("extra acceleration", lambda: cs.Scene([x, y], [X, N + Y, 7], [CONTACT]), SceneError, "3 accelerations for 2"),
    (
        "reaction that appears nowhere",
        lambda: _scene(contacts=[CONTACT, cs.Contact(coordinate=x, reaction=N2)]),
        SceneError,
        "N2 of contact 1",
    ),
    ("contacts=None", lambda: _scene(contacts=None), SceneError, "contacts must be a list"),
    ("a tuple for a Contact", lambda: _scene(contacts=[(y, N)]), SceneError, "write Contact("),
    ("coordinates=None", lambda: cs.Scene(None, [X], [CONTACT]), SceneError, "coordinates must be a list"),
    ("a number for a coordinate", lambda: cs.Scene([x, 3], [X, N], [CONTACT]), SceneError, "dynamicsymbols"),
    ("a coordinate twice", lambda: cs.Scene([y, y], [X, N], [CONTACT]), SceneError, "listed twice"),
    ("a list for an acceleration", lambda: cs.Scene([x, y], [X, [N]], [CONTACT]), SceneError, "SymPy expression"),
    ("eps = inf", lambda: _scene(eps=float("inf")), SceneError, "eps = oo is infinite"),
    ("eps = nan", lambda: _scene(eps=float("nan")), SceneError, "eps = nan is not a number"),
    ("eps = -1", lambda: _scene(eps=-1), SceneError, "must be > 0"),
    ("Coulomb(mu=nan)", lambda: cs.Coulomb(float("nan"), {x: 1}), ComplianceError, "not a number"),
    ("Coulomb(mu=-0.5)", lambda: cs.Coulomb(-0.5, {x: 1}), ComplianceError, "negative"),
    ("Coulomb(mu=oo)", lambda: cs.Coulomb(sp.oo, {x: 1}), ComplianceError, "not finite"),
    ("Coulomb(mu=1j)", lambda: cs.Coulomb(sp.I, {x: 1}), ComplianceError, "not real"),
    ("Coulomb(mu='0.3')", lambda: cs.Coulomb("0.3", {x: 1}), ComplianceError, "is text"),
    ("Viscous(c=-1)", lambda: cs.Viscous(-1, {x: 1}), ComplianceError, "negative"),
    ("a compliance that is no law", lambda: cs.Contact(y, N, compliance=3), SceneError, "not a law"),
    ("a friction that is no law", lambda: cs.Contact(y, N, friction=0.3), SceneError, "not a friction law"),
    ("unilateral='yes'", lambda: cs.Contact(y, N, unilateral="yes"), SceneError, "True or False"),
    ("a gap that is text", lambda: cs.Contact("y", N), ContactsymError, "is text"),
    ("a reaction that is text", lambda: cs.Contact(y, "N"), SceneError, "sympy Symbol"),
    ("stability([])", lambda: cs.scene("brake").stability([]), SignPatternError, "length 0"),
    ("regions([])", lambda: cs.scene("brake").regions([]), SignPatternError, "length 0"),
    ("stability(np.array([1, 0]))", lambda: cs.scene("brake").stability(np.array([1, 0])), SignPatternError, "+1"),
    ("stability('+-')", lambda: cs.scene("brake").stability("+-"), SignPatternError, "must be a list"),
    ("stability((1.0, 1))", lambda: cs.scene("brake").stability((1.0, 1)), SignPatternError, "+1 or -1"),
    ("stability((True, 1))", lambda: cs.scene("brake").stability((True, 1)), SignPatternError, "+1 or -1"),
    ("equilibria(5)", lambda: cs.scene("brake").equilibria(5), SignPatternError, "must be a list"),
    ("name=None", lambda: _scene(name=None), SceneError, "name must be text"),
    ("at=5", lambda: _scene(at=5), SceneError, "at must be a dict"),
    ("at with nan", lambda: _scene(at={X: sp.nan}), SceneError, "not a number"),
    ("parameters=5", lambda: _scene(parameters=5), SceneError, "parameters must be a list"),
    ("parameters of text", lambda: _scene(parameters=["X"]), SceneError, "not a sympy Symbol"),
    ("positive=None", lambda: _scene(positive=None), SceneError, "positive must be a list"),
    ("solve_for='mu'", lambda: _scene(solve_for="mu"), SceneError, "must be a sympy Symbol"),
    ("Lagrangian None", lambda: _lagrangian(None), ContactsymError, "the Lagrangian = None"),
    ("Lagrangian of text", lambda: _lagrangian("x"), ContactsymError, "is text"),
    ("Lagrangian with nan", lambda: _lagrangian(sp.nan * x.diff() ** 2), SceneError, "not a number"),
    ("loads=[1, 2]", lambda: _lagrangian(loads=[1, 2]), SceneError, "must be a pair"),
    ("a mass I (the imaginary unit)", lambda: _lagrangian(sp.I * LAGRANGIAN), SceneError, "imaginary unit I"),
    ("an acceleration with I", lambda: _scene([X, N + sp.I * Y]), SceneError, "imaginary unit I"),
    ("loads=None", lambda: _lagrangian(loads=None), SceneError, "loads must be a list"),
    ("frame=3", lambda: _lagrangian(frame=3), SceneError, "inertial ReferenceFrame"),
    ("scene(None)", lambda: cs.scene(None), SceneError, "must be text"),
    ("scene(3)", lambda: cs.scene(3), SceneError, "must be text"),
]


@pytest.mark.parametrize("label, call, error, words", SCENE_CASES, ids=[c[0] for c in SCENE_CASES])
def test_bad_scene_input_gives_a_clear_error(label, call, error, words):
    with pytest.raises(error) as caught:
        call()
    assert words in str(caught.value)
    assert len(str(caught.value)) < 400


def test_sign_pattern_as_array_is_accepted_as_ints():
    """A NumPy pattern is read as plain ints, the same stage as the tuple (not a second cache entry)."""
    brake = cs.scene("brake")
    assert brake.stability(np.array([1, 1])) is brake.stability((1, 1))
    assert validate.sign_pattern(np.array([1, -1])) == (1, -1)
    assert all(type(s) is int for s in validate.sign_pattern((sp.Integer(1), np.int64(-1))))


def test_a_long_name_is_cut_in_the_message():
    with pytest.raises(SceneError) as caught:
        cs.scene("a" * 100_000)
    assert len(str(caught.value)) < 300
    assert "100002 characters" in str(caught.value)


def test_singular_mass_matrix_names_the_coordinate_without_inertia():
    q1, q2 = dynamicsymbols("q1 q2")
    m = sp.Symbol("m", positive=True)
    lagrangian = m * q1.diff() ** 2 / 2 - m * q2  # q2 has no kinetic energy
    with pytest.raises(SceneError, match=r"singular.*\['q2'\]"):
        cs.Scene.from_lagrangian(lagrangian, [q1, q2], [cs.Contact(coordinate=q1, reaction=N)])


def test_valid_inputs_still_pass():
    s = _scene(eps=sp.Rational(1, 100))
    assert s.eps == sp.Rational(1, 100)
    mu = sp.Symbol("mu", real=True)
    c = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1}))
    assert cs.Scene.from_accelerations([x, y], [0, N - 1], [c]).accelerations[x] == -mu * sp.Abs(N)
    assert cs.Coulomb(0, {x: 1}).mu == 0


# --- numerics ---------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def sliding():
    s = cs.scene("sliding-point")
    xs, xdot = sp.symbols("x xdot", real=True)
    values = {"m": 1, "b": 1, "mu": 0.5, sp.Function("X")(xs, xdot): 2, sp.Function("Y")(xs, xdot): -1}
    return s, values, {xs: 0, xdot: 1}


@pytest.mark.parametrize(
    "options, words",
    [
        ({"method": "Nope"}, "not a solver"),
        ({"method": None}, "not a solver"),
        ({"t_eval": [0, float("nan"), 1]}, "nan"),
        ({"t_eval": [0, 2]}, "outside the span"),
        ({"t_eval": [-1, 0.5]}, "outside the span"),
        ({"t_eval": [0.5, 0.2]}, "not sorted"),
        ({"t_eval": np.array([0.1 + 1j])}, "complex"),
        ({"t_eval": "0 1"}, "text"),
        ({"t_eval": [[0.1], [0.2, 0.3]]}, "not an array"),
    ],
)
def test_bad_simulation_options_are_rejected(sliding, options, words):
    s, values, initial = sliding
    with pytest.raises(NumericsError, match=words):
        nm.simulate_full(s, values, 1e-3, (0, 1), initial, **options)


BRAKE = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 2, "F_y": -4}
BRAKE_LAW = {"Phi_1": -2.1, "Phi_2": -2.1, "Psi_1": -1, "Psi_2": -1}


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda b: nm.fast_cycle(b, BRAKE | BRAKE_LAW, tol=-1), "tol = -1.0 must be > 0"),
        (lambda b: nm.fast_cycle(b, BRAKE | BRAKE_LAW, rtol=0), "rtol = 0.0 must be > 0"),
        (lambda b: nm.fast_cycle(b, BRAKE | BRAKE_LAW, periods=0), "whole number from 1"),
        (lambda b: nm.fast_cycle(b, BRAKE | BRAKE_LAW, samples=1), "whole number from 2"),
        (lambda b: nm.simulate_fast(b, BRAKE | BRAKE_LAW, (0, 1), [0, 0, 0]), r"3 values; .*\['Q_1'"),
        (lambda b: nm.hopf_point(b, BRAKE | BRAKE_LAW, "nu"), "'nu' is not a parameter of 'brake'"),
        (lambda b: nm.hopf_point(b, BRAKE | BRAKE_LAW, "mu", bracket=(0.5, 0.9)), "no Hopf crossing is bracketed"),
        (lambda b: nm.hopf_point(b, BRAKE | BRAKE_LAW, "mu", bracket=(1.2, 0.9)), "low < high"),
    ],
)
def test_bad_numerics_options_are_named_before_any_integration(call, words):
    """Each a ContactsymError with the option named (no numpy broadcast error, no scipy ValueError)."""
    with pytest.raises(ContactsymError, match=words):
        call(cs.scene("brake"))


def test_complex_initial_state_is_rejected_not_cut():
    values = {"phi": 0.7, "mu_1": 0.3, "mu_2": 0.2, "X_1": 0, "X_2": 1, "Y_1": 0, "Y_2": 0, "Phi": -1, "Psi": -1}
    fs = nm.fast_system(cs.scene("painleve-klein-rod"), values)
    with pytest.raises(NumericsError, match="complex"):
        nm.integrate(fs, (0, 1), np.array([1 + 1j, 0]))
    assert nm.integrate(fs, (0, 1), [1.0, 0.0], t_eval=[0, 0.5, 1]).t.tolist() == [0, 0.5, 1]


@pytest.fixture(scope="module")
def classifier():
    m, mu = sp.symbols("m mu", positive=True)
    return nm.PointClassifier([m - mu, mu], [m, mu]), np.array([1.0, 2.0, 3.0]), np.array([2.0, 1.0, 3.0])


@pytest.mark.parametrize("chunk", [-5, 0, 1.5, "8", True, None])
def test_point_classifier_rejects_a_bad_chunk(classifier, chunk):
    pc, m, mu = classifier
    with pytest.raises(NumericsError, match="chunk"):
        pc(m, mu, chunk=chunk)


def test_point_classifier_any_good_chunk_gives_the_same_verdicts(classifier):
    pc, m, mu = classifier
    expected = np.sign(m - mu).astype(int).tolist()  # mu > 0 always; m - mu decides
    for chunk in (1, 2, 3, 1 << 15):
        assert pc(m, mu, chunk=chunk).stable.tolist() == expected


def test_point_classifier_rejects_complex_and_text(classifier):
    pc, m, mu = classifier
    with pytest.raises(NumericsError, match="complex"):
        pc(m + 1j, mu)
    with pytest.raises(NumericsError, match="text"):
        pc("1 2", mu)


def test_every_error_here_is_a_contactsym_error():
    assert issubclass(NumericsError, ContactsymError)
