"""Own scenes end to end: figures from the file's plan, reports and the CLI, never mixed up with built-ins."""

from __future__ import annotations

import json
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import contactsym as cs
from contactsym.cli import main
from contactsym.scenefigures import region_map_data
from contactsym.scenefile import load_scene

matplotlib.use("Agg")

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _renamed(tmp_path: Path, example: str, name: str) -> Path:
    """An example file whose scene takes a built-in scene's name."""
    text = (EXAMPLES / f"{example}.toml").read_text()
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace(f'name = "{example}-file"', f'name = "{name}"'))
    return path


def test_region_map_agrees_with_the_regions_at_sampled_points():
    scene = load_scene(EXAMPLES / "brake.toml")
    data = region_map_data(scene, scene.figure_plan, resolution=30)
    grid = data.grids["stable for every law"]
    rng = np.random.default_rng(0)
    for i, j in rng.integers(0, 30, size=(40, 2)):
        alpha, mu = grid.X[i, j], grid.Y[i, j]
        assert bool(grid.mask[i, j]) == (mu <= abs(1 / np.tan(alpha)))  # (6.3), checked against the grid


def test_own_scene_named_brake_gets_its_own_report(tmp_path, capsys):
    path = _renamed(tmp_path, "brake", "brake")
    assert main(["report", str(path), "--out", str(tmp_path / "out"), "--no-pdf"]) == 0
    report = tmp_path / "out" / "brake"
    tex = (report / "report.tex").read_text()
    data = json.loads((report / "conditions.json").read_text())
    assert "Errata of the paper" not in tex and "special case" not in tex
    assert sorted(p.name for p in (report / "figures").iterdir()) == ["regions.png"]
    assert data["regions"]["stable for every law"]["paper"] == ["(4.4)"]  # not the brake's (6.3)
    assert cs.conditions(cs.scene("brake"))["regions"]["stable for every law"]["paper"] == ["(4.4)", "(6.3)"]


def test_own_scene_named_like_the_rod_gets_no_rod_figures(tmp_path):
    text = (EXAMPLES / "sliding-point.toml").read_text().replace('"sliding-point-file"', '"painleve-klein-rod"')
    scene = cs.read_scene(text, "rod.toml")
    assert scene.name == "painleve-klein-rod" and scene is not cs.scene("painleve-klein-rod")
    result = cs.write_report(scene, tmp_path / "rod", pdf=False)
    assert [f.path.name for f in result.figures] == ["phase_portrait.png"]  # the rod's are rod_f_cases, ...
    assert all(f.path.parent == tmp_path / "rod" / "figures" and f.path.stat().st_size > 0 for f in result.figures)
    assert "Errata of the paper" not in result.tex.read_text()


def test_a_built_in_and_a_file_of_the_same_name_cannot_share_a_report(tmp_path, capsys):
    path = _renamed(tmp_path, "brake", "brake")
    assert main(["report", "brake", str(path), "--out", str(tmp_path / "out"), "--no-pdf"]) == 2
    assert "both named 'brake'" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


def test_cli_takes_files_for_show_and_conditions(capsys):
    assert main(["show", str(EXAMPLES / "sliding-point.toml")]) == 0
    assert capsys.readouterr().out.startswith("scene sliding-point-file: (1.10)")
    assert main(["conditions", str(EXAMPLES / "brake.toml"), "--format", "latex"]) == 0
    assert r"\mu \leq \left|{\cot{\left(\alpha \right)}}\right|" in capsys.readouterr().out
    assert main(["list"]) == 0
    assert "brake-file" not in capsys.readouterr().out


@pytest.mark.parametrize(
    "text, where",
    [
        ('[scene]\ncoordinates = ["x"]\n[[contacts]]\ngap = "x"\nreaction = "N"\nfriction = 3\n', "bad.toml:6: "),
        (
            '[scene]\ncoordinates = ["y"]\n[[contacts]]\ngap = "y"\nreaction = "N"\n[energy]\nkinetic = "os.system"\n',
            "bad.toml:7:14:",
        ),
        ("[scene\n", "bad.toml:1:"),
    ],
)
def test_cli_reports_a_bad_file_in_one_line(tmp_path, capsys, text, where):
    path = tmp_path / "bad.toml"
    path.write_text(text)
    assert main(["show", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{path.parent}/{where}" in err


def test_hopf_line_on_the_map_crosses_alpha_90_at_the_special_case_root():
    """At alpha = 90 deg, Phi_j = -4, Psi_j = -1, m = 1 the special case (6.4) is Psi^2 (mu^2 + 1) + Phi m mu^2 = 0:
    1 - 3 mu^2 = 0, mu = 1/sqrt(3); the map's Hopf curve, from the general condition, changes sign there."""
    scene = load_scene(EXAMPLES / "brake.toml")
    data = region_map_data(scene, scene.figure_plan, resolution=121)
    X, Y, (field,) = data.curves["Hopf line"]
    column = np.argmin(abs(X[0] - np.pi / 2))
    signs = np.sign(field[:, column])
    crossing = Y[np.nonzero(signs[1:] != signs[:-1])[0], column]
    step = Y[1, 0] - Y[0, 0]
    assert len(crossing) == 1 and abs(crossing[0] - 1 / np.sqrt(3)) <= step
