"""Physical admissibility: positive masses and inertias (a positive definite mass matrix), signs
that agree with intervals, friction coefficients that are not negative."""

import pathlib

import numpy as np
import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, event, given, settings
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


def test_a_mass_declared_real_is_refused(tmp_path):
    """A real m may be negative: the mass matrix is not positive definite in the declared domain (the
    sample points give a symbol declared real both signs), so the file is refused, not derived with
    regions that carry a factor m."""
    with pytest.raises(SceneError, match=r"mass matrix is not positive definite.*m = -"):
        leaning_rod(tmp_path, 'm = "positive"', 'm = "real"')


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
        # a scene given by its accelerations is checked where its friction is written out (Abs or sign)
        assert s.inertia in ("proved", "sampled") or (s.contact_space is None and s.inertia == "unchecked"), name
    assert cs.scene("painleve-klein-rod").inertia == "proved"  # G = 2: two unit masses joined by the rod


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


@settings(max_examples=15, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(J=matrices, which=st.integers(0, 2), squared=st.booleans())
def test_a_symbol_declared_real_is_accepted_only_where_both_signs_are_admissible(J, which, squared):
    """Python API: a mass symbol declared real is refused; the same symbol entering the masses
    squared (a length, say, m_i = l**2) is accepted, both signs giving a positive definite matrix."""
    assume(J.det() != 0)
    n = J.rows
    free = sp.Symbol("l", real=True)
    masses = [(free**2 if squared else free) if i == which % n else i + 1 for i in range(n)]
    if squared:
        assert chain(J, masses).inertia in ("proved", "sampled")
    else:
        with pytest.raises(SceneError, match=r"mass matrix is (not positive definite|singular)"):
            chain(J, masses)


# --- scenes given by their accelerations: the frictionless coefficients (Delassus matrix) ------

SLIDING_POINT = """
[scene]
coordinates = ["x", "y"]
[parameters]
m = "positive"
mu = "positive"
X = "real"
Y = "real"
[accelerations]
x = "(X - mu*Abs(N))/m"
y = "(N + Y)/m"
[[contacts]]
gap = "y"
reaction = "N"
"""


def test_an_accelerations_file_with_a_positive_mass_is_proved_admissible():
    assert cs.read_scene(SLIDING_POINT).inertia == "proved"


@pytest.mark.parametrize(
    ("old", "new"),
    [('m = "positive"', 'm = "negative"'), ('y = "(N + Y)/m"', 'y = "(-N + Y)/m"'), ('y = "(N + Y)/m"', 'y = "Y/m"')],
)
def test_an_accelerations_file_whose_reaction_pulls_its_gap_shut_is_refused(old, new):
    with pytest.raises(SceneError, match=r"do not push their gaps open: .*N on y.*signs of the masses"):
        cs.read_scene(SLIDING_POINT.replace(old, new))


def test_the_python_api_refuses_a_negative_mass_in_the_accelerations():
    x, y = dynamicsymbols("x y")
    N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    m = sp.Symbol("m", negative=True)
    contact = cs.Contact(coordinate=y, reaction=N)
    with pytest.raises(SceneError, match=r"coefficient of the reactions \(N on y\) .* is 1/m"):
        cs.Scene.from_accelerations([x, y], [-mu * sp.Abs(N) / m, N / m - 1], [contact])
    friction = cs.Contact(coordinate=y, reaction=N, friction=cs.Coulomb(mu, {x: 1}))  # attached: shown too
    with pytest.raises(SceneError, match=r"do not push their gaps open"):
        cs.Scene.from_accelerations([x, y], [0, N / m - 1], [friction])


def accelerations_mechanism(J: sp.Matrix, masses, k: int, directions):
    """q'' = M^-1 (F + sum_j e_j N_j - mu |N_j| tau_j), M = J^T diag(m) J, contacts on q_1..q_k."""
    n = J.cols
    q = dynamicsymbols(f"q_1:{n + 1}")
    N = sp.symbols(f"N_1:{k + 1}", real=True)
    mu = sp.Symbol("mu", positive=True)
    Minv = (J.T * sp.diag(*masses) * J).inv()
    force = sp.Matrix([-1] * n)  # a load
    for j in range(k):
        force[j] += N[j]
        force -= mu * sp.Abs(N[j]) * sp.Matrix(directions[j * n : (j + 1) * n])
    accelerations = list(Minv * force)
    return Minv, cs.Scene.from_accelerations(
        q, accelerations, [cs.Contact(coordinate=q[j], reaction=N[j]) for j in range(k)]
    )


@settings(max_examples=20, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(
    J=matrices,
    weights=st.lists(st.integers(1, 9), min_size=3, max_size=3),
    negative=st.integers(-1, 2),
    k=st.integers(1, 2),
    directions=st.lists(st.integers(-2, 2), min_size=6, max_size=6),
)
def test_random_accelerations_are_refused_exactly_when_their_delassus_matrix_is_not_semidefinite(
    J, weights, negative, k, directions
):
    """Positive masses: accepted (G = principal part of M^-1 is positive definite). One mass negated
    (``negative``; -1 for none): refused exactly when the frictionless G has a negative eigenvalue or a zero
    diagonal entry (checked independently, by the eigenvalues of the exact G)."""
    assume(J.det() != 0)
    n = J.rows
    k = min(k, n)
    assume(all(any(directions[j * n : (j + 1) * n]) for j in range(k)))  # each contact's friction written out
    masses = [(-w if i == negative else w) for i, w in enumerate(weights[:n])]
    assume(sp.Matrix(J.T * sp.diag(*masses) * J).det() != 0)
    G = (J.T * sp.diag(*masses) * J).inv()[:k, :k]
    eigenvalues = np.linalg.eigvalsh(np.array(G.tolist(), dtype=float))  # G is symmetric
    bad = eigenvalues.min() < -1e-12 or any(G[i, i] == 0 for i in range(k))
    assert not (negative < 0 and bad)  # positive masses: G is positive definite
    event("refused" if bad else "accepted")
    if bad:
        with pytest.raises(SceneError, match=r"do not push their gaps open"):
            accelerations_mechanism(J, masses, k, directions)
    else:
        assert accelerations_mechanism(J, masses, k, directions)[1].inertia in ("proved", "sampled")


# --- the structural proof of a scene file's bodies (files.bodies.inertia_proved) ----------------


def _rods_file(n: int, inertia_divisors, point_masses, slider: bool) -> str:
    """n rods pinned in a chain (angles q_i), rod i of inertia m_i l_i^2 / d_i, point masses M_j at the
    chosen joints, and a slider coordinate x carrying the pin when ``slider``."""
    coordinates = [f"q{i}" for i in range(1, n + 1)] + (["x"] if slider else [])
    base = "x" if slider else "0"
    names = [f"m{i}" for i in range(1, n + 1)] + [f"l{i}" for i in range(1, n + 1)]
    names += [f"M{j}" for j in point_masses]
    lines = ["[scene]", 'name = "rods"', f"coordinates = {coordinates}".replace("'", '"'), "[parameters]"]
    lines += [f'{name} = "positive"' for name in names] + ["[points]"]
    for i in range(1, n + 1):
        x = " + ".join([base] + [f"l{j}*sin(q{j})" for j in range(1, i)] + [f"l{i}*sin(q{i})/2"])
        y = " - ".join(["0"] + [f"l{j}*cos(q{j})" for j in range(1, i)] + [f"l{i}*cos(q{i})/2"])
        lines.append(f'C{i} = ["{x}", "{y}"]')
        lines.append(f'P{i} = ["{x.replace("/2", "")}", "{y.replace("/2", "")}"]')
    for i, d in enumerate(inertia_divisors, 1):
        lines += ["[[bodies]]", f'point = "C{i}"', f'angle = "q{i}"', f'mass = "m{i}"', f'inertia = "m{i}*l{i}^2/{d}"']
    for j in point_masses:
        lines += ["[[masses]]", f'point = "P{j}"', f'mass = "M{j}"']
    tip = " - ".join(["1"] + [f"l{j}*cos(q{j})" for j in range(1, n + 1)])
    lines += ["[[contacts]]", f'gap = "{tip}"', 'reaction = "N"']
    return "\n".join(lines) + "\n"


@settings(max_examples=8, deadline=None, derandomize=True, suppress_health_check=[HealthCheck.too_slow])
@given(
    n=st.integers(1, 3),
    divisors=st.lists(st.integers(1, 12), min_size=3, max_size=3),
    point_masses=st.sets(st.integers(1, 3)),
    slider=st.booleans(),
    seed=st.integers(0, 2**16),
)
def test_a_proof_from_the_bodies_holds_at_random_configurations(n, divisors, point_masses, slider, seed):
    """Rods whose angles are every coordinate: proved by structure, and M is positive definite (numpy
    eigenvalues) at random positive values and angles; a slider coordinate no body turns with: no such proof."""
    from contactsym.mechanism.files import read_spec
    from contactsym.mechanism.files.bodies import inertia_proved

    text = _rods_file(n, divisors[:n], sorted(j for j in point_masses if j <= n), slider)
    proved = inertia_proved(read_spec(text, "rods.toml"))
    assert proved == (not slider)
    scene = cs.read_scene(text, "rods.toml")
    assert scene.inertia in (("proved",) if proved else ("proved", "sampled"))
    M = scene.contact_space.M.applyfunc(scene.plain)
    rng = np.random.default_rng(seed)
    for _ in range(3):
        point = {
            s: float(rng.uniform(-3, 3) if s.name.startswith("q") else np.exp(rng.normal())) for s in M.free_symbols
        }
        values = np.array(M.xreplace(point).evalf(), dtype=float)
        assert np.linalg.eigvalsh((values + values.T) / 2).min() > 0
