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
from ..printing.glyphs import spelled_apart
from ..printing.latex_output import Formula, formulas, tex
from ..stages.stability import generic_minors, hurwitz_letters, hurwitz_names, robustness_formulas
from .plain_text import _escape, own_letters
from .summary import conditions
from .typesetting import WIDTH, _display, _Named, _tidy, width

__all__: list[str] = []


def _section(title: str, intro: str = "") -> str:
    return f"\\section*{{{title}}}\n" + (intro + "\n" if intro else "")


def _chain(scene, named: _Named) -> list[str]:
    letters = own_letters(scene)
    parts = []
    parts.append(
        _section(
            "1. Equations of motion",
            r"The accelerations (1.4), friction written out, as the scene states them.",
        )
    )
    parts += [_display(f, named) for f in formulas(scene)]

    reg = scene.regularized()
    fast = scene.fast_subsystem()
    eps, q = tex(scene.eps), letters.index("q", "j")
    dq = r"\dot q_j" if q == "q_j" else r"\dot{" + q[: -len("_j")] + "}_j"  # as before where q is free
    N = own_letters(scene, reactions=False).index("N", "j")
    x, X, y, Y = (letters.tex(letter) for letter in ("x", "X", "y", "Y"))
    parts.append(
        _section(
            r"2. Regularization (1.6)--(1.9)",
            f"New fast variables ${_generic(fast.u)} = {N}$, ${_generic(fast.v)} = {dq}/{eps}$ and the stretched "
            f"time ${tex(reg.tau)} = {letters.tex('t')}/{eps}$ give ${x}' = {eps} {X}({x}, {y}, {eps})$, "
            f"${y}' = {Y}({x}, {y}, {eps})$ with the slow variables ${x} = ("
            + ", ".join(tex(v) for v in reg.x)
            + f")$; the slow part is below, and ${Y}({x}, {y}, 0)$ is the fast subsystem of Section 3.",
        )
    )
    parts += [_display(f, named) for f in reg.slow_formulas()]  # Y is not shown: not derived here

    laws = []
    for j in range(fast.k):
        for letter, value in (("Phi", fast.Phi[j]), ("Psi", fast.Psi[j])):
            symbol = sp.Symbol(spelled_apart(f"{letter}{_index(fast, j)}", letters.taken))  # as the stage's
            if not (isinstance(value, sp.Symbol) and value.name == symbol.name):
                laws.append(f"${tex(symbol)} = {tex(value)}$")
    law = (
        "here " + ", ".join(laws) if laws else r"here negative symbols: the results hold for every admissible law (1.5)"
    )
    parts.append(
        _section(
            "3. Fast subsystem (2.1)",
            r"The associated system in the stretched time, the slow state frozen on the contact manifold; "
            f"${_letter(fast.Phi, 'Phi', letters)} = \\lim {eps}^2 \\partial {N}/\\partial {q}$, "
            f"${_letter(fast.Psi, 'Psi', letters)} = \\lim {eps} \\partial {N}/\\partial {dq}$ (" + law + ").",
        )
    )
    parts += [_display(f, named) for f in formulas(fast)]

    parts.append(_equilibria_section(scene, named))
    parts.append(_linearization_section(scene, named))
    parts.append(_hurwitz_section(scene, named))
    return parts


def _index(fast, j: int) -> str:
    return "" if fast.k == 1 else f"_{j + 1}"


def _letter(values, letter: str, letters) -> str:
    """LaTeX of Phi_j (Psi_j): as the generic law's symbols print, else the letter apart from the scene's names."""
    return _generic(values) if all(isinstance(v, sp.Symbol) for v in values) else letters.index(letter, "j")


def _generic(symbols, fallback: str = "N_j") -> str:
    """LaTeX of the j-th of ``symbols`` (u_1, u_2 -> u_j; uhat_1 -> \\hat{u}_j; a single R -> R_j)."""
    bases = {sp.Symbol(s.name.partition("_")[0]) for s in symbols}
    return tex(bases.pop()) + "_j" if len(bases) == 1 else fallback


def _equilibria_section(scene, named: _Named) -> str:
    fast = scene.fast_subsystem()
    letters = own_letters(scene)
    text = [_section("4. Equilibria (4.2)")]
    if fast.switching:
        sigma, s, u = letters.tex("sigma"), letters.tex("s"), tex(sp.Symbol(fast.u[0].name.partition("_")[0]))
        sigmas = ", ".join(f"${sigma}_{{{i}}} = {tex(e)}$" for i, e in enumerate(fast.switching, 1))
        text.append(
            f"${letters.tex('f')}$ is smooth on each sign pattern ${s}$ of the switching functions {sigmas}; the "
            f"root ${u}^*$ of a piece is an equilibrium where ${s}_i\\,{sigma}_i({u}^*) > 0$ for every $i$ "
            r"(the conditions in full are in \texttt{conditions.json})."
        )
    pushes = [u for u, one_sided in zip(fast.u, fast.unilateral) if one_sided and u not in fast.switching]
    if pushes:  # no switching function fixes their sign: the existence condition says u_j* > 0
        names = ", ".join(f"${tex(u)}^*$" for u in pushes)
        text.append(f"A one-sided contact only pushes: the root is an equilibrium where {names} $> 0$.")
    try:
        branches = scene.equilibria().branches
    except ContactsymError as error:
        return "\n".join(text) + "\n" + _escape(f"No closed-form equilibria: {error}")
    for branch in branches:
        if branch.signs:
            signs = ", ".join("+" if s == 1 else "-" for s in branch.signs)
            text.append(f"\\paragraph{{Sign pattern ${letters.tex('s')} = ({signs})$.}}")
        rows = [f for f in formulas(branch) if f.key == "equilibrium"]
        for u, row in zip(fast.u, rows):  # u* as the fast subsystem's u prints (uhat beside a user's u)
            numbers, note = paper_equations(scene, "equilibrium")
            text.append(_display(Formula(row.key, tex(u) + "^{*}", row.rhs, "=", numbers, ""), named))
        if pushes and branch.condition == sp.false:
            text.append("It exists nowhere where the scene is declared: its existence condition is False.")
        elif pushes and branch.condition != sp.true:
            text.append("It exists where")
            text.append(_display(Formula("existence", "", branch.condition, "", (), ""), named))
    return "\n".join(text)


def _linearization_section(scene, named: _Named) -> str:
    lin = scene.linearization()
    fast = lin.fast
    k = lin.A.rows
    letters = own_letters(scene)
    J, I, A, Phi, Psi = (letters.tex(letter) for letter in ("J", "I", "A", "Phi", "Psi"))
    u, lam = tex(sp.Symbol(fast.u[0].name.partition("_")[0])), tex(lin.variable)
    text = [
        _section(
            "5. Linearization (4.3)--(4.6)",
            f"At an equilibrium $({u}^*, 0)$ the Jacobian of the fast subsystem is "
            f"${J} = \\begin{{pmatrix}} {Psi} {A} & {Phi} \\\\ {A} & 0 \\end{{pmatrix}}$ (4.5) with "
            f"${Phi} = \\operatorname{{diag}}({_letter(fast.Phi, 'Phi', letters)})$, "
            f"${Psi} = \\operatorname{{diag}}({_letter(fast.Psi, 'Psi', letters)})$, for every compliance law. "
            + (
                f"The signs ${letters.tex('s')}_i = \\pm 1$ stand for the sign pattern. "
                if any(s.name.startswith("s") for s in lin.A.free_symbols if s.is_integer)
                else ""
            )
            + ("Presented in the paper's variables." if scene.presentation else ""),
        )
    ]
    show = scene.present if scene.presentation else (lambda e: e)
    matrix = show(lin.A)
    numbers, note = paper_equations(scene, "A")
    if width(tex(matrix)) <= WIDTH:
        text.append(_display(Formula("A", A, matrix, "=", numbers, note), named))
    else:
        for i in range(k):
            for j in range(k):
                entry = Formula("A", f"{letters.tex('a')}_{{{i + 1}{j + 1}}}", matrix[i, j], "=", numbers, note)
                text.append(_display(entry, named))
    numbers, note = paper_equations(scene, "det A")
    text.append(_display(Formula("det A", r"\det " + A, sp.factor(show(lin.det_A)), "=", numbers, note), named))
    n = lin.charpoly.degree()
    P = tex(sp.Symbol(hurwitz_letters(scene.stability())["p"]))  # phat beside a scene's own p_1
    p = " + ".join(
        f"{P}_{{{s}}} {lam}^{{{s}}}" if s > 1 else (f"{P}_{{1}} {lam}" if s == 1 else f"{P}_{{0}}")
        for s in range(n, -1, -1)
    )
    numbers, _ = paper_equations(scene, "charpoly")
    text.append(_display(Formula("charpoly", f"\\det({lam} {I} - {J})", p, "=", numbers, ""), named))
    coefficients = lin.charpoly.all_coeffs()
    for s, c in zip(range(n, -1, -1), coefficients):
        numbers, _ = paper_equations(scene, "coefficient")
        text.append(_display(Formula("coefficient", f"{P}_{{{s}}}", _tidy(show(c)), "=", numbers, ""), named))
    return "\n".join(text)


def _hurwitz_section(scene, named: _Named) -> str:
    st = scene.stability()
    names, letters = hurwitz_names(st), hurwitz_letters(st)
    n = st.linearization.charpoly.degree()
    generic = generic_minors(n, letters["p"])
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
    for name, (kind, m), condition in zip(names, st.routh_hurwitz.labels, st.hurwitz):
        if kind != "Delta":
            continue
        text.append(_display(Formula("hurwitz", name, generic[m], "=", numbers, ""), named))
        expanded = _tidy(show(condition))
        text.append(_display(Formula("hurwitz", name, expanded, "=", (), ""), named))
    if st.hopf_frequency is not None:
        omega = own_letters(scene).tex("omega")
        text.append(
            f"On the Hopf set ${tex(sp.Symbol(letters['Delta']))}_{{{n - 1}}} = 0$ the roots $\\pm i{omega}$ have "
            f"${omega}^2$ the common root of the real and imaginary parts of $p(i{omega})$:"
        )
        numbers, note = paper_equations(scene, "hopf frequency")
        omega2 = _tidy(show(st.routh_hurwitz.omega_squared))
        text.append(_display(Formula("hopf frequency", omega + "^{2}", omega2, "=", numbers, note), named))
    text += [_display(formula, named) for formula in robustness_formulas(st.robustness)]
    return "\n".join(text)
