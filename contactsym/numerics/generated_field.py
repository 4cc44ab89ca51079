"""The fast subsystem (2.1) in scaled deformations (Q, V), generated once for batches of points.

:class:`FastField` is generated code of the state and the parameters, for
:mod:`contactsym.numerics.continuation` to shoot batches of grid points through.

The field is generated once per scene and laws with the parameters as arguments (unilateral
contacts cut to N = 0 where they open); the Jacobian is generated analytically.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ..errors import NumericsError
from .codegen import _cached, lambdify_cse
from .systems import _clamps, _contact_law, _index, _laws_key
from .values import NumericValues, substitute

__all__ = ["FastField", "fast_field"]


def _stack(values, shape) -> np.ndarray:
    """Generated code returns scalars for constant entries: broadcast each to ``shape``."""
    out = np.empty((len(values), *shape))
    for i, v in enumerate(values):
        out[i] = v
    return out


@dataclass(frozen=True, eq=False)
class FastField:
    """The fast subsystem in (Q, V) as generated code of the state and the parameters.

    ``rhs(z, p)`` and ``jac(z, p)`` take the state as an array of shape (2k, M) and the
    parameters as a sequence of arrays (or numbers) in the order of ``params``; they return
    (2k, M) and (M, 2k, 2k). ``reactions(z, p)`` gives the contact reactions (k, M).
    """

    k: int
    params: tuple
    laws: tuple  # per contact: (N(Q, V, *params), (dN/dQ, dN/dV)(Q, V, *params))
    clamp: np.ndarray
    acceleration: object  # f(u, *params)
    acceleration_jac: object  # df/du(u, *params)

    def reactions_and_slopes(self, z: np.ndarray, p) -> tuple[np.ndarray, np.ndarray]:
        k, shape = self.k, z.shape[1:]
        N = np.empty((k, *shape))
        dN = np.empty((k, 2, *shape))
        with np.errstate(all="ignore"):  # the smooth branch is undefined where a contact opens; masked below
            for j, (value, slope) in enumerate(self.laws):
                Q, V = z[j], z[k + j]
                raw = np.broadcast_to(np.asarray(value(Q, V, *p), dtype=float), shape)
                active = (Q <= 0) & (raw >= 0) if self.clamp[j] else np.ones(shape, dtype=bool)
                N[j] = np.where(active, raw, 0.0)
                live = active & (raw != 0)  # a law cut to 0 outside its domain has no slope there
                dN[j] = np.where(live, _stack(slope(Q, V, *p), shape), 0.0)
        return N, dN

    def reactions(self, z: np.ndarray, p) -> np.ndarray:
        return self.reactions_and_slopes(z, p)[0]

    def opened(self, z: np.ndarray, p) -> np.ndarray:
        """Per point, whether some contact is open (cut to N = 0): the field has a kink there."""
        N = self.reactions(z, p)
        return np.any((N == 0) | (self.clamp[:, None] & (N <= 0)), axis=0)

    def rhs(self, z: np.ndarray, p) -> np.ndarray:
        N, _ = self.reactions_and_slopes(z, p)
        return np.concatenate([z[self.k :], _stack(self.acceleration(*N, *p), z.shape[1:])])

    def jac(self, z: np.ndarray, p) -> np.ndarray:
        return self.rhs_and_jac(z, p)[1]

    def rhs_and_jac(self, z: np.ndarray, p) -> tuple[np.ndarray, np.ndarray]:
        """Both at once (the reactions evaluated once): (2k, M) and (M, 2k, 2k)."""
        k, M = self.k, z.shape[1]
        N, dN = self.reactions_and_slopes(z, p)
        rhs = np.concatenate([z[k:], _stack(self.acceleration(*N, *p), z.shape[1:])])
        dfdu = _stack(self.acceleration_jac(*N, *p), (M,)).reshape(k, k, M)
        J = np.zeros((M, 2 * k, 2 * k))
        J[:, :k, k:] = np.eye(k)
        for j in range(k):  # N_j depends on (Q_j, V_j) only
            J[:, k:, j] = (dfdu[:, j] * dN[j, 0]).T
            J[:, k:, k + j] = (dfdu[:, j] * dN[j, 1]).T
        return rhs, J

    def parameter_values(self, values: NumericValues) -> list[float]:
        """The numbers of ``params`` in ``values``; NumericsError naming those missing."""
        missing = [str(s) for s in self.params if s not in values.numbers]
        if missing:
            raise NumericsError(f"the fast subsystem needs numeric values for {missing}.")
        return [float(values.numbers[s]) for s in self.params]


def fast_field(scene, *, laws: Mapping | None = None, unilateral=None, functions: Mapping | None = None) -> FastField:
    """The fast subsystem of ``scene`` in (Q, V) with its parameters as arguments (generated once, cached).

    Examples
    --------
    >>> import numpy as np
    >>> import contactsym as cs
    >>> from contactsym.laws.library import Hertz
    >>> field = fast_field(cs.scene("brake"), laws={0: Hertz(), 1: Hertz()})
    >>> [str(s) for s in field.params]
    ['F_x', 'F_y', 'alpha', 'm', 'mu']
    >>> z = np.array([[-1.0], [-1.2], [0.0], [0.1]])
    >>> field.rhs(z, [0, -4, np.pi / 2, 1, 1]).shape, field.jac(z, [0, -4, np.pi / 2, 1, 1]).shape
    ((4, 1), (1, 4, 4))
    """
    functions = dict(functions or {})

    def build():
        k, fast = scene.k, scene.fast_subsystem()
        only_functions = NumericValues({}, functions)
        Q = [sp.Symbol(f"Q_{j + 1}", real=True) for j in range(k)]
        V = [sp.Symbol(f"V_{j + 1}", real=True) for j in range(k)]
        law_exprs = []
        for j in range(k):
            law = _contact_law(scene, j, laws)
            cut = substitute(law.reaction_scaled(Q[j], V[j], _index(scene, j)), only_functions)
            smooth = substitute(law.smooth_scaled(Q[j], V[j], _index(scene, j)), only_functions)
            law_exprs.append((cut, [smooth.diff(Q[j]), smooth.diff(V[j])]))
        f = sp.Matrix([substitute(e, only_functions) for e in fast.f])
        u = list(fast.u)
        free = set().union(f.free_symbols, *[sp.Tuple(c, *s).free_symbols for c, s in law_exprs])
        params = tuple(sorted(free - set(u) - set(Q) - set(V), key=str))
        compiled = tuple(
            (lambdify_cse([Q[j], V[j], *params], c), lambdify_cse([Q[j], V[j], *params], s))
            for j, (c, s) in enumerate(law_exprs)
        )
        return FastField(
            k,
            params,
            compiled,
            np.asarray(_clamps(scene, unilateral), dtype=bool),
            lambdify_cse([*u, *params], list(f)),
            lambdify_cse([*u, *params], [e for row in f.jacobian(u).tolist() for e in row]),
        )

    key = ("fast-field", _laws_key(laws), unilateral, frozenset(functions.items()))
    return _cached(scene, key, build)
