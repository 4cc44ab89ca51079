"""A standalone LaTeX report per scene (being split into modules)."""

from .document import (
    WIDTH,
    Figure,
    FigureSource,
    ReportError,
    ReportResult,
    _display,
    _Named,
    compile_pdf,
    conditions,
    report_tex,
    summary_text,
    width,
    write_report,
)

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
