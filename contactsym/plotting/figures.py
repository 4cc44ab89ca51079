"""All figures of a scene as PNG files, from the scene's own module.

What a built-in scene draws, and with which caption, is scene knowledge: the function
``figures(scene, directory, *, resolution, dpi)`` of ``scenes/<name>.py``, asked for
through :func:`contactsym.scenes.paper_knowledge`. A user's scene has none here; its
``[figures]`` plan is drawn by :mod:`contactsym.plotting.plan_figures`.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from pathlib import Path

from ..arguments import between, checked
from ..errors import ReportError
from ..scenes import paper_knowledge
from ..scenes import scene as built_in
from ..validate import shorten

__all__ = ["FIGURE_SCENES", "paper_figures", "save_figure", "scene_figures"]

#: The paper's scenes whose figures :func:`paper_figures` writes, in its order (Fig. 1 first).
#:
#: >>> from contactsym.plotting import FIGURE_SCENES
#: >>> FIGURE_SCENES[0]
#: 'painleve-klein-guides'
FIGURE_SCENES = ("painleve-klein-guides", "painleve-klein-rod", "brake", "sliding-point")


@checked(size="tuple[float, float]", dpi=between(10, 2400))
def save_figure(path: Path, draw: Callable, *, size=(7.0, 5.0), dpi: int = 150) -> Path:
    r"""Call ``draw(figure)`` on a new matplotlib Figure of ``size`` inches and write it to ``path``.

    The Figure is made without pyplot, so drawing many files keeps no global state; the file
    is written beside ``path`` and renamed, all or nothing.

    Examples
    --------
    >>> import tempfile
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     path = save_figure(Path(directory) / "line.png", lambda f: f.add_subplot().plot([0, 1]), dpi=20)
    ...     path.read_bytes()[:4], sorted(p.name for p in Path(directory).iterdir())
    (b'\x89PNG', ['line.png'])
    """
    from matplotlib.figure import Figure  # matplotlib only when a figure is drawn

    figure = Figure(figsize=size)
    draw(figure)
    path = Path(path)
    partial = path.with_name(path.stem + ".partial.png")
    try:
        figure.savefig(partial, dpi=dpi, bbox_inches="tight")
        partial.replace(path)  # all or nothing: a reader never sees half a PNG
    except OSError as error:
        with contextlib.suppress(OSError):  # our own partial file, if it was made
            partial.unlink()
        raise ReportError(
            f"cannot write the figure {shorten(str(path))}: {error.strerror}; choose another path."
        ) from error
    return path


def _directory(directory) -> Path:
    """The folder for figures, made if missing; a name the system refuses is a ReportError."""
    directory = Path(directory)
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except (OSError, ValueError) as error:
        raise ReportError(f"cannot make the folder {shorten(str(directory))}: {error}"[:300]) from error
    return directory


@checked(scene="Scene | str", directory="Path | str", resolution=between(2, 4096), dpi=between(10, 2400))
def scene_figures(scene, directory, *, resolution=400, dpi=150) -> dict[str, Path]:
    """Write one scene's figures as PNGs into ``directory``; returns {LaTeX caption: path}.

    Parameters
    ----------
    scene : Scene
        A built-in scene (others have no figures here: an empty dict).
    directory : str or Path
        Created when missing.
    resolution : int
        Grid points per axis for the region plots (lower is faster).
    dpi : int

    Returns
    -------
    dict of str to Path
        Caption (LaTeX, written from the computed data) -> PNG file.

    Examples
    --------
    >>> import tempfile
    >>> import contactsym as cs
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     written = scene_figures(cs.scene("brake"), directory, resolution=20, dpi=20)
    ...     sorted(p.name for p in written.values())
    ['brake_alpha_mu.png', 'brake_hopf.png']
    """
    figures = paper_knowledge(scene, "figures")
    if figures is None:
        return {}
    directory = _directory(directory)
    return {caption: path for path, caption in figures(scene, directory, resolution=resolution, dpi=dpi)}


@checked(directory="Path | str", resolution=between(2, 4096), dpi=between(10, 2400))
def paper_figures(directory, *, resolution=400, dpi=150) -> list[Path]:
    """Write the figures of the paper's scenes (:data:`FIGURE_SCENES`) as PNGs into ``directory``.

    Parameters
    ----------
    directory : str or Path
        Created when missing.
    resolution : int
        Grid points per axis for the region plots (lower is faster).
    dpi : int

    Returns
    -------
    list of Path
        ``fig1a_guides.png``, ``fig1b_guides.png``, ``rod_f_cases.png``,
        ``rod_phase_portrait.png``, ``brake_alpha_mu.png``, ``brake_hopf.png``,
        ``sliding_point_phase_portrait.png``.

    Examples
    --------
    The figures are :func:`scene_figures` of each scene in :data:`FIGURE_SCENES`; one of them
    here (all four take about half a minute):

    >>> import tempfile
    >>> import contactsym as cs
    >>> FIGURE_SCENES
    ('painleve-klein-guides', 'painleve-klein-rod', 'brake', 'sliding-point')
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     written = scene_figures(cs.scene("sliding-point"), directory, resolution=20, dpi=20)
    ...     sorted(path.name for path in written.values())
    ['sliding_point_phase_portrait.png']
    """
    paths = []
    for name in FIGURE_SCENES:
        paths.extend(scene_figures(built_in(name), directory, resolution=resolution, dpi=dpi).values())
    return paths
