"""Small, predictable algebra used by every stage (no ``simplify``).

- ``reduce_signs``: s**2 = 1 for sign symbols of open sign patterns;
- ``reduce_trig``: cos(x)**2 = 1 - sin(x)**2, a polynomial reduction;
- ``normalize``: the canonical rational form of :mod:`contactsym.algebra.canonical_form` (both
  reductions, one fraction, cancelled; a polynomial in the parameters stays expanded);
- ``present``: an expression rewritten in a scene's presentation variables;
- ``node_count`` and ``expanded_if_small``: a display's expansion only where it stays readable.

The reductions themselves live in :mod:`contactsym.algebra.reductions`, below the canonical form.
"""

from __future__ import annotations

import sympy as sp

from ..arguments import checked
from ..parse import sympy_only
from .canonical_form import canonical
from .reductions import PaperSymbol, SignSymbol, known_sign, reduce_signs, reduce_trig, sign_symbols

__all__ = [
    "PaperSymbol",
    "SignSymbol",
    "sign_symbols",
    "reduce_signs",
    "reduce_trig",
    "normalize",
    "known_sign",
    "present",
    "EXPAND_NODES",
    "node_count",
    "expanded_if_small",
]

#: Past this many nodes an expression is shown as derived: expanded it only grows (a four-link arm's
#: contact accelerations, 31712 nodes, took ~30 s to expand for a display that names them anyway).
EXPAND_NODES = 2000


@checked
def normalize(expr: sp.Expr) -> sp.Expr:
    """The canonical form: s**2 = 1 and sin**2 + cos**2 = 1 used, one cancelled fraction.

    Examples
    --------
    >>> s, m = SignSymbol("s"), sp.Symbol("m", positive=True)
    >>> normalize(s**3/m + (s*m - s)/(m**2 - m))
    2*s/m
    """
    return canonical(expr)


@checked(expr="sp.Basic | sp.MatrixBase", signs="Sequence[int] | None")
def present(expr: sp.Expr, presentation: dict, signs=None) -> sp.Expr:
    """``expr`` rewritten with the substitutions ``presentation`` (e.g. kappa, v_j, mu_pm).

    ``signs`` gives the sign pattern of ``expr`` when it belongs to one piece, so that the
    presentation's sign symbols (v_j = kappa s_j mu_j) take its values. Relations and
    Boolean combinations are rewritten argument by argument.

    Examples
    --------
    >>> a, b, kappa = sp.symbols("a b kappa", real=True)
    >>> s = SignSymbol("s")
    >>> present(a*b + a > 0, {b: kappa*s})
    s*a*kappa + a > 0
    >>> present(a*b, {b: kappa*s}, signs=(-1,))
    -a*kappa
    """
    expr = sympy_only(expr, "the expression")
    if not presentation or expr in (sp.true, sp.false):
        return expr
    if isinstance(expr, (sp.core.relational.Relational, sp.logic.boolalg.BooleanFunction)):
        return expr.func(*[present(arg, presentation, signs) for arg in expr.args])
    if signs is not None:
        values = dict(zip(sign_symbols(len(signs)), signs))
        presentation = {k: sp.sympify(v).subs(values) for k, v in presentation.items()}
    replaced = expr.subs(presentation)
    if isinstance(replaced, sp.MatrixBase):
        return replaced.applyfunc(lambda e: reduce_signs(sp.cancel(sp.expand(e))))
    return reduce_signs(sp.cancel(sp.expand(replaced)))


def node_count(expr: sp.Basic, limit: int) -> int:
    """The number of nodes of ``expr`` (its preorder traversal), counted up to ``limit + 1`` at most.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> node_count(x*y + 1, 100), node_count(x*y + 1, 2)
    (5, 3)
    """
    count = 0
    for count, _ in enumerate(sp.preorder_traversal(expr), 1):
        if count > limit:
            break
    return count


def expanded_if_small(expr: sp.Expr, limit: int = EXPAND_NODES) -> sp.Expr:
    """``sp.expand(expr)`` when ``expr`` has at most ``limit`` nodes, else ``expr`` as it is.

    For display: a formula that large is named, not printed, so expanding it (which can take
    minutes and multiply its size) buys nothing.

    Examples
    --------
    >>> x, y = sp.symbols("x y")
    >>> expanded_if_small((x + y)**2)
    x**2 + 2*x*y + y**2
    >>> expanded_if_small((x + y)**2, limit=3)
    (x + y)**2
    """
    return sp.expand(expr) if node_count(expr, limit) <= limit else expr
