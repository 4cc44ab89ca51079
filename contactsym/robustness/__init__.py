"""Robustness to the contact law for any number of contacts: the Liénard–Chipart conditions as
polynomials in the law, certificates of stability or instability, and witness laws.
"""

from ..deprecation import deprecated_names
from .certificates import (
    amgm_certificate,
    climbed_laws,
    damped_positivstellensatz_certificate,
    fisher_fuller_laws,
    generic_vertex_coefficients,
    positivstellensatz_certificate,
    rational_law,
    sampled_laws,
    vertex_laws,
    weak_damping_laws,
)
from .classify import Certificate, Robustness, WitnessLaw, decide_robustness, nested_sequences, regions
from .classify import decide as decide  # the name of 0.1, deprecated
from .law_polynomials import LawPolynomials, fast_spectral_abscissa, law_ring

__all__ = [
    "Certificate",
    "LawPolynomials",
    "Robustness",
    "WitnessLaw",
    "amgm_certificate",
    "climbed_laws",
    "damped_positivstellensatz_certificate",
    "decide_robustness",
    "fast_spectral_abscissa",
    "fisher_fuller_laws",
    "generic_vertex_coefficients",
    "law_ring",
    "nested_sequences",
    "positivstellensatz_certificate",
    "rational_law",
    "regions",
    "sampled_laws",
    "vertex_laws",
    "weak_damping_laws",
]

# 0.1's robustness.Law, renamed: contactsym.Law is the public contact law
__getattr__ = deprecated_names(__name__, {"Law": "WitnessLaw"}, globals())
