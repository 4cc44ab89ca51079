"""The squeal near a Hopf line from its normal form, vectorised over the bifurcation parameter.

At a Hopf point p* of the fast subsystem (:func:`contactsym.numerics.hopf_point`) the normal
form ``z' = (alpha + i (omega + beta)) z + c1 z |z|^2`` with ``alpha = dalpha (p - p*)`` and
``beta = domega (p - p*)`` predicts, where ``-alpha / Re c1 > 0``, a cycle of radius
``r = sqrt(-alpha / Re c1)``: reaction amplitudes ``2 r |dN . q|`` and the frequency
``omega + beta + Im c1 r^2``. One Hopf point serves every value of p along a line of the
grid, so the cost per grid point is a few array operations.

The truncation error is of the relative size of the neglected terms, ``|c1| r^2 / omega``
(the cubic term against the linear one); :attr:`NormalForm.error` reports it per point, and
the atlas uses the prediction only where it is below its tolerance.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from .fastsystem import FastProblem
from .hopf import HopfCoefficient, _at_point, hopf_point
from .values import NumericValues, numeric_values

__all__ = ["NormalForm", "normal_form"]


@dataclass(frozen=True, eq=False)
class NormalForm:
    """The Hopf normal form along one parameter, ready to evaluate on arrays of its values.

    Attributes
    ----------
    hopf : HopfCoefficient
        The Hopf point (``value``, ``omega``, ``dalpha``, ``l1``, ...).
    domega : float
        d Im(lambda)/d parameter of the critical pair at the Hopf point.
    """

    hopf: HopfCoefficient
    domega: float

    def radius_squared(self, values) -> np.ndarray:
        """``-alpha / Re c1`` at each value: the squared radius where positive (a small cycle)."""
        h = self.hopf
        return -h.dalpha * (np.asarray(values, dtype=float) - h.value) / h.vectors.c1.real

    def amplitude(self, values) -> np.ndarray:
        """Reaction amplitudes (half peak-to-peak, one column per contact); NaN where no small cycle."""
        r2 = self.radius_squared(values)
        r = np.sqrt(np.where(r2 > 0, r2, np.nan))
        return 2 * r[..., None] * np.abs(self.hopf.reaction_vector)

    def omega(self, values) -> np.ndarray:
        """The cycle's angular frequency in tau (``omega/eps`` in t); on the other side, the linear one."""
        h = self.hopf
        offset = np.asarray(values, dtype=float) - h.value
        r2 = np.maximum(self.radius_squared(values), 0.0)
        return h.omega + self.domega * offset + h.vectors.c1.imag * r2

    def error(self, values) -> np.ndarray:
        """Estimated relative error of the prediction: ``|c1| r^2 / omega``, the size of the neglected terms."""
        r2 = np.abs(self.radius_squared(values))
        return np.abs(self.hopf.vectors.c1) * r2 / self.hopf.omega

    def stable(self) -> bool:
        """The small cycle is stable (l1 < 0, supercritical)."""
        return self.hopf.vectors.c1.real < 0


def normal_form(
    scene, values: Mapping, parameter, *, laws: Mapping | None = None, signs=None, bracket=None
) -> NormalForm:
    """The Hopf point along ``parameter`` nearest its value in ``values``, with the frequency's slope.

    Examples
    --------
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> values = {"m": 1, "mu": 1, "alpha": 1.5707963267948966, "F_x": 0, "F_y": -4}
    >>> nf = normal_form(cs.scene("brake"), values, "mu", laws={0: Hertz(), 1: Hertz()})
    >>> nf.hopf.direction, round(nf.hopf.value, 6)
    ('supercritical', 1.074858)
    >>> mu = nf.hopf.value * np.array([0.99, 1.01])
    >>> bool(np.isnan(nf.amplitude(mu)[0]).all()), bool(nf.amplitude(mu)[1, 0] > 0)
    (True, True)
    """
    h = hopf_point(scene, values, parameter, laws=laws, signs=signs, bracket=bracket)
    vals = numeric_values(scene, values)
    step = 1e-6 * max(abs(h.value), 1e-8)

    def frequency(p: float) -> float:
        point = NumericValues({**vals.numbers, h.parameter: sp.Float(p)}, vals.functions)
        eigenvalues = np.linalg.eigvals(_at_point(FastProblem(scene, point, laws, signs=signs))[1])
        return float(eigenvalues[np.argmin(np.abs(eigenvalues - 1j * h.omega))].imag)

    domega = (frequency(h.value + step) - frequency(h.value - step)) / (2 * step)
    return NormalForm(h, domega)
