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
