"""The command line, run in-process: files written, exit codes, one-line errors, JSON contents."""

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import contactsym as cs
from contactsym.cli import main, parse_signs
from contactsym.command_line.output import derivation_chain
from tests.report.test_derivation import NEUTRAL, block

ROOT = Path(__file__).resolve().parents[1]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def one_line_error(err: str) -> str:
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert "error" in lines[0] and "Traceback" not in err
    return lines[0]


def test_list(capsys):
    code, out, err = run(capsys, "list")
    assert code == 0 and err == ""
    assert [line.split()[0] for line in out.splitlines()] == cs.scene_names()


def test_list_prints_each_built_scene_description_without_building_it(capsys, monkeypatch):
    from contactsym import scenes

    expected = [f"{name:24s}{cs.scene(name).description}" for name in cs.scene_names()]
    monkeypatch.setattr(scenes, "_built", {})  # a build during `list` would fill it
    code, out, _ = run(capsys, "list")
    assert code == 0 and out.splitlines() == expected and scenes._built == {}


def test_help_exits_zero(capsys):
    code, out, _ = run(capsys, "report", "--help")
    assert code == 0 and "--out" in out


def test_conditions_json(capsys):
    code, out, err = run(capsys, "conditions", "brake", "--format", "json")
    assert code == 0, err
    data = json.loads(out)
    assert data["scene"] == "brake" and data["k"] == 2
    stable = data["regions"]["stable for every law"]
    assert stable["sympy"] == "mu <= Abs(cot(alpha))"
    assert stable["paper"] == ["(4.4)", "(6.3)"]
    assert data["regions"]["law-dependent"]["sympy"] == "mu > Abs(cot(alpha))"
    assert [entry["name"] for entry in data["hurwitz"]] == ["p_{3}", "p_{2}", "p_{1}", "p_{0}", r"\Delta_{3}"]
    assert data["A"]["paper"] == ["(4.3)", "(6.2)"]
    assert "Phi_1" in data["hopf_frequency"]["sympy"]


def test_conditions_text_and_latex(capsys):
    code, out, _ = run(capsys, "conditions", "painleve-klein-guides")
    assert code == 0
    assert "unstable for every law: v_1 + v_2 > 2*kappa**2   (5.7)" in out
    code, out, _ = run(capsys, "conditions", "brake", "--format", "latex")
    assert code == 0
    assert out.startswith("% contactsym conditions: brake\n\\begin{align*}")
    assert r"\mu \leq \left|{\cot{\left(\alpha \right)}}\right| \tag*{(4.4), (6.3)}" in out
    assert out.rstrip().endswith(r"\end{align*}")


def test_conditions_for_one_sign_pattern(capsys):
    code, out, _ = run(capsys, "conditions", "painleve-klein-guides", "--signs", "+1,-1", "--format", "json")
    assert code == 0
    assert json.loads(out)["signs"] == [1, -1]


def test_parse_signs_never_evaluates_text():
    assert parse_signs("+1, -1") == (1, -1)
    for bad in ("__import__('os')", "2", "1,,x", ""):
        with pytest.raises(cs.SignPatternError):
            parse_signs(bad)


@pytest.mark.parametrize(
    "argv, code, words",
    [
        (("conditions", "brak"), 2, "did you mean 'brake'"),
        (("report", "nope", "--out", "X"), 2, "unknown scene 'nope'"),
        (("conditions", "brake", "--format", "xml"), 2, "invalid choice"),
        (("conditions", "brake", "--signs", "1,x"), 2, "'x' is not a sign"),
        (("conditions", "painleve-klein-guides", "--signs", "1"), 2, "has length 1"),
        (("conditions", "brake", "--signs=-1,1"), 2, "must be +1"),
        (("frobnicate",), 2, "invalid choice"),
        (("report", "brake", "--resolution", "0"), 2, "0 is not positive"),
        (("report", "brake", "--dpi", "lots"), 2, "'lots' is not a whole number"),
    ],
)
def test_errors_are_one_line_with_nonzero_exit(capsys, argv, code, words):
    got, out, err = run(capsys, *argv)
    assert got == code
    assert words in one_line_error(err)


def test_report_to_an_unwritable_directory(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("not a directory")
    code, _, err = run(capsys, "report", "brake", "--out", str(blocker / "reports"))
    assert code == 1
    assert "cannot write to --out" in one_line_error(err)


def test_report_all_scenes_writes_tex_json_figures_and_summary(capfd, tmp_path):
    all_reports = tmp_path
    # coarse figures: this test checks that every figure is made and placed, not how fine it is
    code = main(["report", "--out", str(all_reports), "--no-pdf", "--resolution", "60", "--dpi", "40"])
    out, err = capfd.readouterr()
    assert code == 0, err
    for name in cs.scene_names():
        directory = all_reports / name
        tex = (directory / "report.tex").read_text()
        assert tex.startswith(r"\documentclass") and tex.rstrip().endswith(r"\end{document}")
        pngs = sorted((directory / "figures").glob("*.png"))
        assert pngs, f"no figures for {name}"  # every scene has its figures
        for png in pngs:
            assert f"\\includegraphics[width=0.85\\textwidth]{{figures/{png.name}}}" in tex
        assert not (directory / "report.pdf").exists()  # --no-pdf
        data = json.loads((directory / "conditions.json").read_text())
        assert data["scene"] == name
        assert set(data["regions"]) >= {"stable for every law", "unstable for every law", "Hopf line"}
        if name == "two-leg-block":  # the region is a fold (degree 0), not a cusp
            assert set(data["equilibrium_counts"]) == {"unique", "two or none"}
        assert f"{name}: " in out  # the summary names each scene
        assert f"] {name}: " in err  # progress on stderr
    total = len(cs.scene_names())
    assert f"[1/{total}]" in err and f"[{total}/{total}]" in err
    guides = json.loads((all_reports / "painleve-klein-guides" / "conditions.json").read_text())
    assert guides["regions"]["unstable for every law"]["sympy"] == "v_1 + v_2 > 2*kappa**2"
    assert guides["regions"]["unstable for every law"]["paper"] == ["(5.7)"]
    assert "stable for every law: mu <= Abs(cot(alpha))" in out


@pytest.mark.skipif(
    shutil.which("pdflatex") is None, reason="pdflatex is not installed (apt-get install texlive-latex-base)"
)
def test_report_one_scene_makes_the_pdf(capfd, tmp_path):
    code = main(["report", "sliding-point", "--out", str(tmp_path)])
    out, err = capfd.readouterr()
    assert code == 0, err
    pdf = tmp_path / "sliding-point" / "report.pdf"
    assert pdf.read_bytes().startswith(b"%PDF")
    assert "wrote report.tex, report.pdf, conditions.json" in err
    log = (tmp_path / "sliding-point" / "report.log").read_text(errors="replace")
    assert "figures/sliding_point_phase_portrait.png" in log  # the PDF has its figure
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sliding-point"]


def test_python_dash_m_contactsym_works():
    env = {**os.environ, "PYTHONPATH": str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", "")}
    run = subprocess.run(
        [sys.executable, "-m", "contactsym", "list"], capture_output=True, text=True, env=env, timeout=120
    )
    assert run.returncode == 0, run.stderr
    assert "brake" in run.stdout
    bad = subprocess.run(
        [sys.executable, "-m", "contactsym", "show", "nope"], capture_output=True, text=True, env=env, timeout=120
    )
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1


def test_report_resolution_and_dpi_reach_the_figures(capfd, tmp_path):
    """--dpi sets the pixels of every figure: the same figure at half the dpi has half the width."""
    widths = {}
    for dpi in (40, 80):
        assert (
            main(
                [
                    "report",
                    "sliding-point",
                    "--out",
                    str(tmp_path / str(dpi)),
                    "--no-pdf",
                    "--resolution",
                    "30",
                    "--dpi",
                    str(dpi),
                ]
            )
            == 0
        )
        (png,) = sorted((tmp_path / str(dpi) / "sliding-point" / "figures").glob("*.png"))[:1]
        widths[dpi] = int.from_bytes(png.read_bytes()[16:20], "big")  # the IHDR width of a PNG
    capfd.readouterr()
    assert widths[80] == pytest.approx(2 * widths[40], abs=2)


# --- --limit CAP=N raises a cap for one run ------------------------------------------------

BIG_POWER = '[scene]\ncoordinates = ["y"]\n[parameters]\nY = "positive"\n[accelerations]\ny = "N*(1+Y)^40 - 1"\n'
BIG_POWER += '[[contacts]]\ngap = "y"\nreaction = "N"\n'


def test_limit_raises_a_formula_cap_and_a_file_cap_for_one_run(capsys, tmp_path):
    path = tmp_path / "big.toml"
    path.write_text(BIG_POWER)
    assert main(["show", str(path)]) == 2
    error = capsys.readouterr().err
    assert "MAX_DEGREE = 32" in error and "--limit max_degree=N" in error  # the refusal says how to raise it
    assert main(["--limit", "max_degree=40", "show", str(path)]) == 0
    assert "(Y + 1)**40" in capsys.readouterr().out
    assert main(["conditions", str(path), "--limit", "max_degree=40", "--limit", "max_bytes=50"]) == 2
    error = capsys.readouterr().err
    assert "Limits.max_bytes" in error and "--limit max_bytes=" in error
    assert main(["conditions", str(path), "--limit", "max_degree=40", "--limit", "max_bytes=5000"]) == 0
    capsys.readouterr()
    assert main(["show", str(path)]) == 2  # the caps are back after the run
    assert "MAX_DEGREE = 32" in capsys.readouterr().err


@pytest.mark.parametrize("option", ["max_degre=40", "max_degree", "max_degree=0", "max_degree=x"])
def test_a_bad_limit_is_a_usage_error(capsys, option):
    assert main(["--limit", option, "list"]) == 2
    error = capsys.readouterr().err
    assert "--limit" in error and "\n" not in error.strip()


def test_set_fixes_parameters_before_the_derivation(capsys):
    code, out, err = run(capsys, "show", "brake", "--set", "m=2", "--set", "J=0.5")
    assert code == 0, err
    assert "(fixed: m = 2, J = 1/2)" in out.splitlines()[0]
    assert str(cs.scene("brake").with_values({"m": 2, "J": 0.5}).linearization().A.tolist()) in out


@pytest.mark.parametrize(
    "setting, message",
    [
        ("m", "is not NAME=VALUE"),
        ("m=x", "unknown name 'x'"),
        ("m=__import__", "unexpected character"),
        ("q=1", "'q' is not a parameter"),
        ("m=-1", "declared positive"),
    ],
)
def test_a_bad_set_is_a_usage_error(capsys, setting, message):
    code, _, err = run(capsys, "conditions", "brake", "--set", setting)
    assert code == 2 and message in err


def test_set_takes_exact_constants_and_reduces_the_circle(capsys):
    """--set alpha=pi/2 is pi/2 (the package's parser reads it; no eval); a float's sin^2 + cos^2 reads 1."""
    code, out, err = run(capsys, "conditions", "brake", "--set", "alpha=pi/2")
    assert code == 0, err
    assert "(fixed: alpha = pi/2)" in out and "sin(" not in out and "cos(" not in out
    code, out, err = run(capsys, "conditions", "brake", "--set", "alpha=0.7853981633974483")
    assert code == 0, err
    hopf = next(line for line in out.splitlines() if line.startswith("Hopf frequency"))
    assert "sin(7853981633974483/10000000000000000)" in hopf and "cos(" not in hopf
    code, out, err = run(capsys, "conditions", "brake", "--set", "alpha=pi/7", "--format", "latex")
    assert code == 0 and r"\cos^{2}{\left(\frac{\pi}{7} \right)}" not in out


OWN_WORDS = ["lambda", "lambda_", "tau", "t", "eps", "epsilon", "u", "A", "f", "omega"]


def _words(text: str) -> list[str]:
    return re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text)


@settings(max_examples=10, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(st.lists(st.sampled_from(OWN_WORDS), min_size=1, max_size=3, unique=True))
def test_show_never_prints_a_scene_name_for_the_packages_own(tmp_path_factory, names):
    """`show` of a scene whose parameters take the package's own names (t, eps, lambda, ...): each name occurs
    exactly as often as a neutral stand-in does in the same scene, so no occurrence is the package's."""
    folder = tmp_path_factory.mktemp("names")
    (folder / "drawn.toml").write_text(block(names))
    (folder / "neutral.toml").write_text(block(NEUTRAL[: len(names)]))
    drawn, neutral = (_words(derivation_chain(str(folder / f))) for f in ("drawn.toml", "neutral.toml"))
    for name, stand_in in zip(names, NEUTRAL):
        assert drawn.count(name) == neutral.count(stand_in) > 0, (name, names)


def test_a_name_set_twice_is_refused_not_overwritten(capsys):
    """--set m=2 --set m=3 kept the last value without a word; now neither is taken."""
    assert main(["conditions", "brake", "--set", "m=2", "--set", "m=3"]) == 1
    assert "--set m is given twice (2 and 3)" in capsys.readouterr().err
