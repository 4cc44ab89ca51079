r"""The report's derivation chain, sections 1-6: equations of motion (1.4) to the Routh--Hurwitz conditions (4.7).

Each section displays a stage's formulas as the stage derives them; what a section does not
show is not derived for it (the regularization's fast part Y: its limit is Section 3).
:mod:`~contactsym.report.document` puts them in the document after the title.

Examples
--------
>>> import contactsym as cs
>>> from contactsym.report.typesetting import _Named
>>> parts = _chain(cs.scene("sliding-point"), _Named())
>>> parts[0].splitlines()[0], any(r"\tag*{(3.1), (1.12)}" in part for part in parts)
('\\section*{1. Equations of motion}', True)
"""

from __future__ import annotations

import sympy as sp

from ..errors import ContactsymError
from ..mechanism.equation_numbers import paper_equations
from ..printing.latex_output import Formula, formulas, tex
from ..stages.stability import generic_minors, hurwitz_names, robustness_formulas
from .plain_text import _escape
from .summary import conditions
from .typesetting import WIDTH, _display, _Named, _tidy, width

__all__: list[str] = []


def _section(title: str, intro: str = "") -> str:
    return f"\\section*{{{title}}}\n" + (intro + "\n" if intro else "")


def _chain(scene, named: _Named) -> list[str]:
    parts = []
    parts.append(
        _section(
            "1. Equations of motion",
            r"The accelerations (1.4), friction written out, as the scene states them.",
        )
    )
    parts += [_display(f, named) for f in formulas(scene)]

    reg = scene.regularized()
    parts.append(
        _section(
            r"2. Regularization (1.6)--(1.9)",
            r"New fast variables $u_j = N_j$, $v_j = \dot q_j/\varepsilon$ and the stretched time "
            r"$\tau = t/\varepsilon$ give $x' = \varepsilon X(x, y, \varepsilon)$, $y' = Y(x, y, \varepsilon)$ "
            r"with the slow variables $x = (" + ", ".join(tex(x) for x in reg.x) + r")$; "
            r"the slow part is below, and $Y(x, y, 0)$ is the fast subsystem of Section 3.",
        )
    )
    parts += [_display(f, named) for f in reg.slow_formulas()]  # Y is not shown: not derived here

    fast = scene.fast_subsystem()
    laws = []
    for j in range(fast.k):
        for letter, value in (("Phi", fast.Phi[j]), ("Psi", fast.Psi[j])):
            symbol = sp.Symbol(f"{letter}{_index(fast, j)}")
            if not (isinstance(value, sp.Symbol) and value.name == symbol.name):
                laws.append(f"${tex(symbol)} = {tex(value)}$")
    law = (
        "here " + ", ".join(laws) if laws else r"here negative symbols: the results hold for every admissible law (1.5)"
    )
    parts.append(
        _section(
            "3. Fast subsystem (2.1)",
            r"The associated system in the stretched time, the slow state frozen on the contact manifold; "
            r"$\Phi_j = \lim \varepsilon^2 \partial N_j/\partial q_j$, "
            r"$\Psi_j = \lim \varepsilon \partial N_j/\partial \dot q_j$ (" + law + ").",
        )
    )
    parts += [_display(f, named) for f in formulas(fast)]

    parts.append(_equilibria_section(scene, named))
    parts.append(_linearization_section(scene, named))
    parts.append(_hurwitz_section(scene, named))
    return parts


def _index(fast, j: int) -> str:
    return "" if fast.k == 1 else f"_{j + 1}"


def _equilibria_section(scene, named: _Named) -> str:
    fast = scene.fast_subsystem()
    text = [_section("4. Equilibria (4.2)")]
    if fast.switching:
        sigmas = ", ".join(f"$\\sigma_{{{i}}} = {tex(s)}$" for i, s in enumerate(fast.switching, 1))
        text.append(
            r"$f$ is smooth on each sign pattern $s$ of the switching functions " + sigmas + r"; the root "
            r"$u^*$ of a piece is an equilibrium where $s_i\,\sigma_i(u^*) > 0$ for every $i$ "
            r"(the conditions in full are in \texttt{conditions.json})."
        )
    try:
        branches = scene.equilibria().branches
    except ContactsymError as error:
        return "\n".join(text) + "\n" + _escape(f"No closed-form equilibria: {error}")
    for branch in branches:
        if branch.signs:
            signs = ", ".join("+" if s == 1 else "-" for s in branch.signs)
            text.append(f"\\paragraph{{Sign pattern $s = ({signs})$.}}")
        rows = [f for f in formulas(branch) if f.key == "equilibrium"]
        for row in rows:
            numbers, note = paper_equations(scene, "equilibrium")
            text.append(_display(Formula(row.key, row.lhs, row.rhs, "=", numbers, ""), named))
    return "\n".join(text)


def _linearization_section(scene, named: _Named) -> str:
    lin = scene.linearization()
    k = lin.A.rows
    text = [
        _section(
            "5. Linearization (4.3)--(4.6)",
            r"At an equilibrium $(u^*, 0)$ the Jacobian of the fast subsystem is "
            r"$J = \begin{pmatrix} \Psi A & \Phi \\ A & 0 \end{pmatrix}$ (4.5) with "
            r"$\Phi = \operatorname{diag}(\Phi_j)$, $\Psi = \operatorname{diag}(\Psi_j)$, for every compliance law. "
            + (
                r"The signs $s_i = \pm 1$ stand for the sign pattern. "
                if any(s.name.startswith("s") for s in lin.A.free_symbols if s.is_integer)
                else ""
            )
            + ("Presented in the paper's variables." if scene.presentation else ""),
        )
    ]
    show = scene.present if scene.presentation else (lambda e: e)
    A = show(lin.A)
    numbers, note = paper_equations(scene, "A")
    if width(tex(A)) <= WIDTH:
        text.append(_display(Formula("A", "A", A, "=", numbers, note), named))
    else:
        for i in range(k):
            for j in range(k):
                entry = Formula("A", f"a_{{{i + 1}{j + 1}}}", A[i, j], "=", numbers, note)
                text.append(_display(entry, named))
    numbers, note = paper_equations(scene, "det A")
    text.append(_display(Formula("det A", r"\det A", sp.factor(show(lin.det_A)), "=", numbers, note), named))
    n = lin.charpoly.degree()
    p = " + ".join(
        f"p_{{{s}}} \\lambda^{{{s}}}" if s > 1 else ("p_{1} \\lambda" if s == 1 else "p_{0}") for s in range(n, -1, -1)
    )
    numbers, _ = paper_equations(scene, "charpoly")
    text.append(_display(Formula("charpoly", r"\det(\lambda I - J)", p, "=", numbers, ""), named))
    coefficients = lin.charpoly.all_coeffs()
    for s, c in zip(range(n, -1, -1), coefficients):
        numbers, _ = paper_equations(scene, "coefficient")
        text.append(_display(Formula("coefficient", f"p_{{{s}}}", _tidy(show(c)), "=", numbers, ""), named))
    return "\n".join(text)


def _hurwitz_section(scene, named: _Named) -> str:
    st = scene.stability()
    names = hurwitz_names(st)
    n = st.linearization.charpoly.degree()
    generic = generic_minors(n)
    always = {entry["name"]: entry["always"] for entry in conditions(scene)["hurwitz"] if "always" in entry}
    needed = [name for name in names if name not in always]
    intro = r"Li\'enard--Chipart form: all roots of (4.6) have negative real parts " + (
        f"exactly when ${', '.join(needed)} > 0$" if needed else "always"
    )
    intro += r" (coefficients that are positive numbers are left out"
    intro += "".join(f"; ${name} > 0$ always: {_escape(reason)}" for name, reason in always.items()) + ")."
    text = [_section("6. Routh--Hurwitz conditions (4.7)", intro)]
    show = scene.present if scene.presentation else (lambda e: e)
    numbers, _ = paper_equations(scene, "hurwitz")
    for name, condition in zip(names, st.hurwitz):
        if not name.startswith(r"\Delta"):
            continue
        m = int(name[len(r"\Delta_{") : -1])
        text.append(_display(Formula("hurwitz", name, generic[m], "=", numbers, ""), named))
        expanded = _tidy(show(condition))
        text.append(_display(Formula("hurwitz", name, expanded, "=", (), ""), named))
    if st.hopf_frequency is not None:
        text.append(
            r"On the Hopf set $\Delta_{" + str(n - 1) + r"} = 0$ the roots $\pm i\omega$ have "
            r"$\omega^2$ the common root of the real and imaginary parts of $p(i\omega)$:"
        )
        numbers, note = paper_equations(scene, "hopf frequency")
        omega2 = _tidy(show(st.routh_hurwitz.omega_squared))
        text.append(_display(Formula("hopf frequency", r"\omega^{2}", omega2, "=", numbers, note), named))
    text += [_display(formula, named) for formula in robustness_formulas(st.robustness)]
    return "\n".join(text)
