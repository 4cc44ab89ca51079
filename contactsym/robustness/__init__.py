"""Robustness to the contact law for any number of contacts: the Liénard–Chipart conditions as
polynomials in the law, certificates of stability or instability, and witness laws.
"""

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
from .classify import Certificate, Law, Robustness, decide, nested_sequences, regions
from .law_polynomials import LawPolynomials, fast_spectral_abscissa, law_ring

__all__ = [
    "Certificate",
    "Law",
    "LawPolynomials",
    "Robustness",
    "amgm_certificate",
    "climbed_laws",
    "damped_positivstellensatz_certificate",
    "decide",
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
