"""The classifier's fused float32 loop (numba, ``contactsym[fast]``): the results of the NumPy passes, exactly.

The loop is compiled once per classifier and layout (a second or two each): these tests share one brake
classifier and a few layouts, on one xdist worker, and force the loop on small calls by lowering the
threshold.
"""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym import numerics as nm
from contactsym.numerics import fused

pytestmark = pytest.mark.xdist_group("fused")  # one worker compiles the loop's few layouts once

BRAKE = cs.scene("brake").stability()
NAMES = ["alpha", "m", "mu", "Phi_1", "Phi_2", "Psi_1", "Psi_2"]
PARAMETERS = [{str(s): s for s in set().union(*[h.free_symbols for h in BRAKE.hurwitz])}[n] for n in NAMES]
CLASSIFIER = nm.PointClassifier(BRAKE.hurwitz, PARAMETERS)


def _points(rng, n, on_line):
    """Random brake points; ``on_line`` of them on the Hopf line of the (6.4) slice in floats (in the band)."""
    values = [rng.uniform(0.05, 3.0, n), rng.uniform(0.2, 5, n), rng.uniform(0.05, 3, n)]
    values += list(-np.exp(rng.normal(0, 1.5, (4, n))))
    alpha, m, mu, phi1, phi2, psi1, psi2 = values
    line = rng.choice(n, on_line, replace=False)
    alpha[line], psi2[line] = math.pi / 2, psi1[line]
    phi1[line] = phi2[line] = -(1 + mu[line] ** 2) * psi1[line] ** 2 / (m[line] * mu[line] ** 2)
    return values


def _numpy_paths():
    """The classifier without the fused loop: its NumPy float32 pass, and float64 throughout."""
    single = copy.copy(CLASSIFIER)
    single._fused_run = lambda size, given: None
    float64 = copy.copy(CLASSIFIER)
    float64._single = False
    return single, float64


def _same(ours, theirs) -> bool:
    return (
        np.array_equal(ours.stable, theirs.stable)
        and np.array_equal(ours.signs, theirs.signs)
        and np.array_equal(ours.in_band, theirs.in_band)
        and ours.exact_points == theirs.exact_points
    )


@pytest.fixture
def always_fused(monkeypatch):
    pytest.importorskip("numba")
    monkeypatch.setattr(fused, "FUSED_MIN_POINTS", 1)
    taken = []
    run = fused.FusedPass.run
    monkeypatch.setattr(fused.FusedPass, "run", lambda self, *a: (taken.append(1), run(self, *a))[1])
    return taken


@settings(
    max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture]
)
@given(
    st.integers(0, 2**32 - 1), st.integers(1, 97), st.booleans(), st.sampled_from(["none", "tiny", "huge", "subnormal"])
)
def test_the_fused_loop_gives_the_numpy_results(always_fused, seed, chunk, lone, odd):
    """Random points, some on the Hopf line; chunks of any length (a last chunk of one point); alpha and Psi_2 of
    one value (stride 0) with sin(alpha) given, or arrays with sin(alpha) computed; values outside float32's
    range (a chunk that raises a status flag: the checked loop), or the checked loop throughout: the fused
    loop's stable, signs, band and exact count are those of float64 throughout, array for array."""
    rng = np.random.default_rng(seed)
    n = 3 * chunk + 1
    values = _points(rng, n, on_line=2)
    if lone:  # (the layouts are few: each compiles anew)
        values = [np.broadcast_to(v[:1], (n,)) if i in (0, 6) else v for i, v in enumerate(values)]
    elif odd != "none":  # a value float32 cannot hold (or only as a subnormal number), at a random point
        k, index = rng.integers(n), rng.integers(1, 7)
        values[index][k] = math.copysign({"tiny": 1e-50, "huge": 1e50, "subnormal": 1e-40}[odd], values[index][k])
    functions = [np.sin(values[0])] if lone else None
    flags = fused._status_flags
    if not lone and odd == "none" and seed % 2:  # status flags not readable here: the checked loop only
        fused._status_flags = lambda: None
    try:
        ours = CLASSIFIER(*values, chunk=chunk, function_values=functions)
    finally:
        fused._status_flags = flags
    assert always_fused
    assert _same(ours, _numpy_paths()[1](*values, chunk=chunk, function_values=functions))


@pytest.mark.parametrize("constant", [(0,), (0, 2, 6), (1, 3, 4, 5)])
def test_arguments_of_one_value_are_read_once_with_the_same_results(always_fused, constant):
    """Parameters of one value for every point (stride 0, as an atlas passes its fixed values), alpha among them
    with sin(alpha) computed from it: the loop reads each once (its own layout) and gives the NumPy results."""
    n = 301
    values = _points(np.random.default_rng(11), n, on_line=3)
    values = [np.broadcast_to(v[:1], (n,)) if i in constant else v for i, v in enumerate(values)]
    ours = CLASSIFIER(*values, chunk=64)
    assert always_fused
    assert _same(ours, _numpy_paths()[1](*values, chunk=64))


@pytest.mark.parametrize("bad", [np.nan, np.inf, -np.inf, 0.0, 1.0])
def test_values_the_classifier_refuses_are_refused_with_the_same_error(always_fused, bad):
    """NaN, infinities and values that break a declared sign, in a later chunk: the same error as without numba."""
    values = _points(np.random.default_rng(5), 200, on_line=0)
    values[5][150] = bad  # Psi_1, declared negative
    errors = []
    for classify in (CLASSIFIER, _numpy_paths()[0]):
        with pytest.raises(cs.errors.NumericsError) as error:
            classify(*values, chunk=64)
        errors.append(str(error.value))
    assert errors[0] == errors[1] and "Psi_1" in errors[0]
    assert always_fused


def test_the_loop_computes_the_numpy_pass_s_float32_values_bit_for_bit(always_fused):
    """Points within a few float32 units of the sign test's threshold (on the Hopf line moved by about the test's
    width): the loop's signs are the NumPy float32 pass's, point for point; an operation rounded otherwise
    (a fused multiply-add, float64 arithmetic, a constant rounded otherwise) would move some of them."""
    import numba  # noqa: F401 - the loop's compiler, imported only to skip without it (the fixture)

    n = 4096
    rng = np.random.default_rng(7)
    values = _points(rng, n, on_line=n)
    width = CLASSIFIER._single_widths[0][1]
    values[3] = values[4] = values[3] * (1 + width * np.linspace(-3, 3, n))
    for v in values:  # read-only, as the classifier passes its inputs: the layout compiled for the test above
        v.flags.writeable = False
    single, fast = CLASSIFIER._single_pass, CLASSIFIER._fused
    theirs = np.empty((2, n), dtype=np.int8)
    assert single.run(values, [None], theirs)
    assert {-1, 0, 1} <= set(theirs[1].tolist())  # both sides of the threshold are met
    functions = fast._functions(values, n)
    for kernel in fast.kernel(False):  # unchecked, checked
        ours = np.empty((2, n), dtype=np.int8)
        assert not kernel(*values, *functions, *ours)
        assert np.array_equal(ours, theirs)
        ir = "\n".join(kernel.inspect_llvm().values())
        assert "fmuladd" not in ir and "llvm.fma" not in ir and " contract " not in ir and " fast " not in ir


def test_the_status_flags_see_what_numpy_s_errstate_sees(always_fused):
    """Cleared, then a clean chunk: not raised; an underflow in the compiled loop: raised (where they can be read)."""
    flags = fused._status_flags()
    if flags is None:
        pytest.skip("no floating-point status flags read on this platform: the checked loop runs throughout")
    clear, raised = flags
    unchecked, _ = CLASSIFIER._fused.kernel(False)
    out = np.empty((2, 64), dtype=np.int8)
    for m in (1.0, 2e-38):  # a normal float32 number; m * Phi_1**2 underflows
        values = _points(np.random.default_rng(2), 64, on_line=0)
        values[1][7], values[3][7] = m, -0.5
        functions = CLASSIFIER._fused._functions(values, 64)
        for v in values:
            v.flags.writeable = False
        clear()
        unchecked(*values, *functions, *out)
        assert raised() == (m < 1)


def test_without_numba_or_below_the_threshold_the_numpy_passes_run(monkeypatch):
    values = _points(np.random.default_rng(3), 100, on_line=2)
    expected = _numpy_paths()[1](*values)
    monkeypatch.setattr(fused, "FUSED_MIN_POINTS", 1)
    monkeypatch.setattr(fused, "available", lambda: False)
    monkeypatch.setattr(fused.FusedPass, "run", lambda *a: pytest.fail("the fused loop ran"))
    assert _same(CLASSIFIER(*values), expected)
    monkeypatch.setattr(fused, "available", lambda: True)
    monkeypatch.setattr(fused, "FUSED_MIN_POINTS", 101)
    assert _same(CLASSIFIER(*values), expected)
