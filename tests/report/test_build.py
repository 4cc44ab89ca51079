"""Building a report directory: the scene's own figures, a figure that fails as a note, pdflatex, the files."""

import dataclasses
import json
from pathlib import Path

import pytest

import contactsym as cs
from contactsym.report import FigureSource, compile_pdf, write_report
from tests.report_support import needs_pdflatex, overfull

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
PNG = b"\x89PNG\r\n\x1a\n"


@needs_pdflatex
def test_write_report_for_the_longest_scene_fits_the_page(tmp_path):
    result = write_report(cs.scene("painleve-klein-guides"), tmp_path / "guides")
    assert result.pdf is not None and result.pdf.exists()
    assert (tmp_path / "guides" / "conditions.json").exists()
    log = (tmp_path / "guides" / "report.log").read_text(errors="replace")
    assert max(overfull(log), default=0) < 5, "an expression overflows the page"
    # the guides' own figures, Fig. 1a and 1b of the paper, drawn and read by pdflatex
    assert [figure.path.name for figure in result.figures] == ["fig1a_guides.png", "fig1b_guides.png"]
    assert result.notes == []
    for figure in result.figures:
        assert figure.path.read_bytes().startswith(PNG) and f"figures/{figure.path.name}" in log


def test_figures_are_chosen_by_the_scene_object_not_its_name(tmp_path):
    source = FigureSource(tmp_path)  # shared by the scenes, as `contactsym report` shares it
    text = (EXAMPLES / "brake.toml").read_text().replace('name = "brake-file"', 'name = "brake"')
    users_brake = cs.read_scene(text)  # the built-in brake's name, and its own [figures] plan
    assert users_brake.name == "brake" and users_brake is not cs.scene("brake")
    built_in, notes = source.for_scene(cs.scene("brake"))
    assert [path.name for path, _ in built_in] == ["brake_alpha_mu.png", "brake_hopf.png"] and notes == []
    assert "(6.3)" in built_in[0][1] and "(6.4)" in built_in[1][1]  # the paper's captions
    own, _ = source.for_scene(users_brake)
    assert [path.name for path, _ in own] == ["regions.png"] and "(6.3)" not in own[0][1]
    counts, notes = source.for_scene(cs.scene("painleve-rod"))  # a built-in scene's own figure
    assert [path.name for path, _ in counts] == ["rod_counts.png"] and notes == []
    drawn = [path for path, _ in built_in + own + counts]
    assert len(set(drawn)) == 4 and all(path.read_bytes().startswith(PNG) for path in drawn)


def test_a_figure_that_fails_to_draw_is_a_note_and_the_rest_is_written(tmp_path):
    scene = cs.load_scene(EXAMPLES / "brake.toml")
    plan = scene.figure_plan
    # Psi_1 ** 3 overflows a float on the Hopf line's grid: drawing the region map raises
    scene.figure_plan = dataclasses.replace(plan, values={**plan.values, "Psi_1": -1e300})
    result = write_report(scene, tmp_path / "brake", pdf=False)
    assert result.figures == [] and len(result.notes) == 1
    assert result.notes[0].startswith("No figures: drawing them failed with OverflowError")
    tex = result.tex.read_text()
    assert r"\section*{9. Figures}" in tex and "No figures for this scene." in tex
    assert "No figures: drawing them failed with OverflowError" in tex
    assert r"\section*{7. Regions in closed form}" in tex and r"\end{document}" in tex
    assert json.loads(result.conditions.read_text())["regions"]["stable for every law"]["sympy"]


@needs_pdflatex
def test_a_latex_error_is_one_clear_line(tmp_path):
    tex = tmp_path / "bad.tex"
    tex.write_text(r"\documentclass{article}\begin{document}\undefinedmacro\end{document}")
    with pytest.raises(cs.ContactsymError, match=r"pdflatex failed on .*bad.tex: Undefined control sequence"):
        compile_pdf(tex)


def test_unwritable_directory_is_a_report_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    with pytest.raises(cs.ContactsymError, match="cannot create"):
        write_report(cs.scene("sliding-point"), blocker / "x", pdf=False)
