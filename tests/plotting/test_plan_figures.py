"""Own scenes end to end: figures from the file's plan, reports and the CLI, never mixed up with built-ins."""

from __future__ import annotations

import dataclasses
import functools
import json
from pathlib import Path

import matplotlib
import numpy as np
import pytest

import contactsym as cs
from contactsym.cli import main
from contactsym.mechanism.files.reader import load_scene
from contactsym.plotting.plan_figures import missing_values, region_map_data

matplotlib.use("Agg")

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@functools.cache
def _brake():
    """The brake example, read once for the tests that only read it (scenes are immutable)."""
    return load_scene(EXAMPLES / "brake.toml")


def _renamed(tmp_path: Path, example: str, name: str) -> Path:
    """An example file whose scene takes a built-in scene's name."""
    text = (EXAMPLES / f"{example}.toml").read_text()
    path = tmp_path / f"{name}.toml"
    path.write_text(text.replace(f'name = "{example}-file"', f'name = "{name}"'))
    return path


def test_region_map_agrees_with_the_regions_at_sampled_points():
    scene = _brake()
    data = region_map_data(scene, scene.figure_plan, resolution=30)
    grid = data.grids["stable for every law"]
    rng = np.random.default_rng(0)
    for i, j in rng.integers(0, 30, size=(40, 2)):
        alpha, mu = grid.X[i, j], grid.Y[i, j]
        assert bool(grid.mask[i, j]) == (mu <= abs(1 / np.tan(alpha)))  # (6.3), checked against the grid


@pytest.mark.parametrize("name", ["brake", "painleve-klein-rod"])
def test_own_scene_with_a_built_in_name_gets_its_own_report(tmp_path, name):
    """Built from the sliding point's file: only the name is shared with the built-in."""
    path = tmp_path / "own.toml"
    path.write_text((EXAMPLES / "sliding-point.toml").read_text().replace('"sliding-point-file"', f'"{name}"'))
    assert main(["report", str(path), "--out", str(tmp_path / "out"), "--no-pdf"]) == 0
    report = tmp_path / "out" / name
    tex = (report / "report.tex").read_text()
    data = json.loads((report / "conditions.json").read_text())
    assert "Errata of the paper" not in tex and "special case" not in tex
    assert sorted(p.name for p in (report / "figures").iterdir()) == ["phase_portrait.png"]  # none of the built-in's
    assert data["regions"]["stable for every law"]["paper"] == ["(3.2)"]  # Proposition 3, not the built-in's numbers
    assert cs.conditions(cs.scene("brake"))["regions"]["stable for every law"]["paper"] == ["(4.4)", "(6.3)"]


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
    scene = _brake()
    data = region_map_data(scene, scene.figure_plan, resolution=121)
    X, Y, (field,) = data.curves["Hopf line"]
    column = np.argmin(abs(X[0] - np.pi / 2))
    signs = np.sign(field[:, column])
    crossing = Y[np.nonzero(signs[1:] != signs[:-1])[0], column]
    step = Y[1, 0] - Y[0, 0]
    assert len(crossing) == 1 and abs(crossing[0] - 1 / np.sqrt(3)) <= step


def test_a_plan_without_some_values_skips_a_region_naming_every_missing_value():
    scene = _brake()
    plan = scene.figure_plan
    hopf = scene.regions()["Hopf line"].condition
    assert missing_values(hopf, plan) == []  # the example's plan is complete
    short = dataclasses.replace(plan, values={k: v for k, v in plan.values.items() if k not in ("Phi_1", "m")})
    data = region_map_data(scene, short, resolution=10)
    # the Hopf line (4.7) holds Phi_1 and m; the closed-form stability regions need neither
    assert data.skipped["Hopf line"] == "give [figures] values for Phi_1, m"
    assert {str(s) for s in hopf.free_symbols} >= {"Phi_1", "m"}
    assert sorted(data.grids) == ["law-dependent", "stable for every law"]


def test_a_region_with_no_point_in_the_plane_is_named_not_drawn():
    """The brake's plan moved to where mu > |cot alpha| everywhere: 'stable for every law' has no grid
    point there (checked against (6.3) at every point), so it gets a note and no legend entry."""
    scene = _brake()
    plan = dataclasses.replace(scene.figure_plan, x_range=(1.4, 1.5), y_range=(1.0, 2.0))
    data = region_map_data(scene, plan, resolution=12)
    X, Y = np.meshgrid(np.linspace(1.4, 1.5, 12), np.linspace(1.0, 2.0, 12))
    assert not np.any(Y <= np.abs(1 / np.tan(X)))  # (6.3): empty on this plane
    assert "stable for every law" not in data.grids
    assert data.skipped["stable for every law"] == "no grid point of this plane is in it at the [figures] values"
    assert data.grids["law-dependent"].mask.all()
