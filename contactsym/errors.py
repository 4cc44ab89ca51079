"""Errors raised by contactsym, all in this one module. Each message says what is wrong and how to fix it.

Every error is a :class:`ContactsymError` (a ``ValueError``); the modules that raise them
also import them, so the paths of 0.1 (``contactsym.parse.ParseError``, ...) still work.
"""

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
    ...     cs.scene("painleve-klein-guides").stability(signs=(1, 2))
    ... except cs.SignPatternError as error:
    ...     print(error)
    sign 2 at position 1 must be +1 or -1; write e.g. (1, -1).
    """


class HopfError(ContactsymError):
    """A Hopf question asked where it has no answer: off the Hopf set, or no oscillatory pair.

    Examples
    --------
    The brake at alpha = 0.3 with a damping law has no Hopf crossing near mu = 0.1:

    >>> import contactsym as cs
    >>> from contactsym import numerics
    >>> values = {"m": 1, "mu": 0.1, "alpha": 0.3, "F_x": 0, "F_y": -4}
    >>> values.update({"Phi_1": -1, "Phi_2": -1, "Psi_1": -1, "Psi_2": -1})
    >>> try:
    ...     numerics.hopf_point(cs.scene("brake"), values, "mu")
    ... except HopfError as error:
    ...     print(str(error).split(":")[0])
    Re lambda of the critical pair keeps the sign of -0.0226 within 90% of the start value
    """


class ParseError(ContactsymError):
    """A formula that is not in the grammar of :mod:`contactsym.parse`, or names an unknown symbol.

    Examples
    --------
    The message points at the line and column of the formula:

    >>> import sympy as sp
    >>> from contactsym.parse import parse_expression
    >>> try:
    ...     parse_expression("x + y", {"x": sp.Symbol("x")})
    ... except ParseError as error:
    ...     print(str(error).split(";")[0])
    <formula>:1:5: unknown name 'y'
    """


class SceneFileError(SceneError):
    """A scene file that cannot be read: bad TOML, an unknown key, a missing table or a bad formula.

    Examples
    --------
    The message names the file and line, and what to write instead:

    >>> from contactsym.mechanism.files import read_scene
    >>> try:
    ...     read_scene('[scene]\\ncoordinates = ["y"]\\n[[contacts]]\\ngapp = "y"\\n', "a.toml")
    ... except SceneFileError as error:
    ...     print(str(error).split(";")[0])
    a.toml:4: unknown key 'gapp' in [contacts.0]
    """


class ReportError(ContactsymError):
    """The report could not be written or compiled.

    Examples
    --------
    A report never replaces a folder that contactsym did not write:

    >>> import tempfile
    >>> from pathlib import Path
    >>> import contactsym as cs
    >>> with tempfile.TemporaryDirectory() as directory:
    ...     _ = (Path(directory) / "notes.txt").write_text("mine")
    ...     try:
    ...         cs.write_report(cs.scene("sliding-point"), directory, pdf=False)
    ...     except ReportError as error:
    ...         print("was not written by contactsym" in str(error), (Path(directory) / "notes.txt").exists())
    True True
    """


class AtlasError(ContactsymError):
    """A sweep that cannot start (bad grid, unknown quantity, unreachable scheduler, foreign store).

    Examples
    --------
    >>> from contactsym import atlas
    >>> try:
    ...     atlas.as_quantity("no-such-quantity")
    ... except AtlasError as error:
    ...     print(str(error).split(";")[0])
    unknown quantity 'no-such-quantity'
    """


class UsageError(AtlasError):
    """A bad ``contactsym atlas`` command line (exit code 2).

    Examples
    --------
    >>> from contactsym.atlas.cli import parse_axis
    >>> try:
    ...     parse_axis("mu=0:3")
    ... except UsageError as error:
    ...     print(error)
    --grid mu=0:3: write NAME=START:STOP:COUNT or NAME=V1,V2,...
    """


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


class ArgumentError(ContactsymError, TypeError):
    """An argument of the wrong type or of an impossible value, refused where it enters a public callable.

    Raised by the checks of :mod:`contactsym.arguments`; it is a ``ContactsymError`` (so one
    ``except`` still catches every package error) and a ``TypeError``.

    Examples
    --------
    >>> from contactsym.algebra import hurwitz_matrix
    >>> try:
    ...     hurwitz_matrix("x**2 + 1")
    ... except ArgumentError as error:
    ...     print(error)
    hurwitz_matrix: coefficients = 'x**2 + 1' (str) is not accepted; pass a list or tuple, each item a finite SymPy expression (or relation) or a number.
    """
