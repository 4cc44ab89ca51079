"""The spatial scenes (painleve-rod-3d, stool-3d) against a Newton–Euler derivation in numpy at random
configurations (mass matrix, W, D, Delassus matrix G = W^T M^-1 W, H = W^T M^-1 D), the rod's critical
friction against the same derivation and the planar 4/3, and the stool's robustness claims against eigenvalues."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.robustness.classify import decide_robustness
from contactsym.robustness.law_polynomials import fast_spectral_abscissa
from contactsym.scenes import stool_3d
from tests.scenes.newton_euler import delassus, generalized_force, mass_matrix, rotation

Q = ("x", "y", "z", "psi", "theta", "phi")


_COMPILED: dict = {}


def _numeric(scene, values: dict):
    """M, W and D of the scene's contact space at numbers (coordinates and parameters by name)."""
    if id(scene) not in _COMPILED:
        space = scene.contact_space
        plain = {q: sp.Symbol(str(q.func), real=True) for q in space.coordinates}
        D = sp.Matrix.hstack(*[term[0] for term in space.friction])
        matrices = [m.xreplace(plain) for m in (space.M, space.W, D)]
        symbols = sorted(set().union(*(m.free_symbols for m in matrices)), key=str)
        _COMPILED[id(scene)] = (scene, [s.name for s in symbols], sp.lambdify(symbols, matrices, "numpy"))
    _, names, function = _COMPILED[id(scene)]
    return [np.array(m, dtype=float) for m in function(*[values[n] for n in names])]


def _check_against_newton_euler(scene, values, mass, inertia, arms_body, normal, directions):
    M, W, D = _numeric(scene, values)
    angles = [values[n] for n in ("psi", "theta", "phi")]
    R = rotation(*angles)
    arms = [R @ a for a in arms_body]
    k = len(arms)
    assert np.allclose(M, mass_matrix(mass, inertia, angles), atol=1e-12)
    assert np.allclose(W, np.column_stack([generalized_force(normal, r, angles) for r in arms]), atol=1e-12)
    assert np.allclose(D, np.column_stack([generalized_force(d, r, angles) for r, d in zip(arms, directions)]))
    G, H = W.T @ np.linalg.solve(M, W), W.T @ np.linalg.solve(M, D)
    assert np.allclose(G, delassus(mass, inertia, angles, arms, [normal] * k, [normal] * k), atol=1e-11)
    assert np.allclose(H, delassus(mass, inertia, angles, arms, [normal] * k, directions), atol=1e-11)


# --- the rod ------------------------------------------------------------------------------------


def _rod_point(rng):
    values = dict(zip(Q, [*rng.uniform(-1, 1, 3), rng.uniform(-3, 3), rng.uniform(0.05, 1.5), rng.uniform(-3, 3)]))
    return values | dict(m=rng.uniform(0.5, 3), l=rng.uniform(0.5, 2), J=rng.uniform(0.01, 1), beta=rng.uniform(0, 1.5))


def _rod_newton_euler(v):
    inertia = np.diag([v["J"], v["m"] * v["l"] ** 2 / 3, v["m"] * v["l"] ** 2 / 3])
    sliding = np.array([np.cos(v["psi"] + v["beta"]), np.sin(v["psi"] + v["beta"]), 0.0])
    return v["m"], inertia, [np.array([v["l"], 0, 0])], np.array([0, 0, 1.0]), [sliding]


def test_rod_mass_matrix_delassus_and_h_are_newton_eulers_at_random_configurations():
    # the file gives the same scene: tests/mechanism/files/test_reader.py
    scene = cs.scene("painleve-rod-3d")
    rng = np.random.default_rng(3)
    for _ in range(20):
        values = _rod_point(rng)
        _check_against_newton_euler(scene, values, *_rod_newton_euler(values))


def test_rod_critical_friction_is_newton_eulers_and_the_planar_four_thirds():
    rod = cs.scene("painleve-rod-3d")
    stable = rod.regions()["stable for every law"].condition
    mu, theta, beta = (next(s for s in stable.free_symbols if s.name == n) for n in ("mu", "theta", "beta"))
    assert isinstance(stable, sp.StrictLessThan) and stable.lhs == mu
    critical = stable.rhs  # derived: mu below it, the contact is stable for every law
    # against Newton-Euler: the contact's acceleration per unit N, G - mu H, vanishes at the critical mu
    rng = np.random.default_rng(5)
    for _ in range(40):
        v = _rod_point(rng)
        mass, inertia, arms, normal, sliding = _rod_newton_euler(v)
        R = rotation(v["psi"], v["theta"], v["phi"])
        G = delassus(mass, inertia, [v["psi"], v["theta"], v["phi"]], [R @ arms[0]], [normal], [normal])[0, 0]
        H = delassus(mass, inertia, [v["psi"], v["theta"], v["phi"]], [R @ arms[0]], [normal], sliding)[0, 0]
        derived = float(critical.subs({theta: v["theta"], beta: v["beta"]}))
        assert derived == pytest.approx(G / H, rel=1e-10)
    # in space it is the planar one over cos(beta); in the rod's plane the minimum over theta is 4/3 at tan = 2
    planar = critical.subs(beta, 0)
    assert sp.simplify(critical * sp.cos(beta) - planar) == 0
    assert sp.nsimplify(sp.simplify(planar.subs(theta, sp.atan(2)))) == sp.Rational(4, 3)
    grid = np.linspace(0.05, 1.5, 2901)  # the minimum found without the pipeline: Newton-Euler on a grid
    ratios = [(1 + 3 * np.cos(t) ** 2) / (3 * np.sin(t) * np.cos(t)) for t in grid]
    assert np.tan(grid[int(np.argmin(ratios))]) == pytest.approx(2, abs=5e-3)
    assert min(ratios) == pytest.approx(4 / 3, abs=1e-6)


# --- the stool ----------------------------------------------------------------------------------


def _stool():
    return cs.scene("stool-3d")  # built once, shared with the tests over every built-in scene


def _stool_newton_euler(v):
    arms = [np.array([float(a - stool_3d.CENTRE[0]), float(b - stool_3d.CENTRE[1]), -v["h"]]) for a, b in stool_3d.FEET]
    sliding = np.array([*map(float, stool_3d.SLIDING), 0.0])
    return 1.0, np.diag([float(i) for i in stool_3d.INERTIA]), arms, np.array([0, 0, 1.0]), [sliding] * 3


def test_stool_mass_matrix_delassus_and_h_are_newton_eulers_at_random_configurations():
    stool = _stool()
    rng = np.random.default_rng(7)
    for _ in range(20):
        values = dict(zip(Q, [*rng.uniform(-1, 1, 3), *rng.uniform(-1.4, 1.4, 3)])) | {"h": rng.uniform(0.1, 2)}
        _check_against_newton_euler(stool, values, *_stool_newton_euler(values))


def test_stool_is_classified_with_certificates_or_witness_laws_that_eigenvalues_confirm():
    stool = _stool()
    rng = np.random.default_rng(11)
    verdicts = set()
    for signs in [(1, 1, 1), (1, -1, 1), (-1, 1, -1)]:
        A = stool.linearization(signs=signs).A
        for _ in range(3):
            values = {"mu": rng.uniform(0, 2), "h": rng.uniform(0.1, 2)}
            numeric = A.xreplace({s: sp.Rational(round(values[s.name], 3)) for s in A.free_symbols})
            mass, inertia, arms, normal, sliding = _stool_newton_euler({"h": float(round(values["h"], 3))})
            G = delassus(mass, inertia, [0, 0, 0], arms, [normal] * 3, [normal] * 3)
            H = delassus(mass, inertia, [0, 0, 0], arms, [normal] * 3, sliding)
            expected = G - float(round(values["mu"], 3)) * H * np.array(signs)  # friction -mu |N_j| on each foot
            assert np.allclose(np.array(numeric.tolist(), dtype=float), expected, atol=1e-12)
            result = decide_robustness(numeric)
            verdicts.add(result.verdict)
            assert result.certificate is not None or result.stable_law or result.unstable_law
            for law, stable in ((result.stable_law, True), (result.unstable_law, False)):
                if law is not None:
                    c = np.array([[-float(x) for x in law.Phi]])
                    d = np.array([[-float(x) for x in law.Psi]])
                    assert (fast_spectral_abscissa(expected, c, d)[0] < 0) == stable
    assert len(verdicts) >= 2


def test_the_stool_file_gives_the_stool_scene():
    from contactsym.mechanism.files import load_scene
    from tests.mechanism.files.test_reader import EXAMPLES

    own, built = load_scene(EXAMPLES / "stool-3d.toml").contact_space, _stool().contact_space
    assert (own.M, own.F, own.W, own.friction, own.reactions) == (
        built.M,
        built.F,
        built.W,
        built.friction,
        built.reactions,
    )
