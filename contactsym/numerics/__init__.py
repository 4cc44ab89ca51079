"""Numerics (being split into modules by job)."""

from .simulate import *  # noqa: F403
from .simulate import __all__, __doc__  # noqa: F401
from .simulate import (  # noqa: F401
    NumericsError,
    _branch_at,
    _cached,
    _contact_law,
    _in_domain,
    _laws_key,
    _one_signed_form,
    _one_signed_sums,
    _through_tan,
    _Values,
    first_lyapunov,
    hopf_point,
)
