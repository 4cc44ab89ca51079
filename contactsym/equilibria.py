"""Equilibria (u*, 0) of the fast subsystem: f(u*) = 0 (3.1), (4.2).

f is smooth on each piece of a sign pattern; a root of that piece is an equilibrium
when it lies in the piece: s_i sigma_i(u*) > 0 for every switching function sigma_i.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from .algebra import normalize
from .errors import ContactsymError, SingularJacobianError

__all__ = ["Branch", "Equilibria"]


@dataclass(frozen=True)
class Branch:
    """One equilibrium: its sign pattern, the reactions u* and where it exists.

    Examples
    --------
    >>> import contactsym as cs
    >>> cs.scene("sliding-point").equilibria().branches[0].u_star
    (-Y(x, xdot),)
    """

    signs: tuple
    u_star: tuple
    condition: sp.Basic

    def _repr_latex_(self) -> str:
        from .latex import _repr_latex

        return _repr_latex(self)


def _solve_piece(f: sp.Matrix, u: tuple, signs: tuple) -> list[tuple]:
    """Roots of one smooth piece: a linear solve when f is affine in u."""
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


@dataclass(frozen=True, eq=False)
class Equilibria:
    """All equilibrium branches, one or more per admissible sign pattern.

    Examples
    --------
    >>> import contactsym as cs
    >>> eq = cs.scene("painleve-klein-rod").equilibria()
    >>> len(eq.branches)
    4
    """

    scene: object
    signs: tuple | None

    @cached_property
    def patterns(self) -> list[tuple]:
        return [self.signs] if self.signs is not None else self.scene.sign_patterns()

    @cached_property
    def branches(self) -> tuple[Branch, ...]:
        fast = self.scene.fast_subsystem()
        branches = []
        for pattern in self.patterns:
            for root in _solve_piece(fast.piece(pattern), fast.u, pattern):
                at = dict(zip(fast.u, root))
                inside = [sp.Gt(sp.cancel(s * sw.subs(at)), 0) for s, sw in zip(pattern, fast.switching)]
                branches.append(Branch(pattern, root, sp.And(*inside)))
        return tuple(branches)

    def __iter__(self):
        return iter(self.branches)

    def __len__(self) -> int:
        return len(self.branches)

    def _repr_latex_(self) -> str:
        from .latex import _repr_latex

        return _repr_latex(self)
