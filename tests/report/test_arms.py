"""Every scene that derives gets its report (issue 26): the two-link arm of rods, unilateral; random chains."""

import json
import random
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st

import contactsym as cs
from benchmarks.report_chains import check_chain, random_chain
from contactsym.report import report_tex, write_report
from tests.report_support import needs_pdflatex

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@needs_pdflatex
def test_the_two_link_arm_gets_a_whole_pdf_report_without_p2(tmp_path):
    scene = cs.load_scene(EXAMPLES / "two-link-arm.toml")
    result = write_report(scene, tmp_path / "arm")
    assert result.pdf is not None and result.pdf.read_bytes().startswith(b"%PDF")
    assert len(result.figures) >= 1 and all(f.path.exists() for f in result.figures)
    tex = result.tex.read_text()
    # p_2 is a multiple of det M: dropped from the conditions, with the reason
    assert r"negative real parts exactly when $p_{1}, p_{0} > 0$" in tex
    assert r"$p_{2} > 0$ always: a positive multiple of det M" in tex
    hurwitz = json.loads(result.conditions.read_text())["hurwitz"]
    assert [(h["name"], h.get("always")) for h in hurwitz] == [
        ("p_{2}", "a positive multiple of det M"),
        ("p_{1}", None),
        ("p_{0}", None),
    ]
    # the one-sided section is there, all four cases decided from a and b
    assert r"\subsection*{One-sided contact" in tex and "not decided" not in tex
    assert tex.count(r"\paragraph{Consistent.}") == 2 and r"\paragraph{Indeterminate.}" in tex


def test_the_leaning_rod_example_is_reported_whole():
    tex = report_tex(cs.load_scene(EXAMPLES / "leaning-rod.toml"))
    assert tex.rstrip().endswith(r"\end{document}") and "Not derived" not in tex


@settings(max_examples=2, deadline=None)
@given(st.integers(0, 2**32 - 1))
def test_random_chains_get_a_report_wherever_conditions_succeed(seed):
    # small and numeric to keep the suite fast: benchmarks/report_chains.py runs >= 50 of every size
    chain = random_chain(random.Random(seed), max_links=2, max_contacts=1, symbolic=False)
    outcome, _, detail = check_chain(chain, limit=300)
    assert outcome == "report ok", (str(chain), outcome, detail)
