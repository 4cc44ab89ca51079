"""The conditions as data: JSON that round-trips, its plain-text summary, and counts that cannot be derived."""

import json

import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.report import conditions, report_tex, summary_text


def test_conditions_are_json_and_summarised():
    data = conditions(cs.scene("brake"))
    assert json.loads(json.dumps(data)) == data
    text = summary_text(data)
    assert text.splitlines()[0].startswith("brake: ")
    assert "stable for every law: mu <= Abs(cot(alpha))   (4.4), (6.3)" in text


def test_counts_that_cannot_be_derived_are_a_note_not_an_error():
    x, y = dynamicsymbols("x y")
    N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    # f(u) = u^3 + u - 1 is not piecewise linear: the counts of equilibria have no closed form here
    cubic = cs.Scene.from_accelerations([x, y], [-mu * sp.Abs(N), N**3 + N - 1], [cs.Contact(y, N)], name="cubic")
    data = conditions(cubic)
    assert data["equilibrium_counts"] is None
    assert data["equilibrium_counts_note"].startswith("No equilibrium counts for this scene: f' = 3*u**2 + 1")
    assert r"\paragraph{Number of equilibria.} No equilibrium counts for this scene" in report_tex(cubic)


def test_an_error_while_deriving_the_conditions_is_short_and_says_what_to_do():
    from contactsym.errors import SignPatternError
    from contactsym.report.summary import _located

    scene = cs.scene("brake")
    long_expression = " + ".join(f"m*sin(q{i})**2" for i in range(400))  # a wall of text, as issue 26 met
    error = _located(SignPatternError(f"the sign of {long_expression} does not follow"), scene)
    assert isinstance(error, SignPatternError)  # the class (and so the command line's exit code) is kept
    text = str(error)
    assert len(text) < 700 and "scene 'brake'" in text and "characters)" in text
    assert "[intervals]" in text and "[parameters]" in text


def test_the_regions_say_the_domain_they_are_stated_in():
    """The spatial rod's printed regions divide by sin(theta) cos(beta) cos(theta), positive only in its
    declared domain: the JSON, the summary and the report state that domain, from the scene's own
    declarations; a scene that declares none states none."""
    rod = cs.scene("painleve-rod-3d")
    data = conditions(rod)
    stated = [sp.sympify(entry["sympy"], locals={str(s): s for s in rod.parameters}) for entry in data["domain"]]
    assert stated == [sp.Gt(e, 0) for e in rod.declared_positive]
    assert all(e.is_positive is None for e in rod.declared_positive)  # real declarations, not SymPy facts
    assert "in the domain sin(beta) > 0" in summary_text(data)
    assert "stated in the scene's domain" in report_tex(rod)
    assert "domain" not in conditions(cs.scene("sliding-point"))
