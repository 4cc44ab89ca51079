r"""Typesetting for the report: widths of LaTeX mathematics, line breaking, named long expressions.

A displayed formula must fit the page: :func:`width` estimates the printed width of
LaTeX mathematics; a long equation is broken at the terms of its sums (``split``), a long
Boolean condition one conjunct per line; what would still take more than
:data:`MAX_LINES` lines is replaced by a name (``H_1``) that :class:`_Named` remembers,
so the document can list it with its size.

Examples
--------
>>> import sympy as sp
>>> from contactsym.printing.latex_output import Formula
>>> x, y = sp.symbols("x y")
>>> print(_display(Formula("f", "f", x + y, "=", ("4.6",)), _Named()))
\begin{equation}
f = x + y
\tag*{(4.6)}
\end{equation}
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from functools import lru_cache

import sympy as sp

from ..algebra.basic import node_count as _nodes
from ..algebra.coprime import proved_coprime
from ..printing.latex_output import Formula, tex
from .descriptions import sparse_polynomial
from .plain_text import _note

#: Visible width (in characters of math) of one displayed line, and the most lines one formula may take.
WIDTH = 78
MAX_LINES = 6
#: Past this many nodes a formula is not broken into lines (they hold far fewer): its long sums are named at once.
BREAK_NODES = 1500
#: Past this many nodes a subexpression is split or named unprinted (printing each one to measure it is quadratic).
NARROW_NODES = 600

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
    #: the letter of the names: H, or H with an accent where the scene has its own H_j (plain_text.own_letters)
    letter: str = "H"

    def name(self, expr: sp.Expr) -> sp.Symbol:
        for symbol, known in self.items:
            if known == expr:
                return symbol
        symbol = sp.Symbol(f"{self.letter}_{len(self.items) + 1}")
        self.items.append((symbol, expr))
        return symbol


def _tex(expr) -> str:
    """``tex(expr)``, once per expression: a long formula is printed by several layouts in turn."""
    try:
        return _cached_tex(expr)
    except TypeError:  # a mutable matrix: printed each time
        return tex(expr)


#: Past this many nodes a formula is printed with its terms in SymPy's internal order: sorting them is
#: ~30% of the printing (seconds for a four-link arm's conditions), and nobody reads such a formula whole.
UNORDERED_NODES = 5000


@lru_cache(maxsize=4096)
def _cached_tex(expr) -> str:
    return tex(expr, order="none") if _nodes(expr, UNORDERED_NODES) > UNORDERED_NODES else tex(expr)


def _terms(expr: sp.Expr) -> tuple[str, Iterator[str], str] | None:
    """(prefix, LaTeX of the terms, suffix) of a sum, a multiple of a sum, or a sum over a denominator.

    The terms are printed as :func:`_fill` asks for them: it stops at the first line too many.
    """
    if isinstance(expr, sp.Add):
        return "", map(_tex, expr.as_ordered_terms()), ""
    numerator, denominator = sp.fraction(expr)
    if denominator != 1 and isinstance(sp.expand(numerator), sp.Add):
        prefix = r"\frac{1}{" + _tex(denominator) + r"} \Big("
        return prefix, map(_tex, sp.expand(numerator).as_ordered_terms()), r"\Big)"
    if isinstance(expr, sp.Mul):
        sums = [f for f in expr.args if isinstance(f, sp.Add)]
        if len(sums) == 1:
            rest = sp.Mul(*[f for f in expr.args if f is not sums[0]])
            prefix = ("-" if rest == -1 else _tex(rest)) + r" \Big("
            return prefix, map(_tex, sums[0].as_ordered_terms()), r"\Big)"
    return None


def _fill(first: str, terms: Iterable[str], suffix: str, budget: float) -> list[str] | None:
    """Greedy lines of ``first t1 + t2 ...``; None when they take more than MAX_LINES or a line is too wide.

    Stops at the first line too many or too wide (widths only grow as a line does): a sum of
    hundreds of terms is not laid out to the end to be refused.
    """
    limit = budget + 8
    lines, current = [], first
    for index, term in enumerate(terms):
        joined = term if index == 0 else (f"- {term[1:].lstrip()}" if term.startswith("-") else f"+ {term}")
        piece = f" {joined}"
        if width(current + piece) > budget and width(current) > width(first) + 1:
            lines.append(current)
            current = r"\quad" + piece
        else:
            current += piece
        if len(lines) > MAX_LINES or width(current) > limit:
            return None
    lines.append(current + " " + suffix if suffix else current)
    if len(lines) > MAX_LINES or any(width(line) > limit for line in lines):
        return None
    return lines


def _compact(expr, named: _Named, budget: float):
    """``expr`` with its long sums replaced by names (a product keeps its short factors)."""
    if isinstance(expr, sp.Basic) and _nodes(expr, NARROW_NODES) <= NARROW_NODES and width(_tex(expr)) <= budget:
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
    if not isinstance(expr, str) and _nodes(expr, BREAK_NODES) > BREAK_NODES:  # never printed in full here
        return [f"{head} {_tex(_compact(expr, named, WIDTH - width(head) - 4))}"]
    text = _tex(expr) if not isinstance(expr, str) else expr
    if isinstance(expr, str) or width(head + " " + text) <= WIDTH:
        return [f"{head} {text}"]
    lines = _broken("", expr, "", WIDTH - width(lhs))
    if lines is not None:
        return [f"{head} {lines[0]}"] + ["& " + line for line in lines[1:]]
    compacted = _compact(expr, named, WIDTH - width(head) - 4)
    return [f"{head} {_tex(compacted)}"]


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
    if _nodes(condition, BREAK_NODES) > BREAK_NODES:
        lines = None
    elif width(_tex(left)) >= width(_tex(right)):
        lines = _broken("", left, f" {relation} {_tex(right)}", WIDTH)
    else:
        lines = _broken(f"{_tex(left)} {relation} ", right, "", WIDTH)
    if lines is None:
        budget = WIDTH / 2
        lines = [f"{_tex(_compact(left, named, budget))} {relation} {_tex(_compact(right, named, budget))}"]
    return ["& " + line for line in lines]


def _condition_lines(condition, named: _Named) -> list[str]:
    """A Boolean condition as lines, each starting with ``&``: one conjunct (or disjunct) per line when long."""
    text = _tex(condition)
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
    return [f"& {_tex(_compact(condition, named, WIDTH))}"]


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


#: Past this many nodes an expression is displayed as derived: cancelling it costs more than reading it.
TIDY_NODES = 3000
#: Terms times generators of the cancelled numerator up to which ``factor`` is tried (a multivariate
#: factorization grows steeply with both: 130 terms in 12 symbols took 50 s, 124 in 7 took 1 s).
TIDY_FACTOR_WORK = 1000
#: A polynomial of more terms than this, expanded, is displayed as derived: cancelling and factoring
#: it would not make it fit (the stool's Delta_3, 683 terms: 9 s of cancel, factor_terms and trial division).
#: The same holds for a rational expression whose cancelled numerator has more terms (the stool's
#: omega^2: 534 terms, 63000 characters against 4900 as derived; 8 s of factor_terms and trial division).
TIDY_TERMS = 300
#: The sums inside an expression whose factors are tried as divisors are at most this many nodes:
#: factoring a larger one is the multivariate factorization the trial avoids (the stool's Delta_3,
#: a sum of four products, 683 nodes: 70 s).
TRIAL_NODES = 200


@lru_cache(maxsize=512)
def _tidy(expr):
    """A readable form: the common denominator pulled out, the numerator factored when that is short.

    Cheap rules decide how much work the display gets: a large expression (in nodes, or a polynomial
    in terms once expanded in the sparse ring) is shown as derived,
    and ``factor`` runs only on a numerator small enough (see ``TIDY_FACTOR_WORK``); the shorter
    of the factored and the cancelled form is shown (one fraction, even where the derived sum is
    shorter: its long parts are named apart). Cached per expression.
    """
    if _nodes(expr, TIDY_NODES) > TIDY_NODES:
        return expr
    gens = sorted(expr.free_symbols, key=str)
    expanded = sparse_polynomial(expr, gens)
    if expanded is not None and len(expanded) > TIDY_TERMS:  # no cancelled form of it fits the page
        return expr
    if expanded is None and _long_and_coprime(expr, gens):  # cancel would find that out in seconds
        return expr
    cancelled = sp.cancel(expr)
    if len(sp.Add.make_args(sp.fraction(cancelled)[0])) > TIDY_TERMS:  # cancel gives the numerator expanded
        return expr
    cancelled = sp.factor_terms(cancelled)
    numerator = sp.fraction(cancelled)[0]
    work = len(sp.Add.make_args(sp.expand(numerator))) * len(numerator.free_symbols | numerator.atoms(sp.Function))
    factored = sp.factor(cancelled) if work <= TIDY_FACTOR_WORK else _trial_factored(expr, numerator, cancelled)
    return factored if len(str(factored)) <= len(str(cancelled)) else cancelled


def _long_and_coprime(expr, gens) -> bool:
    """Whether the numerator of ``together(expr)`` has more than TIDY_TERMS terms expanded and is
    proved coprime to its denominator: then ``cancel`` leaves it whole, too long to show (the
    stool's omega^2: 534 terms, 2.3 s of cancel)."""
    numerator, denominator = sp.fraction(sp.together(expr))
    top = sparse_polynomial(numerator, gens)
    if top is None or len(top) <= TIDY_TERMS:
        return False
    bottom = sparse_polynomial(denominator, gens)
    return bottom is not None and proved_coprime(top, bottom)


def _trial_factored(expr, numerator, cancelled):
    """``cancelled`` with the factors it shares with the small sums inside ``expr`` divided out (exact
    polynomial division), the rest left whole: what ``factor`` finds when the rest is irreducible,
    without proving that it is (which is where ``factor`` spends its time)."""
    sums = {sub for sub in sp.preorder_traversal(expr) if sub.is_Add and len(sub.args) <= 12}
    candidates = set()
    for sub in sums:  # each distinct small sum once; a large one (a sum of a few long products) is no candidate
        if _nodes(sub, TRIAL_NODES) <= TRIAL_NODES and sub.is_polynomial():
            candidates |= {f for f, _ in sp.factor_list(sub)[1] if f.is_Add}
    gens = sorted(numerator.free_symbols, key=sp.default_sort_key)
    if not candidates or not gens:
        return cancelled
    try:
        exponents, rest = sp.Poly(numerator, *gens).terms_gcd()
    except sp.PolynomialError:
        return cancelled
    found = []
    for factor in sorted(candidates, key=sp.default_sort_key):
        divisor = sp.Poly(factor, *gens)
        while True:
            quotient, remainder = rest.div(divisor)
            if not remainder.is_zero:
                break
            rest = quotient
            found.append(factor)
    content, primitive = rest.primitive()
    monomial = sp.Mul(*[g**k for g, k in zip(gens, exponents)])
    return content * monomial * sp.Mul(*found) * primitive.as_expr() / sp.factor(sp.fraction(cancelled)[1])
