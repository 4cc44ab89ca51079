"""The report's text never shows one glyph for two things: a scene whose parameters take the package's own
names (lambda, tau, t, x, I, J, eps, ...) reads as the same scene with neutral names.

The check does not know how the package avoids a clash. It compares two reports of one scene: with the
drawn names, and with each drawn name replaced by a neutral one (zqa, zqb, ...). A glyph of a drawn name
must then occur in the first report's mathematics exactly as often as its neutral stand-in occurs in the
second: every occurrence is the user's symbol, none is the package's own letter.
"""

import re

import sympy as sp
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st

from contactsym.mechanism.files import read_scene
from contactsym.printing import look_alike, tex
from contactsym.report import conditions
from contactsym.report.document import report_tex

#: The package's own letters in the report and the spellings a user gives them.
OWN_NAMES = ["lambda", "lambda_", "tau", "t", "x", "y", "X", "Y", "I", "J", "A", "epsilon", "varepsilon"]
OWN_NAMES += ["u", "v", "Phi", "Psi", "N", "q", "a", "b", "f", "H_1", "p_1", "p_0", "omega"]
NEUTRAL = ["zqa", "zqb", "zqc", "zqd"]


def block(names, reaction="R") -> str:
    """A block on a frictionless contact: mass the product of the parameters, pressed by their sum."""
    params = "\n".join(f'{n} = "positive"' for n in names)
    return (
        f'[scene]\nname = "names"\ndescription = "a block"\ncoordinates = ["xi", "eta"]\n[parameters]\n{params}\n'
        f'[points]\nP = ["xi", "eta"]\n[[masses]]\npoint = "P"\nmass = "{"*".join(names)}"\n'
        f'[[loads]]\npoint = "P"\nforce = ["0", "-({" + ".join(names)})"]\n'
        f'[[contacts]]\ngap = "eta"\nreaction = "{reaction}"\n'
    )


_ACCENT = re.compile(r"\\(hat|check|tilde|breve)\{(\\?[A-Za-z]+)\}")
_WORDS = re.compile(r"\\(text|texttt|operatorname|mathrm|paragraph|section\*|subsection\*|tag\*)\{[^{}]*\}")
_MATH = re.compile(r"\$(.+?)\$|\\begin\{(equation|align\*|aligned)\}(.+?)\\end\{\2\}", re.S)


def mathematics(latex: str) -> str:
    """The mathematics of a LaTeX text, accents and words inside it taken out (a glyph under a hat is another)."""
    parts = [m.group(1) or m.group(3) for m in _MATH.finditer(latex)]
    text = " ".join(parts).replace("_{}", "")
    return _WORDS.sub(" ", _ACCENT.sub(r" ACCENT\1 ", text))


def count(glyph: str, math: str) -> int:
    """Occurrences of a glyph (``t``, ``\\lambda``, ``H_{1}``) as a whole symbol: no letter around it, no index."""
    return len(re.findall(r"(?<![\\A-Za-z])" + re.escape(glyph) + r"(?![A-Za-z_^])", math))


def glyph(name: str) -> str:
    return tex(sp.Symbol(name)).replace("_{}", "")


distinct = st.lists(st.sampled_from(OWN_NAMES), min_size=1, max_size=3, unique_by=look_alike)


@settings(max_examples=8, suppress_health_check=[HealthCheck.too_slow])
@given(distinct)
@example(["lambda_", "t", "I"])  # the probe's belt
@example(["p_1", "x", "J"])
def test_no_glyph_of_the_report_stands_for_two_things(names):
    drawn = read_scene(block(names), "drawn.toml")
    neutral = read_scene(block(NEUTRAL[: len(names)]), "neutral.toml")
    for text_of in (report_tex, lambda s: "$" + "$ $".join(e["latex"] for e in conditions(s)["hurwitz"]) + "$"):
        mine, theirs = mathematics(text_of(drawn)), mathematics(text_of(neutral))
        for name, stand_in in zip(names, NEUTRAL):
            assert count(glyph(name), mine) == count(stand_in, theirs) > 0, (name, names)


def test_the_probe_names_print_apart():
    """The issue's belt: lambda_, t, u, I and N are the user's; the package's lambda, t, u, I print with hats."""
    s = read_scene(block(["lambda_", "t", "I"]), "belt.toml")
    latex = report_tex(s)
    assert r"\det(\hat{\lambda} \hat{I} - J)" in latex and r"\tau = \hat{t}/\varepsilon" in latex
    assert r"\hat{t}' = \varepsilon" in latex  # the slow time, not the load t
    assert r"\det(\lambda I - J)" not in latex and r"\tau = t/" not in latex
    assert str(s.linearization().charpoly.gen) == "lambdahat"
