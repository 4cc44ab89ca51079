"""Closed-form regions: the raw Hurwitz/proposition conditions as inequalities a reader writes.

``closed_form`` reduces each relational ``P op 0`` exactly:

1. present it in the scene's variables (kappa, v_j, mu_pm, ...);
2. clear the denominator (its sign must be known) and factor the numerator;
3. drop constant factors, factors of known sign (masses, squares of nonzero symbols,
   Phi < 0, Psi < 0, sines the scene declares positive) flipping the relation for
   negative ones; in ``P > 0`` an even power of an unknown factor f becomes the condition
   f != 0 (in ``P >= 0`` and ``P == 0`` it stays);
4. write what is left as ``small < big`` with the terms of known positive sign on the
   right (``v1 + v2 < 2 kappa**2``, ``-m mu**2 Phi < Psi**2 (mu**2 + 1)``);
5. solve for a parameter the scene names when the condition is ``a x**2 + c`` or
   ``a x + c`` in it (``mu <= |cot(alpha)|``);
6. merge ``x < c`` and ``-x < c`` into ``|x| < c``.

Steps 2-6 are the inequality engine :mod:`contactsym.inequalities`, shared with the
equilibrium counts; this module presents a scene's conditions and wraps them as regions.

Size limits. Past :data:`RAW_OPS` operations a relation is kept exactly as derived (step 1
only); past :data:`FACTOR_TERMS` terms a numerator is kept unfactored (see
:mod:`contactsym.inequalities.closed`, where the numbers for a fully symbolic k = 3 scene are).
A relation that is short as derived but whose expansion may exceed :data:`RAW_TERMS` terms
(:func:`contactsym.algebra.hurwitz.expansion_bound`, read off the tree without expanding) is
kept as derived too: a k = 3 stool's Delta_3 > 0 is 1110 operations as derived and 887 terms
(8040 operations, 12 s of rewriting) expanded. The built-in scenes stay below 500.
All three only skip rewriting: the region means the same. ``closed_form`` reads the names
here at each call, so a caller (a benchmark of the old way, a test) may change them.

A :class:`Region` wraps such a Boolean: ``&``, ``|``, ``~``, ``latex()``, vectorised
``evaluate`` and exact ``contains``; :func:`contactsym.plotting.region_plot` draws it (the
computation never imports the drawing).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from functools import cached_property, reduce

import numpy as np
import sympy as sp
from sympy.core.relational import Relational
from sympy.printing.numpy import NumPyPrinter

from .. import inequalities
from ..algebra.basic import known_sign
from ..algebra.hurwitz import expansion_bound
from ..arguments import checked
from ..errors import ArgumentError, ContactsymError, SceneError
from ..parse import sympy_only
from ..printing.latex_output import tex
from ..printing.shared import SharedPrinting
from ..validate import shorten, sign_pattern

__all__ = [
    "Region",
    "closed_form",
    "known_sign",
    "scene_regions",
    "REGION_NAMES",
    "NO_EQUILIBRIUM",
    "proved_no_equilibrium",
]

#: Relations with more operations (unexpanded) are kept as derived: see the module docstring.
RAW_OPS = inequalities.RAW_OPS
#: Numerators with more terms are not factored: see the module docstring.
FACTOR_TERMS = inequalities.FACTOR_TERMS
#: Relations whose expansion may have more terms are kept as derived: see the module docstring.
RAW_TERMS = 2000


def closed_form(condition, scene=None, solve_for: sp.Symbol | None = None, signs=None) -> sp.Basic:
    """The simplest equivalent form of a condition, in the scene's presentation variables.

    Examples
    --------
    >>> import contactsym as cs
    >>> s = cs.scene("painleve-klein-guides")
    >>> closed_form(s.stability().robustly_unstable, s)
    v_1 + v_2 > 2*kappa**2
    >>> b = cs.scene("brake")
    >>> closed_form(b.stability().robustly_stable, b, solve_for=sp.Symbol("mu", positive=True))
    mu <= Abs(cot(alpha))
    >>> closed_form(s.stability().robustly_stable, s)
    ((v_1 + 1)*(v_2 + 1) >= 0) & (v_1 < 2*kappa**2 + 1) & (v_2 < 2*kappa**2 + 1) & (v_1 + v_2 < 2*kappa**2)
    """
    if scene is not None and not callable(getattr(scene, "present", None)) or isinstance(scene, type):
        raise SceneError(f"scene = {shorten(scene)} must be a Scene (or None), e.g. contactsym.scene('brake').")
    if solve_for is not None and not isinstance(solve_for, sp.Symbol):
        raise SceneError(f"solve_for = {shorten(solve_for)} must be a sympy Symbol (a parameter) or None.")
    signs = None if signs is None else sign_pattern(signs)
    if not isinstance(sympy_only(condition, "the condition"), (sp.logic.boolalg.Boolean, sp.Expr)):
        raise SceneError(f"condition = {shorten(condition)} must be a SymPy condition such as mu < 1.")
    positive = tuple(getattr(scene, "positive_expressions", ()))
    condition = scene.present(condition, signs) if scene is not None else sympy_only(condition, "the condition")
    condition, kept = _set_aside(condition)
    if condition in (sp.true, sp.false) or all(s in kept for s in condition.free_symbols):
        return condition.xreplace(kept)
    # one memo per scene: its regions share most relations and proofs (the answer is the same without it)
    memo = scene.cached("closed forms", lambda: {}) if scene is not None else None
    reduced = inequalities.closed_form(
        condition, positive, solve_for, raw_ops=RAW_OPS, factor_terms=FACTOR_TERMS, memo=memo
    )
    return reduced.xreplace(kept)


def _set_aside(condition: sp.Basic) -> tuple[sp.Basic, dict]:
    """``condition`` with each relation whose expansion may exceed :data:`RAW_TERMS` terms
    replaced by a Boolean stand-in, and {stand-in: relation}."""
    kept = {}

    def large(node):
        return isinstance(node, Relational) and expansion_bound(node.lhs - node.rhs) > RAW_TERMS

    def stand_in(node):
        symbol = sp.Dummy(f"relation{len(kept)}")
        kept[symbol] = node
        return symbol

    if isinstance(condition, Relational):
        return (stand_in(condition), kept) if large(condition) else (condition, kept)
    return condition.replace(large, stand_in), kept


#: The regions every scene offers, from its stability object.
#:
#: >>> from contactsym.stages import REGION_NAMES
#: >>> REGION_NAMES['stable for every law']
#: 'robustly_stable'
REGION_NAMES = {
    "stable for every law": "robustly_stable",
    "unstable for every law": "robustly_unstable",
    "law-dependent": "law_dependent",
    "Hopf line": "hopf",
}


@checked(scene="Scene", signs="Sequence[int] | None")
def scene_regions(scene, signs=None) -> dict[str, Region]:
    """The named closed-form regions of a scene (one sign pattern, or all with symbols s_i).

    Each region is where the linearization (4.5) of the pattern's piece is stable, unstable or
    law-dependent: a claim about the equilibrium where it exists (its existence condition, (4.2)).
    Where no branch exists at all (:func:`proved_no_equilibrium`: a load declared to pull a
    one-sided contact open) every region is False, with the reason :data:`NO_EQUILIBRIUM` in its
    description.

    Examples
    --------
    >>> import contactsym as cs
    >>> scene_regions(cs.scene("brake"))["stable for every law"]
    Region(stable for every law: mu <= Abs(cot(alpha)))
    """
    stability = scene.stability(signs)
    if proved_no_equilibrium(scene, signs):  # nothing to be stable: every region is empty, proved so
        return {
            name: Region(sp.false, name=name, description=f"{scene.name}: {NO_EQUILIBRIUM}") for name in REGION_NAMES
        }
    regions = {}
    for name, attribute in REGION_NAMES.items():
        raw = getattr(stability, attribute)
        if raw is None:
            continue
        condition = closed_form(raw, scene, solve_for=getattr(scene, "solve_for", None), signs=signs)
        regions[name] = Region(condition, name=name, description=f"{scene.name}: {_meaning(attribute, stability.k)}")
    if stability.k >= 3 and stability.undecided != sp.false:  # k <= 2: only det A = 0, where the propositions end
        statements = ("stable for every law", "unstable for every law", "law-dependent")
        named = [regions[n].condition for n in statements if n in regions]
        undecided = sp.Not(sp.Or(*named)) if len(named) == 3 else sp.true  # a numeric A: a statement is undecided
        description = f"{scene.name}: undecided: no statement proved here (each may still hold)"
        regions["undecided"] = Region(undecided, name="undecided", description=description)
    return regions


#: What the regions say where no equilibrium with every contact closed exists.
NO_EQUILIBRIUM = (
    "empty: no equilibrium with every contact closed exists where the scene is declared (the existence "
    "condition of each branch (4.2) is False), so no stability is claimed"
)


@checked(scene="Scene", signs="Sequence[int] | None")
def proved_no_equilibrium(scene, signs=None) -> bool:
    """True when no equilibrium with every contact closed exists where the scene is declared: every
    branch's existence condition (4.2) on ``signs`` is False (False: not proved).

    Consulted where a one-sided contact's sign is left to the existence condition (no switching
    function fixes it: no friction in its gap's equation), so that the declared sign of a load can
    decide it; elsewhere the roots are not derived for this (for a large scene they cost about half
    as much again as its regions: the four-link arm's 9 s became 14 s).

    Examples
    --------
    >>> import contactsym as cs
    >>> proved_no_equilibrium(cs.scene("brake"))
    False
    """
    fast = scene.fast_subsystem()
    if not any(one_sided and u not in fast.switching for u, one_sided in zip(fast.u, fast.unilateral)):
        return False
    try:
        return scene.equilibria(signs).exists is False
    except (ContactsymError, NotImplementedError):  # the roots are not derived in closed form: nothing proved
        return False


def _meaning(attribute: str, k: int) -> str:
    """What a region claims: for k >= 3 the statements are proved on sufficient regions only."""
    if attribute == "hopf":
        return "hopf: Delta_(n-1) = 0 with the other Hurwitz conditions > 0"
    if k >= 3:
        return f"{attribute}: where it is proved (a sufficient region; outside it the statement may still hold)"
    return f"{attribute}: where it is proved"


@checked
@dataclass(frozen=True, eq=False)
class Region:
    """A closed-form Boolean region in a scene's symbols.

    Examples
    --------
    >>> import sympy as sp
    >>> x, y = sp.symbols("x y", real=True)
    >>> r = Region(x + y < 2, name="below") & Region(x > 0)
    >>> r.contains(x=1, y="1/2"), r.contains(x=1, y=1)
    (True, False)
    >>> r.evaluate(x=np.array([0.5, 1.5]), y=np.array([0.0, 1.0])).tolist()
    [True, False]
    >>> print(r.latex())
    x > 0 \\wedge x + y < 2
    """

    condition: sp.Basic
    name: str = ""
    description: str = ""
    symbols: tuple = field(default=())

    def __post_init__(self):
        symbols_ok = isinstance(self.symbols, tuple) and all(isinstance(s, sp.Symbol) for s in self.symbols)
        if not isinstance(self.name, str) or not isinstance(self.description, str) or not symbols_ok:
            raise SceneError("a Region's name and description are text, and its symbols a tuple of symbols.")
        object.__setattr__(self, "condition", sympy_only(self.condition, "a region's condition"))
        if not self.symbols:
            object.__setattr__(self, "symbols", tuple(sorted(self.condition.free_symbols, key=str)))

    def _combine(self, other: Region, op, word: str) -> Region:
        name = f"({self.name} {word} {other.name})" if self.name and other.name else ""
        return Region(op(self.condition, other.condition), name)

    def __and__(self, other: Region) -> Region:
        return self._combine(other, sp.And, "and")

    def __or__(self, other: Region) -> Region:
        return self._combine(other, sp.Or, "or")

    def __invert__(self) -> Region:
        return Region(sp.Not(self.condition), f"not {self.name}" if self.name else "")

    @checked
    def latex(self) -> str:
        return tex(self.condition)

    def _repr_latex_(self) -> str:
        return f"${self.latex()}$"

    def __repr__(self) -> str:
        label = f"{self.name}: " if self.name else ""
        return f"Region({label}{self.condition})"

    @cached_property
    def _by_name(self) -> dict:
        return {str(s): s for s in self.condition.free_symbols}

    @property
    def symbol_names(self) -> dict:
        """The region's free symbols by name, ``{"mu": mu, ...}``: the keywords :meth:`evaluate` takes."""
        return self._by_name

    def _symbols_for(self, values: dict) -> dict:
        unknown = set(values) - set(self._by_name)
        missing = set(self._by_name) - set(values)
        if missing:
            raise ArgumentError(f"give values for {sorted(missing)}; the region depends on them.")
        if unknown:
            raise ArgumentError(f"the region does not depend on {sorted(unknown)}; known: {sorted(self._by_name)}.")
        return {self._by_name[name]: value for name, value in values.items()}

    @cached_property
    def _compiled(self):
        symbols = sorted(self.condition.free_symbols, key=str)
        return symbols, sp.lambdify(symbols, self.condition, modules="numpy", printer=_ConditionPrinter)

    @checked
    def evaluate(self, **arrays) -> np.ndarray:
        """Membership for arrays of parameter values (broadcast with numpy), by symbol name."""
        self._symbols_for(arrays)
        symbols, function = self._compiled
        # not broadcast: the parts in values held fixed stay scalars, computed once (a four-link arm's
        # region on a 200 x 200 plane: 12 s -> 0.3 s); And and Or are binary ufuncs, which broadcast
        arguments = [np.asarray(arrays[str(s)], dtype=float) for s in symbols]
        shape = np.broadcast_shapes(*(a.shape for a in arguments))
        return np.broadcast_to(np.asarray(function(*arguments), dtype=bool), shape)

    @checked
    def contains(self, **exact_values) -> bool:
        """Exact membership: values are converted to rationals (floats exactly, strings parsed as numbers)."""
        values = {s: _exact(v) for s, v in self._symbols_for(exact_values).items()}
        result = self.condition.xreplace(values)
        if result not in (sp.true, sp.false):
            result = result.simplify() if not result.free_symbols else result
        if result not in (sp.true, sp.false):
            raise ArgumentError(f"cannot decide {result} exactly.")
        return bool(result)


class _ConditionPrinter(SharedPrinting, NumPyPrinter):
    """NumPy code of a condition: And and Or as chains of the binary ufuncs (which broadcast a part in
    scalars alone with the rest, where ``logical_and.reduce`` of mixed shapes fails), each compound part
    printed once (a region's parts repeat in the other regions of its scene)."""

    def _print_And(self, expr) -> str:
        return self._chained("logical_and", expr)

    def _print_Or(self, expr) -> str:
        return self._chained("logical_or", expr)

    def _chained(self, ufunc: str, expr) -> str:
        name = self._module_format(f"{self._module}.{ufunc}")
        return reduce(lambda left, right: f"{name}({left}, {right})", map(self._print, expr.args))


def _exact(value) -> sp.Expr:
    """A rational (or exact SymPy number) from an int, float, Fraction, or numeric string."""
    if isinstance(value, sp.Basic):
        if not value.is_number:
            raise ArgumentError(f"{value} is not a number.")
        return value
    if isinstance(value, str):
        try:
            return sp.Rational(value)
        except (TypeError, ValueError) as error:
            raise ArgumentError(f"'{value}' is not a number; give e.g. '3/4' or '0.75'.") from error
    if isinstance(value, float):
        if not np.isfinite(value):
            raise ArgumentError(f"{value} is not finite.")
        return sp.Rational(value)
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer, Fraction)):
        raise ArgumentError(f"{shorten(value)} ({type(value).__name__}) is not a number; give e.g. 3, 0.75 or '3/4'.")
    return sp.Rational(value)
