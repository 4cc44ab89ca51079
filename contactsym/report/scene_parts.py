"""What the report asks of a scene beyond its stages: paper numbers of count regions, special cases, figures.

All of it comes from the scene's own module through
:func:`contactsym.scenes.paper_knowledge`, so a user's scene that shares a built-in name
gets none of the paper's; a scene with a figure plan gets the figures its plan asks for.

Examples
--------
>>> import contactsym as cs
>>> _count_tag(cs.scene("painleve-klein-guides"), "unique")
('5.8',)
>>> _count_tag(cs.scene("brake"), "unique")
()
"""

from __future__ import annotations

from pathlib import Path

from ..plotting.plan_figures import plan_figures
from ..printing.latex_output import Formula
from ..scenes import paper_knowledge, paper_name
from .typesetting import _display, _Named

__all__ = ["FigureSource"]


def _count_tag(scene, name: str) -> tuple:
    """The paper's equation numbers of the count region ``name`` of a built-in scene."""
    for word, numbers in paper_knowledge(scene, "COUNT_EQUATIONS", ()):
        if word in name.lower():
            return numbers
    return ()


def _special_cases(scene, named: _Named) -> list[str]:
    """The paper's special cases of a built-in scene (the brake's (6.4) and its frequency), from its module."""
    text = []
    for i, case in enumerate(paper_knowledge(scene, "special_cases", lambda scene: [])(scene)):
        text.append((r"\paragraph{The paper's special case.} " if i == 0 else "") + case.intro)
        text.append(_display(Formula(case.key, case.lhs, case.rhs, case.relation, case.paper, case.note), named))
    return text


class FigureSource:
    """Figures for the reports: a built-in scene's from ``figures`` in its module, any other's from its plan.

    ``resolution`` (grid points per axis of a region map) and ``dpi``, when given, replace each
    figure's own default (400 and 150 for the paper's figures, 200 and 150 for a plan's).
    """

    def __init__(self, workdir: Path, *, resolution: int | None = None, dpi: int | None = None):
        self.workdir = workdir
        self.options = {name: v for name, v in (("resolution", resolution), ("dpi", dpi)) if v is not None}
        self._own = 0  # scenes other than the paper's, numbered for their figure directories
        self.notes: list[str] = []

    def for_scene(self, scene) -> tuple[list[tuple[Path, str]], list[str]]:
        """[(PNG path, LaTeX caption)] and notes; a figure that fails becomes a note."""
        try:
            if paper_name(scene) is None or getattr(scene, "figure_plan", None) is not None:
                # any other scene, or a built-in one beyond the paper: the figures its plan asks for
                self._own += 1
                return plan_figures(scene, self.workdir / f"own-{self._own}", **self.options)
            figures = paper_knowledge(scene, "figures")
            if figures is None:
                return [], []
            directory = self.workdir / scene.name
            directory.mkdir(parents=True, exist_ok=True)
            return figures(scene, directory, **{"resolution": 400, "dpi": 150, **self.options}), []
        except Exception as error:  # a figure that fails must not cost the rest of the report
            return [], [f"No figures: drawing them failed with {type(error).__name__}: {error}"]
