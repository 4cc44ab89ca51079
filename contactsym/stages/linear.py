"""Linearization of the fast subsystem at an equilibrium (u*, 0): (4.3), (4.5), (4.6).

For any compliance law the Jacobian of (4.1) at (u*, 0) is ``[[Psi A, Phi], [A, 0]]``
(terms with dPhi/du multiply v = 0, terms with dPsi/du multiply f = 0). Its
characteristic polynomial needs only the principal minors of A::

    det(lam^2 I - (lam Psi + Phi) A)
        = sum_S (-1)^|S| lam^(2(k - |S|)) det(A_S) prod_{j in S} (lam Psi_j + Phi_j).
"""

from __future__ import annotations

import itertools
import logging
from dataclasses import dataclass
from functools import cached_property

import sympy as sp

from ..algebra.basic import EXPAND_NODES, PaperSymbol, node_count, normalize, sign_symbols
from ..algebra.canonical_form import TrigFraction, to_fraction
from ..algebra.coprime import cofactors, divided_by_term
from ..arguments import checked, require
from ..deprecation import deprecated_property
from ..errors import ContactsymError
from ..printing.glyphs import OwnLetters, spelled_apart
from ..printing.latex_output import Formula, LatexReprMixin, Numbering, tex
from .minors import FactoredMinors, MinorsInRing, minors_of, polynomial_factors, product_of

__all__ = ["lam", "charpoly", "principal_minors", "Linearization", "linearization_of"]

#: The general theory's numbers: A is (3.2) for k = 1 and (4.3) beyond; (4.5) and (4.6) for k >= 2.
NUMBERS = Numbering(
    {
        "A": (("3.2",), ("4.3",), ("4.3",)),
        "matrix": ((), ("4.5",), ("4.5",)),
        "charpoly": ((), ("4.6",), ("4.6",)),
    }
)


log = logging.getLogger("contactsym")

#: The eigenvalue variable of characteristic polynomials.
#:
#: >>> from contactsym import lam
#: >>> lam**2 - 1
#: lambda**2 - 1
lam = PaperSymbol("lambda")


@checked
def principal_minors(A: sp.Matrix, factors=None, minors: MinorsInRing | None = None) -> dict[tuple[int, ...], sp.Expr]:
    """det(A_S) for every subset S of the indices (the empty set gives 1), in the canonical form.

    ``factors`` = (M, W, V) with A = W^T M^-1 V (a scene in contact space) gives each minor as
    one polynomial over det M (see :class:`~contactsym.stages.minors.FactoredMinors`); ``minors``: those
    of :func:`~contactsym.stages.minors.minors_of` when the caller has them already.

    Examples
    --------
    >>> from contactsym.algebra.basic import SignSymbol
    >>> a, b, s = sp.Symbol("a"), sp.Symbol("b"), SignSymbol("s")
    >>> principal_minors(sp.Matrix([[a, s], [s, b]]))[(0, 1)]
    a*b - 1
    >>> M, W, V = sp.Matrix([[2, 1], [1, 1]]), sp.eye(2), sp.Matrix([[a, 0], [0, 1]])
    >>> principal_minors(W.T * M.inv() * V, (M, W, V))[(0, 1)] == (W.T * M.inv() * V).det()
    True
    """
    _same_size(minors, A, "principal_minors")
    ring = minors_of(A, factors) if minors is None else minors
    k = A.rows
    return {
        S: ring.field.present(ring.minor(S)) for size in range(k + 1) for S in itertools.combinations(range(k), size)
    }


@checked(Phi="Sequence[sp.Expr]", Psi="Sequence[sp.Expr]", positive="Sequence[sp.Expr]")
def charpoly(A: sp.Matrix, Phi, Psi, positive=(), factors=None, minors: MinorsInRing | None = None) -> sp.Poly:
    """The characteristic polynomial of (4.5) from the principal minors of A.

    When the common denominator of its coefficients is not a monomial but has a known sign
    (``positive`` lists expressions known to be positive, e.g. det M of a Lagrangian
    scene), the polynomial is multiplied by it: the same roots, polynomial coefficients;
    with an unknown sign each coefficient stays over it.
    The sum is formed in a polynomial ring (A = P / D, the minors of P, then one division by
    D^k), so nothing is expanded as a SymPy expression; with ``factors`` (see
    :func:`principal_minors`) every minor is over det M and the sum over det M once; ``minors``: A's
    minors when the caller has them already (moved to the ring with the law and lambda, not expanded again).

    Examples
    --------
    >>> a, Phi, Psi = sp.symbols("a Phi Psi")
    >>> charpoly(sp.Matrix([[a]]), [Phi], [Psi]).as_expr()
    -Phi*a - Psi*a*lambda + lambda**2
    """
    k = A.rows
    _same_size(minors, A, "charpoly")
    extra = [*Phi, *Psi, lam]
    minors = (None if minors is None else minors.extended(extra)) or minors_of(A, factors, extra)
    field = minors.field
    law = [field.element(x) for x in (*Phi, *Psi)]
    if any(not x.denom.is_ground for x in law):  # a law with fractions at the equilibrium: sum as expressions
        return _charpoly_of_expression(A, Phi, Psi, positive, factors)
    phi, psi = law[:k], law[k:]
    ring = field.ring
    x = ring.gens[ring.symbols.index(lam)]
    D = minors.denominator
    # lam Psi_j + Phi_j = (lam psi_j phi'_j + phi_j psi'_j) / c_j with c_j = psi'_j phi'_j numbers
    law_denominators = [psi[j].denom * phi[j].denom for j in range(k)]
    total = ring.zero
    for size in range(k + 1):
        for S in itertools.combinations(range(k), size):
            top = minors.top_power
            term = minors.numerator(S) * x ** (2 * (k - size)) * D ** (top - minors.power(S))
            for j in range(k):
                factor = (
                    x * psi[j].numer * phi[j].denom + phi[j].numer * psi[j].denom if j in S else law_denominators[j]
                )
                term = field.reduce_poly(term * factor)
            total += -term if size % 2 else term
    common = D**minors.top_power
    for c in law_denominators:
        common *= c
    fraction = _integral_fraction(field, *_cancelled_in(field.reduce_poly(total), field.reduce_poly(common), x))
    denominator = fraction.denom
    if fraction.denominator_split()[1] != 1:  # not a monomial: multiplied out when its sign is known
        sign = fraction.denominator_sign(positive)
        if sign is not None:
            fraction.numer, denominator = fraction.numer * sign, ring.one
    degree = fraction.numer.degree(x)
    coefficients = {
        (d,): TrigFraction(fraction.numer.coeff_wrt(x, d), denominator, fraction.pairs, fraction.signs).as_expr()
        for d in range(degree + 1)
    }
    coefficients = {d: c for d, c in coefficients.items() if c != 0}
    # a large coefficient is kept as derived (EX): finding a polynomial domain for it parses it again,
    # and a mechanism's sines and cosines of one angle end in EX anyway (a four-link arm: 1 s of 2.6 s)
    large = any(node_count(c, EXPAND_NODES) > EXPAND_NODES for c in coefficients.values())
    return sp.Poly.from_dict(coefficients, lam, domain=sp.EX) if large else sp.Poly.from_dict(coefficients, lam)


def _integral_fraction(field, numerator, denominator) -> TrigFraction:
    """numerator / denominator (reduced, cancelled, no sign symbol in the denominator) with integer
    coprime coefficients and a positive leading denominator coefficient, as TrigField.fraction
    gives it, without a second gcd of the two."""
    domain = field.ring.domain
    scale = 1
    for c in (*numerator.coeffs(), *denominator.coeffs()):
        scale = sp.ilcm(scale, int(domain.denom(c)))
    numerator, denominator = numerator * scale, denominator * scale
    common = sp.igcd(*[int(domain.numer(c)) for c in (*numerator.coeffs(), *denominator.coeffs())]) or 1
    numerator, denominator = numerator.quo_ground(domain(common)), denominator.quo_ground(domain(common))
    if domain.is_negative(denominator.LC):
        numerator, denominator = -numerator, -denominator
    return TrigFraction(numerator, denominator, field.pairs, field.signs)


def _cancelled_in(numerator, denominator, x) -> tuple:
    """numerator / denominator cancelled by their gcd, for a numerator that is a polynomial in
    ``x``: the gcd of the denominator with one coefficient after another (each smaller than the
    whole numerator), stopping at a number."""
    common = denominator
    coefficients = sorted(
        (numerator.coeff_wrt(x, d) for d in range(max(numerator.degree(x), 0) + 1)), key=lambda c: len(c)
    )
    for c in coefficients:
        if common.is_ground:
            break
        if not c or _number_multiple(c, common):  # lambda^(2k)'s coefficient: det M times a number
            continue
        # most of these gcds are 1 or a monomial (a rod's l^2 in det M): proved or read, not computed
        common = cofactors(common, c)[0]
    if common.is_ground:
        return numerator, denominator
    if len(common) == 1:  # a monomial: exponents subtracted (exquo's division would search each remainder)
        return divided_by_term(numerator, common), divided_by_term(denominator, common)
    return numerator.exquo(common), denominator.exquo(common)


def _number_multiple(f, g) -> bool:
    """f = c g for a number c (f, g of one ring)."""
    return len(f) == len(g) and f.mul_ground(g.LC) == g.mul_ground(f.LC)


def _same_size(minors, A: sp.Matrix, label: str) -> None:
    what = f"the minors of A, a {A.rows} x {A.rows} matrix (minors_of(A)), or None"
    require(minors is None or minors.size == A.rows, label, "minors", minors, what)


def _charpoly_of_expression(A: sp.Matrix, Phi, Psi, positive, factors=None) -> sp.Poly:
    """:func:`charpoly` summed as one SymPy expression and brought to the canonical form."""
    k = A.rows
    total = sp.S.Zero
    for S, minor in principal_minors(A, factors).items():
        factor = sp.Mul(*[lam * Psi[j] + Phi[j] for j in S])
        total += (-1) ** len(S) * lam ** (2 * (k - len(S))) * minor * factor
    fraction = to_fraction(total)
    if fraction.denominator_split()[1] != 1:
        sign = fraction.denominator_sign(positive)
        if sign is not None:
            return sp.Poly(sign * fraction.numerator_expr(), lam)
    return sp.Poly(fraction.as_expr(), lam)


@checked(fast="FastSubsystem")
@dataclass(frozen=True, eq=False)
class Linearization(LatexReprMixin):
    """The linearized fast subsystem on one sign pattern.

    With ``signs=None`` each open switching function gets a sign symbol s_i
    (``SignSymbol``, valued +1 or -1), so one object covers every pattern, as the
    paper's (5.4) does with s_j = sign N_j.

    Attributes
    ----------
    A : Matrix
        (4.3) ``df_i/du_j``; for nonlinear f it depends on u = u*, the equilibrium.
    Phi, Psi : tuple
        The law's values at the equilibrium: v = 0 and, for a law that depends on u and
        a piece with one equilibrium, u = u*.
    jacobian : Matrix
        (4.5) ``[[Psi A, Phi], [A, 0]]``, the Jacobian of (2.1) at the equilibrium (``matrix``
        is its deprecated name).
    charpoly : Poly
        (4.6) in :attr:`variable`: ``contactsym.lam``, or lambda with a hat where a symbol of the
        scene prints as lambda (``lambdahat``).

    Examples
    --------
    >>> import contactsym as cs
    >>> lin = cs.scene("brake").linearization()
    >>> lin.A[0, 1]
    mu*sin(alpha)/m - cos(alpha)/m
    >>> lin.det_A
    mu**2*sin(alpha)**2/m**2 + sin(alpha)**2/m**2
    """

    fast: object
    signs: tuple | None = None

    @property
    def scene(self):
        """The scene of the fast subsystem, for callers that need its mechanics (no stage does)."""
        return self.fast.scene

    @cached_property
    def sign_values(self) -> tuple:
        """The signs used: the given pattern, or fixed values and symbols s_i."""
        if self.signs is not None:
            return self.signs
        switching = self.fast.switching
        symbols = sign_symbols(len(switching))
        return tuple(self.fast.fixed_signs.get(sw, s) for sw, s in zip(switching, symbols))

    @cached_property
    def f(self) -> sp.Matrix:
        """f on this piece (Abs/sign replaced by the signs)."""
        return self.fast.piece(self.sign_values)

    @cached_property
    def A(self) -> sp.Matrix:
        if self.factors is not None:
            if self.fast.k == 1 and isinstance(self.minors, FactoredMinors):  # A = (det A): no adjugate of M
                return sp.Matrix([[normalize(self.det_A)]])
            product = product_of(*self.factors)
            if product is not None:
                return product
        return self.fast.jacobian(self.sign_values).applyfunc(normalize)

    @cached_property
    def det_A(self) -> sp.Expr:
        """det A in the canonical form, by fraction-free expansion in a polynomial ring."""
        return self.minors.field.present(self.minors.minor(tuple(range(self.fast.k))))

    def __getstate__(self) -> dict:
        """Pickled (an atlas's workers get the scene) without :attr:`minors`: they hold SymPy polynomial
        rings, which do not pickle reliably (PolyRing.__getstate__ changes the dict it iterates), and
        are derived again where needed."""
        state = self.__dict__.copy()
        state.pop("minors", None)
        return state

    @cached_property
    def minors(self) -> MinorsInRing:
        """A's minors (:func:`~contactsym.stages.minors.minors_of`; with polynomial factors a
        :class:`~contactsym.stages.minors.FactoredMinors`), built once for det A, the principal minors,
        (4.6) and the entries the classification reads."""
        return minors_of(self._minors_source, self.factors)

    @cached_property
    def principal_minors(self) -> dict:
        """{S: det A_S} for every subset S of the contacts, in the canonical form (see
        :func:`principal_minors`: with the scene's factors, each one polynomial over det M)."""
        return principal_minors(self._minors_source, self.factors, self.minors)

    @cached_property
    def factors(self) -> tuple | None:
        """(M, W, V) with A = W^T M^-1 V for a scene built in contact space, else None."""
        jacobian_factors = getattr(self.fast, "jacobian_factors", None)
        return None if jacobian_factors is None else jacobian_factors(self.sign_values)

    @cached_property
    def u_star(self) -> dict:
        """{u_j: u_j*} when this piece has exactly one equilibrium, else {} (Phi, Psi stay in u)."""
        if self.fast.constant_laws:
            return {}
        try:
            roots = self.fast.roots(tuple(self.sign_values))
        except ContactsymError:
            return {}
        return dict(zip(self.fast.u, roots[0])) if len(roots) == 1 else {}

    def _at_equilibrium(self, values) -> tuple:
        """The law's values at the equilibrium: v = 0 and, for a law that depends on u, u = u*."""
        at = {**dict.fromkeys(self.fast.v, 0), **self.u_star}
        return tuple(sp.sympify(x).subs(at) for x in values)

    @cached_property
    def Phi(self) -> tuple:
        return self._at_equilibrium(self.fast.Phi)

    @cached_property
    def Psi(self) -> tuple:
        return self._at_equilibrium(self.fast.Psi)

    @cached_property
    def jacobian(self) -> sp.Matrix:
        """The Jacobian (4.5) of the fast subsystem (2.1) at the equilibrium, ``[[Psi A, Phi], [A, 0]]``."""
        Psi, Phi = sp.diag(*self.Psi), sp.diag(*self.Phi)
        return sp.BlockMatrix([[Psi * self.A, Phi], [self.A, sp.zeros(self.A.rows)]]).as_explicit()

    matrix = deprecated_property("jacobian", "matrix")

    @cached_property
    def variable(self) -> sp.Symbol:
        """lambda of (4.6): ``contactsym.lam``, or a ``PaperSymbol`` with an accent where a symbol of the
        scene prints as lambda (as u becomes uhat), so that p(lambda) never shows the user's lambda beside it."""
        taken = self.fast._taken
        return lam if "lambda" not in taken else PaperSymbol(spelled_apart("lambda", taken))

    @cached_property
    def charpoly(self) -> sp.Poly:
        log.info("scene '%s': characteristic polynomial (4.6) from %d principal minors", self.fast.name, 2**self.fast.k)
        poly = charpoly(self._minors_source, self.Phi, self.Psi, self.fast.positive, self.factors, self.minors)
        return poly if self.variable == lam else poly.replace(lam, self.variable)

    @cached_property
    def _minors_source(self) -> sp.Matrix:
        """A for its minors; with polynomial factors a zero matrix of A's shape: the minors are then read
        off the factors alone, so det A and (4.6) do not wait for A's entries in the canonical form."""
        return sp.zeros(self.fast.k) if polynomial_factors(self.factors) else self.A

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """A (4.3), det A, the matrix (4.5) and p(lambda) (4.6); ``present``: in the presentation variables."""
        show = self.fast.present if present else (lambda expr: expr)
        letters = OwnLetters(self.fast._taken)  # A and J apart from a scene's own A or J (the brake's inertia)

        def row(key, lhs, rhs):
            return NUMBERS.formula(key, lhs, show(rhs), k=self.A.rows, own=self.fast.paper_equations)

        return (
            row("A", letters.tex("A"), self.A),
            row("det A", r"\det " + letters.tex("A"), self.det_A),
            row("matrix", letters.tex("J"), self.jacobian),
            row("charpoly", rf"p({tex(self.variable)})", self.charpoly.as_expr()),
        )


def linearization_of(fast, signs=None) -> Linearization:
    """The Linearization of the fast subsystem ``fast`` on the sign pattern ``signs``, built once per
    fast subsystem (:meth:`FastSubsystem.later_stage`), so that every user of it shares one.

    Examples
    --------
    >>> import contactsym as cs
    >>> fast = cs.scene("brake").fast_subsystem()
    >>> linearization_of(fast) is linearization_of(fast) is cs.scene("brake").linearization()
    True
    """
    return fast.later_stage(("linearization", signs), lambda: Linearization(fast, signs))
