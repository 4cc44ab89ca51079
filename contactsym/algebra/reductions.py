"""The two reductions every stage relies on, and signs from assumptions (no ``simplify``).

- ``SignSymbol`` and ``reduce_signs``: s**2 = 1 for the sign symbols of open sign patterns;
- ``reduce_trig``: cos(x)**2 = 1 - sin(x)**2, a polynomial reduction;
- ``known_sign``: +1 or -1 when it is proved from assumptions, declared positive expressions
  (and exact multiples of them, such as the factor of det M a scene registers) and bounds
  ``|sin|, |cos| <= 1`` on trigonometric polynomials; None otherwise.
- ``PaperSymbol``: the theory's own symbols (u_j, v_j, Phi_j, Psi_j, epsilon, tau, lambda), never
  equal to a user's symbol of the same name.

Below :mod:`contactsym.algebra.canonical_form`, which builds its normal form on these rules;
:mod:`contactsym.algebra.basic` gathers both for the stages.
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp
from sympy.polys.rings import ring

from ..arguments import between, checked
from ..errors import SignPatternError
from ..parse import sympy_only
from .fourier import _fourier_terms
from .sign_bounds import as_fraction, group_ranges, plain_term_range, ranges_sign
from .sign_samples import sampled_signs

__all__ = ["PaperSymbol", "SignSymbol", "sign_symbols", "reduce_signs", "reduce_trig", "known_sign", "quotient_sign"]


class PaperSymbol(sp.Symbol):
    r"""A symbol the theory introduces (u_j, v_j, Phi_j, Psi_j, epsilon, tau, lambda), printed with the paper's name.

    It never equals a user's ``Symbol`` of the same name and assumptions, so a parameter called
    ``u`` stays the user's ``u``; it sorts as a plain symbol of its name, so formulas print in the
    same order as with plain symbols.

    Examples
    --------
    >>> u = PaperSymbol("u", real=True)
    >>> u == sp.Symbol("u", real=True), str(u), sp.latex(PaperSymbol("Phi_1", negative=True))
    (False, 'u', '\\Phi_{1}')
    """

    @classmethod
    def class_key(cls):
        return sp.Symbol.class_key()


class SignSymbol(sp.Symbol):
    """A symbol for sign(sigma) on an open sign pattern: its value is +1 or -1.

    Examples
    --------
    >>> s = SignSymbol("s")
    >>> s.is_integer, s.is_nonzero
    (True, True)
    >>> reduce_signs(s**3)
    s
    """

    def __new__(cls, name, **assumptions):
        if not isinstance(name, str) or not name.strip():
            raise SignPatternError(f"a SignSymbol's name must be text such as 's', not {type(name).__name__}.")
        return super().__new__(cls, name, integer=True, nonzero=True)


@checked(count=between(0, 1000))
def sign_symbols(count: int) -> tuple[SignSymbol, ...]:
    """s (one switching function) or s_1, ..., s_count.

    Examples
    --------
    >>> sign_symbols(1), sign_symbols(3)
    ((s,), (s_1, s_2, s_3))
    >>> all(isinstance(s, SignSymbol) for s in sign_symbols(3))
    True
    """
    if count == 1:
        return (SignSymbol("s"),)
    return tuple(SignSymbol(f"s_{i}") for i in range(1, count + 1))


@checked
def reduce_signs(expr: sp.Expr) -> sp.Expr:
    """Use s**2 = 1 for every SignSymbol s.

    Examples
    --------
    >>> s = SignSymbol("s")
    >>> reduce_signs(s**2 + 3*s**3 - s**4)
    3*s
    """
    return sympy_only(expr, "the expression").replace(  # never sympify text: it would be evaluated
        lambda e: e.is_Pow and isinstance(e.base, SignSymbol) and e.exp.is_Integer,
        lambda e: e.base ** (e.exp % 2),
    )


@checked
def reduce_trig(expr: sp.Expr) -> sp.Expr:
    """Replace cos(x)**n, n >= 2, by cos(x)**(n % 2) (1 - sin(x)**2)**(n // 2), expanded.

    Examples
    --------
    >>> a, m = sp.symbols("alpha m", positive=True)
    >>> reduce_trig(sp.sin(a)**2/m + sp.cos(a)**2/m)
    1/m
    """

    def is_cos_power(e):
        return e.is_Pow and isinstance(e.base, sp.cos) and e.exp.is_Integer and e.exp >= 2

    def rewrite(e):
        n = int(e.exp)
        return e.base ** (n % 2) * (1 - sp.sin(e.base.args[0]) ** 2) ** (n // 2)

    return sp.expand(sympy_only(expr, "the expression").replace(is_cos_power, rewrite))


@checked(positive="Sequence[sp.Expr]")
def known_sign(expr: sp.Expr, positive=()) -> int | None:
    """+1 or -1 when the sign of ``expr`` is proved, else None (never a guess: every answer is exact).

    ``positive`` lists expressions known to be positive in the scene's domain (e.g.
    ``sin(phi)`` for 0 < phi < pi/2, or the factor of det M of a Lagrangian scene). The
    proofs, tried in turn, each cheap:

    1. SymPy's assumptions, the listed expressions standing in as positive symbols;
    2. a product or quotient: the signs of its factors (an even power of a factor of known sign is positive);
    3. an exact multiple c m p of a listed expression p (c a number, m a monomial of known sign);
    4. domination: grouped by their monomials in the symbols of known sign, the terms' trigonometric
       coefficients, written as Fourier sums a_0 + sum(a_k cos(k.q) + b_k sin(k.q)), are bounded by
       a_0 -+ sum(|a_k| + |b_k|) (|sin|, |cos| <= 1; a sign symbol is +-1); when every group has the
       same sign and one a strict one, so has the sum. The same with the polynomial's own monomials
       and sin, cos in [0, 1] where a listed expression says they are positive (a declared interval).

    Examples
    --------
    >>> m = sp.Symbol("m", positive=True)
    >>> Phi = sp.Symbol("Phi", negative=True)
    >>> known_sign(-3*m*Phi), known_sign(Phi - m), known_sign(sp.Symbol("x"))
    (1, -1, None)
    >>> a = sp.Symbol("alpha", positive=True)
    >>> known_sign(sp.sin(a)**2 + 1), known_sign(sp.sin(a)), known_sign(sp.sin(a), [sp.sin(a)])
    (1, None, 1)

    A multiple of a listed positive expression (here det M of a two-link arm over its masses), and a
    trigonometric polynomial whose constant part dominates:

    >>> m1, m2 = sp.symbols("m1 m2", positive=True)
    >>> q1, q2 = sp.symbols("q1 q2", real=True)
    >>> det = 8*m1 - 9*m2*sp.cos(2*q1 - 2*q2) + 15*m2
    >>> known_sign(4*m1*m2 - 9*m2**2*sp.cos(2*q1 - 2*q2)/2 + 15*m2**2/2, [det])
    1
    >>> known_sign(m1 + m2*sp.sin(q1 - q2)**2), known_sign(-3 + sp.cos(q1)*sp.sin(q2) + sp.sin(q1)**2)
    (1, -1)
    >>> known_sign(1 - 2*sp.sin(q1)*sp.cos(q1)) is None  # zero at q1 = pi/4: no proof
    True
    """
    expr = sympy_only(expr, "the expression")
    positive = tuple(sympy_only(p, "a positive expression") for p in positive)
    return _known_sign(expr, positive)


def quotient_sign(expr: sp.Expr, divisor: sp.Expr, positive=()) -> int | None:
    """The sign of ``expr / divisor``, proved as by :func:`known_sign`; None when it does not follow.

    The numerator of ``expr`` is divided exactly by that of ``divisor`` in the normal form with
    sin q**2 + cos q**2 = 1 (where ``sympy.cancel`` sees no common factor), and the signs of the
    quotient and of both denominators are multiplied.

    Examples
    --------
    >>> m, Psi = sp.Symbol("m", positive=True), sp.Symbol("Psi", negative=True)
    >>> q = sp.Symbol("q", real=True)
    >>> b = (sp.sin(q)**2 - sp.cos(q))/(m*(2 + sp.cos(q)))
    >>> quotient_sign(Psi*(sp.cos(q)**2 + sp.cos(q) - 1), b), known_sign(sp.cancel(Psi*(sp.cos(q)**2 + sp.cos(q) - 1)/b))
    (1, None)
    """
    expr, divisor = sympy_only(expr, "the expression"), sympy_only(divisor, "the divisor")
    positive = tuple(sympy_only(p, "a positive expression") for p in positive)
    return _quotient_sign(expr, divisor, positive)


@lru_cache(maxsize=1024)
def _quotient_sign(expr: sp.Expr, divisor: sp.Expr, positive: tuple) -> int | None:
    if divisor == 1:
        return _known_sign(expr, positive)
    if _too_large(expr) or _too_large(divisor):  # before together, which takes seconds on such sizes
        return None
    (n1, d1), (n2, d2) = sp.fraction(sp.together(expr)), sp.fraction(sp.together(divisor))
    if any(_too_large(e) for e in (n1, n2)):
        return None
    signs = [_known_sign(d, positive) for d in (d1, d2)]
    found = _polynomials((n1, n2))
    if None in signs or found is None:
        return None
    (f, g), _ = found
    if not g:
        return None
    quotient, remainder = f.div(g)
    if remainder or not quotient:
        return None
    sign = _known_sign(quotient.as_expr(), positive)
    return None if sign is None else sign * signs[0] * signs[1]


#: Expressions with more nodes than this get only the assumption test: proofs stay cheap.
SIGN_PROOF_LIMIT = 4000


@lru_cache(maxsize=4096)
def _known_sign(expr: sp.Expr, positive: tuple, depth: int = 0) -> int | None:
    sign = _assumed_sign(expr, positive)
    if sign is not None or expr.is_number or depth > 2 or _too_large(expr):
        return sign
    seen = _sampled(expr, positive) if depth == 0 else set()
    if 0 in seen or {-1, 1} <= seen:  # a point of the domain where no strict sign holds: nothing to prove
        return None
    numer, denom = sp.fraction(sp.factor_terms(expr))
    factors = [f for f in sp.Mul.make_args(numer) + sp.Mul.make_args(denom) if f != 1]
    if len(factors) > 1 or factors[0].is_Pow:
        return _product_sign(factors, positive, depth)
    for p in positive:
        sign = _multiple_sign(expr, p, positive, depth)
        if sign is not None:
            return sign
    return _dominated_sign(expr, positive, depth)


def _sampled(expr: sp.Expr, positive: tuple) -> set[int]:
    """:func:`~contactsym.algebra.sign_samples.sampled_signs` of the expressions with their angles expanded."""
    exprs = [_expand_angles(e) for e in (expr, *positive)]
    units = {s for e in exprs for s in e.free_symbols if isinstance(s, SignSymbol)}
    return sampled_signs(exprs[0], exprs[1:], units)


def _assumed_sign(expr: sp.Expr, positive: tuple) -> int | None:
    """The sign SymPy's assumptions give, with the listed expressions as positive symbols."""
    stand_ins = {p: sp.Dummy(positive=True) for p in positive}
    expr = expr.subs(stand_ins) if stand_ins else expr
    if expr.is_positive:
        return 1
    if expr.is_negative:
        return -1
    return None


def _too_large(expr: sp.Expr) -> bool:
    for count, _ in enumerate(sp.preorder_traversal(expr)):
        if count > SIGN_PROOF_LIMIT:
            return True
    return False


def _product_sign(factors, positive: tuple, depth: int) -> int | None:
    """The product of the factors' signs; an even power needs its base's sign too (it must not vanish)."""
    sign = 1
    for factor in factors:
        base, exponent = factor.as_base_exp()
        if not exponent.is_Integer:
            base, exponent = factor, sp.S.One
        part = _known_sign(base, positive, depth + 1)
        if part is None:
            return None
        if part == -1 and exponent % 2:
            sign = -sign
    return sign


def _polynomials(exprs):
    """The expressions as polynomials of one ring in normal form (cos q**2 = 1 - sin q**2, s**2 = 1),
    with the ring's (cos, sin) index pairs; None when one is no polynomial over the rationals."""
    exprs = [_expand_angles(e) for e in exprs]
    trig = set().union(*(e.atoms(sp.sin, sp.cos) for e in exprs))
    angles = sorted({f.args[0] for f in trig}, key=sp.default_sort_key)
    if any(not (a.is_Symbol and a.is_real) for a in angles):
        return None  # sin of a compound or complex argument: no bound by 1 that we can use
    gens = [g for a in angles for g in (sp.cos(a), sp.sin(a))]
    others = set().union(*(e.atoms(sp.Symbol) for e in exprs))
    others |= {f for e in exprs for f in e.atoms(sp.Function) if f not in trig}
    others |= {p for e in exprs for p in e.atoms(sp.Pow) if not p.exp.is_Integer}
    gens += sorted(others, key=sp.default_sort_key)
    pairs = [(2 * i, 2 * i + 1) for i in range(len(angles))]
    R = ring(gens or [sp.Dummy()], sp.QQ)[0]
    try:
        polys = [_reduced(R.from_expr(e), pairs) for e in exprs]
    except (ValueError, TypeError, sp.polys.polyerrors.PolynomialError):
        return None
    return polys, pairs


def _expand_angles(expr: sp.Expr) -> sp.Expr:
    """sin and cos of sums and multiples of angles as polynomials in sin q_i, cos q_i."""
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)) and not e.args[0].is_Symbol,
        lambda e: sp.expand_trig(e.func(sp.expand(e.args[0]))),  # cos(2*(a - b)): the sum expanded first
    )


def _reduced(poly, pairs):
    """The normal form: cos q**2 = 1 - sin q**2 and s**2 = 1 used until no power of either exceeds 1."""
    R = poly.ring
    signs = [i for i, g in enumerate(R.symbols) if isinstance(g, SignSymbol)]
    if signs and any(poly.degree(i) > 1 for i in signs):  # s**2 = 1: each exponent of s taken mod 2, term by term
        reduced = {}
        for monomial, coefficient in poly.terms():
            monomial = tuple(e % 2 if i in signs else e for i, e in enumerate(monomial))
            reduced[monomial] = reduced.get(monomial, 0) + coefficient
        poly = R.from_dict({m: c for m, c in reduced.items() if c})
    squares = [(R.gens[c] ** 2, 1 - R.gens[s] ** 2, c) for c, s in pairs]
    for square, value, i in squares:
        while poly.degree(i) > 1:
            quotient, remainder = poly.div(square)
            poly = quotient * value + remainder
    return poly


def _multiple_sign(expr: sp.Expr, p: sp.Expr, positive: tuple, depth: int) -> int | None:
    """sign(quotient) when expr = quotient * p exactly (p a listed positive expression); else None."""
    if not p.is_Add:
        return None
    found = _polynomials((expr, p))
    if found is None:
        return None
    (f, g), _ = found
    if not g or g.is_ground:
        return None
    quotient, remainder = f.div(g)
    if remainder or not quotient:
        return None
    return _known_sign(quotient.as_expr(), positive, depth + 1)


def _dominated_sign(expr: sp.Expr, positive: tuple, depth: int) -> int | None:
    """The sign of a polynomial in sin, cos and symbols of known sign whose constant parts dominate."""
    numer, denom = expr.as_numer_denom()
    if denom != 1:
        signs = [_dominated_sign(numer, positive, depth), _known_sign(denom, positive, depth + 1)]
        return None if None in signs else signs[0] * signs[1]
    found = _polynomials((expr,))
    if found is None:
        return None
    (poly,), pairs = found
    if not poly:
        return None  # zero: no sign
    gens = poly.ring.symbols
    trig = sorted(i for pair in pairs for i in pair)
    scale = {i: _assumed_sign(g, positive) for i, g in enumerate(gens) if i not in trig}
    real = {i: bool(g.is_real) for i, g in enumerate(gens)}
    bounded = {i for i, g in enumerate(gens) if isinstance(g, SignSymbol)}
    if pairs:
        terms = [
            (rest, a, 0) if not any(k) else (rest, 0, abs(a) + abs(b))
            for (k, rest), (a, b) in _fourier_terms(poly, pairs).items()
        ]
    else:
        terms = [(monom, as_fraction(c), 0) for monom, c in poly.terms()]
    sign = ranges_sign(group_ranges(terms, bounded), scale, real)
    if sign is None and pairs:  # the monomials themselves, sin and cos in [0, 1] where declared positive
        unit = {i for i in trig if _assumed_sign(gens[i], positive) == 1}
        terms = [plain_term_range(monom, as_fraction(c), trig, unit) for monom, c in poly.terms()]
        sign = ranges_sign(group_ranges(terms, bounded), scale, real)
    return sign
