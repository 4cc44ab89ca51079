"""Counts at numeric points: the API, the k = 3 decision against brute force, undecided points, the plot."""

import matplotlib
import numpy as np
import pytest

import contactsym as cs
from benchmarks.counts import stool_scene
from contactsym.errors import ContactsymError
from contactsym.plotting.counts import count_equilibria, count_map_data, count_map_plot, decide_counts

matplotlib.use("Agg")

BLOCK = dict(m=1.838, J=0.5558, a=0.6912, b=0.5569, mu_1=1.5555, mu_2=1.3973)


def test_a_vanishing_determinant_is_undecided_with_its_reason():
    block = cs.scene("two-leg-block")
    on_boundary = {**BLOCK, "a": 0.5, "b": 1.0, "mu_1": 0.5, "mu_2": 0.5}  # 2 a = b (mu_1 + mu_2)
    decision = decide_counts(block, **on_boundary)
    assert decision.label == "undecided" and "vanishes" in decision.method and not decision.counts


def test_missing_or_bad_values_are_refused():
    block = cs.scene("two-leg-block")
    with pytest.raises(ContactsymError, match="mu_2"):
        decide_counts(block, **{k: v for k, v in BLOCK.items() if k != "mu_2"})
    with pytest.raises(ContactsymError, match="finite"):
        count_equilibria(block, Y=np.nan, M=0.0, **BLOCK)
    with pytest.raises(ContactsymError, match="not finite"):
        decide_counts(block, **{**BLOCK, "m": 0.0})
    with pytest.raises(ContactsymError, match="plain symbols"):
        count_equilibria(cs.scene("sliding-point"), m=1.0)


def test_k3_decisions_agree_with_random_loads():
    """Fully symbolic k = 3: the counts found in every cell contain those of random loads, with the degree's parity."""
    scene = stool_scene()
    rng = np.random.default_rng(3)
    names = [f"{x}_{i}{j}" for x in "ac" for i in range(1, 4) for j in range(1, 4)]
    labels = set()
    for _ in range(25):
        point = dict(zip(names, rng.normal(size=18)))
        decision = decide_counts(scene, **point)
        loads = {f"b_{i}": rng.normal(size=400) * 3 for i in range(1, 4)}
        counts, undecided = count_equilibria(scene, **point, **loads)
        found = set(counts[~undecided].tolist())
        assert found <= decision.counts
        assert all(c % 2 == abs(decision.degree) % 2 for c in found)
        labels.add(decision.label)
    assert "unique" in labels and len(labels) >= 2


def test_count_map_data_and_plot():
    data = count_map_data(cs.scene("two-leg-block"), "Y", "M", (-30, 30), (-10, 10), size=31, **BLOCK)
    assert set(data.counts.ravel().tolist()) - {-1} == {0, 2}
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots()
    artists = count_map_plot(data, ax=ax)
    assert len(artists) == 2 and ax.get_xlabel() == "Y"
    plt.close(fig)
