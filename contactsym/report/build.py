"""Building a scene's report directory: figures, ``conditions.json``, ``report.tex`` and ``report.pdf``.

:func:`write_report` writes the files all or nothing (:mod:`contactsym.atomic`);
:func:`compile_pdf` runs pdflatex when it is installed.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from ..atomic import replaced_directory, scratch_directory
from ..errors import ReportError
from ..mechanism.scene import Scene
from ..validate import checked_fields, flag, instance_of, path_text, shorten
from .document import Figure, report_tex
from .scene_parts import FigureSource
from .summary import conditions

__all__ = ["ReportError", "ReportResult", "compile_pdf", "write_report"]


@dataclass
class ReportResult:
    """What :func:`write_report` wrote.

    Examples
    --------
    >>> import tempfile
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> x, y = dynamicsymbols("x y")
    >>> N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    >>> own = cs.Scene.from_accelerations([x, y], [-mu*sp.Abs(N), N - 1], [cs.Contact(y, N)], name="own")
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     result = write_report(own, directory + "/report", pdf=False)
    ...     print(isinstance(result, ReportResult), result.scene, result.tex.name, result.conditions.name,
    ...           result.tex.exists(), result.pdf)
    True own report.tex conditions.json True None
    """

    scene: str
    directory: Path
    tex: Path
    conditions: Path
    pdf: Path | None = None
    figures: list = field(default_factory=list)
    notes: list = field(default_factory=list)

    def __post_init__(self):
        checked_fields(self, ReportError)


# --- files ------------------------------------------------------------------------------------


def compile_pdf(tex: Path, timeout: float = 120) -> Path | None:
    r"""Run pdflatex on ``tex`` in its directory; the PDF, or None when pdflatex is not installed.

    Raises ReportError (with the first LaTeX error line) when pdflatex fails.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     tex = Path(directory) / "hello.tex"
    ...     _ = tex.write_text(r"\documentclass{article}\begin{document}Hello\end{document}")
    ...     pdf = compile_pdf(tex)
    ...     print(pdf is None or (pdf == tex.with_suffix(".pdf") and pdf.exists()))
    True
    """
    tex = Path(path_text(tex, "tex", ReportError))
    ok = isinstance(timeout, (int, float)) and not isinstance(timeout, bool) and 0 < float(timeout) <= 86400
    if not ok:
        raise ReportError(f"timeout = {shorten(timeout)} must be a number of seconds from 0 to 86400.")
    try:
        found = tex.is_file()
    except OSError:  # e.g. a name too long for the file system
        found = False
    if not found:
        raise ReportError(f"{shorten(str(tex))} is not a LaTeX file; give the path of an existing .tex file.")
    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        return None
    command = [pdflatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", tex.name]
    for _ in range(2):  # a second run only when LaTeX asks for it (longtable widths)
        try:
            run = subprocess.run(command, cwd=tex.parent, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired as error:
            raise ReportError(f"pdflatex took more than {timeout:.0f} s on {tex}.") from error
        log = tex.with_suffix(".log")
        log_text = log.read_text(errors="replace") if log.exists() else run.stdout
        if run.returncode != 0:
            first = next((line for line in log_text.splitlines() if line.startswith("!")), "unknown error")
            raise ReportError(f"pdflatex failed on {tex}: {first.lstrip('! ')} (see {log}).")
        if "Rerun LaTeX" not in log_text and "Rerun to get" not in log_text:
            break
    return tex.with_suffix(".pdf")


def write_report(
    scene,
    directory: Path | str,
    *,
    pdf: bool = True,
    figures: FigureSource | None = None,
    progress: Callable[[str], None] | None = None,
    force: bool = False,
) -> ReportResult:
    """Write ``directory/report.tex``, ``conditions.json``, ``figures/*.png`` and ``report.pdf``.

    Works for any Scene: a built-in one, one read from a scene file
    (:func:`contactsym.load_scene`) or one built in Python. The paper's errata, its
    scene-specific equation numbers and figures appear only for the built-in scene objects
    (decided by identity, not by name). Other scenes get the figures of their
    ``figure_plan`` (a scene file's ``[figures]``, or ``scene.figure_plan =
    contactsym.FigurePlan(x, y, x_range, y_range, values)``): region maps in that plane and,
    for one contact, the phase portrait of (2.1).

    ``figures`` shares drawn figures between scenes (one is made when not given);
    ``progress`` receives short messages. ``report.pdf`` is made when ``pdf`` is true and
    pdflatex is installed. All or nothing: the files are written to a directory beside
    ``directory`` that replaces it only when all succeeded (see :mod:`contactsym.atomic`);
    an existing directory holding anything contactsym did not write (a user's file) is replaced
    only with ``force=True``; ``force`` and ``pdf`` must be bools (``force="no"`` is an error
    and touches nothing).

    Examples
    --------
    >>> import tempfile
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> x, y = dynamicsymbols("x y")
    >>> N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    >>> own = cs.Scene.from_accelerations([x, y], [-mu*sp.Abs(N), N - 1], [cs.Contact(y, N)], name="brake")
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     result = write_report(own, directory, pdf=False)
    ...     text = result.tex.read_text()
    >>> "Errata" in text, result.figures, result.notes[0][:40]
    (False, [], 'No figures: give the scene a [figures] t')
    """
    instance_of(
        scene, Scene, "scene", "pass a Scene, e.g. contactsym.scene('brake') or load_scene('my.toml')", ReportError
    )
    directory = Path(path_text(directory, "directory", ReportError))
    pdf, force = flag(pdf, "pdf", ReportError), flag(force, "force", ReportError)
    instance_of(figures, FigureSource, "figures", "pass a FigureSource or None", ReportError, optional=True)
    if progress is not None and not callable(progress):
        raise ReportError(f"progress = {shorten(progress)} must be a function of one message (or None).")
    with replaced_directory(directory, force=force, error=ReportError) as work:
        result = _write_files(scene, work, pdf, figures, progress or (lambda message: None), directory)
    return ReportResult(
        scene.name,
        directory,
        directory / result.tex.name,
        directory / result.conditions.name,
        None if result.pdf is None else directory / result.pdf.name,
        [Figure(directory / "figures" / f.path.name, f.caption) for f in result.figures],
        result.notes,
    )


def _compile_keeping_log(tex: Path, target: Path) -> Path | None:
    """compile_pdf; on failure the log is copied beside ``target``, since the directory of ``tex`` is removed."""
    try:
        return compile_pdf(tex)
    except ReportError as error:
        log, kept = tex.with_suffix(".log"), target.with_name(f"{target.name}-pdflatex.log")
        message = str(error).replace(str(tex), str(target / tex.name))
        if log.exists():
            shutil.copyfile(log, kept)
            message = message.replace(str(log), str(kept))
        raise ReportError(f"{message} The previous report is unchanged.") from error


def _write_files(scene, directory: Path, pdf: bool, figures: FigureSource | None, say, final: Path) -> ReportResult:
    try:
        (directory / "figures").mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise ReportError(f"cannot create {directory / 'figures'}: {error.strerror or error}.") from error
    result = ReportResult(scene.name, directory, directory / "report.tex", directory / "conditions.json")
    say("conditions")
    data = conditions(scene)
    result.conditions.write_text(json.dumps(data, indent=2, ensure_ascii=False) + "\n")
    say("figures")
    with scratch_directory() as scratch:
        source = figures or FigureSource(scratch)
        drawn, notes = source.for_scene(scene)
        placed = []
        for path, caption in drawn:
            target = directory / "figures" / path.name
            if path.resolve() != target.resolve():
                shutil.copyfile(path, target)
            placed.append(Figure(target, caption))
    result.figures, result.notes = placed, list(notes)
    say("LaTeX")
    result.tex.write_text(report_tex(scene, placed, notes))
    if pdf:
        say("pdflatex")
        result.pdf = _compile_keeping_log(result.tex, final)
        if result.pdf is None:
            result.notes.append(
                "pdflatex is not installed: report.pdf was not made (apt-get install texlive-latex-base)."
            )
    return result
