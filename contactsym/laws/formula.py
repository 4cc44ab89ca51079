"""A compliance law written as a formula N(q, q', eps): checked against (1.5) and (1.8), and
inverted by implicit differentiation where no closed-form inverse exists.
"""

from __future__ import annotations

import sympy as sp

from ..arguments import checked
from ..errors import ComplianceError
from ..parse import sympy_only
from ..validate import shorten
from .compliance import Compliance

__all__ = ["ImplicitDeformation", "Law"]


class ImplicitDeformation(sp.Function):
    """The scaled deformation Q(u, v) defined implicitly by ``u = N(Q, v)``.

    No closed-form inverse is needed: its derivatives follow from implicit
    differentiation, ``dQ/du = 1/N_Q`` and ``dQ/dv = -N_V/N_Q``, evaluated at Q itself.
    Each law makes its own subclass (``law.implicit(name)``), so ``sympy.diff`` knows N.

    Examples
    --------
    A cubic spring has no closed-form Q(u, v); its Phi carries Q_1 and differentiates through it:

    >>> import sympy as sp
    >>> q, qd = sp.symbols("q qdot", real=True)
    >>> eps, k, d, c = sp.symbols("epsilon k d c", positive=True)
    >>> cubic = Law(-k*q/eps**2 - c*(q/eps**2)**3 - d*qd/eps, q, qd, eps)
    >>> Phi, Psi = cubic.phi_psi(sp.Symbol("u"), sp.Symbol("v"), 1)
    >>> (Q,) = Phi.atoms(ImplicitDeformation)
    >>> Q
    Q_1(u, v)
    >>> sp.diff(Q, sp.Symbol("u")) == 1 / Phi  # dQ/du = 1/N_Q
    True
    """

    law: Law | None = None

    @checked(u="sp.Expr", v="sp.Expr")
    def __new__(cls, u, v, **options):
        return super().__new__(cls, u, v, **options)

    @classmethod
    def eval(cls, u, v):
        return None

    def fdiff(self, argindex=1):
        law, v = self.law, self.args[1]
        at = {law.Q: self, law.V: v}
        N_Q = law.Phi_QV.xreplace(at)
        return 1 / N_Q if argindex == 1 else -law.Psi_QV.xreplace(at) / N_Q


def _leading(expr: sp.Expr, eps: sp.Symbol) -> sp.Expr:
    """The leading term of ``expr`` as eps -> 0+ (its sign is the sign of expr for small eps)."""
    for power in range(5):
        term = sp.limit(expr / eps**power, eps, 0, "+")
        if term != 0:
            break
    if term.has(sp.oo, sp.S.NegativeInfinity, sp.zoo, sp.nan) or eps in term.free_symbols:
        raise ComplianceError(f"the condition {expr} > 0 has no finite leading term as eps -> 0; write it in q, qdot.")
    return term


class Law(Compliance):
    """A user law ``N(q, q', eps)``, checked against (1.5) and (1.8).

    Parameters
    ----------
    expr : sympy expression
        The reaction as a function of the deformation ``q``, its rate ``qdot`` and ``eps``
        (a SymPy object: text is refused, see :func:`contactsym.parse_expression`).
    q, qdot, eps : sympy.Symbol
        The symbols that ``expr`` uses for them.
    check : bool
        Check the sign conditions (1.5) where the law is used (see ``where``). Turn it off
        only for a law that you know is admissible where it is used.
    where : sequence of sympy expressions
        Expressions in ``q``, ``qdot`` (and ``eps``) that are positive where the law is used,
        e.g. ``[-q]`` for a Hertz contact, which is only defined in compression. (1.5) is
        checked on that set, and the deformation Q(u, v) is the branch inside it.

    The fast subsystem needs Phi and Psi as functions of ``(u, v)``, i.e. the inverse
    ``Q(u, v)`` of ``u = N(Q, v)``. Where SymPy finds a unique closed form it is used;
    otherwise Q is an :class:`ImplicitDeformation` whose derivatives come from implicit
    differentiation, so stability conditions stay exact at any equilibrium.

    Examples
    --------
    >>> import sympy as sp
    >>> q, qd = sp.symbols("q qdot", real=True)
    >>> eps, k, d, c = sp.symbols("epsilon k d c", positive=True)
    >>> law = Law(-k*q/eps**2 - d*qd/eps - c*(qd/eps)**3, q, qd, eps)
    >>> law.phi_psi(sp.Symbol("u"), sp.Symbol("v"), None)
    (-k, -3*c*v**2 - d)
    >>> Law(k*q/eps**2 - d*qd/eps, q, qd, eps)
    Traceback (most recent call last):
    ...
    contactsym.errors.ComplianceError: (1.5) requires dN/dq < 0, but Phi = eps**2 dN/dq = k is not negative; the reaction must grow with the penetration -q.

    A cubic spring has no convenient inverse: Q(u, v) stays implicit.

    >>> cubic = Law(-k*q/eps**2 - c*(q/eps**2)**3 - d*qd/eps, q, qd, eps)
    >>> cubic.phi_psi(sp.Symbol("u"), sp.Symbol("v"), 1)
    (-3*c*Q_1(u, v)**2 - k, -d)
    """

    def __init__(self, expr, q: sp.Symbol, qdot: sp.Symbol, eps: sp.Symbol, *, check: bool = True, where=()):
        if not all(isinstance(s, sp.Symbol) for s in (q, qdot, eps)) or len({q, qdot, eps}) != 3:
            raise ComplianceError(f"q, qdot, eps = {shorten((q, qdot, eps))} must be three different sympy Symbols.")
        if not isinstance(check, bool) or not isinstance(where, (list, tuple)):
            raise ComplianceError("check must be True or False, and where a list of expressions (> 0 where used).")
        self.expr, self.q, self.qdot, self.eps = sympy_only(expr, "the law's expression"), q, qdot, eps
        self.Q = sp.Dummy("Q", real=True)
        self.V = sp.Dummy("V", real=True)
        self.scaled = self._scaled()
        scaling = {q: eps**2 * self.Q, qdot: eps * self.V}
        self.where = tuple(sympy_only(g, "a domain condition of the law") for g in where)
        #: The conditions ``where`` in the scaled variables (Q, V): each is > 0 where the law is used.
        self.domain = tuple(_leading(g.subs(scaling), eps) for g in self.where)
        self.Phi_QV = sp.diff(self.scaled, self.Q)
        self.Psi_QV = sp.diff(self.scaled, self.V)
        self.constant = not (self.Phi_QV.free_symbols | self.Psi_QV.free_symbols) & {self.Q, self.V}
        self._implicit: dict = {}
        if check:
            self._check_signs()

    def __repr__(self) -> str:
        return f"Law({self.expr})"

    def _scaled(self) -> sp.Expr:
        """N at q = eps^2 Q, q' = eps V in the limit eps -> 0 (the scaling (1.8))."""
        scaled = self.expr.subs({self.q: self.eps**2 * self.Q, self.qdot: self.eps * self.V})
        scaled = sp.expand(scaled)  # eps > 0: positive powers of eps leave the bases by themselves
        if self.eps in scaled.free_symbols:
            scaled = sp.limit(scaled, self.eps, 0, "+")
        infinite = scaled.has(sp.oo, sp.S.NegativeInfinity, sp.zoo, sp.nan, sp.DiracDelta)
        if infinite or self.eps in scaled.free_symbols:
            raise ComplianceError(
                f"the law N = {self.expr} is not scaled as (1.8): N(eps^2 Q, eps V) must have a finite "
                "limit as eps -> 0; write stiffness/eps**2 and damping/eps."
            )
        return scaled

    def inside(self) -> dict:
        """A substitution of Q and V by positive variables that covers the domain ``where``.

        Each condition g > 0 is solved for Q (else V) as g = P with P > 0; conditions that
        cannot be solved uniquely are ignored (the check then asks for more)."""
        at: dict = {}
        for g in self.domain:
            g = g.xreplace(at)
            P = sp.Dummy("P", positive=True)
            for x in (self.Q, self.V):
                if x in at or not g.has(x):
                    continue
                solutions = sp.solve(sp.Eq(g, P), x)
                if len(solutions) == 1:
                    at = {y: e.xreplace({x: solutions[0]}) for y, e in at.items()}
                    at[x] = solutions[0]
                    break
        return at

    def _check_signs(self) -> None:
        at = self.inside()
        checks = [
            (self.Phi_QV, "dN/dq < 0", "Phi = eps**2 dN/dq", "the reaction must grow with the penetration -q"),
            (self.Psi_QV, "dN/dq' < 0", "Psi = eps dN/dq'", "the contact must dissipate"),
        ]
        for value, condition, name, why in checks:
            inside = value.xreplace(at)
            if inside.is_negative or sp.expand(inside).is_negative:
                continue
            verdict = "is not negative" if inside.is_negative is False else "cannot be shown negative"
            where = f" where {' > 0, '.join(map(str, self.where))} > 0" if self.where else ""
            hint = "" if inside.is_negative is False else self._sign_hint(value)
            shown = value.xreplace({self.Q: sp.Symbol("Q"), self.V: sp.Symbol("V")})
            raise ComplianceError(f"(1.5) requires {condition}, but {name} = {shown}{where} {verdict}; {why}{hint}.")

    def _sign_hint(self, value: sp.Expr) -> str:
        """Where the sign of ``value`` changes at V = 0, or how to help the check."""
        at_rest = value.subs(self.V, 0)
        zeros = []
        if at_rest.has(self.Q) and at_rest.is_polynomial(self.Q):
            zeros = [z for z in sp.solve(at_rest, self.Q) if z.is_real is not False]
        if zeros:
            return (
                f"; at V = 0 it vanishes at Q = q/eps**2 = {', '.join(map(str, zeros))}: the law is monotone only "
                "between such points; pass where=[...] (e.g. a bound on q) to use it there, or check=False"
            )
        return (
            "; declare the law's parameters positive=True, give where=[...] (e.g. [-q] for a law used only in "
            "compression), or pass check=False if it is admissible where used"
        )

    def implicit(self, name: str) -> type:
        """The :class:`ImplicitDeformation` of this law, printed as ``name``."""
        if name not in self._implicit:
            self._implicit[name] = type(name, (ImplicitDeformation,), {"law": self})
        return self._implicit[name]

    def _closed_form_Q(self, u: sp.Symbol, v: sp.Symbol) -> sp.Expr | None:
        """The unique inverse Q(u, v) inside the domain, if SymPy finds a compact one, else None.

        A domain condition in Q alone (e.g. -Q > 0) is used as Q = Q(P) with P > 0, which
        picks the real branch of a power law. A long closed form (Cardano's formula for a
        cubic spring) is refused: implicit derivatives are shorter and exact."""
        change, unknown = {}, self.Q
        for g in self.domain:
            if g.has(self.Q) and not g.has(self.V):
                P = sp.Dummy("P", positive=True)
                solutions = sp.solve(sp.Eq(g, P), self.Q)
                if len(solutions) == 1:
                    change, unknown = {self.Q: solutions[0]}, P
                    break
        try:
            solutions = sp.solve(sp.Eq(self.scaled.xreplace(change).subs(self.V, v), u), unknown)
        except NotImplementedError:
            return None
        if len(solutions) > 1:  # keep the real (positive) branch for a compressive load u > 0
            load = sp.Dummy(positive=True)
            test = (lambda s: s.is_positive) if change else (lambda s: s.is_real)
            solutions = [s for s in solutions if test(s.subs({u: load, v: 0}))]
        if len(solutions) != 1 or sp.count_ops(solutions[0]) > 4 * sp.count_ops(self.scaled) + 8:
            return None
        return change[self.Q].subs(unknown, solutions[0]) if change else solutions[0]

    def _Q_of(self, u: sp.Symbol, v: sp.Symbol, name: str = "Q") -> sp.Expr:
        key = ("closed", u, v)
        if key not in self._implicit:
            self._implicit[key] = self._closed_form_Q(u, v)
        closed = self._implicit[key]
        return closed if closed is not None else self.implicit(name)(u, v)

    def phi_psi(self, u, v, index):
        if not ({self.Q} & (self.Phi_QV.free_symbols | self.Psi_QV.free_symbols)):
            return tuple(sp.cancel(e.subs(self.V, v)) for e in (self.Phi_QV, self.Psi_QV))
        Q = self._Q_of(u, v, "Q" if index is None else f"Q_{index}")
        if isinstance(Q, ImplicitDeformation):
            return tuple(e.xreplace({self.Q: Q, self.V: v}) for e in (self.Phi_QV, self.Psi_QV))
        return tuple(sp.cancel(e.subs({self.Q: Q, self.V: v})) for e in (self.Phi_QV, self.Psi_QV))

    def deformation(self, u, v, eps, index):
        return eps**2 * self._Q_of(u, v, "Q" if index is None else f"Q_{index}")

    def reaction(self, q, qdot, eps, index):
        """The law as written, and N = 0 outside its domain ``where`` (see :func:`_in_domain`).

        Examples
        --------
        >>> import sympy as sp
        >>> q, qd = sp.symbols("q qdot", real=True)
        >>> eps = sp.Symbol("epsilon", positive=True)
        >>> hertz = Law((-q) ** sp.Rational(3, 2) / eps**3 - qd / eps, q, qd, eps, where=[-q])
        >>> hertz.reaction(sp.Symbol("g"), sp.Symbol("gdot"), sp.Integer(1), None)
        Piecewise((-gdot + Max(0, -g)**(3/2), g < 0), (0, True))
        """
        at = {self.q: q, self.qdot: qdot, self.eps: eps}
        return _in_domain(self.expr.xreplace(at), [w.xreplace(at) for w in self.where])

    def reaction_scaled(self, Q, V, index):
        at = {self.Q: Q, self.V: V}
        return _in_domain(self.scaled.xreplace(at), [w.xreplace(at) for w in self.domain])

    def smooth_scaled(self, Q, V, index):
        return self.scaled.xreplace({self.Q: Q, self.V: V})

    def parameters(self):
        return self.expr.free_symbols - {self.q, self.qdot, self.eps}


def _in_domain(N: sp.Expr, conditions) -> sp.Expr:
    """A law defined only where its conditions are positive (Hertz: in compression) gives N = 0 elsewhere."""
    if not conditions:
        return N
    # NumPy evaluates both branches: keep fractional powers real where the law is not used
    real = {p: sp.Pow(sp.Max(p.base, 0), p.exp) for p in N.atoms(sp.Pow) if not p.exp.is_integer}
    return sp.Piecewise((N.xreplace(real), sp.And(*[sp.Gt(w, 0) for w in conditions])), (0, True))
