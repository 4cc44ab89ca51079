"""The report: a standalone LaTeX document per scene that pdflatex compiles, figures included."""

import json
import re
import shutil
from pathlib import Path

import pytest
import sympy as sp

import contactsym as cs
from contactsym.errata import ERRATA
from contactsym.latex import Formula
from contactsym.report import (
    WIDTH,
    Figure,
    FigureSource,
    _display,
    _Named,
    compile_pdf,
    conditions,
    report_tex,
    summary_text,
    width,
    write_report,
)

needs_pdflatex = pytest.mark.skipif(
    shutil.which("pdflatex") is None, reason="pdflatex is not installed (apt-get install texlive-latex-base)"
)


def overfull(log: str) -> list[float]:
    """Widths (pt) of the overfull boxes pdflatex reports."""
    return [float(w) for w in re.findall(r"Overfull \\hbox \(([0-9.]+)pt too wide\)", log)]


def a_png(path: Path) -> Path:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, ax = plt.subplots(figsize=(3, 2))
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel(r"$v_1$")
    figure.savefig(path, dpi=50)
    plt.close(figure)
    return path


def test_brake_report_cites_the_papers_equations():
    tex = report_tex(cs.scene("brake"))
    for tag in ("(4.1)", "(4.2)", "(4.3), (6.2)", "(4.6)", "(4.7)", "(4.4), (6.3)", "(6.4)", "(2.2)"):
        assert rf"\tag*{{{tag}}}" in tex, tag
    # the paper's special case (6.4), derived with the mass, and omega after it
    assert r"- \Phi m \mu^{2} < \Psi^{2} \left(\mu^{2} + 1\right)" in tex
    assert r"\omega = - \frac{\Psi \left(\mu^{2} + 1\right)}{m \mu}" in tex
    assert r"\mu \leq \left|{\cot{\left(\alpha \right)}}\right|" in tex
    # the errata table: every row
    assert tex.count(r"\\[2pt]") == len(ERRATA)


def test_guides_report_uses_the_papers_variables():
    tex = report_tex(cs.scene("painleve-klein-guides"))
    assert r"v_{1} + v_{2} > 2 \kappa^{2}" in tex and r"\tag*{(5.7)}" in tex
    assert r"\tag*{(4.3), (5.4)}" in tex and r"\tag*{(5.5)}" in tex
    assert r"\item $H_{1}$: a polynomial with" in tex  # the Hopf line's long factor, named


def test_long_expressions_are_broken_or_named():
    x = sp.symbols("x_1:40")
    long_sum = sp.Add(*[(i + 1) * s**2 for i, s in enumerate(x[:24])])
    named = _Named()
    shown = _display(Formula("f", "f", long_sum, "=", ("4.6",)), named)
    assert r"\begin{split}" in shown and named.items == []
    lines = shown.split("\\\\\n")
    assert len(lines) > 1 and all(width(line) <= WIDTH + 8 for line in lines)
    huge = sp.expand(sp.Add(*x) ** 2)  # 780 terms: too long for any page
    named = _Named()
    shown = _display(Formula("g", "", sp.Eq(huge * (x[0] - 1), 0), "", ()), named)
    assert "H_{1}" in shown and len(named.items) == 1 and named.items[0][1] == huge


def test_conditions_are_json_and_summarised():
    data = conditions(cs.scene("brake"))
    assert json.loads(json.dumps(data)) == data
    text = summary_text(data)
    assert text.splitlines()[0].startswith("brake: ")
    assert "stable for every law: mu <= Abs(cot(alpha))   (4.4), (6.3)" in text


def test_figure_source_asks_the_scene_module(tmp_path, monkeypatch):
    import contactsym.scenes.brake as brake_module

    def figures(scene, directory, *, resolution, dpi):
        return [(a_png(directory / "brake_alpha_mu.png"), r"the $(\alpha, \mu)$ plane")]

    monkeypatch.setattr(brake_module, "figures", figures)
    source = FigureSource(tmp_path)
    brake, notes = source.for_scene(cs.scene("brake"))
    assert [(p.name, c) for p, c in brake] == [("brake_alpha_mu.png", r"the $(\alpha, \mu)$ plane")] and notes == []


def test_a_failing_figure_function_becomes_a_note(tmp_path, monkeypatch):
    import contactsym.scenes.brake as brake_module

    def figures(scene, directory, *, resolution, dpi):
        raise RuntimeError("no display")

    monkeypatch.setattr(brake_module, "figures", figures)
    figures, notes = FigureSource(tmp_path).for_scene(cs.scene("brake"))
    assert figures == [] and notes == ["No figures: drawing them failed with RuntimeError: no display"]


@needs_pdflatex
def test_report_with_a_figure_compiles_and_includes_it(tmp_path):
    (tmp_path / "figures").mkdir()
    png = a_png(tmp_path / "figures" / "test_plane.png")
    tex = tmp_path / "report.tex"
    tex.write_text(
        report_tex(cs.scene("brake"), [Figure(png, r"a test figure, $(v_1, v_2)$")], ["a note: 100% & done"])
    )
    pdf = compile_pdf(tex)
    assert pdf is not None and pdf.read_bytes().startswith(b"%PDF")
    log = tex.with_suffix(".log").read_text(errors="replace")
    assert "figures/test_plane.png" in log  # pdflatex read the PNG
    assert max(overfull(log), default=0) < 5, "an expression overflows the page"


@needs_pdflatex
def test_write_report_for_the_longest_scene_fits_the_page(tmp_path):
    result = write_report(cs.scene("painleve-klein-guides"), tmp_path / "guides")
    assert result.pdf is not None and result.pdf.exists()
    assert (tmp_path / "guides" / "conditions.json").exists()
    log = (tmp_path / "guides" / "report.log").read_text(errors="replace")
    assert max(overfull(log), default=0) < 5, "an expression overflows the page"
    if result.figures:  # figures from contactsym.plotting, when this version has it
        for figure in result.figures:
            assert figure.path.exists() and f"figures/{figure.path.name}" in log
    else:
        assert result.notes, "no figures and no note saying why"


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
