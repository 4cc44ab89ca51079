"""The command line's options, read before any work: the argument parser of :mod:`contactsym.cli`,
the caps ``--limit`` raises, the numbers ``--set`` fixes, sign patterns, and the exit codes.

Examples
--------
>>> parse_signs("+,-"), parse_setting("m=2")
((1, -1), ('m', 2))
>>> command_parser().parse_args(["show", "brake"]).scene
'brake'
"""

from __future__ import annotations

import argparse
import difflib
from contextlib import ExitStack
from dataclasses import fields

import sympy as sp

from ..errors import SignPatternError
from ..mechanism.files.spec import Limits, file_limits
from ..parse import CAPS, ParseError, formula_caps, parse_expression
from ..scenes import DEFAULT_SCENE, scene_names
from ..validate import cut, shorten

__all__ = [
    "FAILURE",
    "LIMIT_NAMES",
    "USAGE",
    "command_parser",
    "parse_setting",
    "parse_signs",
    "raised_limits",
]

#: Exit codes.
USAGE, FAILURE = 2, 1


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


def raised_limits(pairs) -> ExitStack:
    """The caps of ``--limit`` in force: file sizes through ``file_limits``, formulas through ``formula_caps``."""
    values = dict(pairs)
    stack = ExitStack()
    sizes = {name: value for name, value in values.items() if name not in CAPS}
    if sizes:
        stack.enter_context(file_limits(Limits(**sizes)))
    stack.enter_context(formula_caps(**{name: value for name, value in values.items() if name in CAPS}))
    return stack


def command_parser() -> argparse.ArgumentParser:
    """The argument parser of ``contactsym``: the commands, their options, ``--limit`` on each."""
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
    bench.add_argument("--quick", action="store_true", help="smaller sweeps, under 3 minutes on 2 cores")
    bench.add_argument(
        "--jobs",
        type=_positive_int,
        metavar="N",
        help="benchmark modules run at once (default: every core with --quick, else 1)",
    )
    bench.add_argument("--json", metavar="FILE", type=_path, help="write the records as a JSON list to FILE")
    bench.add_argument(
        "--out",
        default="contactsym-bench",
        type=_path,
        help="folder for the table and plots (default: contactsym-bench)",
    )
    bench.add_argument("--force", action="store_true", help="replace an --out folder that contactsym did not write")
    from ..atlas.cli import add_atlas_command  # the atlas imports Dask and xarray only when it runs

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
