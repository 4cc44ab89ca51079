"""Coprimality by specialization: the same cofactors and cancelled forms as SymPy's, and no false proof."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from sympy import QQ, ZZ
from sympy.polys.rings import ring

from contactsym.algebra.coprime import cancel, cofactors, divided_by_term, proved_coprime
from tests.helpers import small_fractions

RINGS = {domain: ring("x, y, z", domain)[0] for domain in (ZZ, QQ)}


def polynomials(domain):
    coefficient = st.integers(-6, 6) if domain == ZZ else small_fractions(-6, 6, max_denominator=5)
    term = st.tuples(st.tuples(st.integers(0, 3), st.integers(0, 2), st.integers(0, 2)), coefficient)
    return st.lists(term, min_size=1, max_size=6).map(
        lambda terms: RINGS[domain].from_dict({m: domain.convert(c) for m, c in dict(terms).items() if c})
    )


@st.composite
def pairs(draw):
    """Two polynomials of one ring, often with a common factor multiplied in."""
    domain = draw(st.sampled_from([ZZ, QQ]))
    f, g = draw(polynomials(domain)), draw(polynomials(domain))
    if draw(st.booleans()):
        common = draw(polynomials(domain))
        f, g = f * common, g * common
    return f, g


@settings(max_examples=120)
@given(pairs())
def test_cofactors_and_cancel_equal_sympys(pair):
    f, g = pair
    assert cofactors(f, g) == f.cofactors(g)
    if g:
        assert cancel(f, g) == f.cancel(g)


@settings(max_examples=120)
@given(pairs())
def test_a_proof_of_coprimality_is_never_wrong(pair):
    f, g = pair
    if proved_coprime(f, g):
        h = f.gcd(g)
        assert h.is_ground, (f, g, h)


def test_the_certificate_decides_a_coprime_pair_and_refuses_a_shared_factor():
    R, x, y, z = ring("x, y, z", ZZ)
    assert proved_coprime(x**3 * y + z + 1, x * y * z - 2)
    assert not proved_coprime((x - y) * (z + 1), (x - y) * (z + 2))
    assert not proved_coprime(x * (y + 1), x * (z + 1))  # a monomial factor counts too


@settings(max_examples=60)
@given(st.sampled_from([ZZ, QQ]).flatmap(lambda d: st.tuples(polynomials(d), polynomials(d))))
def test_division_by_a_term_is_sympys_exact_division(pair):
    f, g = pair
    if not g:
        return
    term = g.ring({max(g.monoms()): g.LC})  # g's leading term
    assert divided_by_term(f * term, term) == (f * term).exquo(term)
