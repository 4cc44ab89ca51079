"""The fraction field of the canonical form: angles expanded, P/Q reduced modulo the circle.

Every expression the pipeline derives is a rational function of the parameters, of sign
symbols ``s_j`` (values +-1), and of ``sin q`` and ``cos q`` of a few angles. This module
holds the field those expressions live in (:class:`TrigField`), a fraction P/Q of it in normal
form (:class:`TrigFraction`) and its presentation; :mod:`contactsym.algebra.canonical_form`
builds the canonical form on top (see its docstring for the steps and what is guaranteed).

1. Sines and cosines of integer combinations of angles (``cos(q1 - q2)``, ``sin 2q``) are
   expanded into products of ``sin q_i``, ``cos q_i``; every other function application
   (``Abs(u)``, ``sqrt(m)``, ``Y(x)``) is an opaque generator.
2. The expression becomes P/Q, two polynomials over the integers in these generators
   (SymPy's sparse ``FracField``, which cancels as it goes).
3. P and Q are reduced to the normal form modulo the ideal
   ``(cos^2 q + sin^2 q - 1, ..., s^2 - 1, ...)``: every ``cos q`` to degree at most one,
   every ``s`` to degree at most one. Why this is a normal form: the leading monomials
   ``cos^2 q`` and ``s^2`` of the generators are pairwise coprime, so by Buchberger's first
   criterion the generators are a Groebner basis, and the remainder on division by a
   Groebner basis is unique. Sign symbols in Q are moved up (1/s = s).
4. P/Q is cancelled by its polynomial gcd and its sign fixed (Q's leading coefficient > 0).

Examples
--------
>>> import sympy as sp
>>> x, m = sp.symbols("x m", positive=True)
>>> to_fraction(sp.cos(x)**2/(m*sp.sin(x)**2 - m)).as_expr()
-1/m
"""

from __future__ import annotations

from fractions import Fraction
from functools import reduce

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.polys.fields import FracField

from ..arguments import checked, require
from ..parse import sympy_only
from .coprime import cancel, divided_by_term
from .fourier import fourier_sum, shorter_fourier_terms
from .reductions import SignSymbol, known_sign

__all__ = ["TrigField", "TrigFraction", "present_factor", "to_fraction"]


def _is_angle(x: sp.Expr) -> bool:
    """A symbol, a coordinate q(t), or a real number SymPy leaves inside sin and cos (``pi/7``, a
    parameter fixed at ``157/200``): what sin and cos are taken of, tied by sin^2 + cos^2 = 1."""
    return x.is_Symbol or isinstance(x, AppliedUndef) or (x.is_number and x.is_real is True)


def _integer_combination(arg: sp.Expr) -> bool:
    """True for k1 q1 + k2 q2 + ... with integer k_i and at least two terms or |k| > 1."""
    if _is_angle(arg):
        return False
    terms = sp.Add.make_args(arg)
    for term in terms:
        coeff, rest = term.as_coeff_Mul()
        if not (coeff.is_Integer and _is_angle(rest)):
            return False
    return True


_ROOTS: dict = {}  # (base, q) -> the symbol standing for base**(1/q)
_ROOT_VALUES: dict = {}  # that symbol -> base**(1/q)


def _root_symbol(base: sp.Expr, q: int) -> sp.Symbol:
    if (base, q) not in _ROOTS:
        symbol = sp.Dummy(f"root{len(_ROOTS)}")
        _ROOTS[(base, q)], _ROOT_VALUES[symbol] = symbol, base ** sp.Rational(1, q)
    return _ROOTS[(base, q)]


def _roots_back(expr: sp.Expr) -> sp.Expr:
    """Undo the root symbols of :func:`_expand_angles` (for presentation)."""
    used = {s: _ROOT_VALUES[s] for s in expr.free_symbols if s in _ROOT_VALUES} if _ROOT_VALUES else {}
    return expr.xreplace(used) if used else expr


def _expand_angles(expr: sp.Expr) -> sp.Expr:
    """sin/cos of integer combinations of angles as products of sin q_i, cos q_i; a power
    base**(p/q) as r**p with one symbol r = base**(1/q), so that base**(1/3) and base**(2/3)
    are powers of one generator."""
    expr = expr.replace(
        lambda e: e.is_Pow and e.exp.is_Rational and not e.exp.is_Integer,
        lambda e: _root_symbol(e.base, int(e.exp.q)) ** int(e.exp.p),
    )
    return expr.replace(
        lambda e: isinstance(e, (sp.sin, sp.cos)) and _integer_combination(e.args[0]),
        lambda e: sp.expand_trig(e),
    )


def _generators(expr: sp.Expr) -> list[sp.Expr]:
    """Generators, each angle's cos right before its sin (the reduction's lex order)."""
    angles = sorted({f.args[0] for f in expr.atoms(sp.sin, sp.cos) if _is_angle(f.args[0])}, key=sp.default_sort_key)
    trig = [g for a in angles for g in (sp.cos(a), sp.sin(a))]
    others = set(expr.atoms(sp.Symbol))
    others |= {f for f in expr.atoms(sp.Function) if f not in trig}
    others |= {p for p in expr.atoms(sp.Pow) if not p.exp.is_Integer}
    others |= expr.atoms(sp.Derivative)
    plain = [g for g in others if g.is_Symbol]
    opaque = [g for g in others if not g.is_Symbol]
    return trig + sorted(plain, key=sp.default_sort_key) + sorted(opaque, key=sp.default_sort_key)


@checked
class TrigFraction:
    """P/Q in normal form: two polynomials of one ring, reduced, cancelled.

    Attributes
    ----------
    numer, denom : PolyElement

    Examples
    --------
    >>> x, m = sp.symbols("x m", positive=True)
    >>> fr = to_fraction(sp.cos(x)**2/(m*sp.sin(x)**2 - m))
    >>> type(fr).__name__, fr.numer, fr.denom
    ('TrigFraction', -1, m)
    >>> fr.as_expr()
    -1/m
    """

    def __init__(self, numer, denom, pairs, signs):
        self.numer, self.denom = numer, denom
        self.pairs, self.signs = pairs, signs

    def as_expr(self) -> sp.Expr:
        """The presented expression (see the module docstring)."""
        monomial, rest = _split_monomial(self.denom)
        if rest == 1:
            return _roots_back(_over_monomial(self.numer, monomial))
        numer, scale_n = present_factor(self.numer, self.pairs)
        denom, scale_d = present_factor(rest, self.pairs)
        return (scale_n / scale_d) * numer / (_roots_back(monomial.as_expr()) * denom)

    def denominator_split(self) -> tuple[sp.Expr, object]:
        """(c * monomial, rest): the denominator is their product; rest = 1 for a monomial."""
        monomial, rest = _split_monomial(self.denom)
        return _roots_back(monomial.as_expr()), rest

    def denominator_sign(self, positive=()) -> int | None:
        """The sign of the denominator when it follows from ``positive`` (expressions known
        to be positive): its monomial's sign times those of factors divided out exactly."""
        monomial, rest = self.denominator_split()
        sign = known_sign(monomial, positive)
        for p in positive:
            if sign is None or rest.is_ground:
                break
            factor = _as_poly(p, rest.ring, self.pairs, self.signs)
            if factor is None or factor.is_ground:
                continue
            while not rest.is_ground:
                quotient, remainder = rest.div(factor)
                if remainder:
                    break
                rest = quotient
        if sign is None or not rest.is_ground:
            return None
        return sign * (1 if rest.LC > 0 else -1)

    def numerator_expr(self) -> sp.Expr:
        """The numerator, presented."""
        numer, scale = present_factor(self.numer, self.pairs)
        return scale * numer


def present_factor(poly, pairs) -> tuple[sp.Expr, sp.Rational]:
    """(form, c) with poly = c * form; form in its shorter presentation with integer,
    coprime coefficients and a fixed sign, so one polynomial always reads the same."""
    if not poly:
        return sp.S.Zero, sp.S.One
    terms = shorter_fourier_terms(poly, pairs)
    if terms is None:  # shown as it is: the coefficients divided in the ring
        coefficients = [(int(poly.ring.domain.numer(c)), int(poly.ring.domain.denom(c))) for c in poly.coeffs()]
    else:
        coefficients = [(x.numerator, x.denominator) for pair in terms.values() for x in pair if x]
    # the scale from the coefficients themselves: no expand of a sum of thousands of terms (~6 s of a
    # four-link arm's report, twice per factor)
    scale = sp.Rational(
        reduce(sp.igcd, [abs(p) for p, _ in coefficients]), reduce(sp.ilcm, [q for _, q in coefficients])
    )
    if terms is None:
        domain = poly.ring.domain
        form = poly.mul_ground(domain.convert(scale.q)).quo_ground(domain.convert(scale.p)).as_expr()
    else:
        ratio = Fraction(scale.q, scale.p)
        form = fourier_sum({key: (a * ratio, b * ratio) for key, (a, b) in terms.items()}, poly.ring, pairs)
    if form.could_extract_minus_sign():
        form, scale = -form, -scale
    return _roots_back(form), scale


def _as_poly(expr: sp.Expr, ring, pairs, signs):
    """``expr`` (a polynomial in ``ring``'s generators after expanding angles) in ``ring``,
    reduced, or None."""
    try:
        poly = ring.from_expr(_expand_angles(sympy_only(expr, "the expression")))
    except (ValueError, sp.polys.polyerrors.CoercionFailed):
        return None
    return _reduce(poly, pairs, signs)


def _reduce(poly, pairs, signs):
    """The normal form of a polynomial (see the module docstring): cos^e -> cos^(e mod 2)
    (1 - sin^2)^(e // 2) and s^e -> s^(e mod 2), term by term (what division by the
    Groebner basis gives, without the general division algorithm)."""
    ring = poly.ring
    for i in signs:
        if poly.degree(i) > 1:
            poly = ring.from_dict(_sum_terms((m[:i] + (m[i] % 2,) + m[i + 1 :], c) for m, c in poly.items()))
    for c, s in pairs:
        if poly.degree(c) < 2:
            continue
        kept, by_power = {}, {}
        for monom, coeff in poly.items():
            target = kept if monom[c] < 2 else by_power.setdefault(monom[c] // 2, {})
            lowered = monom[:c] + (monom[c] % 2,) + monom[c + 1 :]
            target[lowered] = target.get(lowered, 0) + coeff
        poly = ring.from_dict(kept)
        one_minus = ring.one - ring.gens[s] ** 2
        for power, part in by_power.items():
            poly += ring.from_dict(part) * one_minus**power
    return poly


def _compose(poly, index: int, value):
    """poly with generator ``index`` replaced by the field element ``value`` (Horner)."""
    field = value.field
    gen = poly.ring.gens[index]
    degree = poly.degree(index)
    if degree <= 0:
        return field.new(poly)
    result = field.new(poly.coeff_wrt(gen, degree))
    for power in range(degree - 1, -1, -1):
        result = result * value + field.new(poly.coeff_wrt(gen, power))
    return result


def _sum_terms(terms) -> dict:
    total: dict = {}
    for monom, coeff in terms:
        total[monom] = total.get(monom, 0) + coeff
    return total


def _over_monomial(poly, monomial) -> sp.Expr:
    """``expand(poly.as_expr() / monomial.as_expr())`` for a one-term ``monomial``, term by term:
    expand would walk a sum of thousands of terms again (10 s of a five-link chain's (4.6))."""
    ((divisor, scale),) = monomial.items()
    to_sympy, gens = poly.ring.domain.to_sympy, poly.ring.symbols
    scale = to_sympy(scale)
    return sp.Add(
        *(
            sp.Mul(to_sympy(c) / scale, *(g ** (a - b) for g, a, b in zip(gens, m, divisor) if a != b))
            for m, c in poly.items()
        )
    )


def _split_monomial(poly):
    """poly = content * monomial * rest, with rest = 1 for a monomial."""
    ring = poly.ring
    content, primitive = poly.primitive()
    exponents = [min(e) for e in zip(*primitive.monoms())] if primitive else [0] * ring.ngens
    monomial = ring({tuple(exponents): ring.domain.one})
    rest = divided_by_term(primitive, monomial)
    return ring({(0,) * ring.ngens: content}) * monomial, rest


@checked(exprs="Sequence[sp.Expr]")
class TrigField:
    """One fraction field for several expressions, with the reduction of the module docstring.

    Examples
    --------
    >>> x, m = sp.symbols("x m", positive=True)
    >>> K = TrigField([sp.sin(x), m])
    >>> K.present(K.reduce(K.element(sp.sin(x))**2 + K.element(sp.cos(x))**2))
    1
    """

    def __init__(self, exprs):
        exprs = [_expand_angles(sympy_only(e, "an expression")) for e in exprs]
        gens = _generators(sp.Tuple(*exprs)) or [sp.Dummy("one")]
        self.field = FracField(gens, sp.QQ)
        self.ring = self.field.ring
        index = {g: i for i, g in enumerate(gens)}
        self.pairs = [
            (index[g], index[sp.sin(g.args[0])]) for g in gens if isinstance(g, sp.cos) and _is_angle(g.args[0])
        ]
        self.signs = [index[g] for g in gens if isinstance(g, SignSymbol)]

    def element(self, expr: sp.Expr):
        """``expr`` as a reduced element of the field."""
        expr = _expand_angles(sympy_only(expr, "the expression"))
        numer, denom = sp.fraction(expr)
        try:  # already one fraction of polynomials (a presented form): no together needed
            parts = self.ring.from_expr(numer), self.ring.from_expr(denom)
        except (ValueError, sp.polys.polyerrors.CoercionFailed):
            numer, denom = sp.fraction(sp.together(expr))
            parts = self.ring.from_expr(numer), self.ring.from_expr(denom)
        return self.reduce(self.field.new(*parts))

    def substituted(self, expr: sp.Expr, values: dict):
        """``expr`` with generators replaced by field elements (``values``), reduced."""
        fits = isinstance(values, dict) and all(
            x in self.ring.symbols and self._owns(v, "field") for x, v in values.items()
        )
        require(fits, "TrigField.substituted", "values", values, "a dict {generator: element of this field}")
        value = self.element(expr)
        for symbol, replacement in values.items():
            index = self.ring.symbols.index(symbol)
            value = self.reduce(_compose(value.numer, index, replacement) / _compose(value.denom, index, replacement))
        return value

    def _owns(self, value, kind: str) -> bool:
        """``value`` is an element of this ring (``kind`` "ring") or field ("field")."""
        mine = self.ring if kind == "ring" else self.field
        theirs = getattr(value, kind, None)
        return theirs is mine or (type(theirs) is type(mine) and theirs == mine)

    def reduce_poly(self, poly):
        """The normal form of an element of this field's ring (sin^2 + cos^2 = 1, s^2 = 1)."""
        if getattr(poly, "ring", None) is not self.ring:  # the check costs an attribute read where it holds
            require(self._owns(poly, "ring"), "TrigField.reduce_poly", "poly", poly, "an element of this field's ring")
        return _reduce(poly, self.pairs, self.signs)

    def reduce(self, value):
        """The normal form of a field element: signs moved up, both parts reduced, cancelled."""
        if getattr(value, "field", None) is not self.field:
            require(self._owns(value, "field"), "TrigField.reduce", "value", value, "an element of this field")
        numer, denom = self.reduce_poly(value.numer), self.reduce_poly(value.denom)
        for i in self.signs:  # no sign in the denominator: d0 + d1 s times d0 - d1 s is d0^2 - d1^2
            if denom.degree(i) > 0:
                gen = self.ring.gens[i]
                d1 = denom.coeff_wrt(gen, 1)
                conjugate = denom - 2 * d1 * gen
                rational = self.reduce_poly(denom * conjugate)
                if rational:  # zero: the denominator vanishes for one sign; keep it as it is
                    numer, denom = self.reduce_poly(numer * conjugate), rational
        return self.field.raw_new(*cancel(numer, denom))  # what field.new does, the gcd proved 1 cheaply

    def fraction(self, value) -> TrigFraction:
        value = self.reduce(value)
        numer, denom = _integral(value.numer, value.denom)
        return TrigFraction(numer, denom, self.pairs, self.signs)

    def present(self, value) -> sp.Expr:
        """The presented sympy expression of a field element."""
        return self.fraction(value).as_expr()


@checked
def to_fraction(expr: sp.Expr) -> TrigFraction:
    """The normal form P/Q of ``expr`` (see the module docstring).

    Examples
    --------
    >>> x, m = sp.symbols("x m", positive=True)
    >>> fr = to_fraction(sp.cos(x)**2/(m*sp.sin(x)**2 - m))
    >>> fr.numer, fr.denom
    (-1, m)
    """
    field = TrigField([expr])
    return field.fraction(field.element(expr))


def _integral(numer, denom):
    """Clear rational coefficients: integer numerator and denominator, denominator content > 0."""
    domain = numer.ring.domain
    scale = reduce(sp.ilcm, [int(domain.denom(c)) for c in list(numer.coeffs()) + list(denom.coeffs())], 1)
    numer, denom = numer * scale, denom * scale
    content_n, content_d = numer.content(), denom.content()
    common = domain.convert(sp.igcd(int(domain.numer(content_n)), int(domain.numer(content_d))) or 1)
    numer, denom = numer.quo_ground(common), denom.quo_ground(common)
    if domain.is_negative(denom.LC):
        numer, denom = -numer, -denom
    return numer, denom
