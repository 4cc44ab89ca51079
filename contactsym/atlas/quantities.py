"""What an atlas measures at each point: built-in quantities and the user's own functions.

A :class:`Quantity` does its symbolic work once, on the machine that calls
:func:`contactsym.atlas.sweep`: :meth:`Quantity.build` returns a :class:`Kernel`, a small
picklable object holding generated NumPy code (``numerics.lambdify_cse`` and
``numerics.PointClassifier``) and plain numbers. Workers receive the kernel, never
expressions to re-derive. The simulated quantities (:func:`cycle`, :func:`catastrophe`)
hold the scene with its derivation already done (fast subsystem, equilibria); their
per-point cost is the integration, plus the substitution of the point's numbers into the
derived system and its code generation (1.7 % of a brake cycle, measured with cProfile).
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from .. import numerics
from .grid import AtlasError, Grid
from .kernel import Kernel, Setup, setup_for
from .pointwise import PointFailure, build_catastrophe, build_cycle, build_function

__all__ = [
    "PointFailure",
    "QUANTITIES",
    "Kernel",
    "Quantity",
    "as_quantity",
    "catastrophe",
    "classification",
    "cycle",
    "equilibrium_count",
    "function",
    "leading_eigenvalue",
    "stable_fraction",
]


@dataclass(frozen=True)
class Quantity:
    """A named measurement: ``build(scene, grid, values)`` does the symbolic work once."""

    name: str
    builder: Callable = field(repr=False)
    options: dict = field(default_factory=dict)

    def build(self, scene, grid: Grid, values: Mapping | None) -> Kernel:
        return self.builder(scene, grid, values, **self.options)

    def key(self) -> str:
        """Identity for a checkpoint: the name and the options (functions by qualified name)."""
        items = sorted((k, getattr(v, "__qualname__", repr(v))) for k, v in self.options.items())
        return f"{self.name}{items}"


def _classifier(setup: Setup, conditions, what: str, extra=()) -> numerics.PointClassifier:
    conditions = [setup.prepare(c, what, extra) for c in conditions]
    try:
        return numerics.PointClassifier(conditions, setup.symbols + tuple(extra))
    except numerics.NumericsError as error:
        raise AtlasError(f"{what}: {error}") from None


def _strict(condition) -> list:
    """``expr > 0`` parts of an equilibrium's existence condition (an And of strict inequalities)."""
    parts = []
    for atom in sp.And.make_args(condition):
        if atom is sp.true:
            continue
        if isinstance(atom, sp.StrictGreaterThan):
            parts.append(atom.lhs - atom.rhs)
        elif isinstance(atom, sp.StrictLessThan):
            parts.append(atom.rhs - atom.lhs)
        else:
            raise AtlasError(
                f"cannot count equilibria: the existence condition {condition} is not strict inequalities."
            )
    return parts or [sp.S.One]


# --- vectorised quantities ---------------------------------------------------------------------


class _LeadingEigenvalue(Kernel):
    outputs = ("leading_eigenvalue", "frequency")
    vectorised = True

    def __init__(self, setup: Setup, matrix: sp.Matrix):
        self.setup, self.size = setup, matrix.rows
        self.function = numerics.lambdify_cse(setup.symbols, list(matrix))

    def evaluate(self, points):
        n = len(points)
        entries = self.function(*self.setup.columns(points))
        M = np.stack([np.broadcast_to(np.asarray(e, dtype=float), (n,)) for e in entries], axis=-1)
        eigenvalues = np.linalg.eigvals(M.reshape(n, self.size, self.size))
        leading = np.take_along_axis(eigenvalues, np.argmax(eigenvalues.real, axis=1)[:, None], axis=1)[:, 0]
        return np.column_stack([leading.real, np.abs(leading.imag)])


def _build_leading_eigenvalue(scene, grid, values, signs=None):
    setup = setup_for(scene, grid, values)
    matrix = setup.prepare(scene.linearization(signs).matrix, "the matrix (4.5)")
    return _LeadingEigenvalue(setup, matrix)


class _Classification(Kernel):
    outputs = ("region", "stable")
    vectorised = True

    def __init__(self, setup: Setup, robust: list, classifier):
        self.setup, self.classifier = setup, classifier
        self.function = numerics.lambdify_cse(setup.symbols, robust)

    def evaluate(self, points):
        n = len(points)
        stable, unstable, dependent = (
            np.broadcast_to(np.asarray(m, dtype=bool), (n,)) for m in self.function(*self.setup.columns(points))
        )
        region = np.select([stable, unstable, dependent], [1.0, -1.0, 0.0], np.nan)
        hurwitz = np.full(n, np.nan)
        if self.classifier is not None:
            hurwitz = self.classifier(*self.setup.columns(points)).stable.astype(float)
        return np.column_stack([region, hurwitz])


def _build_classification(scene, grid, values, signs=None):
    setup = setup_for(scene, grid, values)
    st = scene.stability(signs)
    # None (undecided at a numeric A) proves nothing: such points get no region (NaN)
    robust = [sp.false if b is None else b for b in (st.robustly_stable, st.robustly_unstable, st.law_dependent)]
    robust = [setup.prepare(b, "the robust classification (Propositions 3-8)") for b in robust]
    try:
        classifier = _classifier(setup, st.hurwitz, "the Hurwitz conditions (4.7)")
    except AtlasError:
        classifier = None  # no law given: only the law-independent region
    return _Classification(setup, robust, classifier)


class _StableFraction(Kernel):
    outputs = ("stable_fraction",)
    vectorised = True

    def __init__(self, setup: Setup, classifier, laws: np.ndarray):
        self.setup, self.classifier, self.laws = setup, classifier, laws

    def evaluate(self, points):
        n, count = len(points), len(self.laws)
        columns = [np.repeat(c, count) for c in self.setup.columns(points)]
        columns += [np.tile(self.laws[:, j], n) for j in range(self.laws.shape[1])]
        stable = self.classifier(*columns).stable.reshape(n, count)
        return (stable == 1).mean(axis=1)


def _build_stable_fraction(scene, grid, values, laws=256, magnitudes=(0.1, 10.0), seed=0, signs=None):
    setup = setup_for(scene, grid, values)
    lin = scene.linearization(signs)
    law_symbols = tuple(lin.Phi) + tuple(lin.Psi)
    if not all(isinstance(s, sp.Symbol) and s.is_negative for s in law_symbols):
        raise AtlasError(
            f"the laws of '{scene.name}' are fixed (Phi, Psi = {law_symbols}); sampling laws needs generic contacts."
        )
    taken = sorted(str(s) for s in set(law_symbols) & set(setup.symbols))
    if taken:
        raise AtlasError(f"{taken} are sampled by stable_fraction; do not give them in the grid or values.")
    low, high = np.log10(magnitudes[0]), np.log10(magnitudes[1])
    samples = -(10.0 ** np.random.default_rng(seed).uniform(low, high, size=(int(laws), len(law_symbols))))
    return _StableFraction(
        setup, _classifier(setup, scene.stability(signs).hurwitz, "the Hurwitz conditions (4.7)", law_symbols), samples
    )


class _EquilibriumCount(Kernel):
    outputs = ("equilibrium_count",)
    vectorised = True

    def __init__(self, setup: Setup, classifiers: list):
        self.setup, self.classifiers = setup, classifiers

    def evaluate(self, points):
        columns = self.setup.columns(points)
        return sum((c(*columns).stable == 1).astype(float) for c in self.classifiers)


def _build_equilibrium_count(scene, grid, values):
    setup = setup_for(scene, grid, values)
    what = "the existence conditions of the equilibria (4.2)"
    return _EquilibriumCount(setup, [_classifier(setup, _strict(b.condition), what) for b in scene.equilibria()])


# --- the public constructors ------------------------------------------------------------------


def leading_eigenvalue(*, signs=None) -> Quantity:
    """The eigenvalue of (4.5) with the largest real part: its real part and |imaginary part|."""
    return Quantity("leading_eigenvalue", _build_leading_eigenvalue, {"signs": signs})


def classification(*, signs=None) -> Quantity:
    """``region``: 1 stable for every law, -1 unstable for every law, 0 law-dependent, NaN undecided
    (Propositions 3-8, in floating point); ``stable``: the certified Hurwitz verdict (+1, -1, 0 on the
    boundary) when the law's Phi_j, Psi_j are given, else NaN."""
    return Quantity("classification", _build_classification, {"signs": signs})


def stable_fraction(*, laws: int = 256, magnitudes=(0.1, 10.0), seed: int = 0, signs=None) -> Quantity:
    """The fraction of ``laws`` sampled laws that are stable: Phi_j, Psi_j < 0 with magnitudes
    log-uniform in ``magnitudes`` (the same samples at every point), certified by PointClassifier."""
    options = {"laws": laws, "magnitudes": tuple(magnitudes), "seed": seed, "signs": signs}
    return Quantity("stable_fraction", _build_stable_fraction, options)


def equilibrium_count() -> Quantity:
    """The number of consistent equilibria of the fast subsystem (4.2), certified by PointClassifier."""
    return Quantity("equilibrium_count", _build_equilibrium_count)


def cycle(**options) -> Quantity:
    """Amplitude (half the peak-to-peak of the reactions, largest over the contacts) and angular
    frequency (stretched time) of the stable cycle from :func:`contactsym.numerics.fast_cycle`."""
    return Quantity("cycle", build_cycle, options)


def catastrophe(eps, span, initial: Mapping, **options) -> Quantity:
    """Time to the impact-type catastrophe in :func:`contactsym.numerics.simulate_full` (inf: none in span)."""
    return Quantity("catastrophe", build_catastrophe, {"eps": eps, "span": tuple(span), "initial": initial, **options})


def function(fn: Callable, outputs: Sequence[str] | None = None) -> Quantity:
    """The user's own ``fn(values) -> number, sequence or mapping`` of a point's values by name."""
    if not callable(fn):
        raise AtlasError(f"{fn!r} is not callable; give a function of a mapping of values.")
    names = tuple(outputs) if outputs is not None else (getattr(fn, "__name__", "value"),)
    return Quantity(f"function {getattr(fn, '__qualname__', 'value')}", build_function, {"fn": fn, "outputs": names})


#: Built-in quantities by name, with their default options.
QUANTITIES = {
    "classification": classification,
    "leading_eigenvalue": leading_eigenvalue,
    "stable_fraction": stable_fraction,
    "equilibrium_count": equilibrium_count,
    "cycle": cycle,
    "catastrophe": catastrophe,
}


def as_quantity(quantity) -> Quantity:
    """A :class:`Quantity` from itself, a built-in name or a function."""
    if isinstance(quantity, Quantity):
        return quantity
    if isinstance(quantity, str):
        name = quantity.replace("-", "_")
        if name not in QUANTITIES:
            raise AtlasError(f"unknown quantity {quantity!r}; the built-in ones are {', '.join(QUANTITIES)}.")
        if name == "catastrophe":
            raise AtlasError("the catastrophe quantity needs eps, span and initial: catastrophe(eps, span, initial).")
        return QUANTITIES[name]()
    if callable(quantity):
        return function(quantity)
    raise AtlasError(f"quantity {quantity!r} is neither a Quantity, a built-in name nor a function.")
