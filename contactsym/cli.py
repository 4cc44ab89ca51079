"""Command line: ``contactsym [show] [SCENE]``, ``contactsym list``."""

from __future__ import annotations

import argparse
import sys

import sympy as sp

from .errors import ContactsymError
from .scenes import DEFAULT_SCENE, scene, scene_names


def derivation_chain(name: str) -> str:
    """The derivation chain of a scene, as plain text, stage by stage."""
    s = scene(name)
    fast = s.fast_subsystem()
    lin = s.linearization()
    st = s.stability()
    lines = [f"scene {s.name}: {s.description}", "", "accelerations (1.4):"]
    lines += [f"  {s._plain(q)}'' = {s._plain(g)}" for q, g in s.accelerations.items()]
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
        f"  stable where   {st.robustly_stable}",
        f"  unstable where {st.robustly_unstable}",
        f"  law-dependent where {st.law_dependent}",
    ]
    if st.hopf_frequency is not None:
        lines.append(f"Hopf frequency omega (stretched time) = {st.hopf_frequency}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="contactsym", description="Exact stability of frictional compliant contacts.")
    sub = parser.add_subparsers(dest="command")
    show = sub.add_parser("show", help="print the derivation chain of a scene")
    show.add_argument("scene", nargs="?", default=DEFAULT_SCENE, help=f"one of {', '.join(scene_names())}")
    sub.add_parser("list", help="list the built-in scenes")
    args = parser.parse_args(argv)
    try:
        if args.command == "list":
            for name in scene_names():
                print(f"{name:24s}{scene(name).description}")
            return 0
        name = getattr(args, "scene", DEFAULT_SCENE)
        with sp.evaluate(True):
            print(derivation_chain(name))
        return 0
    except ContactsymError as error:
        print(f"contactsym: error: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
