r"""A standalone LaTeX report per scene: derivation chain, regions, figures, errata.

:func:`report_tex` writes the document; :func:`write_report` writes a scene's
directory (``report.tex``, ``report.pdf`` when pdflatex is present, ``figures/*.png``,
``conditions.json``); :func:`conditions` is the JSON-ready summary of the conditions.

Long expressions are broken across lines at their sums; one that would still take more
than a few lines is named (``H_1``) and its size given, with the full form in
``conditions.json``.

Modules: :mod:`~contactsym.report.typesetting` (widths, line breaking),
:mod:`~contactsym.report.plain_text` (escaping),
:mod:`~contactsym.report.derivation` (the derivation chain's sections),
:mod:`~contactsym.report.document` (the other sections and :func:`report_tex`),
:mod:`~contactsym.report.summary` (the conditions as data),
:mod:`~contactsym.report.scene_parts` (what the report knows of the paper's scenes) and
:mod:`~contactsym.report.build` (the files).

Examples
--------
>>> import contactsym as cs
>>> print(summary_text(conditions(cs.scene("brake"))).splitlines()[2])
  stable for every law: mu <= Abs(cot(alpha))   (4.4), (6.3)
"""

from .build import ReportError, ReportResult, compile_pdf, write_report
from .document import Figure, report_tex

# FigureSource for the command line; the typesetting names also under their old import path
from .scene_parts import FigureSource as FigureSource
from .summary import conditions, summary_text
from .typesetting import WIDTH as WIDTH
from .typesetting import width as width

__all__ = [
    "Figure",
    "ReportError",
    "ReportResult",
    "compile_pdf",
    "conditions",
    "report_tex",
    "summary_text",
    "write_report",
]
