"""Count regions of the built-in scenes on orthant maps, lift-off included, against brute force.

The brute force uses only the derived f (lambdified with its Abs terms): on every
combination of sides (u_j > 0 or < 0 for a bilateral contact, closed u_j > 0 or open
u_j = 0 with f_j > 0 for a unilateral one) the affine piece is measured by finite
differences, solved with the open gaps' accelerations as slacks, and the solution kept
when its signs match. A random constant added to f plays the load (it spans R^k).
"""

import itertools
import zlib

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.counts.orthants import scene_map
from contactsym.errors import ContactsymError
from tests.helpers import variant

ALLOWED = {
    "unique": {1},
    "unique stable": {1},
    "unique unstable": {1},
    "two or none": {0, 2},
    "one or three": {1, 3},
    "none, two or four": {0, 2, 4},
}

#: Sampling ranges by symbol name; other symbols: (-3, 3).
RANGES = {"theta": (0.05, 1.5), "alpha": (0.1, 3.0), "thetadot": (-3, 3)}
SCENES = [
    "brake",
    "double-pendulum-tip",
    "painleve-rod",
    "painleve-rod-bilateral",
    "two-leg-block",
    "two-leg-block-unilateral",
]
# the paper's rod (corners off 0) and guides (presented in v_j, kappa) are checked so in test_counts.py


def sample(symbols, n, rng):
    values = {}
    for s in symbols:
        low, high = RANGES.get(str(s), (0.05, 3.0) if s.is_positive else (-3.0, 3.0))
        values[str(s)] = rng.uniform(low, high, n)
    return values


def brute_counts(scene, values, loads):
    """Solutions for parameter arrays (n,) and loads (n, m, k); -1 where a solution sits on a face."""
    fast = scene.fast_subsystem()
    u, k = fast.u, scene.k
    symbols = sorted(set().union(*(e.free_symbols for e in fast.f)) - set(u), key=str)
    f = sp.lambdify((*u, *symbols), list(fast.f), "numpy")
    n = loads.shape[0]
    args = [values[str(s)] for s in symbols]

    def at(point):
        return np.stack([np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in f(*point, *args)], axis=-1)

    unilateral = [c.unilateral for c in scene.contacts]
    counts = np.zeros(loads.shape[:-1], dtype=int)
    edge = np.zeros(loads.shape[:-1], dtype=bool)
    for sides in itertools.product((1, -1), repeat=k):
        opened = [unilateral[j] and s < 0 for j, s in enumerate(sides)]
        base = [0.0 if o else float(s) for o, s in zip(opened, sides)]
        f0 = at(base)
        columns = []
        for j in range(k):
            if opened[j]:
                columns.append(np.broadcast_to(-np.eye(k)[j], (n, k)))  # -slack_j
            else:
                step = list(base)
                step[j] += 0.5 * sides[j]
                columns.append((at(step) - f0) / (0.5 * sides[j]))
        M = np.stack(columns, axis=-1)  # unknowns: u_j - base_j (closed), slack_j (open)
        rhs = -(f0[:, None, :] + loads)
        x = np.linalg.solve(np.broadcast_to(M[:, None], loads.shape + (k,)), rhs[..., None])[..., 0]
        value = np.where(opened, x, x + np.array(base))  # u_j, or the slack of an open contact
        signed = value * np.where(opened, 1, sides)
        scale = 1e-8 * (1 + np.abs(loads).max(axis=-1, keepdims=True))
        counts += np.all(signed > scale, axis=-1)
        edge |= np.any(np.abs(signed) <= scale, axis=-1)
    return np.where(edge, -1, counts)


def labels(scene, values):
    regions = scene.equilibrium_counts()
    names = np.full(len(next(iter(values.values()))), "", dtype=object)
    for name, region in regions.items():
        inside = region.evaluate(**{s: values[s] for s in region.symbol_names})
        assert not np.any(inside & (names != "")), "two count regions overlap"
        names[np.broadcast_to(inside, names.shape)] = name
    return names


@pytest.mark.parametrize("name", SCENES)
def test_scene_count_regions_against_brute_force(name):
    scene = variant(name)
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    fast = scene.fast_subsystem()
    symbols = sorted(set().union(*(e.free_symbols for e in fast.f)) - set(fast.u), key=str)
    values = sample(symbols, 4000, rng)
    names = labels(scene, values)
    assert set(names) - {""} == set(scene.equilibrium_counts())  # every region is met
    for label in set(names) - {""}:
        chosen = np.flatnonzero(names == label)[:200]
        per_point = max(50, 10_000 // len(chosen) + 1)
        picked = {s: v[chosen] for s, v in values.items()}
        loads = rng.normal(size=(len(chosen), per_point, scene.k)) * np.exp(
            rng.normal(0, 1.5, (len(chosen), per_point, 1))
        )
        counts = brute_counts(scene, picked, loads)
        decided = counts[counts >= 0]
        assert decided.size >= 10_000
        assert set(decided.tolist()) <= ALLOWED[label], (name, label, set(decided.tolist()))  # 0 disagreements
        assert set(decided.tolist()) == ALLOWED[label], (name, label)  # every count of the label occurs


def test_block_counter_example_is_two_or_none():
    block = cs.scene("two-leg-block")
    point = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)
    (name,) = [n for n, r in block.equilibrium_counts().items() if r.contains(**{s: point[s] for s in r.symbol_names})]
    assert name == "two or none"
    # the issue's loads, brute force: (Y, M) = (-24.5, -3.1) none, (0, 5) two
    values = {k: np.array([v, v]) for k, v in point.items()}
    values.update(Y=np.array([-24.5, 0.0]), M=np.array([-3.1, 5.0]))
    assert brute_counts(block, values, np.zeros((2, 1, 2)))[:, 0].tolist() == [0, 2]


def test_block_region_of_the_issue_has_a_negative_orthant_and_degree_zero():
    block = cs.scene("two-leg-block")
    a, b, mu1, mu2 = sp.symbols("a b mu_1 mu_2", positive=True)
    region = block.equilibrium_counts()["two or none"].condition
    assert sp.And(2 * a < b * (mu1 + mu2), sp.Abs(b * mu1 - b * mu2) < 2 * a) in sp.Or.make_args(region)
    assert "one or three" not in block.equilibrium_counts()


def test_unilateral_map_has_the_gap_as_slack():
    rod = scene_map(cs.scene("painleve-rod"))
    assert rod.minus == sp.Matrix([[1]]) and rod.unilateral == (True,)
    block = scene_map(variant("two-leg-block-unilateral"))
    assert block.minus == sp.eye(2)
    # the orthant determinants are the principal minors of A
    A = block.plus
    assert sp.simplify(block.determinant((1, -1)) - A[0, 0]) == 0
    assert block.determinant((-1, -1)) == 1


def test_two_corners_on_one_contact_are_refused_by_the_orthant_map():
    with pytest.raises(ContactsymError, match="two corners"):
        scene_map(cs.scene("painleve-klein-rod"))
