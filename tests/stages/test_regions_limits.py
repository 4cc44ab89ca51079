"""The size limits of contactsym.stages.regions (RAW_OPS, FACTOR_TERMS) change the presentation, never the region."""

from __future__ import annotations

import numpy as np
import sympy as sp

from benchmarks._derive_worker import generic_scene
from contactsym.stages import regions


def _samples(found: dict, n: int = 2000) -> dict:
    rng = np.random.default_rng(1)
    names = sorted({str(s) for r in found.values() for s in r.condition.free_symbols})
    # Phi, Psi are negative in every scene; the rest normal
    return {x: -rng.exponential(size=n) if x[:3] in ("Phi", "Psi") else rng.normal(size=n) for x in names}


def test_limits_keep_every_region(monkeypatch):
    reduced = generic_scene(2).regions()
    monkeypatch.setattr(regions, "RAW_OPS", 20)
    monkeypatch.setattr(regions, "FACTOR_TERMS", 2)
    limited = generic_scene(2).regions()
    assert set(limited) == set(reduced)
    assert any(str(limited[n].condition) != str(reduced[n].condition) for n in reduced)  # the limits did act
    values = _samples(reduced)
    for name, region in reduced.items():
        ours = region.evaluate(**{str(s): values[str(s)] for s in region.condition.free_symbols})
        kept = limited[name].evaluate(**{str(s): values[str(s)] for s in limited[name].condition.free_symbols})
        assert np.array_equal(ours, kept), name


def test_raw_relation_is_the_derived_one(monkeypatch):
    x, y = sp.symbols("x y", real=True)
    condition = sp.Gt((x + y) ** 3 - x * y, 0)
    monkeypatch.setattr(regions, "RAW_OPS", 3)
    assert regions.closed_form(condition) == condition
