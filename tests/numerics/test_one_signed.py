"""One-signed forms: the same sum, cheaper, every sum with terms of one sign."""

from __future__ import annotations

import sympy as sp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from contactsym.numerics.one_signed import _one_signed_form, _one_signed_sums

a, b, c = sp.symbols("a b c", positive=True)
p, q = sp.symbols("p q", negative=True)

monomials = st.tuples(
    st.integers(1, 5), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2), st.integers(0, 2)
)


def _polynomial(terms) -> sp.Expr:
    return sp.Add(*[k * a**i * b**j * c**l * p**r * q**s for k, i, j, l, r, s in terms])


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(monomials, min_size=1, max_size=8), st.sampled_from([1, -1]))
def test_one_signed_form_is_the_same_sum_with_one_signed_sums(terms, sign):
    total = sign * sp.expand(_polynomial(terms) ** 2)  # mixed signs inside, one sign in all
    one_signed = sp.Add(*[t for t in sp.Add.make_args(total) if (sign * t).is_nonnegative])
    form = _one_signed_form(one_signed)
    assert sp.expand(form - one_signed) == 0
    assert _one_signed_sums(form)
    assert sp.count_ops(form) <= sp.count_ops(one_signed)


def test_shared_sums_are_pulled_out_once():
    total = a * p + b * p + c**2 * a * p + c**2 * b * p
    form = _one_signed_form(-total)
    assert sp.expand(form + total) == 0
    assert sp.count_ops(form) < sp.count_ops(total)
