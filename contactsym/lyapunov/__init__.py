"""The first Lyapunov coefficient l1 of a Hopf point of the fast subsystem (2.1): numerically,
symbolically, and as an explicit polynomial in the law's derivatives.
"""

from .coefficient import HopfVectors, hopf_vectors_45, lyapunov_numeric, lyapunov_symbolic
from .polynomial import first_lyapunov_polynomial

__all__ = [
    "HopfVectors",
    "first_lyapunov_polynomial",
    "hopf_vectors_45",
    "lyapunov_numeric",
    "lyapunov_symbolic",
]
