"""Physical admissibility: positive masses and inertias (a positive definite mass matrix), signs
that agree with intervals, friction coefficients that are not negative."""

import pathlib

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.errors import ContactsymError, SceneError

EXAMPLES = pathlib.Path(__file__).parents[2] / "examples"
# the example without its [figures] (whose values are checked first): the mechanics is what refuses
LEANING_ROD = (EXAMPLES / "leaning-rod.toml").read_text().split("[figures]")[0]


def leaning_rod(tmp_path, old: str, new: str):
    assert old in LEANING_ROD
    path = tmp_path / "rod.toml"
    path.write_text(LEANING_ROD.replace(old, new, 1))
    return cs.load_scene(path)


# --- the examples, pinned -------------------------------------------------------


@pytest.mark.parametrize(
    ("old", "new", "coordinate"),
    [
        ('m = "positive"', 'm = "negative"', "x"),
        ('mass = "m"', 'mass = "-m"', "x"),
        ('inertia = "m*l^2/3"', 'inertia = "-m*l^2/3"', "theta"),
        ('inertia = "m*l^2/3"', 'inertia = "0"', "theta"),
    ],
)
def test_negative_or_zero_mass_or_inertia_is_refused(tmp_path, old, new, coordinate):
    with pytest.raises(SceneError, match=rf"mass matrix .*{coordinate}.*(positive|inertia)"):
        leaning_rod(tmp_path, old, new)


def test_the_leaning_rod_itself_is_proved_admissible(tmp_path):
    assert leaning_rod(tmp_path, 'm = "positive"', 'm = "positive"').inertia == "proved"


def test_positive_parameter_with_a_negative_interval_is_refused(tmp_path):
    with pytest.raises(SceneError, match=r"interval \[-2, -1\] has no positive value; change"):
        leaning_rod(tmp_path, 'm = "positive"', 'm = { assume = "positive", interval = [-2, -1] }')


@pytest.mark.parametrize(("old", "new"), [('mu = "mu"', 'mu = "-mu"'), ('mu = "positive"', 'mu = "negative"')])
def test_negative_friction_coefficient_is_refused(tmp_path, old, new):
    with pytest.raises(ContactsymError, match=r"negative; Coulomb friction opposes sliding, so mu >= 0"):
        leaning_rod(tmp_path, old, new)


def test_accelerations_may_have_a_negative_reaction_coefficient():
    """Without a mass matrix nothing is refused: y'' = a N - 1 with a < 0 is friction on a piece (Painleve)."""
    x, y = dynamicsymbols("x y")
    N, a = sp.Symbol("N", real=True), sp.Symbol("a", negative=True)
    s = cs.Scene.from_accelerations([x, y], [0, a * N - 1], [cs.Contact(coordinate=y, reaction=N)])
    assert s.inertia == "unchecked" and s.stability().robustly_unstable == sp.true


def test_builtin_scenes_are_admissible():
    for name in cs.scene_names():
        s = cs.scene(name)
        assert s.inertia in (("unchecked",) if s.contact_space is None else ("proved", "sampled")), name


# --- random mechanisms: M = J^T diag(m) J ----------------------------------------------


def chain(J: sp.Matrix, masses):
    """Point masses m_i at positions (J q)_i: kinetic energy q'^T J^T diag(m) J q' / 2; the contact q_1 = 0."""
    n = J.cols
    q = dynamicsymbols(f"q_1:{n + 1}")
    N = sp.Symbol("N", real=True)
    rates = J * sp.Matrix([qi.diff() for qi in q])
    L = sum(m * r**2 for m, r in zip(masses, rates)) / 2 - sum(q) * sp.Symbol("g", positive=True)
    return cs.Scene.from_lagrangian(L, q, [cs.Contact(coordinate=q[0], reaction=N)])


matrices = st.integers(1, 3).flatmap(
    lambda n: st.lists(st.integers(-3, 3), min_size=n * n, max_size=n * n).map(lambda e: sp.Matrix(n, n, e))
)


@settings(max_examples=25, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(J=matrices, weights=st.lists(st.integers(1, 9), min_size=3, max_size=3), symbolic=st.booleans())
def test_random_positive_masses_are_accepted(J, weights, symbolic):
    assume(J.det() != 0)
    n = J.rows
    masses = sp.symbols(f"m_1:{n + 1}", positive=True) if symbolic else weights[:n]
    scene = chain(J, masses)
    # Cauchy-Binet: each leading minor of J^T diag(m) J is a sum of positive terms, so symbolic masses are proved
    assert scene.inertia == ("proved" if symbolic else "sampled") or scene.inertia == "proved"
    M = scene.contact_space.M
    if not symbolic:  # an independent check: the eigenvalues of the numeric mass matrix are positive
        assert all(ev > 0 for ev in M.evalf().eigenvals(multiple=True))


@settings(max_examples=25, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(J=matrices, weights=st.lists(st.integers(1, 9), min_size=3, max_size=3), which=st.integers(0, 2))
def test_random_mechanism_with_one_negative_mass_is_refused(J, weights, which):
    """By Sylvester's law of inertia J^T diag(m) J has a negative eigenvalue when one m_i < 0 (J invertible)."""
    assume(J.det() != 0)
    n = J.rows
    masses = [(-w if i == which % n else w) for i, w in enumerate(weights[:n])]
    assert min(M_ev for M_ev in (J.T * sp.diag(*masses) * J).evalf().eigenvals(multiple=True)) < 0
    with pytest.raises(
        SceneError, match=r"mass matrix is (not positive definite|singular).*q_"
    ):  # singular: m_i cancel
        chain(J, masses)
