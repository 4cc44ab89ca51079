"""l1 of (2.1) as an explicit polynomial in the derivatives of generic laws at the equilibrium.

With generic laws (1.5), :func:`contactsym.lyapunov.coefficient.first_lyapunov_symbolic` leaves the law's
derivatives at (u*, 0) as symbols (``Phi_1_u``, ``Psi_2_uv``, ...). On a slice where the critical
frequency is rational in the remaining parameters (e.g. the Hopf line solved for one of them),
every intermediate vector of the normal form is a rational function with Gaussian rational
coefficients: reducing each entry with ``sp.cancel`` as it is formed (and solving the two linear
systems by exact elimination) keeps them short, and l1 comes out as one reduced fraction. Its
numerator is a polynomial in the law symbols (of degree 2: the third derivatives of the field
enter g21 once, the second ones twice); its coefficients and its denominator are factored one by
one, each a short expression in the parameters. No ``simplify`` is called.
"""

from __future__ import annotations

import sympy as sp

from .coefficient import fast_hopf_forms, lyapunov_symbolic, multilinear

__all__ = ["first_lyapunov_polynomial"]


def first_lyapunov_polynomial(stability, at: dict | None = None) -> sp.Expr | None:
    """l1 of (2.1) on the Hopf set as ``sum c_a s_a + sum c_ab s_a s_b`` in the law symbols ``s``.

    ``at`` is the slice of :func:`~contactsym.lyapunov.coefficient.first_lyapunov_symbolic` (typically the
    Hopf line solved for one parameter, and law symbols identified across contacts); the
    coefficients ``c`` are reduced rational functions of the remaining parameters, factored.
    Normalization ``<q, q> = <p, q> = 1`` in (u, v): the positive factor ``1/(4 omega <q, q>)``
    is part of every coefficient, and only the sign of l1 is invariant. None without a Hopf set.

    Examples
    --------
    The brake (6.1)-(6.4) at alpha = 90 deg with equal pads, on its Hopf line
    ``Phi = -Psi**2 (1 + mu**2)/(m mu**2)``, with only ``Phi_uu`` nonzero:

    >>> import contactsym as cs
    >>> st = cs.scene("brake").stability()
    >>> P = {str(s): s for s in cs.scene("brake").parameters}
    >>> m, mu, Psi = P["m"], P["mu"], sp.Symbol("Psi", negative=True)
    >>> at = {P["alpha"]: sp.pi / 2, P["Psi_1"]: Psi, P["Psi_2"]: Psi}
    >>> at[P["Phi_1"]] = at[P["Phi_2"]] = -Psi**2 * (1 + mu**2) / (m * mu**2)
    >>> law = {sp.Symbol(f"{w}_{j}_{d}", real=True): 0 for w in ("Phi", "Psi") for j in (1, 2)
    ...        for d in ("u", "v", "uu", "uv", "vv")}
    >>> Phi_uu = sp.Symbol("Phi_uu", real=True)
    >>> law.update({sp.Symbol("Phi_1_uu", real=True): Phi_uu, sp.Symbol("Phi_2_uu", real=True): Phi_uu})
    >>> first_lyapunov_polynomial(st, {**at, **law})
    -Phi_uu*m*mu**3*(3*mu**2 + 5)/(4*(mu**2 + 1)*(mu**2 + 4)*(Psi**2*mu**2 + Psi**2 + mu**2))
    """
    forms = fast_hopf_forms(stability, at)
    if forms is None:
        return None
    J, H, T, omega, q, p = forms
    # the law symbols: in the field's higher derivatives but not in its linear part
    law = set().union(*[sp.sympify(e).free_symbols for e in _flat(H) + _flat(T)]) - J.free_symbols
    l1 = lyapunov_symbolic(J, multilinear(H, 2), multilinear(T, 3), omega, q, p, reduce=sp.cancel)
    numerator, denominator = sp.fraction(l1)
    law = sorted(law & numerator.free_symbols, key=str)
    if not law:
        return sp.factor(numerator) / sp.factor(denominator)
    terms = sp.Poly(numerator, *law).terms()
    return sp.Add(*[sp.factor(c / denominator) * sp.Mul(*[s**e for s, e in zip(law, powers)]) for powers, c in terms])


def _flat(tensor) -> list:
    return [x for t in tensor for x in _flat(t)] if isinstance(tensor, list) else [tensor]
