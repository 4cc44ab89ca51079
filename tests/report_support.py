"""Shared by the report's tests: pdflatex's presence and the overfull boxes of its log."""

import re
import shutil

import pytest

needs_pdflatex = pytest.mark.skipif(
    shutil.which("pdflatex") is None, reason="pdflatex is not installed (apt-get install texlive-latex-base)"
)


def overfull(log: str) -> list[float]:
    """Widths (pt) of the overfull boxes pdflatex reports."""
    return [float(w) for w in re.findall(r"Overfull \\hbox \(([0-9.]+)pt too wide\)", log)]
