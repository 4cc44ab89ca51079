"""flint: SymPy's sparse polynomials against python-flint's ``fmpq_mpoly`` for the canonical form's algebra.

The canonical form (:mod:`contactsym.algebra.canonical_form`) spends its polynomial time in
gcds (``PolyElement.cofactors``, reached through ``FracField.new``'s ``cancel``, ``_settled``'s
gcd and the half-angle step's ``cofactors``) and exact divisions (``div``, ``exquo``). Each
row does the same operation on the same inputs twice in one process: ours = python-flint
(conversion from and back to SymPy's ``PolyElement`` counted in), baseline = SymPy's own
``PolyElement`` (today's way); ratio = baseline / ours; error = 1 when the results differ.

Rows:

- ``captured``: real inputs saved from the pipeline (``flint_inputs.json.gz``, 86 kB): the
  four-link arm's largest cancel (robust classification, 10503 and 3889 terms in 18 variables),
  its half-angle cofactors (2230 and 1817 terms, 13 variables) and the 6-link chain's cancel of
  a field element (607 and 365 terms, 26 variables). The chain's half-angle cofactors of two
  23328-term polynomials (20 variables) were left out: not done in 400 s wall at load 20. Operations: cofactors, cancel (``FracField.new``), exact
  division by the gcd's cofactor, evaluation at a rational point.
- ``replayed``: every ``cancel`` and ``cofactors`` of a real derivation recorded and replayed
  with both: the 3-D stool (``examples/stool-3d.toml``, thousands of small ones) and, without
  ``--quick``, the four-link arm to its Jacobian A.
- ``end to end``: each in a fresh process, cold, CPU seconds: the derivation with SymPy on
  python ground types (today's install) against python-flint installed (SymPy then takes flint
  ground types) with every ``cofactors``/``div``/``exquo`` of at least ``MIN_TERMS`` terms sent
  to ``fmpq_mpoly`` (a benchmark-local routing, the what-if of an implementation); and SymPy on
  flint ground types alone.

Measured (2026-11-28, python-flint 0.9.0, SymPy 1.14 on python ground types, 2 cores at load
3-20, CPU s, one run): the arm's 10503/3889-term cofactors 9.9 s (SymPy) against 0.32 s (flint,
the gcd itself 0.006 s, the rest conversion), 31x; its cancel 10.3 against 0.31; its half-angle
cofactors 0.91 against 0.065 (14x); the chain's cancel 0.43 against 0.024 (18x); evaluation 4-5x;
an exact division whose quotient is trivial 0.5x (conversion alone). All results identical.
End to end the four-link arm to its Hurwitz conditions took 31.8 s against 20.3 s
(1.56x; today's code measured 26.6 s in another run, 1.3x: the CPU time of one run varies by
~20 % at this load), the same conditions; the stool 6.0 s against 5.7 s; SymPy on flint ground
types alone 27.2 s for the arm (no gain). Whether the robust classification, whose largest cancel
is the one above, gains more was not measured: it did not finish in 105 CPU s either way.

Without python-flint every row says so and has no time. ``python -m benchmarks.flint`` prints
the table; ``python -m benchmarks.flint e2e TARGET ENGINE`` is the fresh-process worker.
"""

from __future__ import annotations

import gzip
import json
import os
import random
import subprocess
import sys
import time
from pathlib import Path

from . import record

ROOT = Path(__file__).resolve().parent.parent
INPUTS = Path(__file__).resolve().parent / "flint_inputs.json.gz"
#: Below this many terms the routing keeps SymPy's own code (conversion would cost more).
MIN_TERMS = 30


def _flint():
    try:
        import flint
    except ImportError:
        return None
    return flint


# --- conversion -------------------------------------------------------------------------------


def _context(ring):
    flint = _flint()
    maker = flint.fmpz_mpoly_ctx if ring.domain.is_ZZ else flint.fmpq_mpoly_ctx
    return maker.get(("x", ring.ngens), "lex")


def to_flint(poly, ctx):
    """A SymPy ``PolyElement`` over ZZ (QQ) as an ``fmpz_mpoly`` (``fmpq_mpoly``) of ``ctx``, same variable order."""
    if poly.ring.domain.is_ZZ:
        return ctx.from_dict({m: int(c) for m, c in poly.items()})
    fmpq = _flint().fmpq
    return ctx.from_dict({m: fmpq(int(c.numerator), int(c.denominator)) for m, c in poly.items()})


def from_flint(poly, ring):
    """An ``fmpz_mpoly`` or ``fmpq_mpoly`` back in SymPy's ``ring``."""
    domain, terms = ring.domain, poly.to_dict()  # exponents come as fmpz: SymPy's monomials are ints
    if domain.is_ZZ:
        return ring.from_dict({tuple(map(int, m)): domain.dtype(int(c)) for m, c in terms.items()})
    return ring.from_dict({tuple(map(int, m)): domain.dtype(int(c.p), int(c.q)) for m, c in terms.items()})


def flint_cofactors(f, g):
    """(h, f/h, g/h) as SymPy's ``cofactors`` gives them: h monic over QQ; over ZZ with the contents' gcd, LC > 0."""
    ring, ctx = f.ring, _context(f.ring)
    F, G = to_flint(f, ctx), to_flint(g, ctx)
    H = F.gcd(G)  # lex order as SymPy's ring: QQ monic, ZZ up to sign
    if ring.domain.is_ZZ and H.leading_coefficient() < 0:
        H = -H
    return from_flint(H, ring), from_flint(F / H, ring), from_flint(G / H, ring)


def flint_div(f, g):
    """(q, r) with f = q g + r, r free of multiples of LT(g) (unique for one divisor, over a field)."""
    ctx = _context(f.ring)
    q, r = divmod(to_flint(f, ctx), to_flint(g, ctx))
    return from_flint(q, f.ring), from_flint(r, f.ring)


def _route_through_flint() -> None:
    """The what-if: SymPy's ``cofactors``/``gcd``/``div``/``exquo`` on big QQ/ZZ polynomials done by flint."""
    from sympy.polys.rings import PolyElement

    own = {name: getattr(PolyElement, name) for name in ("cofactors", "div", "exquo")}

    def big(f, g, field=False):
        return (
            type(g) is type(f)
            and f.ring == g.ring
            and (f.ring.domain.is_QQ or (f.ring.domain.is_ZZ and not field))
            and f
            and g
            and max(len(f), len(g)) >= MIN_TERMS
        )

    def cofactors(f, g):
        return flint_cofactors(f, g) if big(f, g) else own["cofactors"](f, g)

    def div(f, g):
        return flint_div(f, g) if big(f, g, field=True) else own["div"](f, g)

    def exquo(f, g):
        if big(f, g):
            quotient, remainder = flint_div(f, g)
            if not remainder:
                return quotient
        return own["exquo"](f, g)

    PolyElement.cofactors, PolyElement.div, PolyElement.exquo = cofactors, div, exquo
    PolyElement.gcd = lambda f, g: cofactors(f, g)[0]


# --- captured inputs --------------------------------------------------------------------------


def _captured():
    """(name, f, g) from the saved pipeline inputs, as SymPy PolyElements over QQ."""
    import sympy as sp
    from sympy.polys.rings import PolyRing

    cases = []
    for case in json.loads(gzip.decompress(INPUTS.read_bytes())):
        ring = PolyRing([sp.Dummy(s) for s in case["symbols"]], sp.QQ)

        def poly(rows, ring=ring):
            return ring.from_dict({tuple(r[:-1]): ring.domain.from_sympy(sp.Rational(r[-1])) for r in rows})

        cases.append((case["name"], poly(case["f"]), poly(case["g"])))
    return cases


def _cpu(function, *args):
    started = time.process_time()
    result = function(*args)
    return time.process_time() - started, result


def _captured_rows(quick: bool) -> list[dict]:
    from sympy.polys.fields import FracField

    rows = []
    for name, f, g in _captured():
        sizes = f"{len(f)} and {len(g)} terms, {f.ring.ngens} variables"
        # cofactors: the gcd and both cofactors
        ours, (h1, *cof1) = _cpu(flint_cofactors, f, g)
        base, (h2, *cof2) = _cpu(f.cofactors, g)
        rows.append(record(f"flint/{name}: cofactors", ours, base, int((h1, *cof1) != (h2, *cof2)), 1, sizes))
        # cancel: what FracField.new does with every fraction it builds
        field = FracField(f.ring.symbols, f.ring.domain)
        base, built = _cpu(field.new, f, g)
        ours, (_, p, q) = _cpu(flint_cofactors, f, g)
        scale = built.numer.LC / p.LC  # the same fraction up to a constant (no 10^7-term product to check it)
        same = built.numer == p.mul_ground(scale) and built.denom == q.mul_ground(scale)
        rows.append(record(f"flint/{name}: cancel", ours, base, int(not same), 1, sizes + "; ours = cofactors"))
        # exact division of f by the gcd's cofactor (what _settled's exquo and _exact do)
        divisor = cof2[0] if len(cof2[0]) > 1 else g
        product = f if divisor is cof2[0] else f * g
        ours, (q1, r1) = _cpu(flint_div, product, divisor)
        base, (q2, r2) = _cpu(product.div, divisor)
        rows.append(record(f"flint/{name}: division", ours, base, int((q1, r1) != (q2, r2)), 1, sizes))
        # evaluation at a rational point (signs of conditions at samples)
        rng = random.Random(5)
        point = [f.ring.domain(rng.randint(1, 9), rng.randint(1, 9)) for _ in range(f.ring.ngens)]
        ours, v1 = _cpu(_flint_value, f, point)
        base, v2 = _cpu(f.evaluate, list(zip(f.ring.gens, point)))
        error = int(_flint().fmpq(int(v2.numerator), int(v2.denominator)) != v1)
        rows.append(record(f"flint/{name}: evaluation", ours, base, error, 1, sizes + "; ours includes the conversion"))
    return rows


def _flint_value(poly, point):
    """``poly`` at ``point`` (QQ coordinates) by flint, the conversion counted."""
    fmpq = _flint().fmpq
    return to_flint(poly, _context(poly.ring))(*[fmpq(int(x.numerator), int(x.denominator)) for x in point])


# --- replayed derivations ---------------------------------------------------------------------


def _recorded(build) -> list[tuple]:
    """Every (op, f, g) of ``cancel`` and ``cofactors`` while ``build()`` derives (outermost calls)."""
    from sympy.polys.rings import PolyElement

    calls, depth = [], [0]
    own = {name: getattr(PolyElement, name) for name in ("cancel", "cofactors")}

    def recording(name):
        def wrapped(f, g):
            if not depth[0] and type(g) is type(f) and f and g:
                calls.append((name, f, g))
            depth[0] += 1
            try:
                return own[name](f, g)
            finally:
                depth[0] -= 1

        return wrapped

    PolyElement.cancel, PolyElement.cofactors = recording("cancel"), recording("cofactors")
    try:
        build()
    finally:
        PolyElement.cancel, PolyElement.cofactors = own["cancel"], own["cofactors"]
    return calls


def _replayed_row(name: str, build) -> dict:
    calls = _recorded(build)
    ours = base = 0.0
    big = 0
    for op, f, g in calls:
        if max(len(f), len(g)) >= MIN_TERMS:
            big += 1
            seconds, _ = _cpu(flint_cofactors, f, g)
            ours += seconds
        else:
            seconds, _ = _cpu(getattr(f, op), g)
            ours += seconds
        seconds, _ = _cpu(getattr(f, op), g)
        base += seconds
    notes = f"{len(calls)} cancel/cofactors replayed, {big} with >= {MIN_TERMS} terms sent to flint"
    return record(f"flint/replayed: {name}", ours, base, None, len(calls), notes)


def _replayed_rows(quick: bool) -> list[dict]:
    import contactsym as cs

    rows = [_replayed_row("stool-3d derivation", lambda: _derive_stool(cs))]
    if not quick:
        rows.append(_replayed_row("four-link arm to A", lambda: _arm(cs).linearization().A))
    return rows


def _derive_stool(cs):
    scene = cs.load_scene(ROOT / "examples" / "stool-3d.toml")
    conditions = scene.stability().hurwitz
    scene.regions()
    return conditions


def _arm(cs):
    return cs.load_scene(ROOT / "examples" / "four-link-arm.toml")


# --- end to end, fresh processes --------------------------------------------------------------

ENGINES = {  # engine -> (SYMPY_GROUND_TYPES, route big gcds/divisions through fmpq_mpoly)
    "sympy": ("python", False),
    "flint-ground-types": ("flint", False),
    "flint": ("flint", True),
}


def _end_to_end(target: str, engine: str, limit: float) -> dict | None:
    ground, _ = ENGINES[engine]
    env = dict(os.environ, SYMPY_GROUND_TYPES=ground, PYTHONPATH=str(ROOT))
    command = [sys.executable, "-m", "benchmarks.flint", "e2e", target, engine]
    try:
        done = subprocess.run(command, cwd=ROOT, env=env, capture_output=True, text=True, timeout=limit, check=True)
    except (subprocess.TimeoutExpired, subprocess.CalledProcessError):
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def _e2e_worker(target: str, engine: str) -> None:
    if ENGINES[engine][1]:
        _route_through_flint()
    from sympy.external.gmpy import GROUND_TYPES

    import contactsym as cs

    started = time.process_time()
    if target == "stool-3d":
        scene = cs.load_scene(ROOT / "examples" / "stool-3d.toml")
        conditions = scene.stability().hurwitz
        scene.regions()
    else:  # the arm to its Hurwitz conditions
        scene = _arm(cs)
        conditions = scene.stability().hurwitz
    seconds = time.process_time() - started
    print(json.dumps({"cpu_s": seconds, "ground": GROUND_TYPES, "conditions": str(conditions)}))


def _end_to_end_rows(quick: bool) -> list[dict]:
    targets = ["stool-3d"] if quick else ["stool-3d", "arm-hurwitz"]
    limit = 300.0 if quick else 1800.0
    rows = []
    for target in targets:
        base = _end_to_end(target, "sympy", limit)
        for engine in ("flint-ground-types", "flint"):
            ours = _end_to_end(target, engine, limit)
            same = None if not (ours and base) else int(ours["conditions"] != base["conditions"])
            notes = f"cold fresh process, CPU s; baseline: SymPy, python ground types; ours: {engine}"
            if not ours or not base:
                notes += f"; a run did not finish in {limit:.0f} s wall"
            rows.append(
                record(
                    f"flint/end to end: {target}, {engine}",
                    ours["cpu_s"] if ours else None,
                    base["cpu_s"] if base else None,
                    same,
                    1,
                    notes + "; error = 1 if the Hurwitz conditions differ",
                )
            )
    return rows


def run(quick: bool, out_dir) -> list[dict]:
    if _flint() is None:
        return [record("flint/all", None, None, None, 0, "python-flint not installed: pip install python-flint")]
    rows = _captured_rows(quick) + _replayed_rows(quick) + _end_to_end_rows(quick)
    if out_dir is not None:
        _plot(Path(out_dir), rows)
    return rows


def _plot(out_dir: Path, rows) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    shown = [r for r in rows if r["ratio"]]
    fig, ax = plt.subplots(figsize=(9, 0.32 * len(shown) + 1.5))
    positions = np.arange(len(shown))
    ax.barh(positions, [r["ratio"] for r in shown], color=["C0" if r["ratio"] >= 1 else "C3" for r in shown])
    ax.axvline(1.0, color="k", lw=0.8)
    ax.set_xscale("log")
    ax.set_yticks(positions, [r["name"].removeprefix("flint/") for r in shown], fontsize=7)
    ax.invert_yaxis()
    ax.set_xlabel("SymPy CPU s / python-flint CPU s (conversion included; > 1: flint faster)")
    ax.set_title("python-flint fmpq_mpoly against SymPy PolyElement, same inputs, one run")
    fig.tight_layout()
    fig.savefig(out_dir / "flint.png", dpi=110)
    plt.close(fig)


def main() -> int:
    rows = run("--quick" in sys.argv, None)
    print("| name | ours_s (flint) | baseline_s (SymPy) | ratio | error | n | notes |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        cells = [r["name"], r["ours_s"], r["baseline_s"], r["ratio"], r["error"], r["n"], r["notes"]]
        print("| " + " | ".join(f"{c:.3g}" if isinstance(c, float) else str(c) for c in cells) + " |")
    return 0


if __name__ == "__main__":  # pragma: no cover
    if len(sys.argv) == 4 and sys.argv[1] == "e2e":
        _e2e_worker(sys.argv[2], sys.argv[3])
    else:
        sys.exit(main())
