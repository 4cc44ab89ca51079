"""Command line.

The argument parser and the text the commands print are in :mod:`contactsym.command_line`.

SCENE is a built-in scene's name or the path of a scene file (``my.toml``, see
:mod:`contactsym.mechanism.files.reader`).

The commands::

    contactsym [show] [SCENE] [--set NAME=VALUE ...]  the derivation chain of a scene, as text
    contactsym list                      the built-in scenes
    contactsym conditions SCENE --format text|latex|json [--signs +1,-1] [--set NAME=VALUE ...]
    contactsym report [SCENE ...] --out DIR [--no-pdf] [--force] [--resolution N] [--dpi N] [--set NAME=VALUE ...]
                                             a LaTeX/PDF report per scene, figures and conditions.json
    contactsym bench [--quick] [--jobs N] [--out DIR] [--json FILE]
                                             the benchmarks (from a source checkout)
    contactsym atlas SCENE QUANTITY --grid NAME=START:STOP:COUNT [--scheduler ADDRESS] [--out FILE.nc]
                                             a parameter sweep (contactsym[atlas]; see contactsym.atlas)

Caps on what a scene file may cost (its size, its number of contacts, ...: the fields of
:class:`contactsym.mechanism.files.Limits`; the powers, numbers and nesting of its formulas:
:data:`contactsym.parse.CAPS`) refuse a file beyond them, naming the cap. ``--limit CAP=N``,
before or after the command and as often as needed, raises one for this run, e.g.
``contactsym --limit max_degree=64 --limit max_contacts=8 report big.toml``.

``--set m1=1 --set l1=1/2`` fixes parameters at numbers before the derivation (a partly
numeric scene, :meth:`contactsym.Scene.with_values`); the value is read by the package's
formula parser (numbers only, never evaluated as Python).

Output directories are written all or nothing (:mod:`contactsym.atomic`): a report or
benchmark directory appears whole or not at all, and one that contactsym did not write
is replaced only with ``--force``. SIGTERM and SIGINT remove the temporary files.

Errors print one line to stderr and give a non-zero exit code: 2 for a bad command
line (an unknown scene, a bad option), 1 for a failure while working (an unwritable
directory, a pdflatex error).
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path

import sympy as sp

from .atomic import last_signal, replaced_directory, scratch_directory, signals_as_exceptions
from .command_line.options import FAILURE, USAGE, command_parser, parse_signs, raised_limits
from .command_line.options import LIMIT_NAMES as LIMIT_NAMES
from .command_line.options import parse_setting as parse_setting
from .command_line.output import conditions_latex, conditions_text, derivation_chain
from .errors import ContactsymError, SceneError, SignPatternError
from .mechanism.files.reader import scene_or_file
from .mechanism.scene import Scene
from .parse import ParseError
from .scenes import DEFAULT_SCENE, scene_description, scene_names
from .validate import cut, named_once, path_text, shorten

__all__ = ["derivation_chain", "main"]

# the argument parser by its name before the split (benchmarks/boundary.py reads it)
_parser = command_parser


def _with_values(s: Scene, values: list) -> Scene:
    return s.with_values(named_once(values)) if values else s


def _progress(message: str) -> None:
    print(f"contactsym: {message}", file=sys.stderr, flush=True)


def _report(
    names: list[str],
    out: str,
    pdf: bool,
    force: bool = False,
    resolution: int | None = None,
    dpi: int | None = None,
    values: list = (),
) -> int:
    from .report import FigureSource, ReportError, conditions, summary_text, write_report  # brings matplotlib

    names = names or scene_names()
    scenes = [_with_values(scene_or_file(name), values) for name in names]  # bad input fails before any work
    seen: dict = {}
    for name, s in zip(names, scenes):
        if seen.setdefault(s.name, name) != name:
            raise SceneError(
                f"'{seen[s.name]}' and '{name}' are both named '{s.name}'; give one a different name in its [scene] table."
            )
    root = Path(path_text(out, "--out", ReportError))  # no empty name, no NUL character
    try:
        root.mkdir(parents=True, exist_ok=True)
        probe = root / ".contactsym-write-test"
        probe.write_text("")
        probe.unlink()
    except OSError as error:
        raise ReportError(f"cannot write to --out {cut(str(root))}: {cut(str(error.strerror or error))}.") from error
    summaries, started = [], time.perf_counter()
    with scratch_directory() as scratch:
        figures = FigureSource(scratch, resolution=resolution, dpi=dpi)
        for index, s in enumerate(scenes, 1):
            clock = time.perf_counter()

            def say(step: str, index=index, name=s.name) -> None:
                _progress(f"[{index}/{len(scenes)}] {name}: {step}")

            result = write_report(s, root / s.name, pdf=pdf, figures=figures, progress=say, force=force)
            for note in result.notes:
                _progress(f"[{index}/{len(scenes)}] {s.name}: note: {note}")
            made = ", ".join(p.name for p in (result.tex, result.pdf, result.conditions) if p is not None)
            _progress(
                f"[{index}/{len(scenes)}] {s.name}: wrote {made} and {len(result.figures)} figures "
                f"in {time.perf_counter() - clock:.1f} s"
            )
            summaries.append(summary_text(conditions(s)))
    print("\n\n".join(summaries))
    print(f"\nreports in {root}/<scene>/ ({time.perf_counter() - started:.1f} s)")
    return 0


def _conditions(name: str, fmt: str, signs: str | None, values: list = ()) -> int:
    from .report import conditions  # the report brings matplotlib, which only the report commands need

    s = _with_values(scene_or_file(name), values)
    pattern = None if signs is None else s.check_signs(parse_signs(signs))
    data = conditions(s, pattern)
    if fmt == "json":
        print(json.dumps(data, indent=2, ensure_ascii=False))
    elif fmt == "latex":
        print(conditions_latex(data))
    else:
        print(conditions_text(data))
    return 0


def _writable_file(path: str) -> None:
    """Fail before a long run, not after it, when ``path`` cannot be written."""
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if target.is_dir() or not folder.is_dir() or not os.access(folder, os.W_OK):
        raise ContactsymError(f"cannot write --json {shorten(path)}: choose a file in an existing, writable folder.")


def _bench(
    quick: bool, json_file: str | None, out: str = "contactsym-bench", force: bool = False, jobs: int | None = None
) -> int:
    root = str(Path(__file__).resolve().parent.parent)  # benchmarks/ sits beside the package in a checkout
    if root not in sys.path:
        sys.path.insert(0, root)
    try:
        from benchmarks.run import main as run_benchmarks  # only in a source checkout, beside the package
    except ImportError as error:
        raise ContactsymError(
            f"the benchmarks are not installed ({error}); run contactsym bench from a source checkout."
        ) from error
    if json_file:
        _writable_file(json_file)
    with replaced_directory(out, force=force) as work:
        code = run_benchmarks(
            (["--quick"] if quick else [])
            + (["--json", json_file] if json_file else [])
            + (["--jobs", str(jobs)] if jobs else [])
            + ["--out", str(work)]
        )
        if code:
            raise ContactsymError(f"the benchmarks failed (exit code {code}); --out {shorten(out)} was left as it was.")
    return code


def _silence_stdout() -> None:
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # stdout without a file descriptor (tests)
        pass


def main(argv: list[str] | None = None) -> int:
    """Run the command line; returns the exit code (0 on success, 128 + the signal when stopped by one)."""
    try:
        with signals_as_exceptions():
            return _main(argv)
    except KeyboardInterrupt as stop:  # a second signal while the first was being handled
        return getattr(stop, "exit_code", 130)


def _main(argv: list[str] | None) -> int:
    try:
        args = command_parser().parse_args(argv)
    except SystemExit as stop:  # --help, or a usage error already printed in one line
        return int(stop.code or 0)
    except KeyboardInterrupt as stop:
        print("contactsym: interrupted", file=sys.stderr)
        return getattr(stop, "exit_code", 130)
    try:
        with sp.evaluate(True), raised_limits(args.limits + getattr(args, "command_limits", [])):
            code = _run(args)
        sys.stdout.flush()
        if last_signal() is not None:  # it landed where Python swallows exceptions (a finalizer): still a stop
            print("contactsym: interrupted", file=sys.stderr)
            return 128 + last_signal()
        return code
    except BrokenPipeError:  # the reader went away (contactsym ... | head): stop quietly
        _silence_stdout()
        return FAILURE
    except (SceneError, SignPatternError, ParseError) as error:  # bad input: a name, a file, a formula
        print(f"contactsym: error: {error}", file=sys.stderr)
        return USAGE
    except ContactsymError as error:
        print(f"contactsym: error: {error}", file=sys.stderr)
        return FAILURE
    except OSError as error:
        text = f"{error.strerror or error}: {error.filename or ''}".rstrip(": ")
        print(f"contactsym: error: {cut(text, 300)}", file=sys.stderr)
        return FAILURE
    except KeyboardInterrupt as stop:  # SIGINT, SIGTERM or SIGHUP as Interrupted: temporary files are gone
        print("contactsym: interrupted", file=sys.stderr)
        return getattr(stop, "exit_code", 130)


def _run(args) -> int:
    if args.command == "list":
        for name in scene_names():
            print(f"{name:24s}{scene_description(name)}")
        return 0
    if args.command == "report":
        return _report(
            args.scenes,
            args.out,
            pdf=not args.no_pdf,
            force=args.force,
            resolution=args.resolution,
            dpi=args.dpi,
            values=args.values,
        )
    if args.command == "conditions":
        return _conditions(args.scene, args.format, args.signs, args.values)
    if args.command == "bench":
        return _bench(args.quick, args.json, args.out, args.force, args.jobs)
    if args.command == "atlas":
        from .atlas.cli import run_atlas  # Dask and xarray, only when the atlas runs

        return run_atlas(args)
    name = getattr(args, "scene", DEFAULT_SCENE)
    values = getattr(args, "values", [])
    print(derivation_chain(_with_values(scene_or_file(name), values) if values else name))
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
