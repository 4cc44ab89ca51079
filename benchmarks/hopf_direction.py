"""hopf_direction: the predicted direction and amplitude of the brake's squeal against simulation.

For each pad law, the Hopf crossing of the fast subsystem (2.1) of the brake (6.1)-(6.4)
is found along mu, l1 computed there (``contactsym.numerics.hopf_point``), and the
fast subsystem simulated on both sides of the line:

- l1 < 0: from inside and outside the predicted cycle at 0.1% to 2% past the line
  (where the predicted amplitude stays below the reaction N*: beyond, the pads lose
  contact and the cycle is no longer small); error = the largest relative gap between
  the predicted and the simulated reaction amplitude (the two runs bracket the true
  cycle), and the fitted exponent of amplitude against distance (1/2 for the
  square-root law);
- l1 > 0: before the line, starts at 0.7x and 1.3x the predicted unstable cycle must
  decay and jump away; error = 1 when they do not (the predicted sign is then wrong).

Each law is checked twice: on the fast subsystem in tau, and on the full system (1.9) at
eps = 1e-3 in t (the disc turning, the pads' gaps as coordinates, started on the predicted
cycle by ``contactsym.numerics.hopf.full_cycle_start``). ours_s: one l1 evaluation (a point on the
line, k = 2); baseline_s: the simulations that confirm it. Also timed: ``Stability.first_lyapunov``
with Hertz pads (symbolic stiffness and damping) against evaluating it at a point (full bench only), and the
brake's closed form ``contactsym.scenes.brake.squeal_direction(scene)``. Plot: ``hopf_direction.png``.
"""

from __future__ import annotations

import time

import numpy as np
import sympy as sp

import contactsym as cs
from contactsym import numerics
from contactsym.laws.library import CubicStiffening, Hertz, HuntCrossley
from contactsym.numerics.hopf import full_cycle_start

from . import record

_q, _qd = sp.symbols("q qdot", real=True)
_eps = sp.Symbol("epsilon", positive=True)
_V = _qd / _eps
BRAKE = {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4}
LAWS = {
    "Hertz": (Hertz(), 1.0),
    "Hunt-Crossley": (HuntCrossley(), 2.0),
    "cubic stiffening": (CubicStiffening(1, 1, 1), 0.5),
    "weakening damping": (
        cs.Law(-_q / _eps**2 - sp.Rational(3, 10) * _V + _V**3 / 30 - _V**5 / 500, _q, _qd, _eps, check=False),
        0.3,
    ),
}


EPS = 1e-3  # the full system (1.9) at this eps, in t = eps tau
#: DOP853's rtol, by --quick. The amplitudes are compared to the prediction at ~1e-2 (error ~0.03); at 1e-6 DOP853
#: takes ~0.6x the steps of 1e-8, at 1e-5 the module costs ~16% less CPU again (29 -> 24 s, 2026-11-28) while the
#: simulated amplitudes move by at most 0.14% (Hertz at 0.5%), the fitted exponents by 0.001 (0.486 -> 0.487,
#: 0.519 -> 0.520) and the subcritical runs by 0.3%: the same signs and the same square-root law.
RTOL = {False: 1e-8, True: 1e-5}
FULL_QUICK = ("Hertz", "weakening damping")  # --quick: the full system for one law of each direction


def _amplitude(values, laws, start, duration, period, rtol) -> np.ndarray:
    """The fast subsystem (2.1) from ``start`` (Q, V) over ``duration`` in tau: half the reactions' range."""
    run = numerics.simulate_fast(
        cs.scene("brake"),
        values,
        (0, duration),
        initial=start,
        laws=laws,
        method="DOP853",
        rtol=rtol,
        t_eval=np.linspace(duration - 2 * period, duration, 2000),
    )
    return (run.reactions.max(axis=1) - run.reactions.min(axis=1)) / 2


def _full_amplitude(h, mu, factor, laws, duration, period, rtol) -> np.ndarray:
    """The full system (1.9) at EPS from the predicted cycle (times ``factor``), the disc turning."""
    values = {**BRAKE, "mu": mu}
    start = full_cycle_start(cs.scene("brake"), h, values, EPS, mu, factor=factor, base={"thetadot": -1})
    run = numerics.simulate_full(
        cs.scene("brake"),
        {**values, "r": 1, "J": 1},
        EPS,
        (0, EPS * duration),
        start,
        laws=laws,
        method="DOP853",
        rtol=rtol,
        t_eval=EPS * np.linspace(duration - 2 * period, duration, 2000),
        dense_output=False,
    )
    return (run.reactions.max(axis=1) - run.reactions.min(axis=1)) / 2


def _runs(h, laws, mu, factors, full: bool, quick: bool = False) -> list[float]:
    """Reaction 1's amplitude after 1.5/alpha (--quick: 1/alpha) from each factor times the predicted cycle."""
    rtol = RTOL[quick]
    duration = (1.0 if quick else 1.5) / abs(h.dalpha * (mu - h.value))
    period = 2 * np.pi / h.omega
    if full:
        return [_full_amplitude(h, mu, f, laws, duration, period, rtol)[0] for f in factors]
    return [_amplitude({**BRAKE, "mu": mu}, laws, h.cycle_start(mu, f), duration, period, rtol)[0] for f in factors]


def _supercritical(h, laws, distances, full=False, quick=False):
    # from 0.8x and 1.2x over 1.5/alpha the gap to the cycle shrinks to 20% e^-3 = 1%; --quick: 0.9x and 1.1x
    # over 1/alpha, 10% e^-2 = 1.4%, at 2/3 of the cost
    factors = (0.9, 1.1) if quick else (0.8, 1.2)
    rows = []
    for d in distances:
        mu = h.value * (1 + d * np.sign(h.dalpha))
        rows.append((d, h.amplitude(mu)[0], *_runs(h, laws, mu, factors, full, quick)))
    return rows


def _subcritical(h, laws, d, full=False, quick=False):
    mu = h.value * (1 - d * np.sign(h.dalpha))
    return (h.amplitude(mu)[0], *_runs(h, laws, mu, (0.7, 1.3), full, quick))


def _direction_records(name, h, laws, distances, ours, curves, quick) -> list[dict]:
    """Fast subsystem and full system at EPS: simulated against predicted, one record each (quick:
    the full system at the largest small distance only, for the laws of FULL_QUICK, at rtol 1e-5)."""
    records = []
    for full in (False, True) if not quick or name in FULL_QUICK else (False,):
        label = f"hopf-direction/{name}" + (f" (full, eps={EPS:g})" if full else "")
        t0 = time.perf_counter()
        if h.direction == "supercritical":
            # weakly nonlinear theory holds while the cycle keeps the pads in contact (amplitude < u*)
            small = [d for d in distances if h.amplitude(h.value * (1 + d * np.sign(h.dalpha)))[0] < h.u_star[0]]
            lost = [d for d in distances if d not in small]
            if quick:  # the two largest where a 1.2x start keeps contact (a margin): the closest take longest
                small = [d for d in small if 1.2 * h.amplitude(h.value * (1 + d * np.sign(h.dalpha)))[0] < h.u_star[0]]
                small = small[-2:]
            rows = _supercritical(h, laws, small[-1:] if full and quick else small, full, quick)
            curves[name, full] = (h, rows)
            error = max(max(abs(lo - p), abs(hi - p)) / p for _, p, lo, hi in rows)
            slope = (
                np.polyfit(np.log([r[0] for r in rows]), np.log([(r[2] + r[3]) / 2 for r in rows]), 1)[0]
                if len(rows) > 1
                else float("nan")
            )
            fit = f"amplitude ~ distance^{slope:.3f} over {small}" if len(rows) > 1 else f"at {rows[0][0]} only"
            notes = f"l1 = {h.l1:.3g} < 0 at mu* = {h.value:.6g}; {fit}" + (
                f"; at {lost} the predicted amplitude exceeds N* = {h.u_star[0]:.3g}: contact loss" if lost else ""
            )
        else:
            predicted, low, high = _subcritical(h, laws, 0.03, full, quick)
            error = 0.0 if (low < 0.7 * predicted and high > 1.3 * predicted) else 1.0
            notes = (
                f"l1 = {h.l1:.3g} > 0 at mu* = {h.value:.6g}; 3% before the line the unstable cycle "
                f"{predicted:.3g}: 0.7x -> {low:.3g}, 1.3x -> {high:.3g} (jump: hysteresis)"
            )
        notes += f"; DOP853 rtol {RTOL[quick]:g}" + (
            f"; --quick: runs of 1/alpha (not 1.5/alpha) from 0.9x and 1.1x (not 0.8x and 1.2x) the predicted cycle, "
            f"at the two largest of {distances} where 1.2x keeps contact, the full system at the largest and for "
            f"{' and '.join(FULL_QUICK)} only"
            if quick
            else ""
        )
        simulated = len(rows) if h.direction == "supercritical" else 1
        records.append(record(label, ours, time.perf_counter() - t0, error, simulated, notes))
    return records


# --quick: the closed form in the derivatives that Hertz and the weakening damper have (notebook 06's
# subset, a few seconds); all ten (LAW_DERIVATIVES, 15-30 s) in the full bench
QUICK_DERIVATIVES = ("Phi_u", "Phi_v", "Phi_uu", "Phi_uv", "Phi_vv", "Psi_vv")


def _symbolic_l1_record() -> dict:
    """Stability.first_lyapunov with Hertz pads (symbolic k, d), against evaluating it at a point (full bench
    only: the subs of its ~180000 operations costs ~10 CPU s)."""
    import sympy as sp

    from contactsym.laws.library import with_laws

    k, d = sp.symbols("k d", positive=True)
    st = with_laws(cs.scene("brake"), Hertz(k, d)).stability()
    assert st.hopf_frequency is not None  # computed here: the Hopf set belongs to the stages, not to l1
    t0 = time.perf_counter()
    l1 = st.first_lyapunov
    ours = time.perf_counter() - t0
    values = {"m": 1, "alpha": np.pi / 2, "F_x": 0, "F_y": -4, "mu": 1}
    laws = {0: Hertz(), 1: Hertz()}
    h = numerics.hopf_point(cs.scene("brake"), values, "mu", laws=laws)
    P = {str(s): s for s in st.linearization.scene.parameters}
    point = {P["m"]: 1, P["alpha"]: sp.pi / 2, P["F_x"]: 0, P["F_y"]: -4, P["mu"]: h.value, k: 1, d: 1}
    t0 = time.perf_counter()
    value = complex(l1.subs(point)).real
    evaluation = time.perf_counter() - t0
    size = sp.count_ops(l1)
    error = 0.0 if value * h.l1 > 0 else 1.0
    return record(
        "hopf-direction/symbolic l1, Hertz pads",
        ours,
        evaluation,
        error,
        size,
        f"Stability.first_lyapunov built in {ours:.2f} s ({size} operations; by hand on one machine: 0.67 s "
        "with <q, q> and <p, q> expanded, 0.39 s without); baseline: evaluating it at mu* by subs "
        f"({evaluation:.2f} s, l1 = {value:.3g}, {'same sign as' if not error else 'other sign than'} numerics: "
        f"error {error:g})",
    )


def _closed_form_record(quick: bool = False) -> dict:
    """The brake's closed form squeal_direction(): the six derivatives of notebook 06 in --quick, all ten else."""
    import sympy as sp

    from contactsym.scenes.brake import LAW_DERIVATIVES, squeal_direction

    derivatives = QUICK_DERIVATIVES if quick else LAW_DERIVATIVES
    t0 = time.perf_counter()
    Phi_line, closed = squeal_direction(cs.scene("brake"), derivatives)
    closed_s = time.perf_counter() - t0
    return record(
        "hopf-direction/closed form, brake alpha = 90 deg",
        closed_s,
        None,
        0.0,
        len(sp.Add.make_args(closed)),
        f"squeal_direction(): Phi* = {Phi_line}, l1 with {len(sp.Add.make_args(closed))} terms in the "
        f"law's derivatives {', '.join(derivatives)}"
        + (" (--quick: the stiffness's and Psi_vv; all ten in the full bench)" if quick else "")
        + ", checked in tests/lyapunov/test_polynomial.py",
    )


def run(quick: bool, out) -> list[dict]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from contactsym.plotting.hopf import hopf_amplitude_data, hopf_amplitude_plot

    # --quick: per law the two largest distances where the runs keep contact (the exponent still fitted: Hertz
    # 0.5-1%, cubic stiffening 1-2%, Hunt-Crossley 0.2-0.3%); 0.001, the slowest to settle, in the full bench
    distances = (0.002, 0.003, 0.005, 0.01, 0.02) if quick else (0.001, 0.003, 0.01, 0.02)
    records, curves = [], {}
    for name, (law, mu0) in LAWS.items():
        laws = {0: law, 1: law}
        numerics.hopf_point(cs.scene("brake"), {**BRAKE, "mu": mu0}, "mu", laws=laws)  # generated code, not timed
        t0 = time.perf_counter()
        h = numerics.hopf_point(cs.scene("brake"), {**BRAKE, "mu": mu0}, "mu", laws=laws)
        records += _direction_records(name, h, laws, distances, time.perf_counter() - t0, curves, quick)
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    # --quick: the symbolic l1's row (its evaluation by subs ~10 CPU s) in the full bench only
    records += ([] if quick else [_symbolic_l1_record()]) + [_closed_form_record(quick)]
    color = None
    for (name, full), (h, rows) in curves.items():
        data = hopf_amplitude_data(h, [r[0] for r in rows], [(r[2] + r[3]) / 2 for r in rows])
        if full:  # the same prediction: only the full system's dots, in the fast runs' colour
            ax.plot(
                data["distance"], data["simulated"], "s", mfc="none", color=color, label=f"{name} full, eps={EPS:g}"
            )
        else:
            color = hopf_amplitude_plot(data, ax=ax, label=name)[0].get_color()
    ax.legend(fontsize="small")
    fig.savefig(out / "hopf_direction.png", dpi=120)
    plt.close(fig)
    return records
