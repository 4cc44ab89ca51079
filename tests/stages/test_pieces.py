"""The roots of a piece: a closed form where f is small, a clear refusal naming the cap where it is not."""

from __future__ import annotations

import pytest
import sympy as sp

import contactsym.stages.pieces as pieces
from contactsym.errors import ContactsymError
from contactsym.stages.pieces import solve_piece


def test_a_root_solves_its_piece():
    u, a, b = sp.symbols("u a b", real=True)
    ((root,),) = solve_piece(sp.Matrix([a * u - b]), (u,), (1,))
    assert sp.simplify(a * root - b) == 0


def test_a_large_f_is_refused_with_the_cap_named_and_solved_once_the_cap_is_raised(monkeypatch):
    u = sp.Symbol("u", real=True)
    c = sp.symbols("c0:12", positive=True)
    f = sp.Matrix([sum(c) * u - sp.Mul(*c)])  # ~40 nodes
    monkeypatch.setattr(pieces, "MAX_ROOT_NODES", 20)
    with pytest.raises(ContactsymError, match="MAX_ROOT_NODES = 20"):
        solve_piece(f, (u,), (1,))
    monkeypatch.setattr(pieces, "MAX_ROOT_NODES", 1000)
    ((root,),) = solve_piece(f, (u,), (1,))
    assert sp.cancel(f[0].subs(u, root)) == 0
