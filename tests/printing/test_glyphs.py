"""Glyphs: names that print alike are one glyph, and the package's own letters are spelled apart from a scene's."""

import sympy as sp
from hypothesis import given
from hypothesis import strategies as st

from contactsym.printing import OwnLetters, look_alike, spelled_apart, tex

#: The package's own letters and the spellings a user might give them (each prints as one of them).
OWN_NAMES = [
    "lambda",
    "lambda_",
    "lamda",
    "tau",
    "t",
    "x",
    "y",
    "X",
    "Y",
    "I",
    "J",
    "A",
    "epsilon",
    "varepsilon",
    "eps",
    "u",
    "u_1",
    "u1",
    "v",
    "Phi",
    "Phi_1",
    "Phi1",
    "Psi",
    "omega",
    "H_1",
    "q_1",
    "s",
    "sigma",
    "f",
    "that",
    "lambdahat",
]
LETTERS = ["lambda", "tau", "t", "x", "y", "X", "Y", "I", "J", "A", "epsilon", "u", "v", "Phi", "Psi", "omega", "f"]


def _glyph(name: str) -> str:
    """What a reader sees: the LaTeX with empty sub- and superscripts dropped."""
    return tex(sp.Symbol(name)).replace("_{}", "").replace("^{}", "")


def test_names_that_print_alike_have_one_spelling():
    assert look_alike("lambda_") == look_alike("lamda") == look_alike("lambda") == "lambda"
    assert look_alike("Phi1") == look_alike("Phi_1") and look_alike("varepsilon") == "epsilon"
    assert look_alike("lambdahat") != "lambda" and look_alike("t") == "t"


@given(st.lists(st.sampled_from(OWN_NAMES), min_size=1, max_size=6, unique=True))
def test_look_alike_agrees_exactly_with_the_printed_glyph(names):
    for a in names:
        for b in names:
            assert (look_alike(a) == look_alike(b)) == (_glyph(a) == _glyph(b)), (a, b)


@given(st.lists(st.sampled_from(OWN_NAMES), min_size=1, max_size=8, unique=True))
def test_own_letters_never_print_as_a_scene_name(names):
    """Whatever names a scene uses, each own letter prints (LaTeX and text) unlike every one of them."""
    letters = OwnLetters(names)
    user_glyphs = {_glyph(n) for n in names}
    user_text = {look_alike(n) for n in names}
    for letter in LETTERS:
        assert letters.tex(letter) not in user_glyphs, letter
        assert look_alike(letters.text(letter)) not in user_text, letter
        if look_alike(letter) not in user_text:
            assert letters.text(letter) == letter  # nothing renamed where nothing clashes
    own = [letters.tex(letter) for letter in LETTERS]
    assert len(set(own)) == len(own)  # and no two own letters alike


def test_an_index_keeps_its_place_and_a_family_counts():
    assert spelled_apart("Phi_1", {"Phi_1"}) == "Phihat_1"
    assert tex(sp.Symbol(spelled_apart("Phi_1", {"Phi_1"}))) == r"\hat{\Phi}_{1}"
    letters = OwnLetters({"q_1", "H1"})
    assert letters.index("q", "j") == r"\hat{q}_j" and letters.indexed("H") == "Hhat"
    assert OwnLetters({"q"}).index("q", "j") == r"\hat{q}_j" and OwnLetters().index("q", "j") == "q_j"
