r"""A standalone LaTeX report per scene: derivation chain, regions, figures, errata.

:func:`report_tex` writes the document; :func:`write_report` writes a scene's
directory (``report.tex``, ``report.pdf`` when pdflatex is present, ``figures/*.png``,
``conditions.json``); :func:`conditions` is the JSON-ready summary of the conditions.

The document uses only packages of Debian's texlive-latex-base (amsmath, amssymb,
graphicx, geometry, longtable, array). Long expressions are broken across lines at
their sums; one that would still take more than a few lines is named (``H_1``) and its
size given, with the full form in ``conditions.json``.

Examples
--------
>>> import contactsym as cs
>>> tex = report_tex(cs.scene("sliding-point"))
>>> tex.startswith(r"\documentclass")
True
>>> r"\tag*{(3.1), (1.12)}" in tex
True
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from .errata import AGREE, latex_table, text_to_latex
from .errors import ContactsymError
from .latex import Formula, tex
from .scene import paper_equations
from .scenes import paper_name
from .stability import hurwitz_names, robustness_formulas

__all__ = [
    "Figure",
    "ReportError",
    "ReportResult",
    "compile_pdf",
    "conditions",
    "report_tex",
    "summary_text",
    "write_report",
]

#: Visible width (in characters of math) of one displayed line, and the most lines one formula may take.
WIDTH = 78
MAX_LINES = 6


class ReportError(ContactsymError):
    """The report could not be written or compiled."""


@dataclass(frozen=True)
class Figure:
    """A PNG for the report: its path and caption (LaTeX)."""

    path: Path
    caption: str


@dataclass
class ReportResult:
    """What :func:`write_report` wrote."""

    scene: str
    directory: Path
    tex: Path
    conditions: Path
    pdf: Path | None = None
    figures: list = field(default_factory=list)
    notes: list = field(default_factory=list)


# --- widths and line breaking ---------------------------------------------------------

_FUNCTION_WIDTH = {"sin": 3, "cos": 3, "tan": 3, "cot": 3, "det": 3, "log": 3, "exp": 3, "sqrt": 1.5}
_ZERO_WIDTH = {"left", "right", "displaystyle", "limits", "begin", "end", "big", "Big", "bigg", "Bigg"}


def _group(tex: str, i: int) -> tuple[str, int]:
    """The brace group starting at tex[i] == '{' (or one character), and the index after it."""
    if i >= len(tex):
        return "", i
    if tex[i] != "{":
        if tex[i] == "\\":
            match = re.match(r"\\[A-Za-z]+", tex[i:])
            if match:
                return match.group(), i + len(match.group())
        return tex[i], i + 1
    depth = 0
    for j in range(i, len(tex)):
        depth += {"{": 1, "}": -1}.get(tex[j], 0)
        if depth == 0:
            return tex[i + 1 : j], j + 1
    return tex[i + 1 :], len(tex)


def width(tex: str) -> float:
    r"""Approximate printed width of LaTeX mathematics, in characters.

    Fractions count their wider part, indices 0.7, ``\left``/``\right`` nothing.

    Examples
    --------
    >>> width(r"\frac{a + b}{c}"), width(r"x^{2} + \sin{\left(\alpha \right)}")
    (3.0, 8.7)
    """
    total, i = 0.0, 0
    while i < len(tex):
        c = tex[i]
        if c == "\\":
            match = re.match(r"\\([A-Za-z]+|.)", tex[i:])
            name = match.group(1)
            i += len(match.group())
            if name == "frac":
                numerator, i = _group(tex, i)
                denominator, i = _group(tex, i)
                total += max(width(numerator), width(denominator))
            elif name in ("text", "mathrm", "operatorname"):
                content, i = _group(tex, i)
                total += len(content)
            elif name in ("begin", "end"):
                _, i = _group(tex, i)
            elif name in _ZERO_WIDTH or name in (",", ";", "!"):
                continue
            elif name in ("quad",):
                total += 2
            elif name == " ":
                total += 0.5
            else:
                total += _FUNCTION_WIDTH.get(name, 1)
        elif c in "^_":
            content, i = _group(tex, i + 1)
            total += 0.7 * width(content)
        elif c in "{} &":
            i += 1
        else:
            total += 1
            i += 1
    return round(total, 2)


@dataclass
class _Named:
    """Long subexpressions replaced by names H_1, H_2, ... while typesetting one report."""

    items: list = field(default_factory=list)

    def name(self, expr: sp.Expr) -> sp.Symbol:
        for symbol, known in self.items:
            if known == expr:
                return symbol
        symbol = sp.Symbol(f"H_{len(self.items) + 1}")
        self.items.append((symbol, expr))
        return symbol


def _describe(expr: sp.Expr) -> str:
    """A short description of a long expression: its kind, number of terms and symbols."""
    numerator, denominator = sp.fraction(sp.together(expr))
    terms = len(sp.Add.make_args(sp.expand(numerator)))
    symbols = ", ".join(f"${tex(s)}$" for s in sorted(expr.free_symbols, key=str))
    kind = "a polynomial" if denominator == 1 else "a rational function, numerator"
    try:
        degree = sp.Poly(sp.expand(numerator), *sorted(expr.free_symbols, key=str)).total_degree()
        size = f"{terms} terms of total degree {degree}"
    except sp.PolynomialError:
        size = f"{terms} terms"
    return f"{kind} with {size} in {symbols}"


def _terms(expr: sp.Expr) -> tuple[str, list[str], str] | None:
    """(prefix, LaTeX of the terms, suffix) of a sum, a multiple of a sum, or a sum over a denominator."""
    if isinstance(expr, sp.Add):
        return "", [tex(t) for t in expr.as_ordered_terms()], ""
    numerator, denominator = sp.fraction(expr)
    if denominator != 1 and isinstance(sp.expand(numerator), sp.Add):
        prefix = r"\frac{1}{" + tex(denominator) + r"} \Big("
        return prefix, [tex(t) for t in sp.expand(numerator).as_ordered_terms()], r"\Big)"
    if isinstance(expr, sp.Mul):
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if len(sums) == 1:
            rest = sp.Mul(*[f for f in expr.args if f is not sums[0]])
            prefix = ("-" if rest == -1 else tex(rest)) + r" \Big("
            return prefix, [tex(t) for t in sums[0].as_ordered_terms()], r"\Big)"
    return None


def _fill(first: str, terms: list[str], suffix: str, budget: float) -> list[str] | None:
    """Greedy lines of ``first t1 + t2 ...``; None when they take more than MAX_LINES."""
    lines, current = [], first
    for index, term in enumerate(terms):
        joined = term if index == 0 else (f"- {term[1:].lstrip()}" if term.startswith("-") else f"+ {term}")
        piece = f" {joined}"
        if width(current + piece) > budget and width(current) > width(first) + 1:
            lines.append(current)
            current = r"\quad" + piece
        else:
            current += piece
    lines.append(current + " " + suffix if suffix else current)
    if len(lines) > MAX_LINES or any(width(line) > budget + 8 for line in lines):
        return None
    return lines


def _compact(expr, named: _Named, budget: float):
    """``expr`` with its long sums replaced by names (a product keeps its short factors)."""
    if isinstance(expr, sp.Basic) and width(tex(expr)) <= budget:
        return expr
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: _compact(e, named, budget / max(expr.cols, 1)))
    if isinstance(expr, sp.Pow) and expr.exp.is_Rational:
        return sp.Pow(_compact(expr.base, named, budget), expr.exp, evaluate=False)
    if isinstance(expr, sp.Mul):
        return sp.Mul(*[_compact(f, named, budget) for f in expr.args], evaluate=False)
    if isinstance(expr, (sp.Add, sp.Function)) or expr.is_Atom is False:
        return named.name(expr)
    return expr


def _broken(first: str, expr, last: str, budget: float) -> list[str] | None:
    """Lines of ``first expr last`` broken at the terms of ``expr``; None when that does not fit."""
    parts = _terms(expr) if isinstance(expr, sp.Expr) else None
    if parts is None:
        return None
    prefix, terms, suffix = parts
    return _fill(f"{first}{prefix}", terms, f"{suffix}{last}", budget)


def _lines(lhs: str, relation: str, expr, named: _Named) -> list[str]:
    """LaTeX lines (for ``split``) of ``lhs relation expr`` that fit the page."""
    head = f"{lhs} &{relation}" if lhs else "&"
    text = tex(expr) if not isinstance(expr, str) else expr
    if isinstance(expr, str) or width(head + " " + text) <= WIDTH:
        return [f"{head} {text}"]
    lines = _broken("", expr, "", WIDTH - width(lhs))
    if lines is not None:
        return [f"{head} {lines[0]}"] + ["& " + line for line in lines[1:]]
    compacted = _compact(expr, named, WIDTH - width(head) - 4)
    return [f"{head} {tex(compacted)}"]


def _relation_tex(relational) -> str:
    return {
        sp.StrictLessThan: "<",
        sp.LessThan: r"\le",
        sp.StrictGreaterThan: ">",
        sp.GreaterThan: r"\ge",
        sp.Equality: "=",
        sp.Unequality: r"\ne",
    }[type(relational)]


def _relational_lines(condition, named: _Named) -> list[str]:
    """A long relation broken at the sums of its longer side; its long sums named when that fails."""
    left, right = condition.lhs, condition.rhs
    relation = _relation_tex(condition)
    if width(tex(left)) >= width(tex(right)):
        lines = _broken("", left, f" {relation} {tex(right)}", WIDTH)
    else:
        lines = _broken(f"{tex(left)} {relation} ", right, "", WIDTH)
    if lines is None:
        budget = WIDTH / 2
        lines = [f"{tex(_compact(left, named, budget))} {relation} {tex(_compact(right, named, budget))}"]
    return ["& " + line for line in lines]


def _condition_lines(condition, named: _Named) -> list[str]:
    """A Boolean condition as lines, each starting with ``&``: one conjunct (or disjunct) per line when long."""
    text = tex(condition)
    if width(text) <= WIDTH:
        return [f"& {text}"]
    if isinstance(condition, sp.core.relational.Relational):
        return _relational_lines(condition, named)
    if isinstance(condition, (sp.And, sp.Or)):
        word = r"\wedge" if isinstance(condition, sp.And) else r"\vee"
        lines = []
        for index, arg in enumerate(condition.args):
            inner = _condition_lines(arg, named)
            if isinstance(arg, (sp.And, sp.Or)):
                inner[0] = inner[0].replace("& ", r"& \left(", 1)
                inner[-1] = inner[-1] + r" \right)" if len(inner) == 1 else inner[-1] + r" \Big)"
                if len(inner) > 1:
                    inner[0] = inner[0].replace(r"\left(", r"\Big(", 1)
            if index:
                inner[0] = inner[0].replace("& ", f"& {word} ", 1)
            lines += inner
        return lines
    return [f"& {tex(_compact(condition, named, WIDTH))}"]


def _equation(lines: list[str], tag: str) -> str:
    """One numbered display: ``split`` when it has several lines."""
    if len(lines) == 1:
        return "\\begin{equation}\n" + lines[0].replace("&", "", 1) + f"\n{tag}\n\\end{{equation}}"
    body = " \\\\\n".join(lines)
    return f"\\begin{{equation}}\n\\begin{{split}}\n{body}\n\\end{{split}}\n{tag}\n\\end{{equation}}"


def _display(formula: Formula, named: _Named) -> str:
    if formula.relation in ("", ":") and not formula.lhs:
        lines = _condition_lines(formula.rhs, named)
    else:
        lines = _lines(formula.lhs, formula.relation, formula.rhs, named)
    text = _equation(lines, formula.tag())
    if formula.note:
        text += "\n" + _note(formula.note)
    return text


def _note(note: str) -> str:
    return r"\noindent{\footnotesize " + _plain_to_latex(note) + r"}\par"


def _plain_to_latex(text: str) -> str:
    """Notes are ASCII plain text with names like Phi_j, Delta_3, mu: typeset them."""
    names = {"Phi": "Φ", "Psi": "Ψ", "Delta": "Δ", "alpha": "α", "phi": "φ", "mu": "μ", "eps": "ε", "deg": "°"}
    for word, symbol in names.items():
        text = re.sub(rf"\b{word}\b", symbol, text)
        text = re.sub(rf"\b{word}_", symbol + "_", text)
    text = text.replace(" °", "°")
    return text_to_latex(text)


_SPECIALS = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "#": r"\#",
    "^": r"\^{}",
    "_": r"\_",
    "%": r"\%",
    "~": r"\~{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
}


def _escape(text: str) -> str:
    """Plain text (a name, a message, a path) for LaTeX: specials escaped, other characters through text_to_latex.

    Examples
    --------
    >>> print(_escape("a_b & 50% of {x}, mu > 2, μ"))
    a\\_b \\& 50\\% of \\{x\\}, mu \\textgreater{} 2, $\\mu$
    """
    out = []
    for c in text:
        if c in _SPECIALS:
            out.append(_SPECIALS[c])
        elif ord(c) < 128:
            out.append(c)
        else:
            try:
                out.append(text_to_latex(c))
            except ValueError:
                out.append("?")
    return "".join(out)


# --- sections ---------------------------------------------------------------------------


def _section(title: str, intro: str = "") -> str:
    return f"\\section*{{{title}}}\n" + (intro + "\n" if intro else "")


def _parameters(scene) -> str:
    rows = []
    for symbol in scene.parameters:
        facts = [name for name in ("positive", "negative", "real") if getattr(symbol, f"is_{name}")]
        rows.append(f"${tex(symbol)}$" + (f" ({facts[0]})" if facts else ""))
    return "Parameters of the fast subsystem: " + ", ".join(rows) + "."


def _chain(scene, named: _Named) -> list[str]:
    from .latex import formulas

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
    parts += [_display(f, named) for f in formulas(reg) if f.lhs.rstrip("'") in {tex(x) for x in reg.x}]

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
    from .latex import formulas

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


def _tidy(expr):
    """A readable form: the common denominator pulled out, the numerator factored when that is short."""
    expr = sp.factor_terms(sp.cancel(expr))
    factored = sp.factor(expr)
    return factored if len(str(factored)) <= len(str(expr)) else expr


def _hurwitz_section(scene, named: _Named) -> str:
    from .stability import generic_minors as _generic_minors

    st = scene.stability()
    names = hurwitz_names(st)
    n = st.linearization.charpoly.degree()
    generic = _generic_minors(n)
    text = [
        _section(
            "6. Routh--Hurwitz conditions (4.7)",
            r"Li\'enard--Chipart form: all roots of (4.6) have negative real parts exactly when "
            f"${', '.join(names)} > 0$" + r" (coefficients that are positive numbers are left out).",
        )
    ]
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
        omega2 = _tidy(show(st.poly.omega_squared))
        text.append(_display(Formula("hopf frequency", r"\omega^{2}", omega2, "=", numbers, note), named))
    text += [_display(formula, named) for formula in robustness_formulas(st.robustness)]
    return "\n".join(text)


def _counts(scene) -> tuple[dict, str]:
    """Equilibrium-count regions, if this version of contactsym has them: ({name: Region}, note)."""
    method = getattr(scene, "equilibrium_counts", None)
    if method is None:
        return {}, "Equilibrium counts are not available in this version of contactsym."
    try:
        counts = method()
    except (ContactsymError, NotImplementedError) as error:
        return {}, f"No equilibrium counts for this scene: {error}"
    from .regions import Region

    if isinstance(counts, dict):
        items = counts.items()
    elif isinstance(counts, (list, tuple)):
        items = [(getattr(r, "name", "") or f"region {i}", r) for i, r in enumerate(counts, 1)]
    else:
        return {}, f"Equilibrium counts came as {type(counts).__name__}, which the report does not know."
    regions = {}
    for name, value in items:
        condition = value.condition if isinstance(value, Region) else getattr(value, "condition", value)
        regions[str(name)] = Region(sp.sympify(condition), name=str(name))
    return regions, ""


#: Paper numbers of count regions, by scene and a word in the region's name.
COUNT_EQUATIONS = {
    "painleve-klein-rod": (
        ("unique", ("3.8", "3.9")),
        ("three", ("3.9",)),
        ("cusp", ("3.9",)),
        ("none", ("3.8",)),
        ("fold", ("3.8",)),
    ),
    "painleve-klein-guides": (("unique", ("5.8",)), ("none", ("5.10",)), ("two", ("5.10",))),
}


def _count_tag(scene, name: str) -> tuple:
    for word, numbers in COUNT_EQUATIONS.get(paper_name(scene) or "", ()):
        if word in name.lower():
            return numbers
    return ()


def _regions_section(scene, named: _Named) -> str:
    text = [
        _section(
            "7. Regions in closed form",
            "Each raw condition factored, factors of known sign dropped, written in the paper's variables.",
        )
    ]
    for name, region in scene.regions().items():
        numbers, note = paper_equations(scene, name)
        text.append(f"\\paragraph{{{_escape(name.capitalize())}.}}")
        text.append(_display(Formula(name, "", region.condition, "", numbers, note), named))
    text += _special_cases(scene, named)
    counts, note = _counts(scene)
    if counts:
        text.append(r"\subsection*{Number of equilibria}")
        for name, region in counts.items():
            text.append(
                f"\\paragraph{{{_escape(name.capitalize())}.}} " + _escape(region.description.split(": ", 1)[-1])
            )
            text.append(_display(Formula(name, "", region.condition, "", _count_tag(scene, name), ""), named))
    elif note:
        text.append(r"\paragraph{Number of equilibria.} " + _escape(note))
    text += _one_sided_section(scene, named)
    return "\n".join(text)


def _one_sided_section(scene, named: _Named) -> list[str]:
    """The one-sided Painleve cases of a unilateral contact (k = 1), with lift-off."""
    if scene.k != 1 or not scene.contacts[0].unilateral:
        return []
    from .one_sided import one_sided_cases

    text = [r"\subsection*{One-sided contact: consistent, inconsistent, indeterminate}"]
    for case in one_sided_cases(scene):
        found = ", ".join(f"{kind} ({'stable' if stable else 'unstable'})" for kind, stable in case.equilibria)
        text.append(f"\\paragraph{{{_escape(case.name.capitalize())}.}} " + _escape(found or "no equilibrium"))
        text.append(_display(Formula(case.name, "", case.region.condition, "", (), ""), named))
    return text


def _special_cases(scene, named: _Named) -> list[str]:
    """The paper's special cases of a scene, derived here: the brake's (6.4) and its frequency."""
    if paper_name(scene) != "brake":  # the built-in brake itself, not a scene that shares its name
        return []
    from .regions import closed_form

    st = scene.stability()
    fast = scene.fast_subsystem()
    Phi, Psi = sp.Symbol("Phi", negative=True), sp.Symbol("Psi", negative=True)
    alpha = next(s for s in scene.parameters if s.name == "alpha")
    equal = {fast.Phi[0]: Phi, fast.Phi[1]: Phi, fast.Psi[0]: Psi, fast.Psi[1]: Psi, alpha: sp.pi / 2}
    stable = closed_form(sp.And(*[sp.Gt(h.subs(equal), 0) for h in st.hurwitz]), scene)
    line = closed_form(st.hopf.subs(equal), scene)
    text = [
        r"\paragraph{The paper's special case.} With $\Phi_j = \Phi$, $\Psi_j = \Psi$ and "
        r"$\alpha = 90^\circ$ the Hurwitz conditions reduce to",
        _display(Formula("special", "", stable, "", ("6.4",), "with the mass m: erratum 13"), named),
    ]
    if isinstance(line, sp.Equality):
        solved = sp.solve(line, Phi, dict=True)
        if len(solved) == 1:
            omega = sp.sqrt(sp.factor(st.poly.omega_squared.subs(equal).subs(solved[0])))
            text.append("and on its boundary, a Hopf bifurcation, the frequency in the stretched time is")
            text.append(_display(Formula("omega", r"\omega", sp.factor(omega), "=", (), "erratum 14"), named))
    return text


def _figures_section(figures: list[Figure], notes: list[str]) -> str:
    text = [_section("9. Figures")]
    for figure in figures:
        text.append(
            "\\begin{figure}[htbp]\n\\centering\n"
            f"\\includegraphics[width=0.85\\textwidth]{{figures/{figure.path.name}}}\n"
            f"\\caption{{{figure.caption}}}\n\\end{{figure}}"
        )
    if not figures:
        text.append("No figures for this scene.")
    for note in notes:
        text.append(r"\noindent " + _escape(note) + r"\par")
    return "\n".join(text)


def _named_section(named: _Named) -> str:
    if not named.items:
        return ""
    lines = [r"\paragraph{Long expressions.} Too long to print here; in full in \texttt{conditions.json}:"]
    lines.append(r"\begin{itemize}")
    for symbol, expr in named.items:
        lines.append(f"\\item ${tex(symbol)}$: " + _describe(expr) + ".")
    lines.append(r"\end{itemize}")
    return "\n".join(lines)


def _errata_section() -> str:
    agree = ", ".join(AGREE)
    return "\n".join(
        [
            _section("Errata of the paper"),
            r"Found by deriving each formula from the mechanics and comparing with the print; the evidence "
            r"for each entry is a test in \texttt{tests/paper/} (see \texttt{docs/errata.md}). "
            r"Derived and in agreement with the print: " + text_to_latex(agree) + ".",
            r"{\small",
            latex_table(),
            "}",
        ]
    )


_PREAMBLE = r"""\documentclass[10pt,a4paper]{article}
\usepackage[margin=2cm]{geometry}
\usepackage{amsmath,amssymb}
\usepackage{graphicx}
\usepackage{longtable,array}
\allowdisplaybreaks
\setlength{\parindent}{0pt}
\setlength{\parskip}{4pt}
"""


def report_tex(scene, figures: list[Figure] | tuple = (), notes: list[str] | tuple = ()) -> str:
    """The standalone LaTeX document of one scene.

    ``figures`` are PNGs in ``figures/`` beside the document; ``notes`` are plain-text
    remarks printed under the figures (e.g. a figure that could not be drawn).
    """
    named = _Named()
    paper = paper_name(scene) is not None  # the paper's own scene object, not one that shares its name
    title = _escape(f"contactsym: {scene.name}")
    description = _escape(scene.description) if scene.description else ""
    body = [
        _PREAMBLE,
        r"\begin{document}",
        f"\\section*{{{title}}}",
        description + r"\par" if description else "",
        r"Derived by contactsym from the mechanics. Numbers on the right, as (4.3), are the equations "
        r"of A.\,P.~Ivanov, \emph{On the properties of solutions of the basic problem of dynamics in "
        r"systems with non-ideal constraints}, PMM, 2005"
        + (
            r"; where the print differs, the derived form is shown and the errata table at the end says why."
            if paper
            else r", whose general results this scene's formulas instantiate."
        ),
        _parameters(scene),
        r"{\small",
    ]
    body += _chain(scene, named)
    body.append(_regions_section(scene, named))
    body.append(_named_section(named))
    body.append(_reduced_section(scene, named))
    body.append("}")
    body.append(_figures_section(list(figures), list(notes)))
    if paper:
        body.append(_errata_section())
    body.append(r"\end{document}")
    return "\n\n".join(part for part in body if part) + "\n"


def _reduced_section(scene, named: _Named) -> str:
    from .latex import formulas

    text = [
        _section(
            "8. Reduced system (2.2)",
            "The slow motion with the reactions of an equilibrium branch: the classical rigid-contact model.",
        )
    ]
    branches = scene.equilibria().branches
    if len(branches) != 1:
        text.append(
            _escape(
                f"The scene has {len(branches)} equilibrium branches; "
                "each has its own reduced system (Scene.reduced_system(signs=...))."
            )
        )
        return "\n".join(text)
    text += [_display(f, named) for f in formulas(scene.reduced_system()) if f.key == "reduced"]
    return "\n".join(text)


# --- conditions as data -------------------------------------------------------------------


def _entry(expr, paper=(), note="") -> dict:
    entry = {"sympy": sp.sstr(expr), "latex": tex(expr)}
    if paper:
        entry["paper"] = [f"({number})" for number in paper]
    if note:
        entry["note"] = note
    return entry


def conditions(scene, signs=None) -> dict:
    """The scene's conditions as JSON-ready data: regions, Hurwitz conditions, A, branches.

    Each expression is given as SymPy text (``sympy``) and LaTeX (``latex``), with the
    paper's equation numbers where it has them. ``signs`` selects one sign pattern.

    Examples
    --------
    >>> import contactsym as cs
    >>> data = conditions(cs.scene("brake"))
    >>> data["regions"]["stable for every law"]["sympy"], data["regions"]["stable for every law"]["paper"]
    ('mu <= Abs(cot(alpha))', ['(4.4)', '(6.3)'])
    """
    st = scene.stability(signs)
    lin = scene.linearization(signs)
    data = {
        "scene": scene.name,
        "signs": None if signs is None else list(signs),
        "description": scene.description,
        "k": scene.k,
        "parameters": [
            {"name": str(s), "assumptions": [a for a in ("positive", "negative", "real") if getattr(s, f"is_{a}")]}
            for s in scene.parameters
        ],
        "regions": {},
        "hurwitz": [],
        "A": _entry(lin.A, *paper_equations(scene, "A")),
        "det_A": _entry(lin.det_A, *paper_equations(scene, "det A")),
        "charpoly": _entry(lin.charpoly.as_expr(), *paper_equations(scene, "charpoly")),
        "hopf_frequency": None,
        "equilibria": [],
        "equilibrium_counts": None,
    }
    if scene.presentation:
        data["presentation"] = {sp.sstr(k): sp.sstr(v) for k, v in scene.presentation.items()}
    for name, region in scene.regions(signs).items():
        data["regions"][name] = _entry(region.condition, *paper_equations(scene, name))
    for name, condition in zip(hurwitz_names(st), st.hurwitz):
        key = "coefficient" if name.startswith("p") else "hurwitz"
        data["hurwitz"].append({"name": name, **_entry(condition, *paper_equations(scene, key))})
    if st.hopf_frequency is not None:
        data["hopf_frequency"] = _entry(st.hopf_frequency)
    if st.robustness is not None:
        data["robustness"] = _robustness_entry(st.robustness)
    try:
        for branch in scene.equilibria(signs).branches:
            data["equilibria"].append(
                {
                    "signs": list(branch.signs),
                    "u_star": [_entry(x) for x in branch.u_star],
                    "condition": _entry(branch.condition),
                }
            )
    except ContactsymError as error:
        data["equilibria"] = {"error": str(error)}
    counts, note = _counts(scene)
    if counts:
        data["equilibrium_counts"] = {
            name: _entry(region.condition, _count_tag(scene, name)) for name, region in counts.items()
        }
    elif note:
        data["equilibrium_counts_note"] = note
    return data


def _robustness_entry(robustness) -> dict:
    """The point decision for a numeric A (k >= 3): verdict, certificate and witness laws."""
    laws = {}
    for name, law in (("stable", robustness.stable_law), ("unstable", robustness.unstable_law)):
        if law is not None:
            laws[name] = {"Phi": [sp.sstr(x) for x in law.Phi], "Psi": [sp.sstr(x) for x in law.Psi]}
    certificate = robustness.certificate
    return {
        "verdict": robustness.verdict,
        "certificate": None if certificate is None else {"kind": certificate.kind, "statement": certificate.statement},
        "witness_laws": laws,
    }


def summary_text(data: dict) -> str:
    """A short plain-text summary of :func:`conditions`: the closed-form regions.

    Examples
    --------
    >>> import contactsym as cs
    >>> print(summary_text(conditions(cs.scene("brake"))).splitlines()[1])
      stable for every law: mu <= Abs(cot(alpha))   (4.4), (6.3)
    """
    lines = [f"{data['scene']}: {data['description']}"]
    for name, entry in data["regions"].items():
        cite = ", ".join(entry.get("paper", []))
        text = entry["sympy"]
        if len(text) > 100:
            text = text[:97] + "..."
        lines.append(f"  {name}: {text}" + (f"   {cite}" if cite else ""))
    for name, entry in (data.get("equilibrium_counts") or {}).items():
        text = entry["sympy"] if len(entry["sympy"]) <= 100 else entry["sympy"][:97] + "..."
        cite = ", ".join(entry.get("paper", []))
        lines.append(f"  equilibria, {name}: {text}" + (f"   {cite}" if cite else ""))
    if data.get("hopf_frequency"):
        text = data["hopf_frequency"]["sympy"]
        lines.append("  Hopf frequency omega: " + (text if len(text) <= 100 else text[:97] + "..."))
    return "\n".join(lines)


# --- figures ------------------------------------------------------------------------------------

#: Words in a figure's file name that tie it to a scene.
FIGURE_WORDS = {
    "sliding-point": ("sliding",),
    "painleve-klein-rod": ("rod",),
    "painleve-klein-guides": ("guides", "fig1"),
    "brake": ("brake",),
}

#: Captions (LaTeX) of the figures of ``contactsym.plotting.paper_figures``, by file name.
CAPTIONS = {
    "fig1a_guides": r"Fig.~1a of the paper, derived: the $(v_1, v_2)$ plane at $\varphi = 60^\circ \ge \arctan\sqrt{2}$, "
    r"where the square (5.8) lies in the stability region (5.6).",
    "fig1b_guides": r"Fig.~1b of the paper, derived: the $(v_1, v_2)$ plane at $\varphi = 45^\circ < \arctan\sqrt{2}$, "
    r"where part of the square (5.8) is law-dependent.",
    "rod_f_cases": r"$f(u)$ of the deformable rod (3.7) in the three cases of \S3: a unique stable root, a fold, a cusp.",
    "rod_phase_portrait": r"Phase portrait of the fast subsystem (2.1) of the rod.",
    "brake_alpha_mu": r"The brake's $(\alpha, \mu)$ plane: stable for every law where $\mu \le |\cot\alpha|$ (6.3), "
    r"law-dependent above.",
    "brake_hopf": r"The brake's Hopf line (6.4) and its frequency $\omega$.",
}


def _paths(result, directory: Path) -> list[tuple[Path, str]]:
    """(path, caption) of the PNGs that a figure function returned or wrote."""
    if isinstance(result, dict):
        items = [(Path(p), str(k)) for k, p in result.items() if isinstance(p, (str, Path))]
    elif isinstance(result, (list, tuple)):
        items = [(Path(p), Path(p).stem.replace("_", " ")) for p in result if isinstance(p, (str, Path))]
    else:
        items = []
    if not items:
        items = [(p, p.stem.replace("_", " ")) for p in sorted(directory.glob("*.png"))]
    return [(p, CAPTIONS.get(p.stem) or _escape(caption)) for p, caption in items if p.suffix == ".png" and p.exists()]


def _scene_of(path: Path) -> str | None:
    stem = path.stem.lower()
    for name, words in FIGURE_WORDS.items():
        if name in stem or any(word in stem for word in words):
            return name
    return None


class FigureSource:
    """Figures for the reports, drawn once by ``contactsym.plotting`` and shared out by scene.

    Uses ``plotting.scene_figures(scene, directory)`` when it exists, else
    ``plotting.paper_figures(directory)`` (once), each figure going to the scene its
    file name names (a figure that names none goes to every scene). Missing functions
    give notes, not errors.
    """

    def __init__(self, workdir: Path):
        self.workdir = workdir
        self._paper: list[tuple[Path, str]] | None = None
        self._own = 0  # scenes other than the paper's, numbered for their figure directories
        self.notes: list[str] = []

    def _plotting(self):
        try:
            from . import plotting
        except ImportError:  # the figures module is not in this version
            return None, "No figures: this version of contactsym has no plotting module."
        return plotting, ""

    def for_scene(self, scene) -> tuple[list[tuple[Path, str]], list[str]]:
        plotting, note = self._plotting()
        if plotting is None:
            return [], [note]
        if paper_name(scene) is None or getattr(scene, "figure_plan", None) is not None:
            # any other scene, or a built-in one beyond the paper: the figures its plan asks for
            from .scenefigures import plan_figures

            self._own += 1
            try:
                return plan_figures(scene, self.workdir / f"own-{self._own}")
            except Exception as error:  # a figure that fails must not cost the rest of the report
                return [], [f"No figures: drawing them failed with {type(error).__name__}: {error}"]
        try:
            if hasattr(plotting, "scene_figures"):
                directory = self.workdir / scene.name
                directory.mkdir(parents=True, exist_ok=True)
                figures = dict(plotting.scene_figures(scene, directory))
                own = getattr(scene, "report_figures", None)  # a scene's own figures: {caption: PNG path}
                figures.update(own(directory) if own is not None else {})
                return _paths(figures, directory), []
            if not hasattr(plotting, "paper_figures"):
                return [], ["No figures: contactsym.plotting has no paper_figures function in this version."]
            if self._paper is None:
                directory = self.workdir / "paper"
                directory.mkdir(parents=True, exist_ok=True)
                self._paper = []  # drawn once, even when drawing fails
                self._paper = _paths(plotting.paper_figures(directory), directory)
        except Exception as error:  # a figure that fails must not cost the rest of the report
            return [], [f"No figures: drawing them failed with {type(error).__name__}: {error}"]
        chosen = [(p, c) for p, c in self._paper if _scene_of(p) in (scene.name, None)]
        notes = []
        if scene.k == 1 and not any("phase" in p.stem for p, _ in chosen):
            portrait, note = self._phase_portrait(plotting, scene)
            chosen += portrait
            notes += [note] if note else []
        if not chosen:
            notes.append("No figure of contactsym.plotting.paper_figures belongs to this scene.")
        return chosen, notes

    def _phase_portrait(self, plotting, scene) -> tuple[list[tuple[Path, str]], str]:
        """A phase portrait of the fast subsystem (2.1) of a one-contact scene."""
        if not (hasattr(plotting, "phase_portrait_data") and hasattr(plotting, "phase_portrait_plot")):
            return [], ""
        from matplotlib.figure import Figure as MplFigure

        try:
            data = plotting.phase_portrait_data(scene.name)
            figure = MplFigure(figsize=(7.0, 5.0))
            plotting.phase_portrait_plot(data, ax=figure.add_subplot())
            path = self.workdir / f"{scene.name.replace('-', '_')}_phase_portrait.png"
            figure.savefig(path, dpi=150, bbox_inches="tight")
        except Exception as error:  # a figure that fails must not cost the rest of the report
            return [], f"No phase portrait: drawing it failed with {type(error).__name__}: {error}"
        return [(path, r"Phase portrait of the fast subsystem (2.1) of this scene.")], ""


# --- files ----------------------------------------------------------------------------------------


def compile_pdf(tex: Path, timeout: float = 120) -> Path | None:
    """Run pdflatex on ``tex`` in its directory; the PDF, or None when pdflatex is not installed.

    Raises ReportError (with the first LaTeX error line) when pdflatex fails.
    """
    pdflatex = shutil.which("pdflatex")
    if pdflatex is None:
        return None
    command = [pdflatex, "-interaction=nonstopmode", "-halt-on-error", "-no-shell-escape", tex.name]
    for _ in range(2):  # a second run only when LaTeX asks for it (longtable widths)
        try:
            run = subprocess.run(command, cwd=tex.parent, capture_output=True, text=True, timeout=timeout)
        except subprocess.TimeoutExpired as error:
            raise ReportError(f"pdflatex took more than {timeout:.0f} s on {tex}.") from error
        log = tex.with_suffix(".log")
        log_text = log.read_text(errors="replace") if log.exists() else run.stdout
        if run.returncode != 0:
            first = next((line for line in log_text.splitlines() if line.startswith("!")), "unknown error")
            raise ReportError(f"pdflatex failed on {tex}: {first.lstrip('! ')} (see {log}).")
        if "Rerun LaTeX" not in log_text and "Rerun to get" not in log_text:
            break
    return tex.with_suffix(".pdf")


def write_report(
    scene,
    directory: Path | str,
    *,
    pdf: bool = True,
    figures: FigureSource | None = None,
    progress: Callable[[str], None] | None = None,
    force: bool = False,
) -> ReportResult:
    """Write ``directory/report.tex``, ``conditions.json``, ``figures/*.png`` and ``report.pdf``.

    Works for any Scene: a built-in one, one read from a scene file
    (:func:`contactsym.load_scene`) or one built in Python. The paper's errata, its
    scene-specific equation numbers and figures appear only for the built-in scene objects
    (decided by identity, not by name). Other scenes get the figures of their
    ``figure_plan`` (a scene file's ``[figures]``, or ``scene.figure_plan =
    contactsym.FigurePlan(x, y, x_range, y_range, values)``): region maps in that plane and,
    for one contact, the phase portrait of (2.1).

    ``figures`` shares drawn figures between scenes (one is made when not given);
    ``progress`` receives short messages. ``report.pdf`` is made when ``pdf`` is true and
    pdflatex is installed. All or nothing: the files are written to a directory beside
    ``directory`` that replaces it only when all succeeded (see :mod:`contactsym.atomic`);
    an existing directory that contactsym did not write is replaced only with ``force``.

    Examples
    --------
    >>> import tempfile
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> import contactsym as cs
    >>> x, y = dynamicsymbols("x y")
    >>> N, mu = sp.Symbol("N", real=True), sp.Symbol("mu", positive=True)
    >>> own = cs.Scene.from_accelerations([x, y], [-mu*sp.Abs(N), N - 1], [cs.Contact(y, N)], name="brake")
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     result = write_report(own, directory, pdf=False)
    ...     text = result.tex.read_text()
    >>> "Errata" in text, result.figures, result.notes[0][:40]
    (False, [], 'No figures: give the scene a [figures] t')
    """
    from .atomic import replaced_directory

    directory = Path(directory)
    with replaced_directory(directory, force=force, error=ReportError) as work:
        result = _write_files(scene, work, pdf, figures, progress or (lambda message: None), directory)
    return ReportResult(
        scene.name,
        directory,
        directory / result.tex.name,
        directory / result.conditions.name,
        None if result.pdf is None else directory / result.pdf.name,
        [Figure(directory / "figures" / f.path.name, f.caption) for f in result.figures],
        result.notes,
    )


def _compile_keeping_log(tex: Path, target: Path) -> Path | None:
    """compile_pdf; on failure the log is copied beside ``target``, since the directory of ``tex`` is removed."""
    try:
        return compile_pdf(tex)
    except ReportError as error:
        log, kept = tex.with_suffix(".log"), target.with_name(f"{target.name}-pdflatex.log")
        message = str(error).replace(str(tex), str(target / tex.name))
        if log.exists():
            shutil.copyfile(log, kept)
            message = message.replace(str(log), str(kept))
        raise ReportError(f"{message} The previous report is unchanged.") from error


def _write_files(scene, directory: Path, pdf: bool, figures: FigureSource | None, say, final: Path) -> ReportResult:
    try:
        (directory / "figures").mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise ReportError(f"cannot create {directory / 'figures'}: {error.strerror or error}.") from error
    result = ReportResult(scene.name, directory, directory / "report.tex", directory / "conditions.json")
    say("conditions")
    data = conditions(scene)
    result.conditions.write_text(json.dumps(data, indent=2, ensure_ascii=False) + "\n")
    say("figures")
    with tempfile.TemporaryDirectory(prefix="contactsym-figures-") as scratch:
        source = figures or FigureSource(Path(scratch))
        drawn, notes = source.for_scene(scene)
        placed = []
        for path, caption in drawn:
            target = directory / "figures" / path.name
            if path.resolve() != target.resolve():
                shutil.copyfile(path, target)
            placed.append(Figure(target, caption))
    result.figures, result.notes = placed, list(notes)
    say("LaTeX")
    result.tex.write_text(report_tex(scene, placed, notes))
    if pdf:
        say("pdflatex")
        result.pdf = _compile_keeping_log(result.tex, final)
        if result.pdf is None:
            result.notes.append(
                "pdflatex is not installed: report.pdf was not made (apt-get install texlive-latex-base)."
            )
    return result
