"""All-or-nothing output: a failed, refused or killed write leaves the old directory whole."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

import contactsym as cs
from contactsym import report
from contactsym.atomic import MARKER, Interrupted, replaced_directory, signals_as_exceptions
from contactsym.cli import main
from contactsym.errors import ContactsymError

ROOT = Path(__file__).resolve().parent.parent


def _snapshot(directory: Path) -> dict:
    return {str(p.relative_to(directory)): p.read_bytes() for p in sorted(directory.rglob("*")) if p.is_file()}


def _old_report(directory: Path) -> dict:
    """A directory that looks like an earlier contactsym report."""
    (directory / "figures").mkdir(parents=True)
    (directory / "report.tex").write_text("old tex")
    (directory / "report.pdf").write_bytes(b"%PDF old")
    (directory / "conditions.json").write_text("{}")
    (directory / "figures" / "old.png").write_bytes(b"png")
    (directory / MARKER).write_text("")
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
    with pytest.raises(report.ReportError, match="--force"):
        report.write_report(cs.scene("sliding-point"), target, pdf=False)
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
