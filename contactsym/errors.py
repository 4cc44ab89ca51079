"""Errors raised by contactsym. Each message says what is wrong and how to fix it."""

from __future__ import annotations


class ContactsymError(ValueError):
    """Base class: bad input or a question the mathematics cannot answer.

    Examples
    --------
    Every package error is a ``ContactsymError`` (and a ``ValueError``), so one ``except`` catches them all:

    >>> import contactsym as cs
    >>> try:
    ...     cs.scene("no-such-scene")
    ... except cs.ContactsymError as error:
    ...     print(type(error).__name__, isinstance(error, ValueError))
    SceneError True
    """


class ComplianceError(ContactsymError):
    """A compliance law breaks the sign or scaling conditions (1.5), (1.8).

    Examples
    --------
    A negative friction coefficient is refused when the law is built:

    >>> import contactsym as cs
    >>> try:
    ...     cs.Coulomb(-1, {})
    ... except cs.ComplianceError as error:
    ...     print(error)
    the friction coefficient mu = -1 is negative; Coulomb friction opposes sliding, so mu >= 0.
    """


class SceneError(ContactsymError):
    """A scene is ill-formed: unknown coordinate, no reaction, unknown name.

    Examples
    --------
    >>> import contactsym as cs
    >>> try:
    ...     cs.scene("no-such-scene")
    ... except cs.SceneError as error:
    ...     print(str(error).split(";")[0])
    unknown scene 'no-such-scene'
    """


class SingularJacobianError(ContactsymError):
    """det A vanishes where a proposition or a solve needs A^{-1}.

    Examples
    --------
    Solving a piece whose linear equations are dependent (det A = 0):

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> from contactsym.stages.fast import solve_piece
    >>> a, b = sp.symbols("a b")
    >>> try:
    ...     solve_piece(sp.Matrix([a + b - 1, 2*a + 2*b]), (a, b), (1,))
    ... except cs.SingularJacobianError as error:
    ...     print(str(error).split(":")[0])
    det A = 0 on the piece with signs (1,)
    """


class SignPatternError(ContactsymError):
    """A sign pattern has the wrong length or values other than +1 and -1.

    Examples
    --------
    >>> import contactsym as cs
    >>> try:
    ...     cs.conditions(cs.scene("painleve-klein-guides"), signs=(1, 2))
    ... except cs.SignPatternError as error:
    ...     print(error)
    sign 2 at position 1 must be +1 or -1; write e.g. (1, -1).
    """


class HopfError(ContactsymError):
    """A Hopf question asked where it has no answer: off the Hopf set, or no oscillatory pair."""


class NumericsError(ContactsymError):
    """Bad numeric input (non-finite parameter, eps <= 0, missing value) or a failed solve.

    Examples
    --------
    A sign asked for without a value for one of the symbols:

    >>> import sympy as sp
    >>> from contactsym.numerics import NumericsError, certified_sign
    >>> x, y = sp.symbols("x y")
    >>> try:
    ...     certified_sign(x - y, {x: 0.1})
    ... except NumericsError as error:
    ...     print(error)
    no value for y; add it to values.
    """

    # defined here, at the bottom of the import graph, so that the input checks (validate, progress) can raise it
    # without importing the numerics they serve; users meet it, and import it, as contactsym.numerics.NumericsError
    __module__ = "contactsym.numerics"
