"""The vectorised quantities' kernels: generated code evaluated on a whole chunk of grid points at once.

Classification, stable fraction and equilibrium count read certified verdicts from
:class:`contactsym.numerics.PointClassifier`, built once per scene and quantity (``_built_classifier``);
the leading eigenvalue batches ``numpy.linalg.eigvals``.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np
import sympy as sp

from .. import numerics
from ..numerics.buffered import NUMPY_FUNCTIONS, BufferedCode, cheapest_trig
from ..stages.regions import proved_no_equilibrium
from .grid import AtlasError, Grid
from .kernel import Kernel, Reasons, Setup, setup_for

__all__: list[str] = []  # kernels, reached through the constructors of contactsym.atlas.quantities


def _classifier(setup: Setup, conditions, what: str, extra=()) -> numerics.PointClassifier:
    """A classifier of the grid's and the fixed symbols (then ``extra``): one per scene and quantity, whatever
    the fixed numbers (they are arguments of its code, read once per chunk: see ``Setup.columns``)."""
    conditions = tuple(setup.prepare(c, what, extra) for c in conditions)
    try:
        return _built_classifier(conditions, setup.symbols + tuple(extra))
    except numerics.NumericsError as error:
        raise AtlasError(f"{what}: {error}") from None


@lru_cache(maxsize=32)
def _built_classifier(conditions: tuple, symbols: tuple) -> numerics.PointClassifier:
    """One classifier per scene and quantity: building one factors every condition (``sp.factor``),
    which costs far more than a sweep's chunk; the classifier is read-only once built."""
    return numerics.PointClassifier(conditions, symbols)


@lru_cache(maxsize=32)
def _robust_function(robust: tuple, symbols: tuple):
    """The robust regions' code, once per scene and fixed values (code generation costs more than a chunk):
    buffered code (truth values as 1.0 and 0.0), else lambdify; and the functions of one grid symbol in it.

    A function of one grid symbol (``sin(alpha)``) is an argument of the code, not an operation: a sweep
    computes it once per value of the axis (see ``_Classification.run``), not once per point."""
    robust = [cheapest_trig(b) for b in robust]
    found = sorted(
        {f for b in robust for f in b.atoms(sp.Function) if f.args[0] in symbols and type(f) in NUMPY_FUNCTIONS},
        key=sp.default_sort_key,
    )
    names = tuple(sp.Dummy(f"f{i}") for i in range(len(found)))
    robust = [b.xreplace(dict(zip(found, names))) for b in robust]
    of_axes = tuple((symbols.index(f.args[0]), getattr(np, NUMPY_FUNCTIONS[type(f)])) for f in found)
    try:
        return _Truths(symbols + names, robust), of_axes
    except numerics.NumericsError:
        pass
    try:
        return BufferedCode(symbols + names, robust), of_axes
    except numerics.NumericsError:
        function = numerics.lambdify_cse(symbols + names, list(robust))
        return (lambda columns, buffers: function(*columns)), of_axes


_COMPARISONS = {sp.StrictGreaterThan: np.greater, sp.GreaterThan: np.greater_equal}
_COMPARISONS |= {sp.StrictLessThan: np.less, sp.LessThan: np.less_equal}
_CONNECTIVES = {sp.And: np.logical_and, sp.Or: np.logical_or}


def _is_truth(b) -> bool:
    """Whether ``b`` is true, false, or And, Or and Not of <, <=, >, >=."""
    if b in (sp.true, sp.false) or type(b) in _COMPARISONS:
        return True
    return (isinstance(b, sp.Not) or type(b) in _CONNECTIVES) and all(_is_truth(a) for a in b.args)


class _Truths:
    """Truth values of And, Or and Not of <, <=, >, >= as bool arrays (or one bool): the sides of the relations
    by buffered code, each comparison and connective into a byte per point (not a float64 1.0 or 0.0)."""

    def __init__(self, arguments: tuple, booleans: list):
        if not all(_is_truth(b) for b in booleans):
            raise numerics.NumericsError("no truth code for these conditions")
        self.relations = sorted({r for b in booleans for r in b.atoms(sp.Rel)}, key=sp.default_sort_key)
        self.code = BufferedCode(arguments, [side for r in self.relations for side in (r.lhs, r.rhs)])
        self.booleans, self.buffers = booleans, self.code.buffers

    def __call__(self, columns: list, buffers: np.ndarray) -> list:
        sides = self.code(columns, buffers)
        truth = {r: _COMPARISONS[type(r)](sides[2 * k], sides[2 * k + 1]) for k, r in enumerate(self.relations)}
        return [self._value(b, truth) for b in self.booleans]

    def _value(self, b, truth: dict):
        if b in (sp.true, sp.false):
            return np.bool_(b is sp.true)
        if isinstance(b, sp.Not):
            return np.logical_not(self._value(b.args[0], truth))
        if type(b) in _CONNECTIVES:
            values = [self._value(a, truth) for a in b.args]
            out = _CONNECTIVES[type(b)](values[0], values[1])
            for value in values[2:]:
                out = _CONNECTIVES[type(b)](out, value, out=out) if out.ndim else _CONNECTIVES[type(b)](out, value)
            return out
        return truth[b]


def _strict(condition) -> list:
    """``expr > 0`` parts of an equilibrium's existence condition (an And of strict inequalities)."""
    if condition == sp.false:  # the branch exists nowhere (a one-sided contact pulled open): never counted
        return [sp.S.NegativeOne]
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
    matrix = setup.prepare(scene.linearization(signs).jacobian, "the matrix (4.5)")
    return _LeadingEigenvalue(setup, matrix)


class _Classification(Kernel):
    outputs = ("region", "stable")
    vectorised = True

    def __init__(self, setup: Setup, robust: list, classifier):
        self.setup, self.classifier = setup, classifier
        self.function, self.of_axes = _robust_function(tuple(setup.specialised(b) for b in robust), setup.swept)

    def evaluate(self, points):
        columns = self.setup.grid_columns(points)
        return self._values(columns, [ufunc(columns[j]) for j, ufunc in self.of_axes])

    def run(self, grid: Grid, start: int, stop: int):
        """The grid's columns as they are made (no matrix of points), each function of an axis once per axis value."""
        try:
            with np.errstate(all="ignore"):
                columns, laid = grid.columns(start, stop), {}  # a function of an axis laid out once for both codes
                functions = [self._of_axis(grid, j, f.__name__, start, stop, laid)[0] for j, f in self.of_axes]
                given = [self._of_axis(grid, j, f, start, stop, laid)[1] for j, f in self._classifier_functions()]
                return self._values(columns, functions, given), Reasons.none(stop - start)
        except Exception:  # noqa: BLE001 - point by point, each failure with its reason (Kernel.__call__)
            return self(grid.points(start, stop))

    def _classifier_functions(self) -> tuple:
        return self.classifier.functions if self.classifier is not None else ()

    def _of_axis(self, grid: Grid, j: int, ufunc: str, start: int, stop: int, laid: dict) -> tuple:
        """A function of a grid axis, once per axis value, laid out as the axis is (kept in ``laid``): (for the robust
        regions' code, for the classifier). The classifier's is None (computed per point by the classifier) for a
        fixed argument, or where the axis values under- or overflow (its certificate assumes neither)."""
        if j >= len(grid.axes):
            return None, None
        if (j, ufunc) not in laid:
            try:
                with np.errstate(all="raise"):
                    along, certified = getattr(np, ufunc)(grid.axes[j]), True
            except FloatingPointError:
                along, certified = getattr(np, ufunc)(grid.axes[j]), False
            column = grid.column(j, start, stop, along=along)
            laid[j, ufunc] = column, column if certified else None
        return laid[j, ufunc]

    def _values(self, columns: list, functions: list, given: list | None = None) -> np.ndarray:
        n = len(columns[0]) if columns else 0
        buffers = self.scratch("robust", (getattr(self.function, "buffers", 0), n))
        # truth values as arrays of the points or, where constant, as one value (copyto broadcasts it)
        masks = (np.asarray(m) for m in self.function(columns + functions, buffers))
        stable, unstable, dependent = (m if m.dtype == bool else m != 0 for m in masks)
        out = np.empty((2, n)).T  # column-major: each output's column is contiguous
        region = out[:, 0]
        region.fill(np.nan)
        for value, mask in ((0.0, dependent), (-1.0, unstable), (1.0, stable)):  # the first that holds wins
            if mask.ndim or mask:  # a mask that is one False changes nothing: no pass over the points
                np.copyto(region, value, where=mask)
        if self.classifier is not None:
            out[:, 1] = self.classifier(*columns, *self.setup.fixed_columns(n), function_values=given).stable
        else:
            out[:, 1] = np.nan
        return out


def _build_classification(scene, grid, values, signs=None):
    setup = setup_for(scene, grid, values)
    st = scene.stability(signs)
    # None (undecided at a numeric A) proves nothing: such points get no region (NaN)
    robust = [sp.false if b is None else b for b in (st.robustly_stable, st.robustly_unstable, st.law_dependent)]
    robust = [setup.prepare(b, "the robust classification (Propositions 3-8)") for b in robust]
    if proved_no_equilibrium(scene, signs):  # no equilibrium in contact anywhere: no region, no verdict (NaN)
        return _Classification(setup, [sp.false] * 3, None)
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
        columns = [np.repeat(c, count) for c in self.setup.grid_columns(points)] + self.setup.fixed_columns(n * count)
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
