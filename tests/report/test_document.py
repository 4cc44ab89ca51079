"""The report's LaTeX document: the paper's equation numbers, its variables, and a figure that pdflatex includes."""

from pathlib import Path

import contactsym as cs
from contactsym.report import Figure, compile_pdf, report_tex
from contactsym.report.errata import ERRATA
from tests.report_support import needs_pdflatex, overfull


def a_png(path: Path) -> Path:
    from matplotlib.figure import Figure as MplFigure

    figure = MplFigure(figsize=(3, 2))
    ax = figure.add_subplot()
    ax.plot([0, 1], [0, 1])
    ax.set_xlabel(r"$v_1$")
    figure.savefig(path, dpi=50)
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


def test_each_count_region_says_why_its_count_holds():
    scene = cs.scene("painleve-klein-guides")
    tex = report_tex(scene)
    for name, region in scene.equilibrium_counts().items():
        reason = region.description.split(": ", 1)[-1]
        heading = rf"\paragraph{{{name.capitalize()}.}} "
        assert heading in tex
        assert tex.split(heading, 1)[1].split("\n", 1)[0].startswith(reason.split(" (")[0]), name
