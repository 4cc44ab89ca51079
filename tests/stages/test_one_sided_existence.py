"""A one-sided contact whose sign no switching function fixes (no friction, or friction at right
angles to the gap) still only pushes: its branch exists where u_j* > 0, and where that is False
throughout the declared domain nothing is claimed stable.

The independent check: the complementarity problem of the contacts (u_j >= 0, f_j >= 0, u_j f_j = 0
for the one-sided ones), enumerated over which contacts are open and solved with NumPy from the
accelerations as the test writes them, at random loads of random mechanisms.
"""

from __future__ import annotations

import itertools
from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.command_line.output import conditions_text, derivation_chain
from contactsym.counts.regions import count_regions
from contactsym.report import conditions
from contactsym.report.summary import summary_text

# --- random mechanisms against the complementarity problem ---------------------------------


def mechanism(G, rough, unilateral):
    """Gaps y_j with y_j'' = sum_i G_ji N_i + r_j |N_j| + b_j, and a sliding coordinate x whose Coulomb
    friction mu |N_1| acts at right angles to every gap (it enters x'' only)."""
    k = len(G)
    ys = dynamicsymbols(f"y1:{k + 1}")
    x = dynamicsymbols("x")
    N = sp.symbols(f"N1:{k + 1}", real=True)
    b = sp.symbols(f"b1:{k + 1}", real=True)
    mu = sp.Symbol("mu", positive=True)
    gaps = [
        sum(sp.Rational(G[j][i]) * N[i] for i in range(k)) + sp.Rational(rough[j]) * sp.Abs(N[j]) + b[j]
        for j in range(k)
    ]
    contacts = [cs.Contact(coordinate=ys[j], reaction=N[j], unilateral=unilateral[j]) for j in range(k)]
    scene = cs.Scene.from_accelerations([x, *ys], [-mu * sp.Abs(N[0]), *gaps], contacts)
    return scene, b


def complementarity_solutions(G, rough, unilateral, loads):
    """Every solution u of the contacts' problem, by enumerating the open one-sided contacts: the closed
    ones solve f = 0 (one-sided: |u_j| = u_j > 0; the rough two-sided ones have r_j = 0 here), the open
    ones have u_j = 0 and f_j > 0."""
    k = len(G)
    A = np.array(G, dtype=float) + np.diag([float(r) for r in rough])
    b = np.array(loads, dtype=float)
    found = []
    one_sided = [j for j in range(k) if unilateral[j]]
    for size in range(len(one_sided) + 1):
        for opened in itertools.combinations(one_sided, size):
            closed = [j for j in range(k) if j not in opened]
            u = np.zeros(k)
            if closed:
                u[closed] = np.linalg.solve(A[np.ix_(closed, closed)], -b[closed])
            f = A @ u + b
            if all(u[j] > 1e-9 for j in closed if unilateral[j]) and all(f[j] > 1e-9 for j in opened):
                found.append((opened, u))
    return found


def holds(condition, values) -> bool:
    return bool(condition.xreplace({s: sp.Float(values[s]) for s in condition.free_symbols}))


@st.composite
def mechanisms(draw):
    k = draw(st.integers(1, 3))
    W = np.array(draw(st.lists(st.lists(st.integers(-3, 3), min_size=k, max_size=k), min_size=k, max_size=k)))
    G = W.T @ W + np.eye(k, dtype=int)  # a Delassus matrix: symmetric positive definite
    unilateral = draw(st.lists(st.booleans(), min_size=k, max_size=k).filter(any))
    # friction entering a one-sided gap (its sign then fixed by the pattern); never a two-sided one's
    rough = [draw(st.sampled_from([0, 0, Fraction(1, 2), Fraction(-1, 4)])) if unilateral[j] else 0 for j in range(k)]
    return [[int(g) for g in row] for row in G], rough, unilateral


@settings(max_examples=30, deadline=None)
@given(mechanism_=mechanisms(), data=st.data())
def test_branches_and_lift_offs_are_the_complementarity_solutions(mechanism_, data):
    G, rough, unilateral = mechanism_
    scene, b = mechanism(G, rough, unilateral)
    equilibria = scene.equilibria()
    assert equilibria.patterns == [(1,) * sum(1 for r, one in zip(rough, unilateral) if one and r)]
    for _ in range(5):
        loads = data.draw(st.lists(st.floats(-5, 5).filter(lambda v: abs(v) > 1e-3), min_size=len(G), max_size=len(G)))
        values = dict(zip(b, loads))
        expected = complementarity_solutions(G, rough, unilateral, loads)
        closed = [branch for branch in equilibria.branches if holds(branch.condition, values)]
        lifted = [lift for lift in equilibria.lift_offs if holds(lift.condition, values)]
        assert len(closed) == sum(1 for opened, _ in expected if not opened), (loads, expected)
        assert sorted(lift.open for lift in lifted) == sorted(opened for opened, _ in expected if opened)
        for branch in closed:
            (u,) = [u for opened, u in expected if not opened]
            assert [float(value.xreplace(values)) for value in branch.u_star] == pytest.approx(list(u))


@settings(max_examples=15, deadline=None)
@given(mechanism_=mechanisms(), data=st.data())
def test_a_unique_count_means_one_equilibrium_in_contact_or_lifted(mechanism_, data):
    """Frictionless normals: A = G is a P-matrix, the counts say "unique", and one equilibrium exists."""
    G, _, unilateral = mechanism_
    scene, b = mechanism(G, [0] * len(G), unilateral)
    assert {name: region.condition for name, region in count_regions(scene).items()} == {"unique": sp.true}
    loads = data.draw(st.lists(st.floats(-5, 5).filter(lambda v: abs(v) > 1e-3), min_size=len(G), max_size=len(G)))
    values = dict(zip(b, loads))
    assert len(complementarity_solutions(G, [0] * len(G), unilateral, loads)) == 1
    equilibria = scene.equilibria()
    found = [e for e in (*equilibria.branches, *equilibria.lift_offs) if holds(e.condition, values)]
    assert len(found) == 1


def test_the_pushing_condition_of_a_two_contact_block():
    """Contact 1 rough (its sign fixed by the pattern), contact 2 smooth: both conditions, each once."""
    G, rough = [[2, 1], [1, 2]], [Fraction(1, 2), 0]
    scene, (b1, b2) = mechanism(G, rough, [True, True])
    (branch,) = scene.equilibria().branches
    A = sp.Matrix(G) + sp.diag(*[sp.Rational(r) for r in rough])
    u = -A.inv() * sp.Matrix([b1, b2])
    expected = sp.And(*[sp.Gt(value, 0) for value in u])
    for point in itertools.product((-2, -0.5, 1, 3), repeat=2):
        values = {b1: point[0], b2: point[1]}
        assert holds(branch.condition, values) == holds(expected, values), point
    assert len(sp.And.make_args(branch.condition)) == 2


# --- declared signs: the probe's belt and pinned rod -------------------------------------------

BELT = """
[scene]
name = "belt-block"
coordinates = ["x", "y"]

[parameters]
E = "positive"
lambda_ = "positive"
t = "{t}"
u = "real"
beta = "positive"
I = "positive"
N = "positive"

[points]
P = ["x", "y"]

[[masses]]
point = "P"
mass = "E"

[[loads]]
point = "P"
force = ["-lambda_*x + u", "-t"]

[[contacts]]
gap = "y"
reaction = "R"
unilateral = true
law = {{ name = "kelvin-voigt", stiffness = "N", damping = "I" }}
friction = {{ mu = "beta", point = "P", direction = ["-1", "0"] }}
"""

PINNED = """
[scene]
name = "pinned-rod"
coordinates = ["theta"]

[intervals]
theta = [0, "pi/2"]

[parameters]
m = "positive"
l = "positive"
g = "{g}"
h = "positive"
mu = "nonnegative"

[points]
G = ["l/2*sin(theta)", "-l/2*cos(theta)"]
A = ["l*sin(theta)", "-l*cos(theta)"]

[[bodies]]
point = "G"
angle = "theta"
mass = "m"
inertia = "m*l^2/12"

[energy]
potential = "m*g*(-l/2*cos(theta))"

[[contacts]]
gap = "h - l*cos(theta)"
reaction = "N"
unilateral = true
friction = {{ mu = "mu", point = "A", direction = ["1", "0"] }}

[at]
h = "l*cos(theta)"
"""


def belt(sign):
    return cs.read_scene(BELT.format(t=sign))


def test_a_pressing_load_of_either_sign_gives_its_condition():
    scene = belt("real")
    (branch,) = scene.equilibria().branches
    t = next(s for s in scene.parameters if s.name == "t")
    assert branch.u_star == (t,) and branch.condition == sp.Gt(t, 0)
    assert scene.equilibria().exists is None
    (lift,) = scene.equilibria().lift_offs
    mass = next(s for s in scene.parameters if s.name == "E")
    for value in (-2, -0.5, 0.5, 2):  # exactly one of the two exists: the sign of the load decides
        point = {t: value, mass: 1.5}
        assert holds(branch.condition, point) != holds(lift.condition, point)


def test_a_pulling_load_leaves_no_equilibrium_in_contact_and_no_stability_claim():
    scene = belt("negative")
    equilibria = scene.equilibria()
    assert [branch.condition for branch in equilibria.branches] == [sp.false]
    assert equilibria.exists is False and equilibria.stable(equilibria.branches[0]) == sp.false
    (lift,) = equilibria.lift_offs
    assert lift.condition == sp.true and lift.stable == sp.true
    regions = scene.regions()
    assert set(regions) == {"stable for every law", "unstable for every law", "law-dependent", "Hopf line"}
    assert all(
        region.condition == sp.false and "no stability is claimed" in region.description for region in regions.values()
    )
    data = conditions(scene)
    assert all(entry["sympy"] == "False" for entry in data["regions"].values())
    assert data["equilibria"][0]["condition"]["sympy"] == "False"
    assert "No equilibrium with every contact closed" in data["equilibria_note"]
    assert "Lift-off of contact 1: exists where True, stable where True" in data["equilibria_note"]
    assert data["equilibrium_counts"] == {"unique": {"sympy": "True", "latex": "\\text{True}"}}  # the lift-off
    for text in (summary_text(data), conditions_text(data)):
        assert "no stability is claimed" in text and "stable for every law: True" not in text
    chain = derivation_chain(scene)
    assert "exists where False" in chain and "no claim" in chain and "stable where   True" not in chain


def test_a_pulling_load_in_the_report():
    from contactsym.report.document import report_tex

    tex = report_tex(belt("negative"))
    assert "It exists nowhere where the scene is declared" in tex
    assert "No equilibrium with every contact closed exists" in tex
    assert "A one-sided contact only pushes" in report_tex(belt("real"))


def test_the_pinned_rod_without_friction_hangs_off_the_floor_when_gravity_points_up():
    up = cs.read_scene(PINNED.format(g="negative")).with_values({"mu": 0})
    (branch,) = up.equilibria().branches
    assert branch.condition == sp.false and up.equilibria().exists is False
    assert all(region.condition == sp.false for region in up.regions().values())
    down = cs.read_scene(PINNED.format(g="positive")).with_values({"mu": 0})
    (branch,) = down.equilibria().branches
    assert branch.condition == sp.true  # g m / 2 > 0: it presses, as declared
    assert down.regions()["stable for every law"].condition == sp.true


def test_friction_in_the_gap_keeps_the_condition_of_its_sign_pattern():
    """With friction the pattern fixes u > 0: the same condition as before, not repeated."""
    rough = cs.read_scene(PINNED.format(g="negative"))
    (branch,) = rough.equilibria().branches
    assert branch.signs == (1,)
    (relation,) = sp.And.make_args(branch.condition)
    assert isinstance(relation, sp.StrictGreaterThan)


def test_the_atlas_counts_no_equilibrium_in_contact_and_classifies_nothing():
    pytest.importorskip("dask")
    from contactsym import atlas

    scene = belt("negative")
    values = {"E": 1, "lambda_": 1, "u": 0, "beta": 0.5, "I": 1, "N": 1}
    ds = atlas.sweep(scene, "equilibrium_count", {"t": [-2.0, -1.0]}, values=values, scheduler="sync")
    assert ds.equilibrium_count.values.tolist() == [0.0, 0.0]
    ds = atlas.sweep(scene, "classification", {"t": [-2.0, -1.0]}, values=values, scheduler="sync")
    assert np.isnan(ds.region.values).all()
