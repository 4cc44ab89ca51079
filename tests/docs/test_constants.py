"""Every public constant is documented where it is defined, with an example that runs.

The site's pages for constants (docs/_ext/constants.py) are written from ``#:`` comments; this
test reads the same comments and runs their ``>>>`` examples as doctests, so a page cannot show
an example that is wrong.
"""

from __future__ import annotations

import doctest
import sys
from pathlib import Path

import pytest

pytest.importorskip("sphinx")
sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "docs" / "_ext"))
import constants  # noqa: E402

CONSTANTS = [(package, name) for package, names in constants.constants().items() for name in names]


def test_the_constants_are_found():
    """The finder sees data and only data: the paper's lambda is one, a function is not."""
    found = {f"{package}.{name}" for package, name in CONSTANTS}
    assert {"contactsym.lam", "contactsym.mechanism.files.SCHEMA", "contactsym.stages.REGION_NAMES"} <= found
    assert "contactsym.scene" not in found and "contactsym.algebra.polynomial_adjugate" not in found


@pytest.mark.parametrize(("package", "name"), CONSTANTS, ids=[f"{p}.{n}" for p, n in CONSTANTS])
def test_every_public_constant_has_a_comment_with_an_example_that_runs(package, name):
    found = constants.comment(package, name)
    assert found, f"{package}.{name} has no '#:' comment where it is defined"
    home, text = found
    assert ">>>" in text, f"the comment of {package}.{name} in {home} has no example"
    test = doctest.DocTestParser().get_doctest(text, {}, f"{package}.{name}", home, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    assert runner.failures == 0, f"the example of {package}.{name} in {home} fails"


def test_a_constant_page_shows_its_comment():
    text = constants.page("contactsym", "lam")
    assert ".. py:data:: lam" in text and ">>> lam**2 - 1" in text and "contactsym.stages.linear" in text
