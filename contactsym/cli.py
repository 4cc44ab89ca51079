"""Command line.

SCENE is a built-in scene's name or the path of a scene file (``my.toml``, see
:mod:`contactsym.mechanism.files.reader`).

The commands::

    contactsym [show] [SCENE] [--set NAME=VALUE ...]  the derivation chain of a scene, as text
    contactsym list                      the built-in scenes
    contactsym conditions SCENE --format text|latex|json [--signs +1,-1] [--set NAME=VALUE ...]
    contactsym report [SCENE ...] --out DIR [--no-pdf] [--force] [--resolution N] [--dpi N] [--set NAME=VALUE ...]
                                             a LaTeX/PDF report per scene, figures and conditions.json
    contactsym bench [--quick] [--out DIR] [--json FILE] the benchmarks (from a source checkout)
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

import argparse
import difflib
import json
import os
import sys
import time
from contextlib import ExitStack
from dataclasses import fields
from pathlib import Path

import sympy as sp

from .atomic import last_signal, replaced_directory, scratch_directory, signals_as_exceptions
from .errors import ContactsymError, SceneError, SignPatternError
from .mechanism.files.reader import scene_or_file
from .mechanism.files.spec import Limits, file_limits
from .mechanism.scene import Scene
from .parse import CAPS, ParseError, formula_caps, parse_expression
from .scenes import DEFAULT_SCENE, scene, scene_names
from .validate import cut, path_text, shorten

__all__ = ["derivation_chain", "main"]

#: Exit codes.
USAGE, FAILURE = 2, 1


def derivation_chain(name) -> str:
    """The derivation chain of a scene (a built-in name, a scene file or a Scene), as plain text.

    Examples
    --------
    >>> print(derivation_chain("sliding-point").splitlines()[0])
    scene sliding-point: (1.10)-(1.12): a point sliding on a rough line, Kelvin-Voigt contact
    """
    s = name if isinstance(name, Scene) else scene_or_file(name)
    fast = s.fast_subsystem()
    lin = s.linearization()
    st = s.stability()
    lines = [f"scene {s.name}: {s.description}", "", "accelerations (1.4):"]
    lines += [f"  {s.plain(q)}'' = {s.plain(g)}" for q, g in s.accelerations.items()]
    lines += ["", "fast subsystem (2.1), tau = t/eps:"]
    lines += [f"  {eq.lhs} = {eq.rhs}" for eq in fast.equations]
    lines += ["", "equilibria f(u*) = 0 (4.2):"]
    for branch in s.equilibria():
        lines.append(f"  signs {branch.signs}: u* = {branch.u_star}, exists where {branch.condition}")
    lines += [
        "",
        f"A (4.3) = {lin.A.tolist()}",
        f"det A = {lin.det_A}",
        f"characteristic polynomial (4.6): {lin.charpoly.as_expr()}",
        "",
        "Hurwitz conditions (4.7), all > 0:",
    ]
    lines += [f"  {c}" for c in st.hurwitz]
    lines += [
        "",
        "for every admissible contact law:",
        f"  stable where   {_verdict_text(st.robustly_stable)}",
        f"  unstable where {_verdict_text(st.robustly_unstable)}",
        f"  law-dependent where {_verdict_text(st.law_dependent)}",
    ]
    if st.k >= 3 and st.A.free_symbols and st.undecided != sp.false:
        lines.append(f"  undecided where {st.undecided}")
    if st.hopf_frequency is not None:
        lines.append(f"Hopf frequency omega (stretched time) = {st.hopf_frequency}")
    return "\n".join(lines)


def _verdict_text(value) -> str:
    """A robustness statement as text: its region, or "undecided" where it is neither proved nor disproved."""
    return "undecided" if value is None else str(value)


# --- conditions -------------------------------------------------------------------------------


def parse_signs(text: str) -> tuple[int, ...]:
    """A sign pattern from the command line: ``+1,-1`` or ``+,-`` (no expression is evaluated).

    Examples
    --------
    >>> parse_signs("+1,-1"), parse_signs("+ -"), parse_signs("1")
    ((1, -1), (1, -1), (1,))
    >>> parse_signs("1,x")
    Traceback (most recent call last):
    ...
    contactsym.errors.SignPatternError: --signs: 'x' is not a sign; write e.g. --signs +1,-1.
    """
    values = {"+1": 1, "1": 1, "+": 1, "-1": -1, "-": -1}
    tokens = text.replace(",", " ").split()
    if not tokens:
        raise SignPatternError("--signs is empty; write e.g. --signs +1,-1.")
    for token in tokens:
        if token not in values:
            raise SignPatternError(f"--signs: {shorten(token)} is not a sign; write e.g. --signs +1,-1.")
    return tuple(values[token] for token in tokens)


def conditions_text(data: dict) -> str:
    """The conditions of :func:`contactsym.report.conditions` as plain text, in full."""
    lines = [f"{data['scene']}: {data['description']}"]
    if data.get("signs"):
        lines.append(f"sign pattern {tuple(data['signs'])}")
    lines.append("closed-form regions:")
    for name, entry in data["regions"].items():
        cite = ", ".join(entry.get("paper", []))
        lines.append(f"  {name}: {entry['sympy']}" + (f"   {cite}" if cite else ""))
    if data.get("equilibrium_counts"):
        lines.append("number of equilibria:")
        for name, entry in data["equilibrium_counts"].items():
            cite = ", ".join(entry.get("paper", []))
            lines.append(f"  {name}: {entry['sympy']}" + (f"   {cite}" if cite else ""))
    lines.append("Routh-Hurwitz conditions (4.7), all > 0:")
    for entry in data["hurwitz"]:
        name = entry["name"].replace("\\", "").replace("{", "").replace("}", "")
        lines.append(
            f"  {name} > 0 always: {entry['always']}" if entry.get("always") else f"  {name} = {entry['sympy']}"
        )
    if data.get("hopf_frequency"):
        lines.append(f"Hopf frequency omega (stretched time tau) = {data['hopf_frequency']['sympy']}")
    return "\n".join(lines)


def conditions_latex(data: dict) -> str:
    r"""The conditions as a LaTeX fragment (amsmath ``align*``), one numbered line each.

    Examples
    --------
    >>> from contactsym.report import conditions
    >>> print(conditions_latex(conditions(scene("brake"))).splitlines()[2])
    \text{stable for every law:} &\quad \mu \leq \left|{\cot{\left(\alpha \right)}}\right| \tag*{(4.4), (6.3)} \\
    """
    lines = [f"% contactsym conditions: {data['scene']}", r"\begin{align*}"]
    rows = []
    for name, entry in data["regions"].items():
        rows.append((name, entry))
    for name, entry in (data.get("equilibrium_counts") or {}).items():
        rows.append((f"equilibria, {name}", entry))
    for entry in data["hurwitz"]:
        rows.append((None, {**entry, "latex": f"{entry['name']} = {entry['latex']}"}))
    if data.get("hopf_frequency"):
        rows.append((None, {**data["hopf_frequency"], "latex": r"\omega = " + data["hopf_frequency"]["latex"]}))
    body = []
    for name, entry in rows:
        label = r"\text{" + name.replace("_", r"\_") + r":} " if name else ""
        tag = r" \tag*{" + ", ".join(entry["paper"]) + "}" if entry.get("paper") else ""
        body.append(f"{label}&\\quad {entry['latex']}{tag}")
    lines.append(" \\\\\n".join(body) + " \\\\")
    lines.append(r"\end{align*}")
    return "\n".join(lines)


# --- the command line ----------------------------------------------------------------------------


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors."""

    def error(self, message: str):
        message = cut(message, 200)
        self.exit(USAGE, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


#: The caps ``--limit`` raises: a scene file's sizes, then its formulas'.
LIMIT_NAMES = tuple(f.name for f in fields(Limits)) + CAPS


def _limit(text: str) -> tuple[str, int]:
    """One ``--limit CAP=N``: a cap's name (:data:`LIMIT_NAMES`) and a whole number >= 1."""
    name, equals, value = text.partition("=")
    name = name.strip()
    if not equals or name not in LIMIT_NAMES:
        close = difflib.get_close_matches(name, LIMIT_NAMES, n=1)
        hint = f"did you mean {close[0]}? " if close else ""
        raise argparse.ArgumentTypeError(
            f"{cut(text, 40)!r} is not CAP=N; {hint}give e.g. --limit max_degree=64 (--help lists the caps)"
        )
    return name, _positive_int(value.strip())


def _add_limit(parser: argparse.ArgumentParser, dest: str) -> None:
    parser.add_argument(
        "--limit",
        dest=dest,
        action="append",
        type=_limit,
        default=[],
        metavar="CAP=N",
        help=f"raise a cap on scene files for this run (repeatable); CAP is one of {', '.join(LIMIT_NAMES)}",
    )


def _raised_limits(pairs) -> ExitStack:
    """The caps of ``--limit`` in force: file sizes through ``file_limits``, formulas through ``formula_caps``."""
    values = dict(pairs)
    stack = ExitStack()
    sizes = {name: value for name, value in values.items() if name not in CAPS}
    if sizes:
        stack.enter_context(file_limits(Limits(**sizes)))
    stack.enter_context(formula_caps(**{name: value for name, value in values.items() if name in CAPS}))
    return stack


def _parser() -> argparse.ArgumentParser:
    names = ", ".join(scene_names()) + ", or a scene file (.toml)"
    parser = _Parser(prog="contactsym", description="Exact stability of frictional compliant contacts.")
    _add_limit(parser, "limits")
    sub = parser.add_subparsers(dest="command", parser_class=_Parser)
    show = sub.add_parser("show", help="print the derivation chain of a scene")
    _add_limit(show, "command_limits")
    show.add_argument("scene", nargs="?", default=DEFAULT_SCENE, help=f"one of {names}")
    _add_set(show)
    sub.add_parser("list", help="list the built-in scenes")
    cond = sub.add_parser("conditions", help="print a scene's stability conditions and regions")
    _add_limit(cond, "command_limits")
    cond.add_argument("scene", help=f"one of {names}")
    cond.add_argument("--format", choices=("text", "latex", "json"), default="text", help="output format")
    cond.add_argument("--signs", help="one sign pattern of the switching functions, e.g. +1,-1")
    _add_set(cond)
    report = sub.add_parser("report", help="write a LaTeX/PDF report per scene, with figures and conditions.json")
    _add_limit(report, "command_limits")
    report.add_argument("scenes", nargs="*", metavar="SCENE", help=f"scenes to report (default: all of {names})")
    report.add_argument(
        "--out", default="contactsym-report", type=_path, help="output directory (default: contactsym-report)"
    )
    report.add_argument("--no-pdf", action="store_true", help="write report.tex but do not run pdflatex")
    report.add_argument("--force", action="store_true", help="replace scene directories that contactsym did not write")
    report.add_argument(
        "--resolution",
        type=_positive_int,
        metavar="N",
        help="grid points per axis of the region maps (default: 400 for the paper's figures, 200 otherwise)",
    )
    report.add_argument("--dpi", type=_positive_int, metavar="N", help="dots per inch of the figures (default: 150)")
    _add_set(report)
    bench = sub.add_parser("bench", help="run the benchmarks (source checkout); table and plots in --out")
    bench.add_argument("--quick", action="store_true", help="smaller sweeps, under 3 minutes")
    bench.add_argument("--json", metavar="FILE", type=_path, help="write the records as a JSON list to FILE")
    bench.add_argument(
        "--out",
        default="contactsym-bench",
        type=_path,
        help="folder for the table and plots (default: contactsym-bench)",
    )
    bench.add_argument("--force", action="store_true", help="replace an --out folder that contactsym did not write")
    from .atlas.cli import add_atlas_command  # the atlas imports Dask and xarray only when it runs

    add_atlas_command(sub)
    return parser


def _add_set(command) -> None:
    command.add_argument(
        "--set",
        dest="values",
        action="append",
        type=parse_setting,
        default=[],
        metavar="NAME=VALUE",
        help="fix a parameter at a number before the derivation (repeat it: --set m1=1 --set l1=0.5)",
    )


def parse_setting(text: str) -> tuple[str, sp.Expr]:
    """``NAME=VALUE`` from the command line: a name and an exact number (the formula parser reads
    the value with no names declared, so only numbers, pi and functions of them pass).

    Examples
    --------
    >>> parse_setting("m1=1/2"), parse_setting("l = 0.1")
    (('m1', 1/2), ('l', 1/10))
    >>> parse_setting("m1")
    Traceback (most recent call last):
    ...
    argparse.ArgumentTypeError: 'm1' is not NAME=VALUE; write e.g. --set m1=1.5
    """
    name, equals, value = text.partition("=")
    name = name.strip()
    if not equals or not name.isidentifier():
        raise argparse.ArgumentTypeError(f"{cut(text)!r} is not NAME=VALUE; write e.g. --set m1=1.5")
    try:
        number = parse_expression(value.strip(), {}, source="--set")
    except ParseError as error:
        raise argparse.ArgumentTypeError(f"--set {cut(name)}: {error}") from None
    if not (number.is_real and number.is_finite):
        raise argparse.ArgumentTypeError(f"--set {cut(name)}: {cut(value)!r} is not a finite real number")
    return name, number


def _with_values(s: Scene, values: list) -> Scene:
    return s.with_values(dict(values)) if values else s


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{cut(text)!r} is not a whole number; give e.g. 100") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"{value} is not positive; give e.g. 100")
    return value


def _path(text: str) -> str:
    """A path argument: not empty (an empty --out would mean the current directory)."""
    if not text.strip():
        raise argparse.ArgumentTypeError("the path is empty; name a file or directory")
    return text


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


def _bench(quick: bool, json_file: str | None, out: str = "contactsym-bench", force: bool = False) -> int:
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
            (["--quick"] if quick else []) + (["--json", json_file] if json_file else []) + ["--out", str(work)]
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
        args = _parser().parse_args(argv)
    except SystemExit as stop:  # --help, or a usage error already printed in one line
        return int(stop.code or 0)
    except KeyboardInterrupt as stop:
        print("contactsym: interrupted", file=sys.stderr)
        return getattr(stop, "exit_code", 130)
    try:
        with sp.evaluate(True), _raised_limits(args.limits + getattr(args, "command_limits", [])):
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
            print(f"{name:24s}{scene(name).description}")
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
        return _bench(args.quick, args.json, args.out, args.force)
    if args.command == "atlas":
        from .atlas.cli import run_atlas  # Dask and xarray, only when the atlas runs

        return run_atlas(args)
    name = getattr(args, "scene", DEFAULT_SCENE)
    values = getattr(args, "values", [])
    print(derivation_chain(_with_values(scene_or_file(name), values) if values else name))
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
