"""Errors raised by contactsym. Each message says what is wrong and how to fix it."""

from __future__ import annotations


class ContactsymError(ValueError):
    """Base class: bad input or a question the mathematics cannot answer."""


class ComplianceError(ContactsymError):
    """A compliance law breaks the sign or scaling conditions (1.5), (1.8)."""


class SceneError(ContactsymError):
    """A scene is ill-formed: unknown coordinate, no reaction, unknown name."""


class SingularJacobianError(ContactsymError):
    """det A vanishes where a proposition or a solve needs A^{-1}."""


class SignPatternError(ContactsymError):
    """A sign pattern has the wrong length or values other than +1 and -1."""


class HopfError(ContactsymError):
    """A Hopf question asked where it has no answer: off the Hopf set, or no oscillatory pair."""


class NumericsError(ContactsymError):
    """Bad numeric input (non-finite parameter, eps <= 0, missing value) or a failed solve."""

    # defined here, at the bottom of the import graph, so that the input checks (validate, progress) can raise it
    # without importing the numerics they serve; users meet it, and import it, as contactsym.numerics.NumericsError
    __module__ = "contactsym.numerics"
