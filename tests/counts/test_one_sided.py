"""The one-sided cases of arms whose det M is no single product, and the case split where a sign does not follow."""

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import contactsym as cs
from contactsym.counts import one_sided
from contactsym.counts.one_sided import one_sided_cases
from contactsym.counts.orthants import scene_map

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"

# Prop. 3 and the one-sided table of the module docstring: (sign b, sign a) -> equilibria
TABLE = {
    (1, -1): ("consistent", (("sliding", True),)),
    (1, 1): ("consistent", (("lift-off", True),)),
    (-1, -1): ("inconsistent", ()),
    (-1, 1): ("indeterminate", (("sliding", False), ("lift-off", True))),
}


def unilateral_double_pendulum():
    text = (EXAMPLES / "double-pendulum-tip.toml").read_text()
    text = text.replace('reaction = "N"\n', 'reaction = "N"\nunilateral = true\n')
    assert "unilateral = true" in text
    return cs.read_scene(text)


ARMS = [unilateral_double_pendulum, lambda: cs.load_scene(EXAMPLES / "two-link-arm.toml")]


@pytest.mark.parametrize("scene_of", ARMS)
def test_arms_get_the_four_cases_of_the_table(scene_of):
    scene = scene_of()
    assert scene.mass_matrix_factor is not None  # det M is no single product here
    cases = one_sided_cases(scene)
    assert len(cases) == 4 and all(case.assumed == () for case in cases)
    # at random points, the signs of b and a computed from the map itself say which case holds
    G = scene_map(scene)
    rng = np.random.default_rng(0)
    values = {"m1": 1.3, "m2": 0.7, "l1": 1.1, "l2": 0.9, "g": 9.81}
    values |= {"q1": rng.uniform(-1.5, 1.5, 400), "q2": rng.uniform(-1.5, 1.5, 400)}
    values |= {"mu": rng.uniform(0, 3, 400), "q1dot": rng.uniform(-3, 3, 400), "q2dot": rng.uniform(-3, 3, 400)}
    signs = []
    for expr in (G.plus[0], G.load[0]):
        symbols = sorted(expr.free_symbols, key=str)
        signs.append(np.sign(sp.lambdify(symbols, expr, "numpy")(*[values[str(s)] for s in symbols])))
    covered = np.zeros(400, dtype=bool)
    for case in cases:
        inside = case.region.evaluate(**{str(s): values[str(s)] for s in case.region.condition.free_symbols})
        pairs = set(zip(signs[0][inside].tolist(), signs[1][inside].tolist()))
        assert len(pairs) == 1, (case.name, pairs)  # each region is one sign case of (b, a)
        assert TABLE[pairs.pop()] == (case.name, case.equilibria)
        assert not (covered & inside).any()
        covered |= inside
    assert covered.all()


def test_an_undecided_sign_splits_the_case_in_two():
    e, f = sp.symbols("e f", real=True)

    def evaluate(known, splits):
        decided = dict(known)
        for expr in (e, f):
            if expr not in decided:
                raise one_sided._Undecided(expr)
        return decided[e] * decided[f]

    cases = one_sided._split(evaluate, ())
    assert cases == [
        (((e, 1), (f, 1)), 1),
        (((e, 1), (f, -1)), -1),
        (((e, -1), (f, 1)), -1),
        (((e, -1), (f, -1)), 1),
    ]


def test_stability_left_undecided_is_none_not_false(monkeypatch):
    # a scene whose Hurwitz conditions are multiples of b: nothing to split, every stability decided
    cases = one_sided_cases(cs.scene("painleve-rod"))
    assert all(stable in (True, False) for case in cases for _, stable in case.equilibria)
    # with the signs of a and b withheld, the sliding existence cannot be decided: it is split, not guessed
    monkeypatch.setattr(one_sided, "_sign_of", lambda expr, known, positive: dict(known).get(expr))
    split = one_sided_cases(cs.scene("painleve-rod"))
    assert any(case.assumed for case in split)
    assert all(stable in (True, False, None) for case in split for _, stable in case.equilibria)
