"""The errata data agree with docs/errata.md and typeset without unknown characters."""

import re
from pathlib import Path

import pytest

from contactsym.report.errata import AGREE, ERRATA, markdown_table, text_to_latex

DOC = (Path(__file__).resolve().parents[2] / "docs" / "errata.md").read_text()


def test_docs_table_is_the_data():
    table = "\n".join(line for line in DOC.splitlines() if line.startswith("|"))
    assert table == markdown_table()


def test_docs_agree_list_is_the_data():
    sentence = re.search(r"agree with the print: (.*?)\.\n\n", DOC, flags=re.S).group(1)
    assert " ".join(sentence.split()) == ", ".join(AGREE)


def test_numbers_run_from_1():
    assert [e.number for e in ERRATA] == list(range(1, len(ERRATA) + 1))


def test_every_cell_becomes_ascii_latex_with_balanced_math():
    for e in ERRATA:
        for cell in (e.formula, e.printed, e.derived, e.kind, e.holds_when):
            tex = text_to_latex(cell)
            assert tex.isascii(), (cell, tex)
            assert tex.replace(r"\$", "").count("$") % 2 == 0, (cell, tex)
            assert "$$" not in tex, (cell, tex)


def test_text_to_latex_cases():
    assert text_to_latex("μ ≤ |cot α|") == r"$\mu \le | \cot \alpha |$"
    assert text_to_latex("Φ_j = Ψ_j") == r"$\Phi _{j} = \Psi _{j}$"
    assert text_to_latex("ẍ, ÿ") == r"$\ddot{x} , \  \ddot{y}$"
    assert text_to_latex("sign slip; the proposition stands") == "sign slip; the proposition stands"
    assert text_to_latex('"since a12a21 > 0"') == r"``since $a_{12} a_{21} > 0$''"
    assert text_to_latex("a11 < 0 and (V increases)") == r"$a_{11} < 0$ and ($V$ increases)"
    assert text_to_latex("50% & #1") == r"50\% \& \#1"


def test_unknown_characters_are_refused():
    with pytest.raises(ValueError, match="no LaTeX for the character"):
        text_to_latex("∮ f")
