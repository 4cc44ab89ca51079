"""Errors raised by contactsym, all in this one module. Each message says what is wrong and how to fix it.

Every error is a :class:`ContactsymError` (a ``ValueError``); the modules that raise them
also import them, so the paths of 0.1 (``contactsym.parse.ParseError``, ...) still work.
"""

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


class ParseError(ContactsymError):
    """A formula that is not in the grammar of :mod:`contactsym.parse`, or names an unknown symbol."""


class SceneFileError(SceneError):
    """A scene file that cannot be read: bad TOML, an unknown key, a missing table or a bad formula."""


class ReportError(ContactsymError):
    """The report could not be written or compiled."""


class AtlasError(ContactsymError):
    """A sweep that cannot start (bad grid, unknown quantity, unreachable scheduler, foreign store)."""


class UsageError(AtlasError):
    """A bad ``contactsym atlas`` command line (exit code 2)."""


class NumericsError(ContactsymError):
    """Bad numeric input (non-finite parameter, eps <= 0, missing value) or a failed solve."""

    # defined here, at the bottom of the import graph, so that the input checks (validate, progress) can raise it
    # without importing the numerics they serve; users meet it, and import it, as contactsym.numerics.NumericsError
    __module__ = "contactsym.numerics"
