"""The switching functions read from m(u) at one exact point agree with the whole reaction part."""

import sympy as sp

import contactsym as cs
from contactsym.stages.fast_space import reaction_part, switching_of_factors
from contactsym.stages.pieces import switching_functions


def test_the_switching_functions_of_m_u_are_those_of_the_reaction_part():
    for name in ("painleve-rod",):
        fast = cs.scene(name).fast_subsystem()
        factors = fast.reaction_factors
        whole = switching_functions(reaction_part(*factors), fast.u)
        assert switching_of_factors(*factors, fast.u) == whole and whole, name


def test_a_friction_that_no_gap_feels_is_left_to_the_whole_reaction_part():
    u, mu = sp.symbols("u mu", real=True)
    M, W = sp.diag(2, 3), sp.Matrix([0, 1])
    loads = sp.Matrix([[0, 1], [1, 0]])  # the friction pushes along x, the gap is y: H = 0
    multipliers = [u, -mu * sp.Abs(u)]
    assert switching_of_factors(M, W, loads, multipliers, (u,)) is None
    assert switching_functions(reaction_part(M, W, loads, multipliers), (u,)) == ()
