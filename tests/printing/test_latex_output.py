"""LaTeX of every stage object and region: exact strings for small scenes, paper citations."""

import re

import pytest
import sympy as sp
from sympy.physics.mechanics import dynamicsymbols

import contactsym as cs
from contactsym.mechanism.scene import paper_equations
from contactsym.printing.latex_output import Formula, formulas, latex
from contactsym.stages.stability import hurwitz_names


@pytest.fixture(scope="module")
def point():
    """The README's scene: a point on a rough line, generic compliance (k = 1)."""
    x, y = dynamicsymbols("x y")
    N, mu, X, Y = sp.symbols("N mu X Y", real=True)
    return cs.Scene.from_accelerations([x, y], [X - mu * sp.Abs(N), N + Y], [cs.Contact(coordinate=y, reaction=N)])


@pytest.fixture(scope="module")
def pair():
    """Two coupled bilateral contacts with a constant coupling c (k = 2, one sign pattern)."""
    q1, q2 = dynamicsymbols("q_1 q_2")
    N1, N2, c, Y1, Y2 = sp.symbols("N_1 N_2 c Y_1 Y_2", real=True)
    contacts = [cs.Contact(coordinate=q1, reaction=N1), cs.Contact(coordinate=q2, reaction=N2)]
    return cs.Scene.from_accelerations([q1, q2], [N1 + c * N2 + Y1, N2 + Y2], contacts)


def test_scene_is_its_accelerations_1_4(point):
    assert latex(point) == r"\begin{aligned} \ddot{x} &= X - \mu \left|{N}\right| \\ \ddot{y} &= N + Y \end{aligned}"
    assert latex(point, tags=True) == (
        r"\begin{aligned} \ddot{x} &= X - \mu \left|{N}\right| && \text{(1.4)} \\ "
        r"\ddot{y} &= N + Y && \text{(1.4)} \end{aligned}"
    )


def test_fast_subsystem_in_the_form_3_1(point):
    assert latex(point.fast_subsystem(), tags=True) == (
        r"\begin{aligned} u' &= \Phi v + \Psi f{\left(u \right)} && \text{(3.1)} \\ "
        r"v' &= f{\left(u \right)} && \text{(3.1)} \\ "
        r"f{\left(u \right)} &= Y + u && \text{(3.1)} \end{aligned}"
    )


def test_fast_subsystem_of_two_contacts_cites_4_1(pair):
    rows = formulas(pair.fast_subsystem())
    assert [row.body for row in rows] == [
        r"u_{1}' = \Phi_{1} v_{1} + \Psi_{1} f_{1}{\left(u_{1},u_{2} \right)}",
        r"v_{1}' = f_{1}{\left(u_{1},u_{2} \right)}",
        r"u_{2}' = \Phi_{2} v_{2} + \Psi_{2} f_{2}{\left(u_{1},u_{2} \right)}",
        r"v_{2}' = f_{2}{\left(u_{1},u_{2} \right)}",
        r"f_{1}{\left(u_{1},u_{2} \right)} = Y_{1} + c u_{2} + u_{1}",
        r"f_{2}{\left(u_{1},u_{2} \right)} = Y_{2} + u_{2}",
    ]
    assert {row.cite() for row in rows} == {"(4.1)"}


def test_equilibria_branch_and_reduced_system_are_latex_not_repr(point):
    assert latex(point.equilibria()) == r"\begin{aligned} u^{*} &= - Y \end{aligned}"
    assert (
        latex(point.equilibria().branches[0], tags=True)
        == r"\begin{aligned} u^{*} &= - Y && \text{(3.2)} \end{aligned}"
    )
    assert latex(point.reduced_system(), tags=True) == (
        r"\begin{aligned} N &= - Y && \text{(2.2)} \\ \ddot{x} &= X - \mu \left|{Y}\right| && \text{(2.2)} \end{aligned}"
    )


def test_branch_with_signs_states_where_it_exists():
    x, y = dynamicsymbols("x y")
    N, mu, Y = sp.symbols("N mu Y", real=True)
    rod = cs.Scene.from_accelerations([x, y], [0, N + mu * sp.Abs(N) + Y], [cs.Contact(coordinate=y, reaction=N)])
    branch = rod.equilibria(signs=(1,)).branches[0]
    assert latex(branch) == (
        r"\begin{aligned} u^{*} &= - \frac{Y}{\mu + 1} \\ "
        r"& \text{where } s = \left(+\right):\ - \frac{Y}{\mu + 1} > 0 \end{aligned}"
    )


def test_linearization_of_two_contacts_cites_4_3_4_5_4_6(pair):
    lin = pair.linearization()
    rows = formulas(lin)
    assert [(row.key, row.cite()) for row in rows] == [
        ("A", "(4.3)"),
        ("det A", ""),
        ("matrix", "(4.5)"),
        ("charpoly", "(4.6)"),
    ]
    assert rows[0].body == r"A = \left[\begin{matrix}1 & c\\0 & 1\end{matrix}\right]"
    assert rows[2].body == (
        r"J = \left[\begin{matrix}\Psi_{1} & \Psi_{1} c & \Phi_{1} & 0\\0 & \Psi_{2} & 0 & \Phi_{2}"
        r"\\1 & c & 0 & 0\\0 & 1 & 0 & 0\end{matrix}\right]"
    )


def test_stability_names_the_conditions_of_4_7(pair):
    st = pair.stability()
    assert hurwitz_names(st) == ["p_{3}", "p_{2}", "p_{1}", "p_{0}", r"\Delta_{3}"]
    rows = formulas(st)
    delta = next(row for row in rows if row.lhs == r"\Delta_{3}")
    assert delta.body == r"\Delta_{3} = - p_{0} p_{3}^{2} - p_{1}^{2} p_{4} + p_{1} p_{2} p_{3}"
    assert delta.cite() == "(4.7)"
    summary = next(row for row in rows if row.relation == ">")
    assert summary.body == r"p_{3}, p_{2}, p_{1}, p_{0}, \Delta_{3} > 0"
    stable = next(row for row in rows if row.key == "stable for every law")
    assert (stable.cite(), stable.note) == ("(4.4)", "Proposition 6")


def test_k1_stability_cites_proposition_3(point):
    assert latex(point.stability(), tags=True) == (
        r"\begin{aligned} p_{1} &= - \Psi \\ p_{0} &= - \Phi \\ p_{1}, p_{0} &> 0 && \text{(3.2)} \\ "
        r"\text{stable for every law} &: \ \text{True} && \text{(3.2)} \\ "
        r"\text{unstable for every law} &: \ \text{False} && \text{(3.2)} \\ "
        r"\text{law-dependent} &: \ \text{False} \\ \text{Hopf line} &: \ \text{False} \end{aligned}"
    )


def test_regularized_is_1_9(point):
    assert latex(point.regularized()) == (
        r"\begin{aligned} t' &= \varepsilon \\ x' &= \varepsilon \dot{x} \\ "
        r"\dot{x}' &= \varepsilon \left(X - \mu \left|{u}\right|\right) \\ "
        r"u' &= \Phi v + \Psi \left(Y + u\right) \\ v' &= Y + u \end{aligned}"
    )


def test_region_prints_its_condition():
    x, y = sp.symbols("x y", real=True)
    region = cs.regions.Region(sp.And(x > 0, x + y < 2), name="r")
    assert latex(region) == r"x > 0 \wedge x + y < 2"
    assert region._repr_latex_() == r"$x > 0 \wedge x + y < 2$"


def test_brake_regions_and_paper_numbers():
    brake = cs.scene("brake")
    assert latex(brake.regions()["stable for every law"]) == r"\mu \leq \left|{\cot{\left(\alpha \right)}}\right|"
    numbers, note = paper_equations(brake, "stable for every law")
    assert numbers == ("4.4", "6.3") and "erratum 12" in note
    assert paper_equations(brake, "A")[0] == ("4.3", "6.2")
    assert paper_equations(cs.scene("painleve-klein-guides"), "det A")[0] == ("5.5",)
    assert paper_equations(cs.scene("painleve-klein-rod"), "fast")[0] == ("3.1",)


def test_fast_subsystem_number_depends_on_k(point, pair):
    assert paper_equations(point, "fast")[0] == ("3.1",)
    assert paper_equations(pair, "fast")[0] == ("4.1",)

    class Three:
        k, name = 3, "user"

    assert paper_equations(Three(), "fast")[0] == ("2.1",)


def test_every_stage_object_and_region_has_repr_latex_with_citations():
    s = cs.scene("brake")
    objects = [
        s,
        s.regularized(),
        s.fast_subsystem(),
        s.equilibria(),
        s.equilibria().branches[0],
        s.linearization(),
        s.stability(),
        s.reduced_system(),
    ]
    for obj in objects:
        shown = obj._repr_latex_()
        assert shown.startswith(r"$\displaystyle \begin{aligned}") and shown.endswith(r"\end{aligned}$"), type(obj)
        assert r"\text{(" in shown, type(obj)  # each cites the paper
        assert "object at 0x" not in shown and "Branch(" not in shown
    for region in s.regions().values():
        assert region._repr_latex_().startswith("$")


def test_formula_tag_and_unknown_objects():
    assert Formula("x", "x", sp.Integer(1)).tag() == r"\notag"
    assert Formula("x", "x", sp.Integer(1), paper=("4.3", "5.4")).tag() == r"\tag*{(4.3), (5.4)}"
    assert latex(sp.Symbol("alpha") ** 2) == r"\alpha^{2}"
    with pytest.raises(TypeError, match="no formulas for int"):
        formulas(3)


def test_present_uses_the_papers_variables():
    guides = cs.scene("painleve-klein-guides")
    det = next(row for row in formulas(guides.linearization(), present=True) if row.key == "det A")
    assert det.rhs == sp.sympify(det.rhs)  # a SymPy expression
    assert {s.name for s in det.rhs.free_symbols} == {"kappa", "v_1", "v_2"}


@pytest.mark.parametrize("name", ["painleve-klein-rod", "painleve-klein-guides"])
def test_latex_uses_the_papers_letters(name):
    """The paper writes varepsilon and varphi; SymPy's default is epsilon and phi."""
    scene = cs.scene(name)
    text = latex(scene.regularized()) + latex(scene.stability())
    assert r"\varphi" in text or r"\varepsilon" in text
    assert not re.search(r"\\(epsilon|phi)(?![A-Za-z])", text)
    assert r"\Phi" in latex(scene.stability())  # capital Phi is the law's stiffness, unchanged
