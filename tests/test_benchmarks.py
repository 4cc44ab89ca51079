"""The record format of the benchmarks (benchmarks/__init__.py)."""


def test_benchmark_record_format_smoke():
    # the benchmarks themselves never run in the test suite; only their record format is checked
    from benchmarks import record
    from benchmarks.run import markdown

    r = record("demo", 0.5, 2.0, 0, 10, "a | note")
    assert set(r) == {"name", "ours_s", "baseline_s", "ratio", "error", "n", "notes"}
    assert r["ratio"] == 4.0
    table = markdown([r, record("missing", 1.0, None, None, 1, "")], quick=True, seconds=1.0)
    assert "| demo | 0.5 | 2 | 4 | 0 | 10 | a / note |" in table and "| missing | 1 | - | - | - | 1 |  |" in table


def test_benchmark_table_header_says_wall_cpu_load_and_modules():
    from benchmarks import record
    from benchmarks.run import markdown

    table = markdown(
        [record("demo", 0.5, 2.0, 0, 10, "")], True, 170.0, 151.0, [("squeal", 30.4, 25.6)], ("1.5", "2.0")
    )
    header = table.splitlines()[2]
    assert "170 s wall in all (151 CPU s)" in header and "load average 1.5 at the start, 2.0 at the end" in header
    assert "Per module, wall / CPU s: squeal 30 / 26." in table


def test_parallel_runs_are_said_in_the_table_and_every_module_has_a_place_in_the_order():
    import pytest

    from benchmarks import BENCHMARKS, record
    from benchmarks.run import LONGEST_FIRST, main, markdown

    header = markdown([record("demo", 0.5, 2.0, 0, 10, "")], True, 170.0, 300.0, jobs=2).splitlines()[2]
    assert "2 modules at a time, each in a fresh interpreter" in header
    assert "one after the other" in markdown([], False, 1.0).splitlines()[2]
    assert sorted(LONGEST_FIRST) == sorted(BENCHMARKS)  # the schedule knows every module
    with pytest.raises(SystemExit):
        main(["--jobs", "0", "--only"])  # refused before anything runs
