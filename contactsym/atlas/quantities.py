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

from ..validate import shorten
from .grid import AtlasError, Grid
from .kernel import Kernel, once_per_scene
from .options import check_options
from .pointwise import SQUEAL_METHODS, PointFailure, build_catastrophe, build_cycle, build_function, build_squeal
from .vectorised import (
    _build_classification,
    _build_equilibrium_count,
    _build_leading_eigenvalue,
    _build_stable_fraction,
)

__all__ = [
    "PointFailure",
    "QUANTITIES",
    "SQUEAL_METHODS",
    "Kernel",
    "Quantity",
    "as_quantity",
    "catastrophe",
    "classification",
    "cycle",
    "equilibrium_count",
    "function",
    "leading_eigenvalue",
    "squeal",
    "stable_fraction",
]


@dataclass(frozen=True)
class Quantity:
    """A named measurement: ``build(scene, grid, values)`` does the symbolic work once.

    Examples
    --------
    >>> from contactsym import atlas
    >>> quantity = atlas.stable_fraction(laws=64)
    >>> isinstance(quantity, atlas.Quantity), quantity.name, quantity.options["laws"]
    (True, 'stable_fraction', 64)
    """

    name: str
    builder: Callable = field(repr=False)
    options: dict = field(default_factory=dict)

    def __post_init__(self):
        if not isinstance(self.name, str) or not callable(self.builder) or not isinstance(self.options, dict):
            raise AtlasError("a Quantity needs a name (text), a builder (a function) and options (a dict).")

    def build(self, scene, grid: Grid, values: Mapping | None) -> Kernel:
        if self.builder in _VECTORISED:  # their kernels are kept per scene: see once_per_scene
            return once_per_scene(self.builder, scene, grid, values, self.options)
        return self.builder(scene, grid, values, **self.options)

    def key(self) -> str:
        """Identity for a checkpoint: the name and the options (functions by qualified name)."""
        items = sorted((k, getattr(v, "__qualname__", repr(v))) for k, v in self.options.items())
        return f"{self.name}{items}"


# --- the public constructors ------------------------------------------------------------------


def leading_eigenvalue(*, signs=None) -> Quantity:
    """The eigenvalue of (4.5) with the largest real part: its real part and |imaginary part|.

    Examples
    --------
    The brake with a damping law (all Phi_j, Psi_j < 0): a stable focus, its largest real part < 0:

    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym import atlas
    >>> law = {"alpha": 1.0, "m": 1, "Phi_1": -1, "Phi_2": -1, "Psi_1": -1, "Psi_2": -1}
    >>> kernel = leading_eigenvalue().build(cs.scene("brake"), atlas.as_grid({"mu": [0.5, 1.5]}), law)
    >>> kernel.outputs
    ('leading_eigenvalue', 'frequency')
    >>> values, reasons = kernel(np.array([[0.5], [1.5]]))
    >>> bool((values[:, 0] < 0).all()), bool((values[:, 1] > 0).all())
    (True, True)
    """
    check_options("leading_eigenvalue", {"signs": signs})
    return Quantity("leading_eigenvalue", _build_leading_eigenvalue, {"signs": signs})


def classification(*, signs=None) -> Quantity:
    """``region``: 1 stable for every law, -1 unstable for every law, 0 law-dependent, NaN undecided
    (Propositions 3-8, in floating point); ``stable``: the certified Hurwitz verdict (+1, -1, 0 on the
    boundary) when the law's Phi_j, Psi_j are given, else NaN.

    Examples
    --------
    The brake at alpha = 1: stable for every law at mu = 0.5, law-dependent at mu = 1.5:

    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", classification(), {"mu": [0.5, 1.5]}, values={"alpha": 1.0, "m": 1},
    ...                  scheduler="threads")
    >>> ds.region.values.tolist()
    [1.0, 0.0]
    """
    check_options("classification", {"signs": signs})
    return Quantity("classification", _build_classification, {"signs": signs})


def stable_fraction(*, laws: int = 256, magnitudes=(0.1, 10.0), seed: int = 0, signs=None) -> Quantity:
    """The fraction of ``laws`` sampled laws that are stable: Phi_j, Psi_j < 0 with magnitudes
    log-uniform in ``magnitudes`` (the same samples at every point), certified by PointClassifier.

    Examples
    --------
    Where the brake is stable for every law (mu = 0.5), every sampled law is stable:

    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", stable_fraction(laws=16), {"mu": [0.5, 1.5]}, values={"alpha": 1.0, "m": 1},
    ...                  scheduler="threads")
    >>> fraction = ds.stable_fraction.values
    >>> float(fraction[0]), bool(0 < fraction[1] < 1)
    (1.0, True)
    """
    options = {"laws": laws, "magnitudes": magnitudes, "seed": seed, "signs": signs}
    check_options("stable_fraction", options)
    options["magnitudes"] = tuple(magnitudes)
    return Quantity("stable_fraction", _build_stable_fraction, options)


def equilibrium_count() -> Quantity:
    """The number of consistent equilibria of the fast subsystem (4.2), certified by PointClassifier.

    Examples
    --------
    >>> from contactsym import atlas
    >>> ds = atlas.sweep("brake", equilibrium_count(), {"mu": [0.5, 1.5]},
    ...                  values={"alpha": 1.0, "m": 1, "F_x": 1, "F_y": -1}, scheduler="threads")
    >>> ds.equilibrium_count.values.tolist()
    [1.0, 1.0]
    """
    return Quantity("equilibrium_count", _build_equilibrium_count)


def cycle(**options) -> Quantity:
    """Amplitude (half the peak-to-peak of the reactions, largest over the contacts) and angular
    frequency (stretched time) of the stable cycle from :func:`contactsym.numerics.fast_cycle`.

    Examples
    --------
    The options go on to :func:`contactsym.numerics.fast_cycle` (a sweep of cycles integrates at every
    point: see :func:`contactsym.atlas.sweep`):

    >>> quantity = cycle(samples=512)
    >>> quantity.name, quantity.options
    ('cycle', {'samples': 512})
    >>> as_quantity("cycle").name
    'cycle'
    """
    check_options("cycle", options)
    return Quantity("cycle", build_cycle, options)


def squeal(
    parameter: str, *, laws: Mapping | None = None, tol: float = 0.002, simulate: bool = True, **options
) -> Quantity:
    """The squeal's amplitude (half peak-to-peak of the reactions, largest over the contacts) and
    frequency (tau) near a Hopf line crossed along ``parameter``, with per point the ``method``
    (codes in ``SQUEAL_METHODS``: 0 stable equilibrium, 1 normal form, 2 simulation, 3 continuation),
    its estimated relative ``error``, ``contact_loss`` (1 where a pad opens on the cycle) and the
    Floquet ``multiplier`` that decides stability (the largest nontrivial one, < 1: stable).

    Per line of the grid along ``parameter``: one Hopf point (:func:`contactsym.numerics.normal_form.normal_form`);
    one cycle by shooting calibrates the normal form's error estimate ``|c1| r^2 / omega`` on the line
    (it gives the order, the constant is measured: about 7 for the brake with Hertz pads); the normal
    form gives the value where the calibrated estimate is within ``tol`` and the pads keep contact;
    the other points are cycles continued by shooting from the neighbouring point's cycle
    (:mod:`contactsym.numerics.branches`, all lines of a chunk in one batch). Where neither applies
    (no Hopf point, l1 > 0, a pad opens) :func:`contactsym.numerics.fast_cycle` (``options``) simulates,
    unless ``simulate=False`` (then NaN with the reason, e.g. "contact loss: ...").

    Examples
    --------
    >>> quantity = squeal("mu", tol=0.01, simulate=False)
    >>> quantity.name, quantity.options["tol"]
    ('squeal', 0.01)
    """
    return Quantity(
        "squeal", build_squeal, {"parameter": parameter, "laws": laws, "tol": tol, "simulate": simulate, **options}
    )


def catastrophe(eps, span, initial: Mapping, **options) -> Quantity:
    """Time to the impact-type catastrophe in :func:`contactsym.numerics.simulate_full` (inf: none in span).

    Examples
    --------
    The catastrophe needs a start, so it has no default and is not a built-in name alone:

    >>> quantity = catastrophe(0.01, (0, 5), {"x": 0.0})
    >>> quantity.name, quantity.options["span"]
    ('catastrophe', (0, 5))
    >>> try:
    ...     as_quantity("catastrophe")
    ... except AtlasError as error:
    ...     print(str(error).split(":")[0])
    the catastrophe quantity needs eps, span and initial
    """
    check_options("catastrophe", {"eps": eps, "span": span, "initial": initial, **options})
    return Quantity("catastrophe", build_catastrophe, {"eps": eps, "span": tuple(span), "initial": initial, **options})


def function(fn: Callable, outputs: Sequence[str] | None = None) -> Quantity:
    """The user's own ``fn(values) -> number, sequence or mapping`` of a point's values by name.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym import atlas
    >>> def friction_ratio(values):
    ...     return values["mu"] / values["m"]
    >>> grid = atlas.as_grid({"mu": [0.5, 1.5]})
    >>> kernel = function(friction_ratio).build(cs.scene("brake"), grid, {"m": 2})
    >>> kernel(grid.points(0, grid.size))[0].tolist()
    [[0.25], [0.75]]
    >>> try:
    ...     function(42)
    ... except AtlasError as error:
    ...     print(error)
    42 is not callable; give a function of a mapping of values.
    """
    if not callable(fn):
        raise AtlasError(f"{shorten(fn)} is not callable; give a function of a mapping of values.")
    names = outputs if outputs is not None else (getattr(fn, "__name__", "value"),)
    check_options("function", {"fn": fn, "outputs": names})
    names = tuple(names)
    return Quantity(f"function {getattr(fn, '__qualname__', 'value')}", build_function, {"fn": fn, "outputs": names})


#: The builders whose kernels are kept per scene (vectorised: no state of their own).
_VECTORISED = (_build_leading_eigenvalue, _build_classification, _build_stable_fraction, _build_equilibrium_count)

#: Built-in quantities by name, with their default options.
#:
#: >>> from contactsym.atlas import QUANTITIES
#: >>> 'classification' in QUANTITIES
#: True
QUANTITIES = {
    "classification": classification,
    "leading_eigenvalue": leading_eigenvalue,
    "stable_fraction": stable_fraction,
    "equilibrium_count": equilibrium_count,
    "cycle": cycle,
    "catastrophe": catastrophe,
}


def as_quantity(quantity) -> Quantity:
    """A :class:`Quantity` from itself, a built-in name or a function.

    Examples
    --------
    >>> as_quantity("leading-eigenvalue")
    Quantity(name='leading_eigenvalue', options={'signs': None})
    >>> def twice_mu(values):
    ...     return 2 * values["mu"]
    >>> as_quantity(twice_mu).options["outputs"]
    ('twice_mu',)
    >>> try:
    ...     as_quantity("nope")
    ... except AtlasError as error:
    ...     print(str(error).split(";")[0])
    unknown quantity 'nope'
    """
    if isinstance(quantity, Quantity):
        return quantity
    if isinstance(quantity, str):
        name = quantity.replace("-", "_")
        if name not in QUANTITIES:
            raise AtlasError(f"unknown quantity {shorten(quantity)}; the built-in ones are {', '.join(QUANTITIES)}.")
        if name == "catastrophe":
            raise AtlasError("the catastrophe quantity needs eps, span and initial: catastrophe(eps, span, initial).")
        return QUANTITIES[name]()
    if callable(quantity):
        return function(quantity)
    raise AtlasError(f"quantity {shorten(quantity)} is neither a Quantity, a built-in name nor a function.")
