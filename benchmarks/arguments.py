"""The cost of the argument checks (``contactsym.arguments.checked``): ``python -m benchmarks.arguments``.

Each row times one call of a checked public callable and of the same function undecorated
(``__wrapped__``), side by side in one run, best of five repeats; the difference is what
the check costs per call. The checks run once per call at the boundary, never inside a loop.
"""

from __future__ import annotations

import timeit

import sympy as sp

import contactsym as cs
from contactsym.algebra import hurwitz_matrix, reduce_signs
from contactsym.counts import orthant_patterns
from contactsym.laws import Generic


def rows() -> list[tuple[str, float, float]]:
    brake = cs.scene("brake")
    big = brake.stability().hurwitz[-1]
    u, v = sp.symbols("u v")
    cases = [
        ("orthant_patterns(2)", orthant_patterns, (2,)),
        ("hurwitz_matrix(4 symbols)", hurwitz_matrix, (sp.symbols("a0:4"),)),
        ("Generic().phi_psi(u, v, 1)", Generic.phi_psi, (Generic(), u, v, 1)),
        (f"reduce_signs(Delta, {sp.count_ops(big)} operations)", reduce_signs, (big,)),
        ("Scene.freeze(Delta)", cs.Scene.freeze, (brake, big)),
    ]
    out = []
    for label, function, args in cases:
        raw = function.__wrapped__
        number = 200
        checked = min(timeit.repeat(lambda f=function, a=args: f(*a), number=number, repeat=5)) / number
        plain = min(timeit.repeat(lambda f=raw, a=args: f(*a), number=number, repeat=5)) / number
        out.append((label, checked, plain))
    return out


def main() -> None:
    print("| call | checked (us) | unchecked (us) | cost of the check (us) |")
    print("|---|---|---|---|")
    for label, checked, plain in rows():
        print(f"| `{label}` | {checked * 1e6:.1f} | {plain * 1e6:.1f} | {(checked - plain) * 1e6:.1f} |")


if __name__ == "__main__":  # pragma: no cover
    main()
