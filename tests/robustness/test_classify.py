"""Robustness to the contact law for any k: every claim of decide_robustness() against eigenvalues of (4.5).

Each point is checked over 10^4 sampled laws (log-uniform |Phi_j|, |Psi_j| in 1e-3..1e3, in
batches of numpy eigenvalues); each witness law is re-checked by a second derivation of the
Liénard–Chipart signs (``linear.charpoly`` and ``hurwitz.Hurwitz`` in SymPy) and by eigenvalues.
"""

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from hypothesis import event, example, given, settings
from hypothesis import strategies as st
from hypothesis.control import currently_in_test_context
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.algebra.hurwitz import Hurwitz
from contactsym.errors import ContactsymError
from contactsym.robustness.certificates import (
    amgm_certificate,
    damped_positivstellensatz_certificate,
    positivstellensatz_certificate,
    vertex_laws,
)
from contactsym.robustness.classify import decide_robustness, nested_sequences, regions
from contactsym.robustness.law_polynomials import LawPolynomials, fast_spectral_abscissa, law_ring
from contactsym.stages.linear import charpoly
from tests.stool import h, mu, stool_scene

LAWS = 10_000


def sampled_abscissae(A, count=LAWS, seed=0):
    rng = np.random.default_rng(seed)
    k = A.rows
    c = 10.0 ** rng.uniform(-3, 3, (count, k))
    d = 10.0 ** rng.uniform(-3, 3, (count, k))
    Af = np.array(A.tolist(), dtype=float)
    top = fast_spectral_abscissa(Af, c, d)
    scale = np.abs(Af).sum() * (c.max(axis=1) + d.max(axis=1))
    return top, 1e-9 * np.maximum(1.0, scale)


def hurwitz_signs_by_sympy(A, law) -> bool:
    """Stable at the law, by the pipeline's own charpoly and Liénard–Chipart conditions."""
    conditions = Hurwitz(charpoly(A, law.Phi, law.Psi)).conditions
    return all(sp.sympify(c) > 0 for c in conditions)


def eigen_abscissa(A, law) -> float:
    c = np.array([-float(x) for x in law.Phi])
    d = np.array([-float(x) for x in law.Psi])
    return float(fast_spectral_abscissa(np.array(A.tolist(), dtype=float), c[None], d[None])[0])


def check_claims(A, seed=0):
    """decide_robustness(A) is not contradicted by 10^4 laws, and its witnesses are right."""
    result = decide_robustness(A)
    if currently_in_test_context():
        event(result.verdict)  # the undecided fraction shows in --hypothesis-show-statistics
    top, tol = sampled_abscissae(A, seed=seed)
    if result.verdict == "stable":
        assert (top < tol).all(), "a sampled law is unstable"
    if result.verdict == "unstable":
        assert (top > -tol).all(), "a sampled law is stable"
    for law, stable in ((result.stable_law, True), (result.unstable_law, False)):
        if law is not None:
            assert law.stable == stable
            assert all(x < 0 for x in law.Phi + law.Psi)
            assert hurwitz_signs_by_sympy(A, law) == stable
            assert (eigen_abscissa(A, law) < 0) == stable
    if result.verdict == "law-dependent":
        assert result.stable_law is not None and result.unstable_law is not None
    if result.verdict in ("stable", "unstable"):
        assert result.certificate is not None and result.certificate.verdict == result.verdict
    return result


def uniform_matrices(k):
    entry = st.integers(-200, 200).map(lambda n: sp.Rational(n, 100))
    return st.lists(entry, min_size=k * k, max_size=k * k).map(lambda xs: sp.Matrix(k, k, xs))


@settings(max_examples=20, deadline=None)
@given(uniform_matrices(3), st.integers(0, 2**16))
@example(sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]]), 0)
def test_random_3x3_claims_hold_over_sampled_laws(A, seed):
    check_claims(A, seed)


@settings(max_examples=3, deadline=None)
@given(uniform_matrices(4), st.integers(0, 2**16))
def test_random_4x4_claims_hold_over_sampled_laws(A, seed):
    check_claims(A, seed)


# --- the stool (k = 3, derived by the pipeline) -------------------------------------------

_stool = stool_scene()


@settings(max_examples=8, deadline=None)
@given(
    st.sampled_from([(1, 1, 1), (1, -1, 1), (-1, 1, 1), (1, 1, -1)]),
    st.integers(0, 200).map(lambda n: sp.Rational(n, 100)),
    st.integers(20, 300).map(lambda n: sp.Rational(n, 100)),
)
def test_stool_claims_hold_over_sampled_laws(signs, mu_value, h_value):
    A = _stool.linearization(signs=signs).A.xreplace({mu: mu_value, h: h_value})
    assert A.shape == (3, 3) and not A.free_symbols
    check_claims(A)


def test_stool_without_friction_is_stable_for_every_law():
    """mu = 0: A = W^T M^-1 W is symmetric positive definite (Proposition 7)."""
    A = _stool.linearization(signs=(1, 1, 1)).A.xreplace({mu: 0, h: 1})
    result = check_claims(A)
    assert result.verdict == "stable"


def test_stool_regions_claim_no_more_than_is_proved():
    """The symbolic stool's regions (field notes, k = 3): every point lies in exactly one of the named
    regions, "undecided" included; where a statement's region holds, the point decision at the numeric A
    (checked against 10^4 laws, its witnesses by eigenvalues) says the same. At mu = 0.05, h = 1, where
    3,000 sampled laws were all stable, the region says undecided and the point decision finds two exact
    witness laws: law-dependent (the unstable law has Phi_1/Phi_2 ~ 10^-10, which sampling misses)."""
    regions = _stool.regions((1, 1, 1))
    names = ("stable for every law", "unstable for every law", "law-dependent", "undecided")
    assert set(names) <= set(regions)
    verdicts = {
        "stable for every law": "stable",
        "unstable for every law": "unstable",
        "law-dependent": "law-dependent",
    }
    A = _stool.linearization(signs=(1, 1, 1)).A
    for mu_value, h_value in ((sp.Rational(1, 20), 1), (1, 2), (sp.Rational(3, 2), sp.Rational(1, 2))):
        point = {mu: mu_value, h: h_value}
        inside = [name for name in names if regions[name].condition.xreplace(point) == sp.true]
        assert len(inside) == 1, (point, inside)
        result = check_claims(A.xreplace(point))
        assert verdicts.get(inside[0], result.verdict) == result.verdict
        if mu_value == sp.Rational(1, 20):
            assert inside == ["undecided"] and result.verdict == "law-dependent"


# --- k = 2: Proposition 6 exactly ----------------------------------------------------------


def _symbolic_k2():
    q = dynamicsymbols("q_1:3")
    N = sp.symbols("N_1:3", real=True)
    a = sp.Matrix(2, 2, lambda i, j: sp.Symbol(f"a_{i + 1}{j + 1}", real=True))
    G = [a[j, 0] * N[0] + a[j, 1] * N[1] for j in range(2)]
    contacts = [cs.Contact(coordinate=q[j], reaction=N[j]) for j in range(2)]
    return a, cs.Scene.from_accelerations(q, G, contacts).stability()


_a2, _stability2 = _symbolic_k2()
small = st.sampled_from([0, 1, -1, 2, -2, sp.Rational(1, 2), -sp.Rational(1, 3), 3, sp.Rational(5, 2)])


@settings(max_examples=100, deadline=None)
@given(st.lists(small, min_size=4, max_size=4).map(lambda xs: sp.Matrix(2, 2, xs)))
@example(sp.Matrix([[1, 0], [5, 1]]))  # a_12 a_21 = 0: the AM-GM certificate holds with equality
@example(sp.Matrix([[1, 1], [-1, 1]]))  # the brake at alpha = 90 deg
@example(sp.Matrix([[2, 1], [1, 0]]))  # a_22 = 0: Delta_3's vertex gives the unstable law
def test_k2_reproduces_proposition_6(A):
    values = {_a2[i, j]: A[i, j] for i in range(2) for j in range(2)}
    flags = {
        "stable": _stability2.robustly_stable,
        "unstable": _stability2.robustly_unstable,
        "law-dependent": _stability2.law_dependent,
    }
    expected = [name for name, flag in flags.items() if flag.xreplace(values) == sp.true]
    result = decide_robustness(A)
    if A.det() == 0:  # a zero eigenvalue for every law; Proposition 6 needs det A != 0
        assert result.verdict == "unstable" and set(expected) <= {"unstable"}
    else:
        assert [result.verdict] == expected
        for law, stable in ((result.stable_law, True), (result.unstable_law, False)):
            if law is not None:
                assert hurwitz_signs_by_sympy(A, law) == stable


@settings(max_examples=100, deadline=None)
@given(st.lists(small, min_size=4, max_size=4).map(lambda xs: sp.Matrix(2, 2, xs)))
@example(sp.Matrix([[1, 0], [5, 1]]))
@example(sp.Matrix([[2, 1], [-1, 0]]))
def test_k2_necessary_region_with_vertices_is_proposition_6(A):
    values = {_a2[i, j]: A[i, j] for i in range(2) for j in range(2)}
    needs = regions(A, vertices=True)["stable for every law needs"]
    assert needs in (sp.true, sp.false)
    if A.det() != 0:
        assert needs == _stability2.robustly_stable.xreplace(values)


# --- closed-form regions ---------------------------------------------------------------------


@settings(max_examples=15, deadline=None)
@given(uniform_matrices(3))
def test_closed_form_regions_agree_with_the_point_decision_and_eigenvalues(A):
    symbols = sp.Matrix(3, 3, lambda i, j: sp.Symbol(f"x_{i}{j}", real=True))
    closed = {name: r.xreplace(dict(zip(symbols, A))) for name, r in regions(symbols).items()}
    assert closed == {name: r for name, r in regions(A).items()}  # substitution commutes
    result = decide_robustness(A)
    top, tol = sampled_abscissae(A, count=2000)
    if closed["unstable for every law"] == sp.true:
        assert result.verdict == "unstable" and (top > -tol).all()
    if closed["stable law exists"] == sp.true:
        assert result.stable_law is not None
    if closed["unstable law exists"] == sp.true:
        assert result.verdict != "stable"
    if regions(A, vertices=True)["stable for every law needs"] == sp.false:  # a Newton vertex is negative
        assert result.verdict != "stable"
    if result.verdict == "stable":
        assert regions(A, vertices=True)["stable for every law needs"] == sp.true
    if closed["law-dependent"] == sp.true:
        assert result.verdict == "law-dependent"


# --- the certificates one by one -------------------------------------------------------------


def test_amgm_is_exact_at_equality_and_fails_beyond():
    R, (c1, c2, d1, d2) = law_ring(2)
    assert amgm_certificate(c1**2 + c2**2) == "coefficients"
    assert amgm_certificate(c1**2 - 2 * c1 * c2 + c2**2) == "amgm"  # (c1 - c2)^2: equality
    assert amgm_certificate(c1**2 - 2 * c1 * c2 + c2**2 - R(Fraction(1, 10**40)) * c1 * c2) is None
    assert amgm_certificate(-c1) is None


def test_vertex_laws_make_their_condition_negative():
    lp = LawPolynomials(sp.Matrix([[1, 2, 0], [1, 1, 0], [0, 0, 1]]))  # m_12 = -1 < 0
    laws = vertex_laws(lp, lp.conditions())
    assert laws
    for c, d in laws:
        assert min(lp.values_at(c, d)) < 0


def test_positivstellensatz_certificate_is_exact():
    A = sp.Matrix([[13, -17, -13], [-11, -13, 12], [15, 3, -19]]) / 10  # det A > 0, no nested sequence
    lp = LawPolynomials(A)
    assert lp.minors[(0, 1, 2)] > 0 and not nested_sequences(lp.minors)
    p = [g for (kind, _), g in zip(lp.labels, lp.conditions()) if kind == "p"]
    assert all(any(v > 0 for v in g.values()) for g in p)  # no single p_s is a certificate
    assert positivstellensatz_certificate(lp, p) is not None
    result = check_claims(A)
    assert result.verdict == "unstable" and result.certificate.kind == "Positivstellensatz"


def test_damped_positivstellensatz_certificate_where_the_plain_one_fails():
    """(P8): a_22 > 0 is the only positive diagonal entry; on the laws with p_5 > 0 some other p_s is <= 0."""
    A = sp.Matrix([[-176, 53, 149], [-65, 55, -114], [-136, -200, -1]]) / 100
    lp = LawPolynomials(A)
    assert lp.minors[(0, 1, 2)] > 0 and not nested_sequences(lp.minors)
    p = [g for (kind, _), g in zip(lp.labels, lp.conditions()) if kind == "p"]
    assert positivstellensatz_certificate(lp, p) is None
    assert damped_positivstellensatz_certificate(lp, p[1:]) is not None
    result = check_claims(A)
    assert result.verdict == "unstable" and result.certificate.kind == "damped Positivstellensatz"
    # independently: sampled laws with p_5 > 0 have some p_s <= 0, s < 5 (floats, from the minors)
    rng = np.random.default_rng(1)
    law = 10.0 ** rng.uniform(-3, 3, (LAWS, 6))
    values = np.array([sum(float(v) * np.prod(law**e, axis=1) for e, v in lp.p[s].items()) for s in range(6)]).T
    assert (values[:, 5] > 0).any()
    assert (values[values[:, 5] > 0, :5].min(axis=1) <= 1e-12 * np.abs(values).max()).all()


def test_a_stable_law_without_a_nested_sequence():
    """P6's converse is false: no nested sequence of positive principal minors, yet a stable law."""
    A = sp.Matrix([[1605, -411, 698], [1762, -478, -1444], [-1948, 559, -922]]) / 1000
    lp = LawPolynomials(A)
    assert lp.minors[(0, 1, 2)] > 0 and not nested_sequences(lp.minors)
    assert not regions(A)["stable law exists"]
    Phi = (-sp.Rational(9940, 50), -sp.Rational(2839, 1000), -sp.Rational(3529, 10000))
    Psi = (-sp.Rational(1164, 25), -sp.Rational(1277, 50), -sp.Rational(9211, 1000))
    assert all(sp.sympify(c) > 0 for c in Hurwitz(charpoly(A, Phi, Psi)).conditions)
    assert check_claims(A).verdict == "law-dependent"


def test_decide_rejects_symbolic_and_bad_matrices():
    with pytest.raises(ContactsymError, match="numeric A"):
        decide_robustness(sp.Matrix([[sp.Symbol("a")]]))
    with pytest.raises(ContactsymError, match="square"):
        decide_robustness(sp.Matrix([[1, 2]]))
    with pytest.raises(ContactsymError, match="finite"):
        decide_robustness(np.array([[np.nan]]))


def test_report_and_latex_show_the_point_decision():
    from contactsym.printing.latex_output import latex
    from contactsym.report import conditions

    q = dynamicsymbols("q_1:4")
    N = sp.symbols("N_1:4", real=True)
    A = sp.Matrix([[2, 1, 0], [-1, 2, 1], [0, -1, 2]])
    G = [sum(A[j, i] * N[i] for i in range(3)) for j in range(3)]
    scene = cs.Scene.from_accelerations(q, G, [cs.Contact(coordinate=q[j], reaction=N[j]) for j in range(3)])
    data = conditions(scene)["robustness"]
    assert data["verdict"] == "law-dependent"
    for name, stable in (("stable", True), ("unstable", False)):
        law = data["witness_laws"][name]
        Phi, Psi = [sp.Rational(x) for x in law["Phi"]], [sp.Rational(x) for x in law["Psi"]]
        assert all(sp.sympify(c) > 0 for c in Hurwitz(charpoly(A, Phi, Psi)).conditions) == stable
    text = latex(scene.stability())
    assert r"\text{robustness}" in text and r"(\Phi, \Psi)_{\text{unstable}}" in text


@settings(max_examples=30, deadline=None)
@given(st.lists(st.integers(-3, 3), min_size=9, max_size=9), st.integers(0, 8))
def test_regions_from_given_minors_are_the_regions_from_A(entries, symbolic):
    """regions(A, minors=...) (a scene passes its factored minors) says what regions(A) says, with the
    minors computed independently here by SymPy's determinant."""
    import itertools

    from contactsym.robustness.closed_form import regions

    a = sp.Symbol("a", real=True)
    A = sp.Matrix(3, 3, [a if i == symbolic else e for i, e in enumerate(entries)])
    minors = {
        S: sp.expand(A.extract(list(S), list(S)).det())
        for r in range(1, 4)
        for S in itertools.combinations(range(3), r)
    }
    given_minors, derived = regions(A, minors=minors), regions(A)
    assert given_minors.keys() == derived.keys()
    for name in derived:  # the same conditions (both forms of each minor are expanded polynomials in a)
        for value in (-2, sp.Rational(-1, 3), 0, sp.Rational(1, 2), 3):
            assert bool(given_minors[name].subs(a, value)) == bool(derived[name].subs(a, value))
    with pytest.raises(cs.ArgumentError, match="principal minor"):
        regions(A, minors={(0,): A[0, 0]})
