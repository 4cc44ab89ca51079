"""Stability of an equilibrium of the fast subsystem, and its robustness to the law.

``hurwitz`` holds the expressions that must all be positive for asymptotic stability
of (4.5) (Liénard–Chipart form of (4.7)). The robustness classification follows the
paper:

- k = 1: Proposition 3 (f'(u*) > 0 stable, < 0 unstable, for every law),
  Proposition 4 (every piece has f' > 0: a unique stable reaction for every load),
  Proposition 5 (constant Phi, Psi: no cycles);
- k = 2: Proposition 6 with Remarks 1-2: stable for every law, unstable for every law,
  or law-dependent (a Hopf bifurcation is possible);
- k >= 3: Propositions 7 (A symmetric positive definite) and 8 (det A < 0 or all
  a_ss < 0), widened by the closed-form certificates of :mod:`contactsym.robustness.classify`
  (some p_s <= 0 for every law; law-dependent where a nested sequence of positive
  principal minors gives a stable law and a negative principal minor an unstable one).
  For a numeric A, ``robustness`` holds the point decision with its certificate or
  witness laws, and ``undecided`` is True only where neither decides.

The regions are built in :mod:`contactsym.stages.classification`. For a mechanism with k = 2 and
large entries they are read off |det M| A (:func:`contactsym.stages.minors.positive_multiple`),
and the Hurwitz conditions off the factors of A (:class:`~contactsym.stages.minors.FactoredMinors`):
neither waits for A's entries in the canonical form (the four-link, two-contact arm: Hurwitz
conditions and classification 18.8 s CPU, against 29 s and about 500 s before).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import sympy as sp

from ..algebra.basic import normalize
from ..algebra.hurwitz import EXPAND_TERMS, Hurwitz, expansion_bound
from ..arguments import checked
from ..deprecation import deprecated_property
from ..errors import SingularJacobianError
from ..lyapunov.coefficient import first_lyapunov_symbolic
from ..printing.glyphs import OwnLetters
from ..printing.latex_output import Formula, LatexReprMixin, Numbering
from .classification import classification_matrix, proved_regions
from .linear import linearization_of
from .stability_formulas import generic_minors, hurwitz_letters, hurwitz_names, robustness_formulas, shortest_form
from .verdicts import NAMES as VERDICT_NAMES
from .verdicts import Verdict, classification_verdicts, with_point_decision

if TYPE_CHECKING:
    from ..robustness.classify import Robustness

__all__ = [
    "Stability",
    "generic_minors",
    "hurwitz_letters",
    "hurwitz_names",
    "robustness_formulas",
    "shortest_form",
    "stability_of",
]

#: The general theory's numbers and propositions, for k = 1, k = 2 and k >= 3 contacts.
NUMBERS = Numbering(
    {
        "coefficient": ((), ("4.6",), ("4.6",)),
        "hurwitz": (("3.2",), ("4.7",), ("4.7",)),
        "stable for every law": (("3.2",), ("4.4",), ("4.4",)),
        "unstable for every law": (("3.2",), (), ()),
        "Hopf line": ((), ("4.7",), ("4.7",)),
        "unique for every load": (("3.3",),) * 3,
    },
    {
        "stable for every law": ("Proposition 3", "Proposition 6", "Proposition 7"),
        "unstable for every law": ("Proposition 3", "Proposition 6", "Proposition 8"),
        "law-dependent": ("", "Remarks 1-2: Hopf bifurcation possible", ""),
        "Hopf line": ("", "Delta_3 = 0: Remarks 1-2", ""),
        "unique for every load": ("Proposition 4", "", ""),
    },
)

#: The robustness statements that :meth:`Stability.formulas` prints, with their attributes.
_STATEMENTS = (
    ("stable for every law", "robustly_stable"),
    ("unstable for every law", "robustly_unstable"),
    ("law-dependent", "law_dependent"),
    ("Hopf line", "hopf"),
)


#: How a statement that is neither proved nor disproved prints.
UNDECIDED_TEX = r"\text{undecided}"


def robustness_regions(A: sp.Matrix, minors: dict | None = None) -> dict:
    """:func:`contactsym.robustness.classify.regions`, imported when first needed (k >= 3): it brings
    scipy.optimize, a second of import time that scenes with k <= 2 never pay."""
    from ..robustness.classify import regions  # scipy.optimize: imported for k >= 3 only

    return regions(A, minors=minors)


def _gt(expr) -> sp.Basic:
    return sp.Gt(expr, 0)


@dataclass(frozen=True, eq=False)
class Stability(LatexReprMixin):
    """Stability conditions of one sign pattern (or all, with sign symbols).

    Attributes
    ----------
    hurwitz : list
        Expressions that are all > 0 exactly when (4.5) is asymptotically stable.
    robustly_stable, robustly_unstable : sympy Boolean or None
        Stable (unstable) for every admissible law (1.5). Three-valued as SymPy's logic: for a
        numeric A ``true`` where proved, ``false`` where disproved, None where undecided (it
        agrees with ``robustness``); for a symbolic A the region where it is proved, and
        ``verdicts`` says where it is disproved.
    law_dependent : sympy Boolean or None
        Stable for some laws and unstable for others (for k >= 3 a sufficient region), three-valued alike.
    verdicts : dict of Verdict
        The three statements by attribute name, each with its proved and disproved regions.
    robustness : Robustness or None
        For a numeric A and k >= 3: the point decision with its certificate or witness laws.
    undecided : sympy Boolean
        Where no statement is proved (det A = 0 for k <= 2).
    hopf : sympy Boolean
        Delta_(n-1) = 0 with the other Hurwitz conditions positive.
    hopf_frequency : sympy expression or None
        omega on the Hopf set, in the stretched time tau.

    Examples
    --------
    >>> import contactsym as cs
    >>> st = cs.scene("sliding-point").stability()
    >>> st.robustly_stable
    True
    """

    linearization: object

    @cached_property
    def A(self) -> sp.Matrix:
        return self.linearization.A

    @cached_property
    def k(self) -> int:
        return self.linearization.fast.k

    @cached_property
    def routh_hurwitz(self) -> Hurwitz:
        """The Routh–Hurwitz data of the characteristic polynomial (4.6): minors, conditions (4.7),
        Liénard–Chipart labels, the Hopf set and omega**2 (``poly`` is its deprecated name)."""
        if self.linearization.det_A == 0:  # the canonical form: 0 is the only form of zero, no expand needed
            raise SingularJacobianError(
                f"det A = 0 identically for A = {self.A.tolist()}: the equilibrium is not isolated and has a "
                "zero eigenvalue for every law; the propositions need det A != 0. Check the scene's reactions."
            )
        numbers, _ = NUMBERS("hurwitz", self.k, self.linearization.fast.paper_equations)
        return Hurwitz(self.linearization.charpoly, numbers)

    poly = deprecated_property("routh_hurwitz", "poly")

    @cached_property
    def hurwitz(self) -> list[sp.Expr]:
        logging.getLogger("contactsym").info("Hurwitz conditions (4.7) of a degree-%d polynomial", 2 * self.k)
        return self.routh_hurwitz.conditions

    @cached_property
    def _closed(self) -> dict | None:
        """The closed-form regions of :func:`contactsym.robustness.classify.regions` (k >= 3)."""
        if self.k < 3:
            return None
        # with the principal minors given, regions reads A's shape only: A's entries are not computed
        return robustness_regions(sp.zeros(self.k), self.linearization.principal_minors)

    @cached_property
    def _classification(self) -> tuple:
        """The regions where each statement is proved (Propositions 3-8 and the closed forms):
        :func:`contactsym.stages.classification.proved_regions`."""
        positive = self.linearization.fast.positive
        leading = None
        if self.k >= 3:  # det A[:m, :m] from the minors the scene has (factored over det M), not from A again
            leading = [self.linearization.principal_minors[tuple(range(m))] for m in range(1, self.k + 1)]
        return proved_regions(self._sign_matrix, self.linearization.det_A, self._closed, positive, leading=leading)

    @cached_property
    def _read_of_A(self) -> tuple[sp.Matrix, bool]:
        """:func:`~contactsym.stages.classification.classification_matrix`: what the classification reads
        of A, with no division where A's entries would each need a gcd, and whether A has symbols."""
        return classification_matrix(self.linearization)

    @property
    def _sign_matrix(self) -> sp.Matrix:
        return self._read_of_A[0]

    @property
    def _symbolic(self) -> bool:
        return self._read_of_A[1]

    @cached_property
    def verdicts(self) -> dict[str, Verdict]:
        """Each robustness statement by attribute name, with where it is proved and where disproved.

        For a numeric A (k >= 3) that the closed forms leave open, the point decision
        :attr:`robustness` is added as evidence. See :mod:`contactsym.stages.verdicts`.
        """
        proved = dict(zip(VERDICT_NAMES, self._classification))
        verdicts = classification_verdicts(self.k, proved, self._closed)
        if self.k < 3 or self._symbolic or all(v.at() is not None for v in verdicts.values()):
            return verdicts
        return with_point_decision(verdicts, self.robustness)

    def _verdict(self, name: str) -> sp.Basic | None:
        verdict = self.verdicts[name]
        return verdict.proved if self._symbolic else verdict.at()

    @cached_property
    def robustly_stable(self) -> sp.Basic | None:
        return self._verdict("robustly_stable")

    @cached_property
    def robustly_unstable(self) -> sp.Basic | None:
        return self._verdict("robustly_unstable")

    @cached_property
    def law_dependent(self) -> sp.Basic | None:
        return self._verdict("law_dependent")

    @cached_property
    def robustness(self) -> Robustness | None:
        """The point decision of :func:`contactsym.robustness.classify.decide_robustness` for a numeric A (k >= 3), else None."""
        if self.k < 3 or self._symbolic or self.linearization.det_A == 0:
            return None
        from ..robustness.classify import decide_robustness  # see robustness_regions: imported for k >= 3 only

        return decide_robustness(self.A)

    @cached_property
    def undecided(self) -> sp.Basic:
        """Where no statement is proved: a region for a symbolic A, ``true`` or ``false`` for a numeric one."""
        return sp.Not(sp.Or(*[self.verdicts[name].proved for name in VERDICT_NAMES]))

    @cached_property
    def hopf(self) -> sp.Basic:
        if self.k == 1:
            return sp.false  # p_1 = -a Psi and p_0 = -a Phi vanish together: no Hopf point
        return self.routh_hurwitz.hopf_set

    @cached_property
    def hopf_frequency(self) -> sp.Expr | None:
        if self.k == 1 or self.routh_hurwitz.omega_squared is None:
            return None
        omega_squared = self.routh_hurwitz.omega_squared
        if expansion_bound(omega_squared) > EXPAND_TERMS:  # kept as N/Delta_(n-3): sqrt would ask each factor's sign
            return sp.Pow(omega_squared, sp.S.Half, evaluate=False)
        return sp.sqrt(omega_squared)

    @cached_property
    def _short_coefficients(self) -> dict:
        """{p_s: its shortest exact form, -p_s: minus it} for the polynomial coefficients of (4.6)."""
        fast = self.linearization.fast
        law_symbols = set().union(*[sp.sympify(e).free_symbols for e in (*fast.Phi, *fast.Psi)])
        shorter = {}
        for coefficient in self.linearization.charpoly.all_coeffs():
            short = shortest_form(sp.sympify(coefficient), law_symbols)
            if short is not coefficient:
                shorter.update({coefficient: short, -coefficient: -short})
        return shorter

    @cached_property
    def hopf_printed(self) -> sp.Basic:
        """:attr:`hopf` with each coefficient p_s of (4.6) in its shortest form (:func:`shortest_form`): the same set."""
        return self.hopf.xreplace(self._short_coefficients) if self.hopf not in (sp.true, sp.false) else self.hopf

    @cached_property
    def hopf_frequency_printed(self) -> sp.Expr | None:
        """:attr:`hopf_frequency` with each coefficient p_s of (4.6) in its shortest form: the same number.

        Examples
        --------
        >>> import contactsym as cs
        >>> st = cs.scene("brake").stability()
        >>> sp.expand(st.hopf_frequency_printed**2 - st.hopf_frequency**2)
        0
        """
        omega = self.hopf_frequency
        return None if omega is None else omega.xreplace(self._short_coefficients)

    @cached_property
    def first_lyapunov(self) -> sp.Expr | None:
        """The first Lyapunov coefficient l1 of (2.1) at the equilibrium, valid on the Hopf set.

        l1 < 0: supercritical (a small stable cycle past the line, amplitude ~ sqrt(distance));
        l1 > 0: subcritical (a jump and hysteresis). Normalization ``<q, q> = <p, q> = 1`` in
        (u, v); only the sign is invariant. A generic law contributes its derivatives at
        (u*, 0) as symbols (``Phi_1_u`` = dPhi_1/du_1, ...). None where there is no Hopf set.
        See :mod:`contactsym.lyapunov.coefficient`.
        """
        return first_lyapunov_symbolic(self)

    # --- k = 1: Propositions 3, 4, 5 ------------------------------------------------

    @cached_property
    def propositions(self) -> dict[str, sp.Basic]:
        """The propositions that apply, by name, each with its condition."""
        if self.k == 1:
            return {
                "Proposition 3 (stable)": self.robustly_stable,
                "Proposition 3 (unstable)": self.robustly_unstable,
                "Proposition 4 (unique stable reaction for every load)": self.unique_for_every_load,
                "Proposition 5 (no cycles)": sp.true if self.no_cycles else sp.false,
            }
        if self.k == 2:
            return {
                "Proposition 6 (stable for every law)": self.robustly_stable,
                "Proposition 6 (unstable for every law)": self.robustly_unstable,
                "Remarks 1-2 (law-dependent, Hopf possible)": self.law_dependent,
            }
        closed = self._closed
        return {
            "Proposition 7 (stable for every law)": self.robustly_stable,
            "Proposition 8 (unstable for every law)": self.robustly_unstable,
            "some p_s <= 0 for every law (unstable for every law)": closed["unstable for every law"],
            "nested positive principal minors (a stable law exists)": closed["stable law exists"],
            "a negative principal minor (an unstable law exists)": closed["unstable law exists"],
        }

    @cached_property
    def unique_for_every_load(self) -> sp.Basic:
        """Proposition 4: f' > 0 on every piece of f (k = 1 only)."""
        fast = self.linearization.fast
        slopes = []
        for pattern in fast.sign_patterns():
            slope = fast.piece(pattern).jacobian(fast.u)[0]
            slopes.append(_gt(normalize(slope)))
        return sp.And(*slopes)

    @cached_property
    def no_cycles(self) -> bool:
        """Proposition 5: constant Phi and Psi exclude periodic solutions (k = 1)."""
        return self.k == 1 and self.linearization.fast.constant_laws

    # --- formulas -------------------------------------------------------------------

    @checked
    def formulas(self, present: bool = False) -> tuple[Formula, ...]:
        """The conditions (4.7) by name, the robustness statements, omega and the point decision."""
        fast = self.linearization.fast
        show = fast.present if present else (lambda expr: expr)

        def row(key, lhs, rhs, relation="="):
            return NUMBERS.formula(key, lhs, rhs, k=self.k, own=fast.paper_equations, relation=relation)

        names = hurwitz_names(self)
        generic = generic_minors(self.linearization.charpoly.degree(), hurwitz_letters(self)["p"])
        rows = []
        for name, (kind, index), condition in zip(names, self.routh_hurwitz.labels, self.hurwitz):
            if kind == "Delta":
                rows += [row("hurwitz", name, generic[index]), row("hurwitz", "", show(condition))]
            else:
                rows.append(row("coefficient", name, show(condition)))
        rows.append(row("hurwitz", ", ".join(names), sp.S.Zero, ">"))
        for key, attribute in _STATEMENTS:
            value = self.hopf_printed if attribute == "hopf" else getattr(self, attribute)
            rows.append(row(key, r"\text{" + key + "}", UNDECIDED_TEX if value is None else show(value), ":"))
        if self.k >= 3 and self._symbolic and self.undecided != sp.false:
            rows.append(row("undecided", r"\text{undecided}", show(self.undecided), ":"))
        if self.hopf_frequency is not None:
            omega = OwnLetters(fast._taken).tex("omega")  # omegahat beside a scene's omega
            rows.append(row("hopf frequency", omega, show(self.hopf_frequency_printed)))
        return tuple(rows) + robustness_formulas(self.robustness)


def stability_of(fast, signs=None) -> Stability:
    """The Stability of the fast subsystem ``fast`` on the sign pattern ``signs``, built once per fast
    subsystem: :class:`~contactsym.stages.equilibria.Equilibria` and the scene share it.

    Examples
    --------
    >>> import contactsym as cs
    >>> fast = cs.scene("brake").fast_subsystem()
    >>> stability_of(fast).linearization is cs.scene("brake").linearization()
    True
    """
    return fast.later_stage(("stability", signs), lambda: Stability(linearization_of(fast, signs)))
