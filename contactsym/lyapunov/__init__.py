"""The first Lyapunov coefficient l1 of a Hopf point of the fast subsystem (2.1).

One concept, l1 (its sign tells a soft from a hard onset of the cycle), in four variants:

- :func:`first_lyapunov_symbolic` ``(stability)``: symbolic, for a scene's equilibrium on its
  Hopf set; the same as the stage attribute :attr:`Stability.first_lyapunov`;
- :func:`first_lyapunov_polynomial` ``(stability, at)``: symbolic, as an explicit polynomial in
  the derivatives of generic laws;
- :func:`contactsym.numerics.first_lyapunov_at` ``(scene, values)``: numeric, at a parameter point
  on the Hopf set, with the predicted cycle (:func:`contactsym.numerics.hopf_point` moves a point there);
- :func:`first_lyapunov_from_derivatives` ``(J, H, T)``: numeric, for any vector field, from its
  derivative tensors at the point (the kernel of the numeric variant).

:func:`lyapunov_symbolic` is the symbolic kernel: l1 from the derivative forms and the eigenvectors.
"""

from .coefficient import (
    HopfVectors,
    first_lyapunov_from_derivatives,
    first_lyapunov_symbolic,
    hopf_vectors_45,
    lyapunov_symbolic,
)
from .coefficient import lyapunov_numeric as lyapunov_numeric  # the name of 0.1, deprecated
from .polynomial import first_lyapunov_polynomial

__all__ = [
    "HopfVectors",
    "first_lyapunov_from_derivatives",
    "first_lyapunov_polynomial",
    "first_lyapunov_symbolic",
    "hopf_vectors_45",
    "lyapunov_symbolic",
]
