"""What the report knows of the paper's built-in scenes: count equation numbers, the brake's special case, figures.

Kept together, with their bodies as they were in ``report.py``, because this knowledge
moves to the scenes' own modules (``scenes/<name>.py``, asked for through
:func:`contactsym.scenes.paper_knowledge`): the pieces are :data:`COUNT_EQUATIONS` with
:func:`_count_tag`, :func:`_special_cases`, :data:`FIGURE_WORDS`, :data:`CAPTIONS` and
the paper branch of :meth:`FigureSource.for_scene` (with :func:`_paths`, :func:`_scene_of`
and :meth:`FigureSource._phase_portrait`).

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

import sympy as sp

from .. import plotting
from ..latex import Formula
from ..regions import closed_form
from ..scenefigures import plan_figures
from ..scenes import paper_name
from .typesetting import _display, _escape, _Named

__all__ = ["CAPTIONS", "COUNT_EQUATIONS", "FIGURE_WORDS", "FigureSource"]

# --- equation numbers and special cases -----------------------------------------------------------

#: Paper numbers of count regions, by scene and a word in the region's name.
COUNT_EQUATIONS = {
    "painleve-klein-rod": (
        ("unique", ("3.8", "3.9")),
        ("three", ("3.9",)),
        ("cusp", ("3.9",)),
        ("none", ("3.8",)),
        ("fold", ("3.8",)),
    ),
    "painleve-klein-guides": (("unique", ("5.8",)), ("none", ("5.10",)), ("two", ("5.10",))),
}


def _count_tag(scene, name: str) -> tuple:
    for word, numbers in COUNT_EQUATIONS.get(paper_name(scene) or "", ()):
        if word in name.lower():
            return numbers
    return ()


def _special_cases(scene, named: _Named) -> list[str]:
    """The paper's special cases of a scene, derived here: the brake's (6.4) and its frequency."""
    if paper_name(scene) != "brake":  # the built-in brake itself, not a scene that shares its name
        return []
    st = scene.stability()
    fast = scene.fast_subsystem()
    Phi, Psi = sp.Symbol("Phi", negative=True), sp.Symbol("Psi", negative=True)
    alpha = next(s for s in scene.parameters if s.name == "alpha")
    equal = {fast.Phi[0]: Phi, fast.Phi[1]: Phi, fast.Psi[0]: Psi, fast.Psi[1]: Psi, alpha: sp.pi / 2}
    stable = closed_form(sp.And(*[sp.Gt(h.subs(equal), 0) for h in st.hurwitz]), scene)
    line = closed_form(st.hopf.subs(equal), scene)
    text = [
        r"\paragraph{The paper's special case.} With $\Phi_j = \Phi$, $\Psi_j = \Psi$ and "
        r"$\alpha = 90^\circ$ the Hurwitz conditions reduce to",
        _display(Formula("special", "", stable, "", ("6.4",), "with the mass m: erratum 13"), named),
    ]
    if isinstance(line, sp.Equality):
        solved = sp.solve(line, Phi, dict=True)
        if len(solved) == 1:
            omega = sp.sqrt(sp.factor(st.poly.omega_squared.subs(equal).subs(solved[0])))
            text.append("and on its boundary, a Hopf bifurcation, the frequency in the stretched time is")
            text.append(_display(Formula("omega", r"\omega", sp.factor(omega), "=", (), "erratum 14"), named))
    return text


# --- figures --------------------------------------------------------------------------------

#: Words in a figure's file name that tie it to a scene.
FIGURE_WORDS = {
    "sliding-point": ("sliding",),
    "painleve-klein-rod": ("rod",),
    "painleve-klein-guides": ("guides", "fig1"),
    "brake": ("brake",),
}

#: Captions (LaTeX) of the figures of ``contactsym.plotting.paper_figures``, by file name.
CAPTIONS = {
    "fig1a_guides": r"Fig.~1a of the paper, derived: the $(v_1, v_2)$ plane at $\varphi = 60^\circ \ge \arctan\sqrt{2}$, "
    r"where the square (5.8) lies in the stability region (5.6).",
    "fig1b_guides": r"Fig.~1b of the paper, derived: the $(v_1, v_2)$ plane at $\varphi = 45^\circ < \arctan\sqrt{2}$, "
    r"where part of the square (5.8) is law-dependent.",
    "rod_f_cases": r"$f(u)$ of the deformable rod (3.7) in the three cases of \S3: a unique stable root, a fold, a cusp.",
    "rod_phase_portrait": r"Phase portrait of the fast subsystem (2.1) of the rod.",
    "brake_alpha_mu": r"The brake's $(\alpha, \mu)$ plane: stable for every law where $\mu \le |\cot\alpha|$ (6.3), "
    r"law-dependent above.",
    "brake_hopf": r"The brake's Hopf line (6.4) and its frequency $\omega$.",
}


def _paths(result, directory: Path) -> list[tuple[Path, str]]:
    """(path, caption) of the PNGs that a figure function returned or wrote."""
    if isinstance(result, dict):
        items = [(Path(p), str(k)) for k, p in result.items() if isinstance(p, (str, Path))]
    elif isinstance(result, (list, tuple)):
        items = [(Path(p), Path(p).stem.replace("_", " ")) for p in result if isinstance(p, (str, Path))]
    else:
        items = []
    if not items:
        items = [(p, p.stem.replace("_", " ")) for p in sorted(directory.glob("*.png"))]
    return [(p, CAPTIONS.get(p.stem) or _escape(caption)) for p, caption in items if p.suffix == ".png" and p.exists()]


def _scene_of(path: Path) -> str | None:
    stem = path.stem.lower()
    for name, words in FIGURE_WORDS.items():
        if name in stem or any(word in stem for word in words):
            return name
    return None


class FigureSource:
    """Figures for the reports, drawn once by ``contactsym.plotting`` and shared out by scene.

    Uses ``plotting.scene_figures(scene, directory)`` when it exists, else
    ``plotting.paper_figures(directory)`` (once), each figure going to the scene its
    file name names (a figure that names none goes to every scene). Missing functions
    give notes, not errors.
    """

    def __init__(self, workdir: Path):
        self.workdir = workdir
        self._paper: list[tuple[Path, str]] | None = None
        self._own = 0  # scenes other than the paper's, numbered for their figure directories
        self.notes: list[str] = []

    def for_scene(self, scene) -> tuple[list[tuple[Path, str]], list[str]]:
        if paper_name(scene) is None or getattr(scene, "figure_plan", None) is not None:
            # any other scene, or a built-in one beyond the paper: the figures its plan asks for
            self._own += 1
            try:
                return plan_figures(scene, self.workdir / f"own-{self._own}")
            except Exception as error:  # a figure that fails must not cost the rest of the report
                return [], [f"No figures: drawing them failed with {type(error).__name__}: {error}"]
        try:
            if hasattr(plotting, "scene_figures"):
                directory = self.workdir / scene.name
                directory.mkdir(parents=True, exist_ok=True)
                figures = dict(plotting.scene_figures(scene, directory))
                own = getattr(scene, "report_figures", None)  # a scene's own figures: {caption: PNG path}
                figures.update(own(directory) if own is not None else {})
                return _paths(figures, directory), []
            if not hasattr(plotting, "paper_figures"):
                return [], ["No figures: contactsym.plotting has no paper_figures function in this version."]
            if self._paper is None:
                directory = self.workdir / "paper"
                directory.mkdir(parents=True, exist_ok=True)
                self._paper = []  # drawn once, even when drawing fails
                self._paper = _paths(plotting.paper_figures(directory), directory)
        except Exception as error:  # a figure that fails must not cost the rest of the report
            return [], [f"No figures: drawing them failed with {type(error).__name__}: {error}"]
        chosen = [(p, c) for p, c in self._paper if _scene_of(p) in (scene.name, None)]
        notes = []
        if scene.k == 1 and not any("phase" in p.stem for p, _ in chosen):
            portrait, note = self._phase_portrait(plotting, scene)
            chosen += portrait
            notes += [note] if note else []
        if not chosen:
            notes.append("No figure of contactsym.plotting.paper_figures belongs to this scene.")
        return chosen, notes

    def _phase_portrait(self, plotting, scene) -> tuple[list[tuple[Path, str]], str]:
        """A phase portrait of the fast subsystem (2.1) of a one-contact scene."""
        if not (hasattr(plotting, "phase_portrait_data") and hasattr(plotting, "phase_portrait_plot")):
            return [], ""
        from matplotlib.figure import Figure as MplFigure  # matplotlib only when a figure is drawn

        try:
            data = plotting.phase_portrait_data(scene.name)
            figure = MplFigure(figsize=(7.0, 5.0))
            plotting.phase_portrait_plot(data, ax=figure.add_subplot())
            path = self.workdir / f"{scene.name.replace('-', '_')}_phase_portrait.png"
            figure.savefig(path, dpi=150, bbox_inches="tight")
        except Exception as error:  # a figure that fails must not cost the rest of the report
            return [], f"No phase portrait: drawing it failed with {type(error).__name__}: {error}"
        return [(path, r"Phase portrait of the fast subsystem (2.1) of this scene.")], ""
