r"""LaTeX through SymPy's printer, and the :class:`Formula` rows that stage objects print as.

A leaf module: it knows no stage. Each stage object says what its formulas are, the way
SymPy objects own their printing: ``obj.formulas(present=False)`` returns a tuple of
:class:`Formula`, one formula-level result each, with the paper equations it corresponds
to, e.g. the fast subsystem (2.1)/(3.1)/(4.1), the matrix A (4.3), the linearization (4.5),
the characteristic polynomial (4.6) and the Routh–Hurwitz conditions (4.7). The numbers of
the general theory live with the stages (a :class:`Numbering` each); scenes that reproduce
an example of the paper carry its numbers ((5.4) for the guides' A, (6.3) for the brake's
robust stability, ...). :func:`latex` joins the formulas in an ``aligned`` block;
``_repr_latex_`` of each stage shows them with their citations.

Examples
--------
>>> import contactsym as cs
>>> lin = cs.scene("brake").linearization()
>>> [(f.key, f.cite()) for f in formulas(lin)]
[('A', '(4.3), (6.2)'), ('det A', ''), ('matrix', '(4.5)'), ('charpoly', '(4.6)')]
>>> print(formulas(lin)[0].tag())
\tag*{(4.3), (6.2)}
>>> print(latex(cs.scene("sliding-point").linearization().det_A))
\frac{1}{m}
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache

import sympy as sp
from sympy.printing.latex import LatexPrinter

from ..errors import ArgumentError, ContactsymError
from .shared import SharedPrinting

__all__ = ["Formula", "LatexReprMixin", "Numbering", "formulas", "latex", "prime", "signs_latex", "tex"]


class _PaperPrinter(SharedPrinting, LatexPrinter):
    """SymPy's LaTeX printer with the paper's letters: \\varepsilon and \\varphi for the
    symbols (and functions) named epsilon and phi; each compound part printed once (:mod:`.shared`)."""

    def _deal_with_super_sub(self, string: str, style: str = "plain") -> str:
        # once per name and style: a long formula prints the same symbols many times
        return _paper_letters(string, style, bool(self._settings.get("disable_split_super_sub")))


@lru_cache(maxsize=4096)
def _paper_letters(string: str, style: str, unsplit: bool) -> str:
    printer = LatexPrinter({"disable_split_super_sub": True}) if unsplit else _PLAIN  # the one setting read
    plain = LatexPrinter._deal_with_super_sub(printer, string, style)
    return re.sub(r"\\(epsilon|phi)(?![A-Za-z])", r"\\var\1", plain)


_PLAIN = LatexPrinter()


def tex(expr, **settings) -> str:
    r"""LaTeX of a SymPy object, as ``sympy.latex`` prints it but in the paper's letters.

    Examples
    --------
    >>> eps, phi_1 = sp.symbols("epsilon phi_1")
    >>> tex(eps**2 * sp.sin(phi_1))
    '\\varepsilon^{2} \\sin{\\left(\\varphi_{1} \\right)}'
    """
    return _PaperPrinter(settings).doprint(expr)


@dataclass(frozen=True)
class Formula:
    r"""One formula-level result: ``lhs relation rhs``, and where the paper has it.

    Attributes
    ----------
    key : str
        What the formula is: ``"A"``, ``"fast"``, ``"equilibrium"``, ...
    lhs : str
        LaTeX of the left side ("" for a condition standing alone).
    rhs : sympy object or str
        The right side (a str is taken as LaTeX).
    relation : str
        LaTeX of the relation, ``"="`` by default ("" for a condition).
    paper : tuple of str
        Equation numbers of the paper, most general first, e.g. ``("4.3", "6.2")``.
    note : str
        A remark for the reader (a correction of the print, a proposition's name).

    Examples
    --------
    >>> f = Formula("A", "A", sp.Symbol("a"), paper=("4.3",))
    >>> f.body, f.cite(), f.tag()
    ('A = a', '(4.3)', '\\tag*{(4.3)}')
    """

    key: str
    lhs: str
    rhs: object
    relation: str = "="
    paper: tuple = ()
    note: str = ""

    def __post_init__(self):
        texts = (self.key, self.lhs, self.relation, self.note)
        if not all(isinstance(text, str) for text in texts) or not isinstance(self.paper, tuple):
            raise ArgumentError(
                f"Formula {str(self.key)[:60]}: key, lhs, relation and note must be text and paper a tuple of "
                "equation numbers."
            )

    @property
    def rhs_latex(self) -> str:
        return self.rhs if isinstance(self.rhs, str) else tex(self.rhs)

    @property
    def body(self) -> str:
        """The formula as one line of LaTeX mathematics."""
        return " ".join(part for part in (self.lhs, self.relation, self.rhs_latex) if part)

    def cite(self) -> str:
        """The paper's equation numbers, ``"(4.3), (6.2)"`` ("" when the paper has no number)."""
        return ", ".join(f"({number})" for number in self.paper)

    def tag(self) -> str:
        """An amsmath ``\\tag*`` with the citation, or ``\\notag``."""
        return f"\\tag*{{{self.cite()}}}" if self.paper else r"\notag"


# --- where the paper has a formula ---------------------------------------------------


@dataclass(frozen=True)
class Numbering:
    """The general theory's equation numbers (§§1-4) of some formula keys, and their notes.

    Parameters
    ----------
    numbers : dict
        ``{key: (numbers for k = 1, for k = 2, for k >= 3)}``.
    notes : dict
        ``{key: (note for k = 1, for k = 2, for k >= 3)}``.

    A scene's own numbers (``{key: (numbers, note)}``, or ``"key:detail"`` for one row)
    follow the general ones.

    Examples
    --------
    >>> general = Numbering({"A": (("3.2",), ("4.3",), ("4.3",))}, {"A": ("", "", "Prop. 7")})
    >>> general("A", 2, {"A": (("6.2",), "erratum")})
    (('4.3', '6.2'), 'erratum')
    >>> (general | Numbering({"B": (("1",),) * 3}))("B", 5)
    (('1',), '')
    """

    numbers: dict
    notes: dict = field(default_factory=dict)

    def __post_init__(self):
        if not isinstance(self.numbers, dict) or not isinstance(self.notes, dict):
            raise ArgumentError("Numbering: numbers and notes must be dicts {key: (k = 1, k = 2, k >= 3)}.")

    def __call__(self, key: str, k: int, own: dict | None = None, detail=None) -> tuple[tuple, str]:
        """(numbers, note) of ``key`` for k contacts, the scene's own numbers ``own`` appended."""
        column = min(k, 3) - 1
        numbers = self.numbers.get(key, ((), (), ()))[column]
        note = self.notes.get(key, ("", "", ""))[column]
        own = own or {}
        extra_numbers, extra_note = own.get(f"{key}:{detail}", own.get(key, ((), "")))
        numbers = tuple(dict.fromkeys(tuple(numbers) + tuple(extra_numbers)))
        return numbers, "; ".join(n for n in (note, extra_note) if n)

    def __or__(self, other: Numbering) -> Numbering:
        return Numbering({**self.numbers, **other.numbers}, {**self.notes, **other.notes})

    def formula(self, key, lhs, rhs, *, k: int, own=None, relation="=", detail=None) -> Formula:
        """A :class:`Formula` cited with the numbers of ``key``."""
        return Formula(key, lhs, rhs, relation, *self(key, k, own, detail))


def prime(symbol) -> str:
    """LaTeX of ``symbol'``, a derivative in the stretched time.

    Examples
    --------
    >>> import sympy as sp
    >>> print(prime(sp.Symbol("u_1")))
    u_{1}'
    """
    return tex(symbol) + "'"


def signs_latex(signs) -> str:
    r"""A sign pattern as ``(+, -)``.

    Examples
    --------
    >>> print(signs_latex((1, -1)))
    \left(+, -\right)
    """
    if isinstance(signs, (str, bytes)) or not isinstance(signs, (tuple, list)) or any(s not in (1, -1) for s in signs):
        raise ArgumentError(f"signs_latex: signs = {str(signs)[:60]} must be a tuple of +1 and -1, e.g. (1, -1).")
    return r"\left(" + ", ".join("+" if s == 1 else "-" for s in signs) + r"\right)"


def formulas(obj, *, present: bool = False) -> tuple[Formula, ...]:
    r"""The formula-level results of a stage object, a branch or a region, in order.

    A stage object gives them itself (its ``formulas`` method); a region (an object with a
    ``condition`` and a ``latex()``) is one condition. ``present=True`` rewrites the
    linearization and stability formulas in the scene's presentation variables (kappa,
    v_j, mu_pm, ...).

    Examples
    --------
    >>> import contactsym as cs
    >>> fast = cs.scene("sliding-point").fast_subsystem()
    >>> [(f.key, f.body, f.cite()) for f in formulas(fast)][:2]
    [('fast', "u' = - 2 b f{\\left(u \\right)} - v", '(3.1), (1.12)'), ('fast', "v' = f{\\left(u \\right)}", '(3.1), (1.12)')]
    """
    if not isinstance(present, bool):  # this printer imports no checks (it is a leaf): its own line
        raise ArgumentError(f"formulas: present = {str(present)[:60]} must be True or False.")
    own = getattr(obj, "formulas", None)
    if callable(own):
        return tuple(own(present=present))
    if _is_region(obj):
        return (Formula(obj.name or "region", "", obj.condition, ""),)
    raise ArgumentError(f"no formulas for {type(obj).__name__}; give a stage object, a Branch or a Region.")


def _is_region(obj) -> bool:
    return isinstance(getattr(obj, "condition", None), sp.Basic) and callable(getattr(obj, "latex", None))


def _aligned(rows: tuple[Formula, ...], tags: bool) -> str:
    lines = []
    for row in rows:
        relation = row.relation if row.relation in ("", ":") else row.relation + " "
        line = f"{row.lhs} &{relation}{row.rhs_latex}" if row.lhs else f"& {row.rhs_latex}"
        line = line.replace("&:", r"&: \ ")
        if tags and row.paper:
            line += r" && \text{" + row.cite() + "}"
        lines.append(line)
    return r"\begin{aligned} " + r" \\ ".join(lines) + r" \end{aligned}"


def latex(obj, *, present: bool = False, tags: bool = False) -> str:
    r"""LaTeX for a scene, a stage object, a branch, a region, or any SymPy object.

    Stage objects print as an ``aligned`` block of their :func:`formulas`;
    ``tags=True`` adds each formula's paper equation numbers in a column on the right,
    ``present=True`` uses the scene's presentation variables. A region prints as its
    condition; anything else goes to ``sympy.latex``.

    Examples
    --------
    >>> import contactsym as cs
    >>> print(cs.latex(cs.scene("sliding-point").fast_subsystem()))
    \begin{aligned} u' &= - 2 b f{\left(u \right)} - v \\ v' &= f{\left(u \right)} \\ f{\left(u \right)} &= \frac{u}{m} + \frac{Y{\left(x,\dot{x} \right)}}{m} \end{aligned}
    >>> print(cs.latex(cs.scene("brake").regions()["stable for every law"]))
    \mu \leq \left|{\cot{\left(\alpha \right)}}\right|
    >>> print(cs.latex(cs.scene("sliding-point").equilibria(), tags=True))
    \begin{aligned} u^{*} &= - Y{\left(x,\dot{x} \right)} && \text{(3.2)} \end{aligned}
    """
    if not isinstance(present, bool) or not isinstance(tags, bool):
        raise ContactsymError(f"present and tags must be True or False, not {present!r:.40} and {tags!r:.40}.")
    if _is_region(obj):
        return obj.latex()
    if not callable(getattr(obj, "formulas", None)):
        return tex(obj)
    return _aligned(formulas(obj, present=present), tags)


class LatexReprMixin:
    """Gives a class with ``formulas()`` its Jupyter display: the formulas with their citations.

    The stage classes (and :class:`~contactsym.mechanism.scene.Scene`) inherit it, so
    ``_repr_latex_`` is written once; it adds no state (``__slots__ = ()``).

    Examples
    --------
    >>> import contactsym as cs
    >>> print(cs.scene("sliding-point").equilibria()._repr_latex_())
    $\\displaystyle \\begin{aligned} u^{*} &= - Y{\\left(x,\\dot{x} \\right)} && \\text{(3.2)} \\end{aligned}$
    """

    __slots__ = ()

    def _repr_latex_(self) -> str:
        return f"$\\displaystyle {latex(self, tags=True)}$"
