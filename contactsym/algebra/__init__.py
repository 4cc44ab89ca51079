"""Algebra under every stage: the canonical form in several angles, the reductions modulo
sin^2 + cos^2 = 1 and s^2 = 1, fraction-free linear algebra, Routh–Hurwitz conditions,
Fourier presentation and interval signs. No ``simplify`` anywhere.
"""

from .basic import normalize, present
from .canonical_form import TrigField, TrigFraction, canonical, to_fraction
from .fourier import best_form
from .fraction_free import adjugate_and_det, adjugate_and_det_in_field, polynomial_adjugate, solve_fraction_free, t
from .hurwitz import Hurwitz, hopf_omega_squared, hurwitz_matrix, hurwitz_minors, lienard_chipart
from .intervals import interval_sign
from .reductions import SignSymbol, known_sign, reduce_signs, reduce_trig, sign_symbols

__all__ = [
    "Hurwitz",
    "SignSymbol",
    "TrigField",
    "TrigFraction",
    "adjugate_and_det",
    "adjugate_and_det_in_field",
    "best_form",
    "canonical",
    "hopf_omega_squared",
    "hurwitz_matrix",
    "hurwitz_minors",
    "interval_sign",
    "known_sign",
    "lienard_chipart",
    "normalize",
    "polynomial_adjugate",
    "present",
    "reduce_signs",
    "reduce_trig",
    "sign_symbols",
    "solve_fraction_free",
    "t",
    "to_fraction",
]
