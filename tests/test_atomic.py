"""All-or-nothing output: a failed, refused or killed write leaves the old directory whole."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

import contactsym as cs
from benchmarks import signals as signal_trials
from contactsym import report
from contactsym.atomic import (
    MARKER,
    Interrupted,
    last_signal,
    remove_leftovers,
    replaced_directory,
    scratch_directory,
    signals_as_exceptions,
)
from contactsym.cli import main
from contactsym.errors import ContactsymError

ROOT = Path(__file__).resolve().parent.parent


def _snapshot(directory: Path) -> dict:
    return {str(p.relative_to(directory)): p.read_bytes() for p in sorted(directory.rglob("*")) if p.is_file()}


def _old_report(directory: Path) -> dict:
    """A directory that looks like an earlier contactsym report (written through replaced_directory)."""
    with replaced_directory(directory) as work:
        (work / "figures").mkdir(parents=True)
        (work / "report.tex").write_text("old tex")
        (work / "report.pdf").write_bytes(b"%PDF old")
        (work / "conditions.json").write_text("{}")
        (work / "figures" / "old.png").write_bytes(b"png")
    return _snapshot(directory)


def test_a_new_directory_appears_whole_with_its_marker(tmp_path):
    with replaced_directory(tmp_path / "out") as work:
        assert work.parent == tmp_path and work.name.startswith(".out.new-")
        (work / "a").write_text("1")
        assert not (tmp_path / "out").exists()  # nothing visible until the block ends
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [MARKER, "a"]


def test_a_marked_directory_is_replaced_and_the_old_one_removed(tmp_path):
    _old_report(tmp_path / "out")
    with replaced_directory(tmp_path / "out") as work:
        (work / "b").write_text("2")
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [MARKER, "b"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]


@pytest.mark.parametrize("failure", [RuntimeError("figures failed"), KeyboardInterrupt(), Interrupted(15)])
def test_a_failure_leaves_the_old_directory_whole(tmp_path, failure):
    before = _old_report(tmp_path / "out")
    with pytest.raises(type(failure)):
        with replaced_directory(tmp_path / "out") as work:
            (work / "report.tex").write_text("new")
            raise failure
    assert _snapshot(tmp_path / "out") == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out"]  # no temporary sibling left


def test_a_directory_contactsym_did_not_write_needs_force(tmp_path):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "report.tex").write_text("my thesis")
    with pytest.raises(ContactsymError, match="not written by contactsym.*--force"):
        with replaced_directory(mine):
            pytest.fail("the block must not run")
    assert (mine / "report.tex").read_text() == "my thesis"
    with replaced_directory(mine, force=True) as work:
        (work / "report.tex").write_text("new")
    assert (mine / "report.tex").read_text() == "new" and (mine / MARKER).exists()
    with replaced_directory(mine):  # now marked: replaced without force
        pass


def test_the_current_directory_is_never_replaced(tmp_path, monkeypatch):
    (tmp_path / "inner").mkdir()
    monkeypatch.chdir(tmp_path / "inner")
    for target in (".", "..", str(tmp_path)):
        with pytest.raises(ContactsymError, match="current directory"):
            with replaced_directory(target, force=True):
                pass
    assert (tmp_path / "inner").is_dir()


def test_a_file_in_the_way_is_an_error(tmp_path):
    (tmp_path / "out").write_text("a file")
    with pytest.raises(ContactsymError, match="not a directory"):
        with replaced_directory(tmp_path / "out", force=True):
            pass


def test_sigterm_becomes_an_exception_only_inside_the_block():
    before = signal.getsignal(signal.SIGTERM)
    with pytest.raises(Interrupted) as caught:
        with signals_as_exceptions():
            os.kill(os.getpid(), signal.SIGTERM)
            time.sleep(5)  # the handler raises before this ends
    assert caught.value.exit_code == 128 + signal.SIGTERM
    assert signal.getsignal(signal.SIGTERM) == before


# --- reports ----------------------------------------------------------------------------------------------


@pytest.mark.parametrize("step", ["report_tex", "compile_pdf"])
def test_a_report_that_fails_midway_leaves_the_old_report_whole(tmp_path, monkeypatch, step):
    target = tmp_path / "sliding-point"
    before = _old_report(target)

    def fail(*args, **kwargs):
        raise report.ReportError(f"{step} failed")

    monkeypatch.setattr(report.build, step, fail)
    with pytest.raises(report.ReportError, match=f"{step} failed"):
        report.write_report(cs.scene("sliding-point"), target, pdf=True)
    assert _snapshot(target) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sliding-point"]


@pytest.mark.skipif(shutil.which("pdflatex") is None, reason="pdflatex is not installed")
def test_a_pdflatex_failure_keeps_the_old_report_and_the_log(tmp_path, monkeypatch):
    target = tmp_path / "sliding-point"
    before = _old_report(target)
    bad = r"\documentclass{article}\begin{document}\undefinedmacro\end{document}"
    monkeypatch.setattr(report.build, "report_tex", lambda *args: bad)
    with pytest.raises(report.ReportError) as caught:
        report.write_report(cs.scene("sliding-point"), target, pdf=True)
    kept = tmp_path / "sliding-point-pdflatex.log"
    assert "Undefined control sequence" in str(caught.value) and str(kept) in str(caught.value)
    assert "previous report is unchanged" in str(caught.value) and ".new-" not in str(caught.value)
    assert "undefinedmacro" in kept.read_text(errors="replace")
    assert _snapshot(target) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sliding-point", "sliding-point-pdflatex.log"]


def test_a_report_replaces_its_own_old_report_but_not_a_users_files(tmp_path):
    target = tmp_path / "sliding-point"
    _old_report(target)
    result = report.write_report(cs.scene("sliding-point"), target, pdf=False)
    assert result.tex == target / "report.tex" and result.tex.read_text().startswith(r"\documentclass")
    assert not (target / "report.pdf").exists() and not (target / "figures" / "old.png").exists()
    assert all(f.path.parent == target / "figures" and f.path.exists() for f in result.figures)
    (target / MARKER).unlink()  # as if the user had written this directory
    before = _snapshot(target)
    with pytest.raises(report.ReportError, match="--force"):
        report.write_report(cs.scene("sliding-point"), target, pdf=False)
    assert _snapshot(target) == before
    assert report.write_report(cs.scene("sliding-point"), target, pdf=False, force=True).tex.exists()


def test_cli_report_refuses_a_users_directory_and_an_empty_out(capsys, tmp_path):
    mine = tmp_path / "brake"
    mine.mkdir()
    (mine / "report.tex").write_text("my thesis")
    assert main(["report", "brake", "--out", str(tmp_path), "--no-pdf"]) == 1
    err = capsys.readouterr().err
    assert "not written by contactsym" in err and len(err.strip().splitlines()) == 1
    assert (mine / "report.tex").read_text() == "my thesis"
    assert main(["report", "brake", "--out", ""]) == 2
    assert "the path is empty" in capsys.readouterr().err


def test_cli_bench_checks_its_paths_before_running(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    started = time.perf_counter()
    assert main(["bench", "--quick", "--json", str(tmp_path / "missing" / "x.json")]) == 1
    assert "cannot write --json" in capsys.readouterr().err
    assert main(["bench", "--quick", "--out", ""]) == 2
    (tmp_path / "contactsym-bench").mkdir()
    (tmp_path / "contactsym-bench" / "notes.md").write_text("mine")
    assert main(["bench", "--quick"]) == 1  # the default folder exists and is not contactsym's
    assert "--force" in capsys.readouterr().err
    assert time.perf_counter() - started < 10  # no benchmark ran
    assert sorted(p.name for p in tmp_path.iterdir()) == ["contactsym-bench"]


def test_sigterm_during_a_cli_report_leaves_no_mix_and_no_temporary_files(tmp_path):
    out, scratch = tmp_path / "reports", tmp_path / "tmp"
    scratch.mkdir()
    before = _old_report(out / "sliding-point")
    env = {
        **os.environ,
        "TMPDIR": str(scratch),
        "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""),
    }
    command = [sys.executable, "-m", "contactsym", "report", "sliding-point", "--out", str(out), "--no-pdf"]
    child = subprocess.Popen(command, env=env, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    try:
        for line in child.stderr:  # wait until the report is being written
            if "sliding-point: conditions" in line:
                break
        child.send_signal(signal.SIGTERM)
        child.wait(timeout=60)
    finally:
        child.kill()
    assert child.returncode == 128 + signal.SIGTERM
    assert _snapshot(out / "sliding-point") == before  # the old report, whole
    assert sorted(p.name for p in out.iterdir()) == ["sliding-point"]  # no temporary sibling
    assert list(scratch.iterdir()) == []  # no contactsym-figures-* left behind


# --- force is a bool; a user's file is never touched without force=True ---------------------------------


@pytest.mark.parametrize("force", ["no", "yes", 1, 0, None, [], "False"])
def test_force_must_be_a_bool_and_a_wrong_one_touches_nothing(tmp_path, force):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "thesis.tex").write_text("two years of work")
    before = _snapshot(mine)
    with pytest.raises(report.ReportError, match="force = .* must be True or False"):
        cs.write_report(cs.scene("sliding-point"), mine, pdf=False, force=force)
    with pytest.raises(ContactsymError, match="must be True or False"):
        with replaced_directory(mine, force=force):
            pytest.fail("the block must not run")
    assert _snapshot(mine) == before and sorted(p.name for p in tmp_path.iterdir()) == ["mine"]


@pytest.mark.parametrize("pdf", ["no", None, 0])
def test_every_flag_of_write_report_is_a_bool(tmp_path, pdf):
    with pytest.raises(report.ReportError, match="pdf = .* must be True or False"):
        cs.write_report(cs.scene("sliding-point"), tmp_path / "out", pdf=pdf)
    assert list(tmp_path.iterdir()) == []


def test_a_users_file_added_to_a_report_directory_is_kept_without_force(tmp_path):
    target = tmp_path / "sliding-point"
    _old_report(target)
    (target / "thesis.tex").write_text("mine")
    (target / "figures" / "sketch.png").write_bytes(b"mine too")
    before = _snapshot(target)
    with pytest.raises(report.ReportError, match="'figures/sketch.png' \\(and 1 more\\), which contactsym did not"):
        cs.write_report(cs.scene("sliding-point"), target, pdf=False)
    assert _snapshot(target) == before
    cs.write_report(cs.scene("sliding-point"), target, pdf=False, force=True)
    assert not (target / "thesis.tex").exists()  # replaced, as asked


def test_a_marker_without_the_list_of_written_files_needs_force(tmp_path):
    old = tmp_path / "old"
    old.mkdir()
    (old / MARKER).write_text("Written by contactsym; the next report replaces this directory.\n")
    (old / "report.tex").write_text("could be anyone's")
    with pytest.raises(ContactsymError, match="listing what contactsym wrote"):
        with replaced_directory(old):
            pass
    assert (old / "report.tex").read_text() == "could be anyone's"


def test_new_folders_follow_the_umask(tmp_path):
    previous = os.umask(0o027)
    try:
        with replaced_directory(tmp_path / "out") as work:
            (work / "sub").mkdir()
        with scratch_directory() as scratch:
            scratch_mode = scratch.stat().st_mode & 0o777
    finally:
        os.umask(previous)
    assert (tmp_path / "out").stat().st_mode & 0o777 == 0o750
    assert (tmp_path / "out" / "sub").stat().st_mode & 0o777 == 0o750
    assert scratch_mode == 0o750


# --- leftovers of killed runs ---------------------------------------------------------------------------


def _dead_pid() -> int:
    child = subprocess.Popen([sys.executable, "-c", "pass"])
    child.wait()
    return child.pid


def test_the_next_run_removes_what_a_killed_run_left_and_nothing_else(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    monkeypatch.setattr(tempfile, "tempdir", None)  # TMPDIR is read again
    host = signal_trials_host()
    dead, alive = _dead_pid(), os.getpid()
    stale = [tmp_path / f".out.new-{host}-{dead}-abc", tmp_path / f".out.old-{host}-{dead}-def"]
    stale += [tmp_path / "tmp" / f"contactsym-figures-{host}-{dead}-ghi"]
    kept = [tmp_path / f".out.new-{host}-{alive}-jkl", tmp_path / f".out.new-otherhost-{dead}-mno"]
    kept += [tmp_path / ".out.new-abcdefgh", tmp_path / f".mine.new-{host}-{dead}-pqr"]
    for folder in stale + kept:
        folder.mkdir()
        (folder / "report.tex").write_text("partial")
    with replaced_directory(tmp_path / "out") as work, scratch_directory():
        (work / "a").write_text("1")
    assert not any(p.exists() for p in stale) and all(p.exists() for p in kept)
    assert remove_leftovers(tmp_path, ".out.new-") == []


def signal_trials_host() -> str:
    return "".join(c for c in __import__("socket").gethostname() if c.isalnum())[:32] or "host"


@pytest.fixture(scope="module")
def startup() -> float:
    """The interpreter's own start-up (site, before any line of contactsym): signals come after it."""
    return signal_trials.interpreter_startup() + 0.05


@pytest.mark.parametrize("delay", [0.3, 2.5])
def test_kill_9_leftovers_are_removed_by_the_next_run(tmp_path, delay, startup):
    passed, detail = signal_trials.kill_trial(tmp_path, startup + delay)
    assert passed, detail


@pytest.mark.parametrize("delay", [0.0, 0.2, 1.0, 3.0])  # 0 and 0.2: while contactsym imports
def test_sigint_stops_the_command_line_with_130_and_no_traceback(tmp_path, delay, startup):
    passed, detail = signal_trials.sigint_trial(tmp_path, startup + delay)
    assert passed, detail


class _InterruptedFinalizer:
    def __del__(self):
        raise KeyboardInterrupt  # what a SIGINT landing in a finalizer looks like


def test_an_interrupt_swallowed_by_a_finalizer_still_stops_the_block(capfd):
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        with signals_as_exceptions():
            _InterruptedFinalizer()  # collected at once: Python calls the unraisable hook
            time.sleep(5)  # the interrupt is delivered again and ends the sleep
    assert time.monotonic() - started < 4, "the interrupt waited for the sleep to end"
    assert "Exception ignored" not in capfd.readouterr().err


def test_the_command_line_reports_a_signal_that_arrived_even_if_the_run_finished(monkeypatch, capsys):
    import contactsym.cli as cli

    def run_swallowing(args):
        try:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(1)
        except KeyboardInterrupt:
            pass  # as a finalizer or a careless except would
        return 0

    monkeypatch.setattr(cli, "_run", run_swallowing)
    assert main(["list"]) == 130
    assert last_signal() == signal.SIGINT and "interrupted" in capsys.readouterr().err
