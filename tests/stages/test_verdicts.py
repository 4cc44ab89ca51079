"""Three-valued robustness verdicts: never False for "not proved", and in agreement with the point decision.

For random numeric A (k = 2, 3) each of ``robustly_stable``, ``robustly_unstable`` and
``law_dependent`` is checked against :func:`contactsym.robustness.classify.decide` (run here
on its own) and against eigenvalues of (4.5) over sampled laws: true only where proved (and
then confirmed by eigenvalues), false only where disproved (a certificate or an exact witness
law), None otherwise.
"""

import json

import numpy as np
import pytest
import sympy as sp
from hypothesis import event, example, given, settings
from hypothesis import strategies as st
from hypothesis.control import currently_in_test_context

from contactsym.cli import derivation_chain
from contactsym.report.summary import conditions
from contactsym.robustness.classify import decide
from contactsym.stages.verdicts import NAMES, Verdict, classification_verdicts
from tests.stages.test_stability import (
    as_float,
    general_matrices,
    law_search_k2,
    sampled_laws,
    spd_matrices,
    spectra,
    symbolic,
    user_scene,
    values_for,
)

#: What each verdict of decide() proves.
PROVES = {"stable": "robustly_stable", "unstable": "robustly_unstable", "law-dependent": "law_dependent"}

#: 3 x 3 matrices met by a random search, one per kind of evidence (seeded: tests/stages/test_verdicts.py history).
PS_UNSTABLE = [[2, -3, -1], [-3, 0, 3], [-3, -1, -1]]  # Positivstellensatz certificate of instability
DAMPED_UNSTABLE = [[-3, -2, -3], [0, 3, 2], [2, 2, -1]]  # damped Positivstellensatz certificate
LAW_DEPENDENT = [[-1, 3, -1], [-2, 2, -2], [-1, 1, 0]]  # two exact witness laws
UNDECIDED = [[3, -2, 0], [-2, -3, 2], [-3, -2, 0]]  # an unstable law, no certificate either way


def small_integer_matrices(k):
    """Integer entries in -3..3: many law-dependent and some undecided points for k = 3."""
    return st.lists(st.integers(-3, 3), min_size=k * k, max_size=k * k).map(lambda xs: sp.Matrix(k, k, xs))


def law_arrays(law):
    return np.array([[-float(x) for x in law.Phi]]), np.array([[-float(x) for x in law.Psi]])


def check_verdicts(A, fresh=True):
    """Every verdict of a numeric A against decide() and eigenvalues; returns the verdicts.

    ``fresh=False`` (k >= 3) takes the scene's own point decision as the reference once the scene's A is
    checked to be exactly A: ``decide`` is the deterministic ``decide_robustness(A)`` (300 laws, seed 0)
    that :attr:`Stability.robustness` runs, so a second run only computes the same decision again."""
    A = sp.Matrix(A)
    k = A.rows
    stability = user_scene(A).stability()
    got = {name: getattr(stability, name) for name in NAMES}
    assert all(v is None or v in (sp.true, sp.false) for v in got.values()), got
    proved = [name for name, v in got.items() if v == sp.true]
    assert len(proved) <= 1, got
    assert (stability.undecided == sp.true) == (not proved)
    if k >= 3:
        assert stability.robustness is not None
        if stability.robustness.verdict != "undecided":  # the properties read what the point decision proved
            assert proved == [PROVES[stability.robustness.verdict]]
    if fresh or k < 3:
        reference = decide(A)  # a fresh decision, also for k = 2
    else:
        assert stability.A == A, (stability.A, A)
        reference = stability.robustness  # = decide(A): the same deterministic function of the same A
    # never False where a certificate or a witness says otherwise
    if reference.verdict != "undecided":
        assert got[PROVES[reference.verdict]] == sp.true, (reference.summary(), got)
        assert all(got[name] == sp.false for name in NAMES if name != PROVES[reference.verdict])
    if reference.stable_law is not None:
        assert got["robustly_unstable"] == sp.false
    if reference.unstable_law is not None:
        assert got["robustly_stable"] == sp.false
    # never False without evidence (k >= 3: the point decision is the evidence; k = 2: Proposition 6)
    if k >= 3:
        evidence = {
            "robustly_stable": reference.verdict in ("unstable", "law-dependent") or reference.unstable_law is not None,
            "robustly_unstable": reference.verdict in ("stable", "law-dependent") or reference.stable_law is not None,
            "law_dependent": reference.verdict in ("stable", "unstable"),
        }
        for name, value in got.items():
            assert value != sp.false or evidence[name], f"{name} is False without evidence: {reference.summary()}"
            assert value is not None or reference.verdict == "undecided"
    # where True, eigenvalues of (4.5) over sampled laws agree
    P, S = law_search_k2(A) if k == 2 else sampled_laws(k, seed=0)
    top, _, tol = spectra(as_float(A), P, S)
    if got["robustly_stable"] == sp.true:
        assert (top < tol).all(), "a sampled law is unstable"
    if got["robustly_unstable"] == sp.true:
        assert (top > -tol).all(), "a sampled law is stable"
    if got["law_dependent"] == sp.true:
        if reference.verdict == "law-dependent":
            top_stable = spectra(as_float(A), *law_arrays(reference.stable_law))[0][0]
            top_unstable = spectra(as_float(A), *law_arrays(reference.unstable_law))[0][0]
            assert top_stable < 0 < top_unstable
        else:
            assert (top < -tol).any() and (top > tol).any(), "no stable and unstable law among the samples"
    if currently_in_test_context():
        event(next((name for name in proved), "undecided"))
    return got


@settings(max_examples=100)
@given(general_matrices(2))
def test_k2_verdicts_agree_with_the_point_decision_and_eigenvalues(A):
    if A.det() == 0:  # the propositions need det A != 0; p_0 = 0 for every law
        return
    check_verdicts(A)


@settings(max_examples=40)
@given(st.one_of(general_matrices(3), spd_matrices(3), small_integer_matrices(3)))
@example(sp.Matrix(PS_UNSTABLE))
@example(sp.Matrix(DAMPED_UNSTABLE))
@example(sp.Matrix(LAW_DEPENDENT))
@example(sp.Matrix(UNDECIDED))
def test_k3_verdicts_agree_with_the_point_decision_and_eigenvalues(A):
    if A.det() == 0:
        return
    check_verdicts(A, fresh=False)  # test_the_issue_examples runs decide() afresh on the four examples


@pytest.mark.parametrize(
    "A, expected",
    [
        (PS_UNSTABLE, (sp.false, sp.true, sp.false)),  # was robustly_unstable = False
        (DAMPED_UNSTABLE, (sp.false, sp.true, sp.false)),
        (LAW_DEPENDENT, (sp.false, sp.false, sp.true)),  # was law_dependent = False
        (UNDECIDED, (sp.false, None, None)),  # was robustly_unstable = False and law_dependent = False
    ],
)
def test_the_issue_examples(A, expected):
    assert tuple(check_verdicts(A).values()) == expected


def test_undecided_prints_as_undecided():
    scene = user_scene(sp.Matrix(UNDECIDED))
    chain = derivation_chain(scene)
    assert "unstable where undecided" in chain and "law-dependent where undecided" in chain
    assert "stable where   False" in chain
    data = json.loads(json.dumps(conditions(scene)))
    assert data["regions"]["unstable for every law"]["sympy"] == "undecided"
    assert data["regions"]["law-dependent"]["sympy"] == "undecided"
    assert data["regions"]["stable for every law"]["sympy"] == "False"
    assert data["robustness"]["verdict"] == "undecided"
    assert data["regions"]["undecided"]["sympy"] == "True"  # the report's section 7 lists it too
    assert scene.regions()["undecided"].condition == sp.true
    rows = {f.key: f for f in scene.stability().formulas()}
    assert "undecided" in rows["law-dependent"].rhs


def test_symbolic_k3_names_its_undecided_region():
    A, stability = symbolic(3)
    assert stability.undecided not in (sp.true, sp.false)
    keys = [f.key for f in stability.formulas()]
    assert "undecided" in keys
    scene = user_scene(A)
    regions = scene.regions()
    assert "undecided" in regions and "undecided" in conditions(scene)["regions"]
    assert "undecided where" in derivation_chain(scene)
    # at a point of the undecided region no statement is proved, and none is False without a reason
    values = values_for(3, sp.Matrix(UNDECIDED))
    assert stability.undecided.xreplace(values) == sp.true
    at = {name: stability.verdicts[name].at(values) for name in NAMES}
    assert at == {"robustly_stable": sp.false, "robustly_unstable": None, "law_dependent": None}


def test_k1_k2_statements_are_decided_off_det_zero_and_disproved_by_det_zero():
    a = sp.Symbol("a", real=True)
    verdicts = classification_verdicts(
        1, {"robustly_stable": a > 0, "robustly_unstable": a < 0, "law_dependent": sp.false}
    )
    assert [verdicts[n].at({a: 2}) for n in NAMES] == [sp.true, sp.false, sp.false]
    assert [verdicts[n].at({a: -2}) for n in NAMES] == [sp.false, sp.true, sp.false]
    assert [verdicts[n].at({a: 0}) for n in NAMES] == [sp.false, None, sp.false]  # p_0 = 0 for every law


def test_a_verdict_both_proved_and_disproved_is_an_error():
    from contactsym.errors import ContactsymError

    with pytest.raises(ContactsymError, match="both proved and disproved"):
        Verdict(sp.true, sp.true).at()
