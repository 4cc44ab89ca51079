"""Each stage is built from the one before: Linearization(fast, signs), Stability(lin), Equilibria(fast).

The fast subsystem carries what the later stages need; once it is derived, the scene may be
gone. A tripwire in place of the scene shows that no later stage asks it.
"""

import copy

import pytest
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.errors import SceneError
from contactsym.printing.latex_output import formulas
from contactsym.stages.equilibria import Equilibria
from contactsym.stages.linear import Linearization
from contactsym.stages.stability import Stability, stability_of

#: What a FastSubsystem derives from its scene and then carries.
CARRIED = (
    "k",
    "u",
    "v",
    "f",
    "Phi",
    "Psi",
    "switching",
    "_depends_on_u",
    "constant_laws",
    "compliances",
    "unilateral",
    "fixed_signs",
    "positive",
    "presentation",
    "paper_equations",
    "name",
    "parameters",
)


class Tripwire:
    """Stands for the scene after the fast subsystem is derived: any question to it fails."""

    def __getattr__(self, name):
        raise AssertionError(f"a later stage asked the scene for {name!r}")


def detached_fast(scene):
    """A copy of the scene's fast subsystem with everything it carries, and a tripwire for its scene."""
    fast = scene.fast_subsystem()
    for name in CARRIED:
        getattr(fast, name)
    alone = copy.copy(fast)  # the cached values come along in __dict__
    vars(alone).pop("_later_stages", None)  # but not the stages built from the original
    object.__setattr__(alone, "scene", Tripwire())
    return alone


def test_the_tripwire_trips():
    fast = detached_fast(cs.scene("sliding-point"))
    with pytest.raises(AssertionError, match="asked the scene for 'contacts'"):
        fast.scene.contacts  # noqa: B018


@pytest.mark.parametrize("name", ["sliding-point", "painleve-rod", "brake"])
def test_stages_after_the_fast_subsystem_never_ask_the_scene(name):
    scene = cs.scene(name)
    fast = detached_fast(scene)
    lin = Linearization(fast)
    st = Stability(lin)
    assert lin.A == scene.linearization().A
    assert lin.charpoly == scene.linearization().charpoly
    assert st.hurwitz == scene.stability().hurwitz
    assert (st.robustly_stable, st.robustly_unstable) == (
        scene.stability().robustly_stable,
        scene.stability().robustly_unstable,
    )
    assert formulas(lin) == formulas(scene.linearization())  # the paper's numbers travel with the fast subsystem
    assert formulas(st, present=True) == formulas(scene.stability(), present=True)
    eq = Equilibria(fast)
    assert eq.branches == scene.equilibria().branches
    assert eq.lift_offs == scene.equilibria().lift_offs
    assert [eq.stable(b) for b in eq.branches] == [scene.equilibria().stable(b) for b in eq.branches]
    if fast.k == 1:  # Proposition 4 enumerates the sign patterns from the fast subsystem
        assert st.unique_for_every_load == scene.stability().unique_for_every_load


def test_a_pattern_of_the_scene_is_a_stage_of_its_own():
    guides = cs.scene("painleve-klein-guides")
    fast = detached_fast(guides)
    for signs in fast.sign_patterns():
        lin = Linearization(fast, signs)
        assert lin.sign_values == signs
        assert lin.det_A == guides.linearization(signs).det_A
    s1, s2 = Linearization(fast).sign_values  # open patterns: one sign symbol per switching function
    assert {s1, s2} == set(guides.linearization().A.free_symbols & {s1, s2})


def test_the_scene_shares_its_stages_with_equilibria():
    """Equilibria is built from the fast subsystem alone, and takes each pattern's Stability from the
    fast subsystem's own stages, which the scene shares: nothing is derived twice."""
    rod = cs.scene("painleve-rod")
    eq = rod.equilibria()
    assert set(vars(eq)) <= {"fast", "signs", "patterns", "branches", "lift_offs"}  # no callback from the scene
    (pattern,) = rod.sign_patterns()
    assert eq._stability(pattern) is rod.stability(pattern) is stability_of(rod.fast_subsystem(), pattern)
    assert rod.stability(pattern).linearization is rod.linearization(pattern)
    assert sp.And(*[sp.Gt(h, 0) for h in rod.stability(pattern).hurwitz]) == eq.stable(eq.branches[0])


def _point(**options):
    x, y = dynamicsymbols("x y")
    N, mu, X, Y = sp.symbols("N mu X Y", real=True)
    contact = cs.Contact(coordinate=y, reaction=N)
    return cs.Scene.from_accelerations([x, y], [X - mu * sp.Abs(N), N + Y], [contact], **options)


def test_a_scene_carries_its_own_paper_numbers_to_every_stage():
    """Numbers travel with the scene, not with its name: any scene may cite its source."""
    own = _point(equations={"A": (("7.1",), "my paper"), "fast": (("7.0",), "")})
    assert formulas(own.linearization())[0].paper == ("3.2", "7.1")
    assert formulas(own.linearization())[0].note == "my paper"
    cited = {(row.key, row.cite()) for row in formulas(own.fast_subsystem())}
    assert cited == {("fast", "(3.1), (7.0)"), ("f", "(3.1)")}
    assert formulas(_point().linearization())[0].paper == ("3.2",)
    brake = cs.scene("brake")
    assert brake.equations is brake.fast_subsystem().paper_equations
    assert brake.equations == cs.scenes.paper_knowledge(brake, "EQUATIONS")


@pytest.mark.parametrize(
    "equations", [{"A": "7.1"}, {"A": ("7.1", "")}, {"A": ((7.1,), "")}, {1: (("7.1",), "")}, {"A": (("7.1",),)}]
)
def test_malformed_paper_numbers_are_refused(equations):
    with pytest.raises(SceneError, match="must be"):
        _point(equations=equations)
