"""The smooth pieces of the fast subsystem: its switching functions (the arguments of Abs and
sign that depend on the reactions), f on the piece of a sign pattern, and the roots of a piece.
"""

from __future__ import annotations

import sympy as sp

from ..algebra.basic import normalize
from ..arguments import checked
from ..errors import ContactsymError, SingularJacobianError

__all__ = ["MAX_ROOT_NODES", "check_root_size", "switching_functions", "on_piece", "solve_piece"]

#: Largest f (expression nodes, summed over its entries) whose roots are derived in closed form: past
#: it the closed form would take minutes and pages (the roots of a four-link arm's piece are
#: A^-1 b with b of ~6000 terms). Raise it (``contactsym.stages.pieces.MAX_ROOT_NODES = N``) to
#: derive them anyway; the stability conditions never need them.
MAX_ROOT_NODES = 6000


def _canonical(arg: sp.Expr, u) -> tuple[sp.Expr, int]:
    """(sigma, c) with arg = c * sigma, c a nonzero number, sigma increasing in the first u it has."""
    first = next(x for x in u if arg.has(x))
    content, sigma = sp.expand(arg).as_content_primitive()  # |2 u - 2 w| and |u - w| switch together
    return (-sigma, -content) if sp.diff(sigma, first).could_extract_minus_sign() else (sigma, content)


@checked(exprs="Sequence[sp.Expr]", u="Sequence[sp.Expr]")
def switching_functions(exprs, u) -> tuple[sp.Expr, ...]:
    """The distinct arguments of Abs and sign in ``exprs`` that depend on ``u``.

    Examples
    --------
    >>> import sympy as sp
    >>> u1, u2, y = sp.symbols("u_1 u_2 y", real=True)
    >>> switching_functions([sp.Abs(u1) + sp.sign(-u1) + sp.Abs(u2 + y) + sp.Abs(y)], [u1, u2])
    (u_1, u_2 + y)
    """
    found = set()
    for expr in exprs:
        for atom in sp.sympify(expr).atoms(sp.Abs, sp.sign):
            if atom.args[0].has(*u):
                found.add(_canonical(atom.args[0], u)[0])
    order = {symbol: i for i, symbol in enumerate(u)}
    return tuple(sorted(found, key=lambda s: (min(order[x] for x in s.free_symbols if x in order), str(s))))


@checked(expr="sp.Expr", switching="Sequence[sp.Expr]", signs="Sequence[sp.Expr]", u="Sequence[sp.Expr]")
def on_piece(expr, switching, signs, u) -> sp.Expr:
    """``expr`` on the piece where sign(switching[i]) = signs[i]; signs may be symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> u, s = sp.symbols("u s", real=True)
    >>> on_piece(2*u + sp.Abs(-u) - sp.sign(u), [u], [s], [u])
    s*u - s + 2*u
    """
    by_sigma = dict(zip(switching, signs))
    replacements = {}
    for atom in sp.sympify(expr).atoms(sp.Abs, sp.sign):
        if not atom.args[0].has(*u):
            continue
        sigma, c = _canonical(atom.args[0], u)
        if sigma in by_sigma:
            s = by_sigma[sigma]
            replacements[atom] = abs(c) * s * sigma if atom.func is sp.Abs else sp.sign(c) * s
    return sp.sympify(expr).xreplace(replacements)


@checked
def solve_piece(f: sp.Matrix, u: tuple, signs: tuple) -> list[tuple]:
    """Roots of one smooth piece ``f`` of the fast subsystem: a linear solve when f is affine in u.

    Examples
    --------
    >>> u, a = sp.symbols("u a", real=True)
    >>> solve_piece(sp.Matrix([2*u - a]), (u,), (1,))
    [(a/2,)]
    """
    check_root_size(f, signs)
    polys = [fj.as_poly(*u) for fj in f]
    if all(p is not None and p.total_degree() <= 1 for p in polys):
        A, b = sp.linear_eq_to_matrix(list(f), list(u))
        det = normalize(A.det(method="berkowitz"))
        if det == 0:
            raise SingularJacobianError(
                f"det A = 0 on the piece with signs {signs}: the equilibria are not isolated and "
                "f(u) = 0 cannot be solved for u; choose parameters with det A != 0."
            )
        adjugate = A.adjugate(method="berkowitz")
        return [tuple(sp.factor_terms(sp.cancel(normalize(x) / det)) for x in adjugate * b)]
    try:
        solutions = sp.solve(list(f), list(u), dict=True)
    except NotImplementedError:
        solutions = []
    if not solutions and _no_real_root(f, u):
        return []
    if not solutions:
        raise ContactsymError(
            f"sympy found no closed-form root of the piece {list(f)} with signs {signs}; "
            "solve f(u) = 0 numerically (contactsym.numerics)."
        )
    return [tuple(sol[x] for x in u) for sol in solutions if all(x in sol for x in u)]


def _no_real_root(f: sp.Matrix, u: tuple) -> bool:
    """True when f is polynomial in u, SymPy finds all its complex roots and none is real
    (u^2 + 1 = 0). An empty real solve alone proves nothing: it is also empty for
    u^5 + u + a, and for other functions solve may return only some roots."""
    if any(fj.as_poly(*u) is None for fj in f):
        return False
    free = [sp.Dummy() for _ in u]
    try:
        roots = sp.solve(list(f.xreplace(dict(zip(u, free)))), free, dict=True)
    except NotImplementedError:
        return False
    complete = roots and all(all(z in root for z in free) for root in roots)
    return bool(complete) and all(any(sp.im(root[z]).is_nonzero for z in free) for root in roots)


@checked(signs="Sequence")
def check_root_size(f: sp.Matrix, signs, what: str = "the roots of f") -> None:
    """Refuse (a ContactsymError naming the cap) an f with more than :data:`MAX_ROOT_NODES` nodes,
    counted only until the cap is passed, so a large f is refused at once: what is derived from the
    roots or the load in closed form (equilibria, their counts) would take minutes and pages.

    Examples
    --------
    >>> import sympy as sp
    >>> u, a = sp.symbols("u a", real=True)
    >>> check_root_size(sp.Matrix([2*u - a]), (1,)) is None
    True
    """
    count = 0
    for fj in f:
        for _ in sp.preorder_traversal(fj):
            count += 1
            if count > MAX_ROOT_NODES:
                raise ContactsymError(
                    f"{what} on the piece with signs {tuple(signs)} are not derived in closed form: f has "
                    f"more than contactsym.stages.pieces.MAX_ROOT_NODES = {MAX_ROOT_NODES} expression nodes, and "
                    "they would take minutes and pages; raise the cap to derive them anyway, or find the "
                    "equilibria numerically (contactsym.numerics) at chosen parameter values."
                )
