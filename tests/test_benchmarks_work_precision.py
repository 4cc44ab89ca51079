"""The decision rules of the work-precision benchmark (the benchmark itself never runs here)."""

import doctest
import math

from benchmarks import work_precision as wp


def test_doctests_of_the_decision_rules():
    assert doctest.testmod(wp, optionflags=doctest.NORMALIZE_WHITESPACE).failed == 0


def test_equal_error_holds_both_systems_to_the_same_bound():
    eps0 = 1e-4
    reduced = [(eps0, 1e-3, 1e-4, 1e-7, 26), (eps0, 1e-8, 3e-4, 6e-9, 38), (eps0, 1e-10, 5e-4, 5e-9, 62)]
    rows = [
        (eps0, "Radau", True, 1e-6, 0.010, 1.01e-8, 500, True),  # just above 2 x 5e-9: does not count
        (eps0, "LSODA", True, 1e-9, 0.008, 3e-9, 500, True),
        (eps0, "BDF", False, 1e-9, 0.001, 1e-9, 500, False),  # failed runs never count
        (1e-2, "LSODA", True, 1e-9, 0.0001, 1e-12, 500, True),  # another eps never counts
    ]
    found = wp.equal_error_speed(rows, reduced, eps0)
    assert found["target"] == 1e-8
    assert found["reduced"][1] == 1e-8 and found["reduced_cpu"] == 3e-4  # the 1e-7 run misses the bound
    assert found["full"][1] == "LSODA" and found["full_cpu"] == 0.008
    assert math.isnan(wp.equal_error_speed(rows[:1], reduced, eps0)["full_cpu"])


def test_rhs_summary_leaves_out_failed_pairs_and_reports_them():
    pairs = [
        ("Radau", 1e-3, 100, 110, 3, 3, True),
        ("Radau", 1e-9, 100, 400_001, 3, 0, False),
        ("BDF", 1e-3, 50, 150, 1, 9, True),
        ("LSODA", 1e-3, 40, 40, 0, 0, True),
    ]
    s = wp.rhs_summary(pairs)
    assert (s["analytic"], s["fd"], s["n"]) == (150, 260, 2)
    assert s["failed"] == [("Radau", 1e-9)]
    assert s["per_solver"] == {"Radau": 1.1, "BDF": 3.0, "LSODA": 1.0}
    assert "not reached (1.73x)" in wp._rhs_notes("demo", s, [1e-3])


def test_quick_retimes_only_the_full_runs_that_can_decide_the_ratio():
    eps0 = 1e-4
    reduced = [(eps0, 1e-8, 3e-4, 5e-9, 38)]  # target 1e-8
    rows = [
        (eps0, "LSODA", True, 1e-9, 0.008, 3e-9, 500, True, 1),  # the cheapest reaching the target
        (eps0, "Radau", True, 1e-9, 0.015, 2e-9, 500, True, 1),  # within 2x: timed again
        (eps0, "BDF", True, 1e-9, 0.020, 2e-9, 500, True, 1),  # beyond 2x: kept as timed once
        (eps0, "BDF", False, 1e-6, 0.001, 1e-6, 500, True, 1),  # misses the target
    ]
    timed = []

    class Run:
        cpu_s = 0.004

    def simulate(method, analytic, rtol, budget):
        timed.append((method, analytic, rtol))
        return Run()

    assert wp._retime_candidates(rows, reduced, simulate, 1000) == 2
    assert set(timed) == {("LSODA", True, 1e-9), ("Radau", True, 1e-9)} and len(timed) == 2 * wp.DECISIVE_REPEAT
    assert [r[4] for r in rows] == [0.004, 0.004, 0.020, 0.001]
    assert rows[0][5:] == (3e-9, 500, True, 1)  # error, counts and success untouched
