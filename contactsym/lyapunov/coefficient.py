"""The first Lyapunov coefficient l1 of a Hopf point, numerically and symbolically.

Write a vector field near an equilibrium as ``x' = J x + B(x, x)/2 + C(x, x, x)/6 + ...``
with ``B`` and ``C`` the second and third derivatives. At a Hopf point ``J`` has the
eigenvalues ``+-i omega`` (omega > 0), ``J q = i omega q`` and ``J^T p = -i omega p``.

Derivation (centre manifold and normal form, projected on the eigenvectors). Put
``x = z q + conj(z q) + h(z, conj z)`` with ``h`` quadratic and ``<p, q> = conj(p)^T q = 1``,
so that ``z = <p, x>`` to first order. The quadratic part of ``h`` solves the homological
equations ``J h20 - 2 i omega h20 = -B(q, q)`` and ``J h11 = -B(q, conj q)``. The ``z^2 conj z``
coefficient of ``z' = <p, x'>`` is then

    g21 = <p, C(q, q, conj q)> + 2 <p, B(q, h11)> + <p, B(conj q, h20)>
        = <p, C(q, q, conj q)> - 2 <p, B(q, J^-1 B(q, conj q))> + <p, B(conj q, (2 i omega - J)^-1 B(q, q))>,

and the near-identity change that removes the quadratic terms leaves
``z' = i omega z + c1 z |z|^2 + ...`` with ``Re c1 = Re g21 / 2``: the quadratic terms of the
z-equation only change ``Im c1``. With ``r = |z|``, ``r' = alpha r + Re(c1) r^3`` once the real
part ``alpha`` of the critical pair is nonzero, so a small cycle of radius
``r^2 = -alpha / Re c1`` exists where ``alpha`` and ``Re c1`` have opposite signs.

Normalization: ``<q, q> = 1`` and ``<p, q> = 1``, and ``l1 = Re c1 / omega`` (time scaled by
omega). Rescaling q by ``s`` multiplies ``l1`` by ``|s|^2``: only its sign is invariant,
and so is the cycle it predicts. ``l1 < 0``: supercritical (a small stable cycle grows as
``sqrt(alpha)`` past the line); ``l1 > 0``: subcritical (a small unstable cycle before the
line, a jump and hysteresis past it). The cycle's component ``x_i`` oscillates with
amplitude (half peak-to-peak) ``2 r |q_i|`` to leading order.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import sympy as sp
from sympy.polys.matrices import DomainMatrix

from ..deprecation import deprecated_alias
from ..errors import HopfError
from ..laws import Generic

__all__ = [
    "HopfVectors",
    "first_lyapunov_from_derivatives",
    "first_lyapunov_symbolic",
    "hopf_vectors_45",
    "lyapunov_symbolic",
]


@dataclass(frozen=True)
class HopfVectors:
    """Numeric result at a Hopf point (normalization ``<q, q> = <p, q> = 1``).

    Attributes
    ----------
    l1 : float
        The first Lyapunov coefficient ``Re c1 / omega``.
    c1 : complex
        The cubic coefficient of the normal form ``z' = i omega z + c1 z |z|^2``.
    omega : float
        The frequency of the critical pair.
    q, p : ndarray
        The critical eigenvector and the adjoint one.

    Examples
    --------
    The normal form ``z' = i z - z |z|^2`` (supercritical: l1 < 0):

    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> r2 = x**2 + y**2
    >>> J, H, T = derivative_tensors(sp.Matrix([-y - x*r2, x - y*r2]), [x, y], {x: 0, y: 0})
    >>> h = lyapunov_numeric(J, H, T)
    >>> isinstance(h, HopfVectors), round(h.omega, 12), round(h.l1, 12)
    (True, 1.0, -2.0)
    >>> h.radius(-0.01) is None  # the pair not yet unstable: no small cycle
    True
    """

    l1: float
    c1: complex
    omega: float
    q: np.ndarray
    p: np.ndarray

    def radius(self, alpha: float) -> float | None:
        """The cycle's radius |z| when the critical pair has real part ``alpha``; None if no small cycle."""
        ratio = -alpha / self.c1.real
        return float(np.sqrt(ratio)) if ratio > 0 else None


def critical_pair(J: np.ndarray, tol: float = 1e-6) -> tuple[complex, np.ndarray]:
    """The eigenvalue with Im > 0 nearest the imaginary axis, and its eigenvector.

    Raises HopfError when no eigenvalue has Im > 0, or when the nearest one is farther than
    ``tol * |lambda|`` from the axis (the point is off the Hopf set; the message says how far).
    """
    values, vectors = np.linalg.eig(J)
    upper = np.flatnonzero(values.imag > 1e-12 * max(1.0, np.max(np.abs(values))))
    if upper.size == 0:
        raise HopfError(f"the Jacobian has no complex pair (eigenvalues {np.round(values, 6)}): no Hopf point here.")
    i = upper[np.argmin(np.abs(values[upper].real))]
    lam = values[i]
    if abs(lam.real) > tol * abs(lam):
        raise HopfError(
            f"the point is off the Hopf set: the critical eigenvalues are {lam.real:.6g} +- {lam.imag:.6g} i, "
            f"so Re(lambda)/omega = {lam.real / lam.imag:.3g} (tolerance {tol:g}); l1 is defined where "
            "Re(lambda) = 0: move the point onto the line (e.g. with contactsym.numerics.hopf_point)."
        )
    return lam, vectors[:, i]


def first_lyapunov_from_derivatives(J, hessian, third, *, tol: float = 1e-6) -> HopfVectors:
    """l1 of any vector field, numerically, from its Jacobian ``J[i, j]``, ``hessian[i, j, k]`` and
    ``third[i, j, k, l]`` at a point on its Hopf set (``lyapunov_numeric`` is its deprecated name).

    Examples
    --------
    The Hopf normal form ``x' = -y + s x (x^2 + y^2)``, ``y' = x + s y (x^2 + y^2)`` with
    ``s = -1``: its cycle at ``Re lambda = alpha`` has radius ``sqrt(alpha)``.

    >>> import sympy as sp
    >>> x, y = sp.symbols("x y")
    >>> r2 = x**2 + y**2
    >>> F = sp.Matrix([-y - x*r2, x - y*r2])
    >>> J, H, T = derivative_tensors(F, [x, y], {x: 0, y: 0})
    >>> h = first_lyapunov_from_derivatives(J, H, T)
    >>> round(h.l1, 12), round(float(2 * h.radius(0.01) * abs(h.q[0])), 12)
    (-2.0, 0.1)
    """
    J = np.asarray(J, dtype=float)
    H = np.asarray(hessian, dtype=float)
    T = np.asarray(third, dtype=float)
    lam, q = critical_pair(J, tol)
    omega = float(lam.imag)
    q = q / np.linalg.norm(q)
    values, left = np.linalg.eig(J.T)
    p = left[:, np.argmin(np.abs(values + 1j * omega))]
    p = p / np.conj(np.vdot(p, q))  # <p, q> = conj(p)^T q = 1

    def B(a, b):
        return np.einsum("ijk,j,k->i", H, a, b)

    n = J.shape[0]
    h11 = -np.linalg.solve(J, B(q, np.conj(q)))
    h20 = np.linalg.solve(2j * omega * np.eye(n) - J, B(q, q))
    cubic = np.einsum("ijkl,j,k,l->i", T, q, q, np.conj(q))
    g21 = np.vdot(p, cubic) + 2 * np.vdot(p, B(q, h11)) + np.vdot(p, B(np.conj(q), h20))
    c1 = complex(g21) / 2
    return HopfVectors(c1.real / omega, c1, omega, q, p)


def derivative_tensors(F: sp.Matrix, x, at: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Numeric J, hessian and third-derivative tensors of a numeric-coefficient field at ``at``."""
    n = len(x)
    J = F.jacobian(x)
    H = [[J[i, j].diff(x[k]) for k in range(n)] for i in range(n) for j in range(n)]
    T = [[[h.diff(x[m]) for m in range(n)] for h in row] for row in H]
    as_array = np.vectorize(lambda e: float(sp.sympify(e).xreplace(at)), otypes=[float])
    return (
        as_array(np.array(J.tolist(), dtype=object)),
        as_array(np.array(H, dtype=object)).reshape(n, n, n),
        as_array(np.array(T, dtype=object)).reshape(n, n, n, n),
    )


# --- symbolic ---------------------------------------------------------------------------


def _conjugate(expr: sp.Expr) -> sp.Expr:
    """Complex conjugate of an expression whose symbols are all real: I -> -I."""
    return sp.sympify(expr).xreplace({sp.I: -sp.I})


def _dot(p, x) -> sp.Expr:
    """<p, x> = conj(p)^T x."""
    return sp.Add(*[_conjugate(a) * b for a, b in zip(p, x)])


def hopf_vectors_45(A: sp.Matrix, Phi, Psi, omega: sp.Expr) -> tuple[sp.Matrix, sp.Matrix]:
    """Critical eigenvectors of (4.5), ``J = [[Psi A, Phi], [A, 0]]``, at ``lambda = i omega``.

    With q = (x, y): ``A x = i omega y`` and ``Psi A x + Phi y = i omega x`` give
    ``x = (Psi - i Phi/omega) y`` and ``(A D + omega^2) y = 0``, ``D = Phi + i omega Psi`` (k x k).
    For the adjoint p = (a, b), ``J^T p = -i omega p`` gives ``b = i Phi a/omega`` and
    ``(A^T conj(D) + omega^2) a = 0``. Both small systems are singular exactly on the Hopf set;
    the null vector is read off the first row that is not zero, which holds for k = 2.

    Examples
    --------
    One contact with A = 1, Phi = -4, Psi = 0: J has the pair +-2i; q and p are its eigenvectors:

    >>> import sympy as sp
    >>> q, p = hopf_vectors_45(sp.Matrix([[1]]), [-4], [0], 2)
    >>> J = sp.Matrix([[0, -4], [1, 0]])
    >>> J * q - 2*sp.I*q == sp.zeros(2, 1), J.T * p + 2*sp.I*p == sp.zeros(2, 1)
    (True, True)
    """
    k = A.rows
    Phi_, Psi_ = sp.diag(*Phi), sp.diag(*Psi)
    D = Phi_ + sp.I * omega * Psi_
    M = A * D + omega**2 * sp.eye(k)
    N = A.T * _conjugate_matrix(D) + omega**2 * sp.eye(k)
    y, a = _null_vector(M), _null_vector(N)
    q = sp.Matrix.vstack((Psi_ - sp.I * Phi_ / omega) * y, y)
    p = sp.Matrix.vstack(a, sp.I * Phi_ * a / omega)
    return q, p


def _conjugate_matrix(M: sp.Matrix) -> sp.Matrix:
    return M.applyfunc(_conjugate)


def _null_vector(M: sp.Matrix) -> sp.Matrix:
    if M.rows == 1:
        return sp.Matrix([1])
    if M.rows == 2:
        return sp.Matrix([-M[0, 1], M[0, 0]]) if (M[0, 0], M[0, 1]) != (0, 0) else sp.Matrix([-M[1, 1], M[1, 0]])
    basis = M.nullspace()
    if len(basis) != 1:
        raise HopfError(f"the critical eigenvector of (4.5) is not determined symbolically ({len(basis)} found).")
    return basis[0]


def lyapunov_symbolic(J: sp.Matrix, B, C, omega: sp.Expr, q: sp.Matrix, p: sp.Matrix, reduce=None) -> sp.Expr:
    """l1 = Re g21 / (2 omega) in the normalization <q, q> = <p, q> = 1, for real symbols.

    ``B(a, b)`` and ``C(a, b, c)`` return the multilinear forms as matrices; ``q`` and ``p``
    are critical eigenvectors of any scale (they are normalized here). The expression is
    valid on the Hopf set only. ``reduce`` (e.g. ``sp.cancel``) is applied to every entry of
    every intermediate vector, so that the result is a reduced rational function when the
    inputs are; without it nothing is simplified.

    Examples
    --------
    >>> s, w = sp.symbols("s omega", positive=True)
    >>> J = sp.Matrix([[0, -w], [w, 0]])
    >>> def B(a, b): return sp.zeros(2, 1)
    >>> def C(a, b, c):  # third derivative of s*(x^2 + y^2)*(x, y)
    ...     dot = lambda u, v: u[0]*v[0] + u[1]*v[1]
    ...     return 2*s*(dot(a, b)*c + dot(a, c)*b + dot(b, c)*a)
    >>> q, p = sp.Matrix([1, -sp.I]), sp.Matrix([1, -sp.I])
    >>> lyapunov_symbolic(J, B, C, w, q, p, reduce=sp.cancel)
    2*s/omega
    """
    reduce_given, reduce = reduce is not None, reduce or (lambda e: e)

    def each(M: sp.Matrix) -> sp.Matrix:
        return M.applyfunc(reduce)

    n = J.rows
    q, p = each(q), each(p)
    # expanding <q, q> and <p, q> only shortens them when they are reduced; otherwise it costs half the time
    expand = sp.expand if reduce_given else (lambda e: e)
    q_norm = reduce(expand(_dot(q, q)))
    p = each(p / _conjugate(reduce(expand(_dot(p, q)))))
    qb = q.applyfunc(_conjugate)
    solve = _exact_solve if reduce_given else (lambda M, b: M.LUsolve(b))
    h11 = each(-solve(J, each(B(q, qb))))
    h20 = each(solve(2 * sp.I * omega * sp.eye(n) - J, each(B(q, q))))
    g21 = sum((reduce(_dot(p, v)) for v in (C(q, q, qb), 2 * B(q, h11), B(qb, h20))), sp.S.Zero)
    return reduce((g21 + _conjugate(g21)) / (4 * omega * q_norm))


def _exact_solve(M: sp.Matrix, b: sp.Matrix) -> sp.Matrix:
    """M^-1 b by Gauss-Jordan elimination over the exact domain of the entries (rational functions
    with Gaussian rational coefficients here): no symbolic pivot tests, results already cancelled."""
    augmented = DomainMatrix.from_Matrix(M.row_join(b)).to_field()
    reduced, pivots = augmented.rref()
    if len(pivots) < M.rows or pivots[-1] >= M.cols:
        raise HopfError("the linear system of the normal form is singular (a zero or 2 i omega eigenvalue).")
    return reduced.to_Matrix()[:, M.cols :]


def multilinear(derivatives: sp.MutableDenseNDimArray | list, order: int):
    """The form ``(a, b, ...) -> sum D[i, j, k, ...] a_j b_k ...`` from a nested derivative list."""

    def form(*vectors):
        rows = []
        for D_i in derivatives:
            total = sp.S.Zero
            for index in np.ndindex(*([len(vectors[0])] * order)):
                entry = D_i
                for j in index:
                    entry = entry[j]
                if entry != 0:
                    total += entry * sp.Mul(*[v[j] for v, j in zip(vectors, index)])
            rows.append(total)
        return sp.Matrix(rows)

    return form


# --- the fast subsystem (2.1) in (u, v) -------------------------------------------------


def _derivative_name(base: sp.Symbol, counts: tuple[int, int]) -> sp.Symbol:
    """Phi_1 with (2, 1) -> Phi_1_uuv: the derivative of a generic law at the equilibrium."""
    return sp.Symbol(f"{base.name}_{'u' * counts[0]}{'v' * counts[1]}", real=True)


def _law_function(fast, j: int, which: str) -> sp.Expr:
    return sp.Function(f"{which}{j}")(fast.u[j], fast.v[j])


def first_lyapunov_symbolic(stability, at: dict | None = None, reduce=None) -> sp.Expr | None:
    """l1 of (2.1) at its equilibrium on the Hopf set, symbolically (None without a Hopf set); this is
    :attr:`Stability.first_lyapunov` (``fast_first_lyapunov`` is its deprecated name).

    The field ``u_j' = Phi_j(u_j, v_j) v_j + Psi_j(u_j, v_j) f_j(u)``, ``v_j' = f_j(u)`` is
    differentiated with Phi_j, Psi_j and f_j as functions; at the equilibrium f_j = 0, the
    derivatives of f come from the piece and those of the law from the law. A generic law
    (1.5) contributes symbols: ``Phi_1_u`` is dPhi_1/du_1 and ``Psi_2_uv`` is
    d^2 Psi_2/du_2 dv_2 at (u*, 0). The eigenvectors come from the block form (4.5)
    (:func:`hopf_vectors_45`); the normalization is ``<q, q> = 1`` in (u, v).

    ``at`` is substituted before the linear algebra (a slice of parameter space, the
    Hopf line solved for one parameter): the result is then far shorter. Its keys may be
    the parameters and the derivative symbols. ``reduce`` is passed to :func:`lyapunov_symbolic`.

    Examples
    --------
    One contact has no Hopf set ((3.1) is a plane system with trace Psi A < 0 wherever A > 0):

    >>> import contactsym as cs
    >>> first_lyapunov_symbolic(cs.scene("sliding-point").stability()) is None
    True
    """
    forms = fast_hopf_forms(stability, at)
    if forms is None:
        return None
    J, H, T, omega, q, p = forms
    return lyapunov_symbolic(J, multilinear(H, 2), multilinear(T, 3), omega, q, p, reduce)


def fast_hopf_forms(stability, at: dict | None = None) -> tuple | None:
    """``(J, H, T, omega, q, p)`` of (2.1) at its equilibrium, for :func:`lyapunov_symbolic`.

    ``H`` and ``T`` are the nested second and third derivatives of the field (see
    :func:`first_lyapunov_symbolic`). None without a Hopf set.
    """
    lin = stability.linearization
    fast, k = lin.fast, stability.k
    if stability.hopf_frequency is None:
        return None
    given = dict(at or {})
    at = {**dict.fromkeys(fast.v, 0), **lin.u_star}
    omega = sp.sqrt(sp.factor(stability.routh_hurwitz.omega_squared.subs(given))) if given else stability.hopf_frequency
    F = [sp.Function(f"f{j}")(*fast.u) for j in range(k)]
    Phi = [_law_function(fast, j, "Phi") for j in range(k)]
    Psi = [_law_function(fast, j, "Psi") for j in range(k)]
    state = list(fast.u) + list(fast.v)
    rhs = [Phi[j] * fast.v[j] + Psi[j] * F[j] for j in range(k)] + F
    law_values = {**dict(zip(Phi, lin.Phi)), **dict(zip(Psi, lin.Psi)), **dict.fromkeys(F, 0)}
    pieces = lin.f

    def at_equilibrium(expr: sp.Expr) -> sp.Expr:
        replace = {}
        for d in expr.atoms(sp.Derivative):
            function, variables = d.expr, [x for x, n in d.variable_count for _ in range(n)]
            if function in F:
                actual = pieces[F.index(function)]
            else:
                j = (Phi + Psi).index(function) % k
                generic = (fast.Phi if function in Phi else fast.Psi)[j]
                if isinstance(fast.compliances[j], Generic):
                    counts = (variables.count(fast.u[j]), variables.count(fast.v[j]))
                    replace[d] = _derivative_name(generic, counts)
                    continue
                actual = generic
            replace[d] = sp.diff(actual, *variables).subs(at)
        return expr.xreplace(replace).xreplace(law_values).subs(at).subs(given)

    n = 2 * k
    memo: dict = {}

    def derivative(i: int, *index: int) -> sp.Expr:  # symmetric in index: each sorted tuple once
        key = (i, *sorted(index))
        if key not in memo:
            memo[key] = at_equilibrium(sp.diff(rhs[i], *[state[a] for a in key[1:]]))
        return memo[key]

    H = [[[derivative(i, a, b) for b in range(n)] for a in range(n)] for i in range(n)]
    T = [[[[derivative(i, a, b, c) for c in range(n)] for b in range(n)] for a in range(n)] for i in range(n)]
    A = lin.A.subs(at).subs(given)
    Phi_star, Psi_star = ([sp.sympify(x).subs(given) for x in values] for values in (lin.Phi, lin.Psi))
    q, p = hopf_vectors_45(A, Phi_star, Psi_star, omega)
    J = lin.jacobian.subs(at).subs(given)
    return J, H, T, omega, q, p


# the names of 0.1, kept: they warn
lyapunov_numeric = deprecated_alias(first_lyapunov_from_derivatives, "lyapunov_numeric")
fast_first_lyapunov = deprecated_alias(first_lyapunov_symbolic, "fast_first_lyapunov")
