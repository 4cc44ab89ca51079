"""Partly numeric scenes: Scene.with_values, [values] in a file (the derivation with numbers put in
first agrees with the symbolic derivation evaluated afterwards, at random points)."""

import math
import random
from pathlib import Path

import pytest
import sympy as sp

import contactsym as cs
from contactsym.mechanism.files import SceneFileError, read_scene

ARM = (Path(__file__).parents[2] / "examples" / "two-link-arm.toml").read_text()


def test_numbers_first_agree_with_numbers_after():
    """A and det A of the arm with masses and lengths fixed, against the symbolic ones evaluated there."""
    rng = random.Random(3)
    symbolic = read_scene(ARM, "arm.toml")
    values = {name: sp.Rational(rng.randint(1, 9), rng.randint(1, 5)) for name in ("m1", "m2", "l1", "l2")}
    fixed = symbolic.with_values(values)
    assert {str(k): v for k, v in fixed.fixed_values.items()} == values
    assert "fixed: m1 = " in fixed.description
    A_fixed, A_symbolic = fixed.linearization().A, symbolic.linearization().A
    names = {str(x): x for x in A_symbolic.free_symbols}
    assert not {"m1", "m2", "l1", "l2"} & {str(x) for x in A_fixed.free_symbols}
    for _ in range(3):
        point = {name: rng.uniform(-1.2, 1.2) for name in ("q1", "q2")} | {"mu": rng.uniform(0.1, 2), "s": 1}
        both = {names[n]: v for n, v in (point | values).items() if n in names}
        here = {x: point[str(x)] for x in A_fixed.free_symbols}
        assert float(A_fixed[0, 0].subs(here)) == pytest.approx(float(A_symbolic[0, 0].subs(both)), rel=1e-10)


def test_the_values_table_of_a_file_is_with_values():
    from_file = read_scene(ARM + '\n[values]\nm1 = 1\nl1 = "1/2"\nm2 = 0.3\n', "arm.toml")
    direct = read_scene(ARM, "arm.toml").with_values({"m1": 1, "l1": sp.Rational(1, 2), "m2": 0.3})
    assert (
        from_file.fixed_values
        == direct.fixed_values
        == {
            sp.Symbol("m1", positive=True): 1,
            sp.Symbol("l1", positive=True): sp.Rational(1, 2),
            sp.Symbol("m2", positive=True): sp.Rational(3, 10),  # a float is the decimal it prints
        }
    )
    assert from_file.linearization().A == direct.linearization().A


@pytest.mark.parametrize(
    "values, message",
    [
        ({"m1": -1}, "m1 is declared positive"),
        ({"zz": 1}, "not a parameter of the scene"),
        ({"h": 1}, "placed on the contact manifold"),
        ({"m1": math.nan}, "finite real number"),
        ({"m1": math.inf}, "finite real number"),
        ({"m1": True}, "finite real number"),
        ({"m1": "1"}, "finite real number"),
        ({"m1": sp.I}, "finite real number"),
        ({"m1": sp.Float(0.5) * sp.pi}, "without a float inside"),
        ({"m1": -sp.sqrt(2)}, "m1 is declared positive"),
        ({sp.Symbol("m1"): 1}, "not a parameter"),  # a symbol of the same name but other assumptions
    ],
)
def test_bad_values_are_refused_with_the_reason(values, message):
    with pytest.raises(cs.SceneError, match=message):
        read_scene(ARM, "arm.toml").with_values(values)


def test_a_value_outside_a_declared_interval_is_refused():
    text = (
        '[scene]\ncoordinates = ["x"]\n[parameters]\nalpha = [0, "pi"]\n[accelerations]\nx = "N*sin(alpha) - 1"\n'
        '[[contacts]]\ngap = "x"\nreaction = "N"\n'
    )
    scene = read_scene(text, "a.toml")
    fast = scene.with_values({"alpha": 1}).fast_subsystem()
    assert fast.f[0] == fast.u[0] * sp.sin(1) - 1
    with pytest.raises(cs.SceneError, match="declares positive"):
        scene.with_values({"alpha": 4})


def test_a_values_table_names_only_declared_parameters():
    with pytest.raises(SceneFileError, match="'zz' is not a declared parameter"):
        read_scene(ARM + "\n[values]\nzz = 1\n", "arm.toml")


def test_a_scene_proved_positive_keeps_its_verdict_without_a_second_check(monkeypatch):
    from contactsym.mechanism import scene as scene_module

    scene = cs.scene("painleve-rod")
    assert scene.inertia == "proved"
    monkeypatch.setattr(scene_module, "check_inertia", lambda s: "checked again")
    assert scene.with_values({"m": 2}).inertia == "proved"


# --- exact constants: pi/2, sqrt(2)/2; sin^2 + cos^2 of a fixed angle reduced -------------------------


def _squares_left(expr, angle) -> bool:
    """Whether ``expr`` still holds cos(angle)**n with n >= 2 (sin^2 + cos^2 = 1 not used)."""
    return any(p.base == sp.cos(angle) and p.exp >= 2 for p in sp.sympify(expr).atoms(sp.Pow))


@pytest.mark.parametrize("value", [sp.pi / 4, sp.pi / 2, 3 * sp.pi / 4])
def test_a_multiple_of_pi_is_fixed_exactly(value):
    """The brake with alpha = pi/4, pi/2, 3 pi/4: sin and cos exact, and the regions agree with the symbolic ones there."""
    brake = cs.scene("brake")
    fixed = brake.with_values({"alpha": value})
    assert fixed.fixed_values == {sp.Symbol("alpha", positive=True): value} and f"alpha = {value}" in fixed.description
    st = fixed.stability()
    assert not st.robustly_stable.atoms(sp.sin, sp.cos) and not st.hopf_frequency.atoms(sp.sin, sp.cos)
    alpha = next(x for x in brake.stability().robustly_stable.free_symbols if x.name == "alpha")
    m, mu = sp.symbols("m mu", positive=True)
    for point in ({m: 1, mu: sp.Rational(1, 2)}, {m: 2, mu: 3}):
        symbolic = brake.stability().robustly_stable.xreplace({alpha: value, **point})
        assert bool(symbolic) == bool(st.robustly_stable.xreplace(point))


def test_sqrt_values_are_exact():
    fixed = read_scene(ARM, "arm.toml").with_values({"m1": sp.sqrt(2) / 2, "l1": sp.sqrt(3)})
    assert set(fixed.fixed_values.values()) == {sp.sqrt(2) / 2, sp.sqrt(3)}
    assert not {"m1", "l1"} & {str(x) for x in fixed.linearization().A.free_symbols}


@pytest.mark.parametrize("value", [0.7853981633974483, sp.pi / 7, sp.Rational(157, 200)])
def test_sin_squared_plus_cos_squared_of_a_fixed_angle_is_reduced(value):
    """A float (read as its decimal), or a multiple of pi SymPy leaves unevaluated: sin^2 c + cos^2 c = 1 is used."""
    st = cs.scene("brake").with_values({"alpha": value}).stability()
    c = sp.Rational(repr(value)) if isinstance(value, float) else value
    assert st.hopf_frequency.has(sp.sin(c))  # the angle is there, as sin(c)
    for expr in (*st.hurwitz, st.hopf_frequency, st.robustly_stable):
        assert not _squares_left(expr, c), expr
    assert "cos(" not in str(st.hopf_frequency)  # sin^2 + cos^2 of the same argument reads 1


def test_a_multiple_angle_of_a_fixed_parameter_is_expanded_first():
    from contactsym.mechanism.fixed_values import _put

    a = sp.Symbol("alpha", positive=True)
    put = _put(sp.sin(2 * a) ** 2 + sp.cos(2 * a) ** 2, {a: sp.pi / 7})
    assert not put.has(sp.sin(2 * sp.pi / 7)) and not put.has(sp.cos(2 * sp.pi / 7))
