"""The printed forms of the stability conditions: generic Hurwitz minors, shortest forms, point-decision rows.

The generic Hurwitz minors, the shortest exact form of a coefficient, and the rows of a point decision.

Split from :mod:`contactsym.stages.stability` (which re-exports these names): none of them is a stage.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import sympy as sp

from ..algebra.hurwitz import hurwitz_minors
from ..arguments import between, checked
from ..errors import ArgumentError
from ..inequalities import factor_list
from ..printing.glyphs import OwnLetters
from ..printing.latex_output import Formula, tex
from ..validate import shorten
from .linear import lam

if TYPE_CHECKING:
    from ..robustness.classify import Robustness  # noqa: F401 - the hint of robustness_formulas

__all__ = ["generic_minors", "hurwitz_letters", "hurwitz_names", "robustness_formulas", "shortest_form"]


def shortest_form(polynomial: sp.Expr, outer=()) -> sp.Expr:
    """The shortest of: ``polynomial`` as it is, factored, and grouped by the monomials in ``outer``
    (e.g. the law's Phi_j, Psi_j) with each group's coefficient factored. Exact: the same polynomial.

    Only a polynomial in symbols (of at most 400 terms; factored whole up to 100) is rewritten; the factoring is
    :func:`contactsym.inequalities.factor_list` (cheap where variables of degree 1 split it).

    Examples
    --------
    >>> a, b, c, d, P, Q = sp.symbols("a b c d Phi Psi")
    >>> shortest_form(P * Q * a * d - P * Q * b * c + P * a + Q * d, (P, Q))
    Phi*Psi*(a*d - b*c) + Phi*a + Psi*d
    >>> shortest_form(a * c + a * d + b * c + b * d)
    (a + b)*(c + d)
    """
    if not isinstance(polynomial, sp.Add) or len(polynomial.args) > 400:
        return polynomial
    symbols = polynomial.free_symbols
    if not polynomial.is_polynomial(*symbols):
        return polynomial
    # factoring a long irreducible sum costs a second and finds nothing: the whole is factored up to 100 terms
    candidates = [polynomial, _factored(polynomial) if len(polynomial.args) <= 100 else polynomial]
    inner = sorted(symbols - set(outer), key=str)
    if inner and symbols & set(outer):
        groups = sp.Poly(polynomial, *sorted(symbols & set(outer), key=str)).as_dict()
        gens = sorted(symbols & set(outer), key=str)
        candidates.append(
            sp.Add(
                *[
                    sp.Mul(*[g**e for g, e in zip(gens, powers)]) * _factored(sp.expand(c))
                    for powers, c in groups.items()
                ]
            )
        )
    return min(candidates, key=sp.count_ops)


def _factored(polynomial: sp.Expr) -> sp.Expr:
    if not isinstance(polynomial, sp.Add):
        return polynomial
    coefficient, factors = factor_list(polynomial)
    return sp.Mul(coefficient, *[base**power for base, power in factors])


@checked(n=between(1, 12))
def generic_minors(n: int, letter: str = "p") -> dict[int, sp.Expr]:
    """Delta_m in the coefficients p_n, ..., p_0 (symbols ``p_s``, or ``<letter>_s`` with ``letter``) of a degree-n polynomial, m = 1..n.

    Examples
    --------
    >>> generic_minors(2)[2], generic_minors(2, "phat")[2]
    (p_0*p_1, phat_0*phat_1)
    """
    p = [sp.Symbol(f"{letter}_{s}") for s in range(n + 1)]
    minors = hurwitz_minors(sp.Poly(sum(p[s] * lam**s for s in range(n + 1)), lam))
    return {m: sp.expand(minor) for m, minor in enumerate(minors, 1)}


@checked(robustness="Robustness | None")
def robustness_formulas(robustness) -> tuple[Formula, ...]:
    """The point decision of :func:`contactsym.robustness.classify.decide_robustness`: verdict, certificate, witness laws.

    Examples
    --------
    >>> from contactsym.robustness import decide_robustness
    >>> rows = robustness_formulas(decide_robustness(sp.Matrix([[1, 0, 0], [0, -1, 0], [0, 0, 1]])))
    >>> [row.key for row in rows]
    ['robustness', 'certificate']
    >>> print(rows[0].rhs)
    \\text{unstable}
    >>> robustness_formulas(None)
    ()
    """
    if robustness is None:
        return ()
    if not all(hasattr(robustness, name) for name in ("verdict", "certificate", "stable_law", "unstable_law")):
        # the hint names a class imported for k >= 3 only (scipy), so the decorator cannot check it here
        raise ArgumentError(
            f"robustness_formulas: robustness = {shorten(robustness)} is not accepted; pass the Robustness that "
            "contactsym.robustness.decide_robustness returns, or None."
        )
    rows = [Formula("robustness", r"\text{robustness}", r"\text{" + robustness.verdict + "}", ":")]
    if robustness.certificate is not None:
        statement = robustness.certificate.statement.replace("_", r"\_")
        rows.append(Formula("certificate", r"\text{certificate}", r"\text{" + statement + "}", ":"))
    for name, law in (("stable", robustness.stable_law), ("unstable", robustness.unstable_law)):
        if law is not None:
            values = r",\ ".join([tex(sp.Tuple(*law.Phi)), tex(sp.Tuple(*law.Psi))])
            rows.append(Formula("witness", r"(\Phi, \Psi)_{\text{" + name + "}}", values))
    return tuple(rows)


@checked(stability="Stability")
def hurwitz_names(stability) -> list[str]:
    r"""LaTeX names of ``stability.hurwitz``: coefficients ``p_s`` of (4.6), minors ``Delta_m`` of (4.7).

    Examples
    --------
    >>> import contactsym as cs
    >>> hurwitz_names(cs.scene("brake").stability())
    ['p_{3}', 'p_{2}', 'p_{1}', 'p_{0}', '\\Delta_{3}']
    """
    letters = {kind: tex(sp.Symbol(name)) for kind, name in hurwitz_letters(stability).items()}
    return [f"{letters[kind]}_{{{index}}}" for kind, index in stability.routh_hurwitz.labels]


def hurwitz_letters(stability) -> dict[str, str]:
    """The names of the coefficients p_s and the minors Delta_m: ``phat``, ``Deltahat`` where the scene has its
    own p or p_1 (Delta), so that a printed condition never shows the scene's p_1 for a coefficient.

    Examples
    --------
    >>> import contactsym as cs
    >>> hurwitz_letters(cs.scene("brake").stability())
    {'p': 'p', 'Delta': 'Delta'}
    """
    own = OwnLetters(getattr(stability.linearization.fast, "_taken", ()))
    return {kind: own.indexed(kind) for kind in ("p", "Delta")}
