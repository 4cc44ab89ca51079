"""Scene files in space: frames (sequences and Euler parameters), 3-D points, bodies and contacts, and the bad input
the spatial reader refuses (gimbal lock, inertia tensors not positive definite, friction not tangent)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from sympy.physics.mechanics import ReferenceFrame, dynamicsymbols

from contactsym.mechanism.files import SceneFileError, read_spec
from contactsym.mechanism.files.space import Space, is_identity, singular_set

ROD = (Path(__file__).resolve().parents[3] / "examples" / "painleve-rod-3d.toml").read_text()


def refused(text: str) -> str:
    with pytest.raises(SceneFileError) as raised:
        read_spec(text, "rod.toml")
    message = str(raised.value)
    assert message.startswith("rod.toml:") and "\n" not in message
    return message


def test_the_rod_file_reads_into_a_space_whose_end_is_the_rods_end():
    spec = read_spec(ROD, "rod.toml")
    space = Space(spec.space)
    assert [f.sequence for f in spec.space.frames] == ["zyx"]
    assert str(spec.contacts[0].gap) == "-l*sin(theta(t)) + z(t)"
    direction = spec.contacts[0].friction.direction
    assert is_identity(sum(d**2 for d in direction), 1) and direction[2] == 0
    # the end's position, at random numbers, against the rotation matrix written out
    end = space.points["A"].pos_from(space.origin).to_matrix(space.frame)
    x, y, z, psi, theta, phi = dynamicsymbols("x y z psi theta phi")
    rng = np.random.default_rng(2)
    for _ in range(5):
        numbers = dict(zip((x, y, z, psi, theta, phi), rng.uniform(-2, 2, 6)))
        l_value = rng.uniform(0.5, 2)
        at = {**numbers, sp.Symbol("l", positive=True): l_value}
        c, s = np.cos(numbers[psi]), np.sin(numbers[psi])
        axis = np.array([c * np.cos(numbers[theta]), s * np.cos(numbers[theta]), -np.sin(numbers[theta])])
        expected = np.array([numbers[x], numbers[y], numbers[z]]) + l_value * axis
        assert np.allclose(np.array(end.xreplace(at), dtype=float).ravel(), expected)


@pytest.mark.parametrize(
    "kind, sequence, factor",
    [("body_fixed", "zyx", "cos"), ("body_fixed", "zxz", "sin"), ("space_fixed", "xyz", "cos")],
)
def test_the_singular_set_is_where_the_angular_velocity_map_loses_rank(kind, sequence, factor):
    a2 = sp.Symbol("a2", real=True)
    assert singular_set(kind, sequence) == getattr(sp, factor)(a2)
    # numerically: the map from the angles' rates to omega is singular there, regular elsewhere
    angles = dynamicsymbols("b1:4")
    P, F = ReferenceFrame("P"), ReferenceFrame("F")
    getattr(F, f"orient_{kind}")(P, angles, sequence)
    omega = F.ang_vel_in(P).to_matrix(P)
    E = omega.jacobian([a.diff() for a in angles])
    for middle, singular in ((sp.pi / 2 if factor == "cos" else 0, True), (sp.Rational(1, 3), False)):
        value = E.xreplace({angles[0]: sp.Rational(1, 5), angles[1]: middle, angles[2]: sp.Rational(2, 7)})
        assert (abs(float(value.det())) < 1e-12) == singular


def test_gimbal_lock_is_refused_naming_the_angles():
    assert "gimbal lock" in refused(ROD.replace('theta = [0, "pi/2"]', "theta = [0, 2]"))
    message = refused(ROD.replace('theta = [0, "pi/2"]', "theta = [0, 2]"))
    assert "angles psi, theta, phi" in message and "pi/2" in message and "interval" in message
    message = refused(ROD + '\n[at]\ntheta = "pi/2"\n')
    assert "gimbal lock at the configuration [at]" in message and "cos(theta) = 0" in message
    message = refused(ROD.replace('angles = ["psi", "theta", "phi"]', 'angles = ["psi", "-pi/2", "phi"]'))
    assert "for every configuration" in message and "(psi, -pi/2, phi)" in message
    # a sequence whose lock is elsewhere is read: zxz locks at theta = 0, outside (0, pi/2)
    assert read_spec(ROD.replace('"zyx"', '"zxz"'), "rod.toml").space.frames[0].sequence == "zxz"


@pytest.mark.parametrize(
    "inertia",
    [
        '["0", "m*l^2/3", "m*l^2/3"]',
        '["J", "-m", "m"]',
        '["1", "1", "1", "2", "0", "0"]',
        '["1", "1", "1", "0", "1", "0"]',
    ],
)
def test_an_inertia_tensor_that_is_not_positive_definite_is_refused(inertia):
    text = ROD.replace('inertia = ["J", "m*l^2/3", "m*l^2/3"]', f"inertia = {inertia}")
    assert "not positive definite" in refused(text)


def test_a_positive_definite_tensor_with_products_is_read():
    text = ROD.replace('inertia = ["J", "m*l^2/3", "m*l^2/3"]', 'inertia = ["2", "2", "2", "1/2", "1/2", "0"]')
    assert read_spec(text, "rod.toml").space.bodies[0].inertia[3:] == (sp.Rational(1, 2), sp.Rational(1, 2), 0)


def test_a_friction_direction_not_tangent_to_the_contact_is_refused_with_the_normal_named():
    message = refused(ROD.replace('"sin(psi + beta)", "0"]', '"0", "sin(psi + beta)"]'))
    assert "not tangent" in message and "normal [0, 0, 1]" in message and "cos(beta + psi)" in message
    tilted = ROD.replace('normal = ["0", "0", "1"]', 'normal = ["0", "3/5", "4/5"]')
    assert "normal [0, 3/5, 4/5]" in refused(tilted)
    # tangent to the tilted plane: read
    along = tilted.replace('["cos(psi + beta)", "sin(psi + beta)", "0"]', '["1", "0", "0"]')
    assert read_spec(along, "rod.toml").contacts[0].friction.direction == (1, 0, 0)


@pytest.mark.parametrize(
    "old, new, words",
    [
        ('normal = ["0", "0", "1"]', 'normal = ["0", "1", "1"]', "not a unit vector"),
        ('"sin(psi + beta)", "0"]', '"sin(psi + beta)", "1"]', "not a unit vector"),
        ('"cos(psi + beta)"', '"cos(psi + beta + theta\')"', "not the rates"),
        ('normal = ["0", "0", "1"]', 'normal = ["sin(theta)", "0", "cos(theta)"]', "fixed"),
        ('"zyx"', '"zzx"', "twice in a row"),
        ('"zyx"', '"zyw"', "three axes"),
        ("dimensions = 3", "", "add dimensions = 3"),
        ("dimensions = 3", "dimensions = 4", "must be 2"),
        ('offset = ["l", "0", "0"]', 'offset = ["l", "0"]', "three formulas"),
        ('frame = "rod"\nmass', 'angle = "theta"\nmass', "turns with a frame"),
        (
            'body_fixed = "zyx", angles = ["psi", "theta", "phi"]',
            'euler_parameters = ["1", "0", "0", "1"]',
            "unit quaternion",
        ),
    ],
)
def test_bad_spatial_input_gives_one_line_with_the_fix(old, new, words):
    assert old in ROD
    assert words in refused(ROD.replace(old, new, 1))


def test_euler_parameters_orient_a_frame_as_the_sequence_does():
    # a turn by theta about y as a unit quaternion (cos(theta/2), 0, sin(theta/2), 0) and as zyx (0, theta, 0)
    quaternion = ROD.replace(
        'body_fixed = "zyx", angles = ["psi", "theta", "phi"]',
        'euler_parameters = ["cos(theta/2)", "0", "sin(theta/2)", "0"]',
    )
    sequence = ROD.replace('angles = ["psi", "theta", "phi"]', 'angles = ["0", "theta", "0"]')
    gaps = [read_spec(text, "rod.toml").contacts[0].gap for text in (quaternion, sequence)]
    assert is_identity(gaps[0] - gaps[1], 0)
