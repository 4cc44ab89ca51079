"""Checks at the public boundary: every bad input becomes one of the package's own errors.

Each function takes what a user passed, checks its type, shape and finiteness, and
returns it in the form the pipeline expects, or raises a :class:`ContactsymError`
subclass whose message says what is wrong and how to fix it. User text in messages is
cut to :data:`SHOWN` characters, so a huge name cannot flood a terminal.

Text that would have to be parsed is not handled here: no function in this module
passes anything to ``sympify`` that is not already a number or a SymPy object.
The text-cutting rule (:func:`cut`, :func:`shorten`) and the checks of flags, paths and
dataclass fields are defined in :mod:`contactsym.boundary.plain_values`.

Examples
--------
>>> sign_pattern([1, -1])
(1, -1)
>>> sign_pattern([1, 0])
Traceback (most recent call last):
...
contactsym.errors.SignPatternError: sign 0 at position 1 must be +1 or -1; write e.g. (1, -1).
>>> shorten("ab" * 1000, limit=10)
"'ababababa... (2002 characters)"
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import numpy as np
import sympy as sp
from sympy.physics.vector import Point, ReferenceFrame, Vector

from .boundary.plain_values import NUMBER_TYPES, SHOWN, checked_fields, cut, flag, instance_of, path_text, shorten
from .errors import ComplianceError, ContactsymError, NumericsError, SceneError, SignPatternError

__all__ = [
    "SHOWN",
    "chunk_size",
    "checked_fields",
    "flag",
    "instance_of",
    "path_text",
    "contact_fields",
    "cut",
    "finite_expression",
    "finite_number",
    "friction_coefficient",
    "lagrangian_parts",
    "output_times",
    "positive_parameter",
    "reactions_act",
    "real_array",
    "scene_name",
    "scene_options",
    "scene_parts",
    "shorten",
    "sign_pattern",
    "solver_method",
]

_NOT_FINITE = (sp.nan, sp.zoo, sp.oo, sp.S.NegativeInfinity)


def _sequence(value, what: str, hint: str, error=SceneError) -> tuple:
    """A list or tuple (or other finite iterable that is not text or a mapping) as a tuple."""
    if isinstance(value, (str, bytes, dict)) or not isinstance(value, Iterable):
        raise error(f"{what} must be a list, not {type(value).__name__} {shorten(value)}; {hint}.")
    return tuple(value)


# --- SymPy objects and numbers ---------------------------------------------------------------


def finite_expression(expr, what: str, error=SceneError) -> sp.Expr:
    """A SymPy object or number without nan, oo or zoo in it.

    Examples
    --------
    >>> import sympy as sp
    >>> finite_expression(sp.Symbol("N") + 1, "the acceleration")
    N + 1
    >>> finite_expression(float("inf") * sp.Symbol("N"), "the acceleration")
    Traceback (most recent call last):
    ...
    contactsym.errors.SceneError: the acceleration = oo*N is not finite (it contains oo); write it with finite numbers.
    """
    if isinstance(expr, NUMBER_TYPES) and not isinstance(expr, bool):
        expr = sp.sympify(expr)
    if not isinstance(expr, sp.Basic):
        raise error(f"{what} must be a SymPy expression or a number, not {type(expr).__name__} {shorten(expr)}.")
    bad = [str(b) for b in _NOT_FINITE if expr.has(b)]
    if bad:
        kind = "is not a number" if bad == ["nan"] else "is not finite"
        raise error(f"{what} = {shorten(expr)} {kind} (it contains {', '.join(bad)}); write it with finite numbers.")
    return expr


def positive_parameter(value, what: str, why: str, error=SceneError) -> None:
    """Reject wrong types, nan and infinities in a parameter that must be a finite positive number or symbol.

    Text is let through: whoever parses it checks the result again.
    """
    if isinstance(value, str):
        return
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (sp.Basic, *NUMBER_TYPES)):
        raise error(f"{what} must be a number or a SymPy symbol, not {type(value).__name__} {shorten(value)}.")
    if isinstance(value, NUMBER_TYPES):
        value = sp.sympify(value)
    if value.has(*_NOT_FINITE):
        kind = "not a number" if value.has(sp.nan) else "infinite"
        raise error(f"{what} = {shorten(value)} is {kind}; {why}: pass a finite positive number or positive Symbol.")


def friction_coefficient(mu, what: str = "the friction coefficient mu") -> sp.Expr:
    """A finite friction coefficient that is not negative (a symbol is taken as it is declared).

    Examples
    --------
    >>> friction_coefficient(0.5)
    0.500000000000000
    >>> friction_coefficient(-0.5)
    Traceback (most recent call last):
    ...
    contactsym.errors.ComplianceError: the friction coefficient mu = -0.500000000000000 is negative; Coulomb friction opposes sliding, so mu >= 0.
    """
    if isinstance(mu, (str, bytes)):
        raise ComplianceError(f"{what} = {shorten(mu)} is text; pass a number or a SymPy symbol such as mu.")
    mu = finite_expression(mu, what, ComplianceError)
    if mu.is_negative:
        raise ComplianceError(f"{what} = {shorten(mu)} is negative; Coulomb friction opposes sliding, so mu >= 0.")
    if mu.is_real is False:
        raise ComplianceError(f"{what} = {shorten(mu)} is not real; pass a real number.")
    return mu


# --- scenes ------------------------------------------------------------------------------------


def named_once(pairs, option: str = "--set") -> dict:
    """``(name, value)`` pairs of a repeated option as a dict, each name once: a second value for a
    name is refused, never kept silently in place of the first.

    Examples
    --------
    >>> named_once([("m", 1), ("mu", 2)])
    {'m': 1, 'mu': 2}
    >>> named_once([("m", 2), ("m", 3)])
    Traceback (most recent call last):
    ...
    contactsym.errors.ContactsymError: --set m is given twice (2 and 3); give each name once.
    """
    found: dict = {}
    for name, value in pairs:
        if name in found:
            raise ContactsymError(f"{option} {name} is given twice ({found[name]} and {value}); give each name once.")
        found[name] = value
    return found


def scene_name(name) -> str:
    """A scene name must be text (the message never repeats more than SHOWN characters of it)."""
    if not isinstance(name, str):
        raise SceneError(f"a scene name must be text such as 'brake', not {type(name).__name__} {shorten(name)}.")
    return name


def _coordinate(q) -> sp.Basic:
    if not isinstance(q, (sp.core.function.AppliedUndef, sp.Symbol)):
        raise SceneError(
            f"coordinate {shorten(q)} ({type(q).__name__}) is not a coordinate; "
            "make them with sympy.physics.mechanics.dynamicsymbols('x y')."
        )
    return q


def scene_parts(coordinates, accelerations, contacts, *, derived: bool = False) -> tuple[tuple, tuple | None, tuple]:
    """Coordinates, accelerations and contacts of a scene, checked for type and shape.

    ``derived``: the accelerations come later from a Lagrangian, so None is expected.

    Examples
    --------
    >>> import sympy as sp
    >>> from sympy.physics.mechanics import dynamicsymbols
    >>> from contactsym import Contact
    >>> y = dynamicsymbols("y")
    >>> scene_parts([y], [sp.Symbol("N") - 1, 7], [Contact(y, sp.Symbol("N"))])
    Traceback (most recent call last):
    ...
    contactsym.errors.SceneError: got 2 accelerations for 1 coordinates; give one per coordinate.
    """
    coordinates = _sequence(coordinates, "coordinates", "e.g. dynamicsymbols('x y')")
    coordinates = tuple(_coordinate(q) for q in coordinates)
    if not coordinates:
        raise SceneError("a scene needs at least one coordinate.")
    if len(set(coordinates)) != len(coordinates):
        raise SceneError(f"a coordinate is listed twice in {shorten(list(coordinates))}; list each once.")
    if not (derived and accelerations is None):
        accelerations = _check_accelerations(coordinates, accelerations)
    contacts = _sequence(contacts, "contacts", "give a list of Contact(coordinate=..., reaction=...)")
    for index, contact in enumerate(contacts):
        if not _is_contact(contact):
            raise SceneError(
                f"contact {index} is a {type(contact).__name__} {shorten(contact)}; "
                "write Contact(coordinate=y, reaction=N) for each contact."
            )
    if not contacts:
        raise SceneError("a scene needs at least one Contact.")
    return coordinates, accelerations, contacts


def _is_contact(value) -> bool:
    """A scene.Contact, recognised by its fields: scene.py imports this module, so it cannot be imported here."""
    return all(hasattr(value, name) for name in ("coordinate", "reaction", "compliance", "friction", "unilateral"))


def scene_options(name, description, at, presentation, parameters, positive, solve_for) -> None:
    """The keyword options of a Scene: text, mappings, sequences of SymPy objects."""
    for what, text in (("name", name), ("description", description)):
        if not isinstance(text, str):
            raise SceneError(f"{what} must be text, not {type(text).__name__} {shorten(text)}.")
    for what, mapping in (("at", at), ("presentation", presentation)):
        if mapping is not None and not isinstance(mapping, dict):
            raise SceneError(f"{what} must be a dict {{symbol: expression}}, not {type(mapping).__name__}.")
        for key, value in (mapping or {}).items():  # text is refused by parse.sympy_only
            if not isinstance(key, (str, bytes)):
                finite_expression(key, f"a key of {what}")
            if not isinstance(value, (str, bytes)):
                finite_expression(value, f"{what}[{shorten(key)}]")
    if parameters is not None:
        for symbol in _sequence(parameters, "parameters", "give a list of sympy Symbols"):
            if not isinstance(symbol, sp.Symbol):
                raise SceneError(f"parameter {shorten(symbol)} is not a sympy Symbol.")
    for expr in _sequence(positive, "positive", "give a tuple of expressions positive in the scene's domain"):
        finite_expression(expr, "an expression of positive")
    if solve_for is not None and not isinstance(solve_for, sp.Symbol):
        raise SceneError(f"solve_for = {shorten(solve_for)} must be a sympy Symbol (a parameter).")


def lagrangian_parts(lagrangian, loads, frame) -> None:
    """A finite Lagrangian, loads as (Point or ReferenceFrame, Vector) pairs, and an optional frame."""
    finite_expression(lagrangian, "the Lagrangian")
    _real_valued(lagrangian, "the Lagrangian")
    for load in _sequence(loads, "loads", "give a list of (Point or ReferenceFrame, Vector) pairs"):
        if not (isinstance(load, (tuple, list)) and len(load) == 2 and isinstance(load[0], (Point, ReferenceFrame))):
            raise SceneError(f"load {shorten(load)} must be a pair (Point or ReferenceFrame, Vector).")
        if not isinstance(load[1], Vector) and load[1] != 0:
            raise SceneError(f"the force or torque of load {shorten(load)} must be a sympy Vector.")
        for components, _ in getattr(load[1], "args", ()):
            _real_valued(components, f"load {shorten(load)}")
    if frame is not None and not isinstance(frame, ReferenceFrame):
        raise SceneError(f"frame = {shorten(frame)} must be the inertial ReferenceFrame (or None).")


def _real_valued(expr, what: str) -> None:
    """Mechanics is real: the imaginary unit in a mass, a length or a load is a slip (``sp.I`` for an inertia ``I``)."""
    if isinstance(expr, sp.Basic) and expr.has(sp.I):
        raise SceneError(
            f"{what} contains the imaginary unit I ({shorten(expr)}); masses, lengths and loads are real. For an "
            "inertia named I use a symbol: sp.Symbol('I', positive=True)."
        )


def _check_accelerations(coordinates: tuple, accelerations) -> tuple:
    accelerations = _sequence(accelerations, "accelerations", "give one expression per coordinate")
    if len(accelerations) != len(coordinates):
        raise SceneError(
            f"got {len(accelerations)} accelerations for {len(coordinates)} coordinates; give one per coordinate."
        )
    for q, g in zip(coordinates, accelerations):
        if not isinstance(g, (str, sp.Basic, *NUMBER_TYPES)) or isinstance(g, bool):
            raise SceneError(f"the acceleration of {q} must be a SymPy expression, not {type(g).__name__}.")
        _real_valued(g, f"the acceleration of {q}")
    return accelerations


def contact_fields(coordinate, compliance, friction, unilateral) -> None:
    """The fields of a Contact other than its reaction (checked by the Contact itself)."""
    if not isinstance(coordinate, (str, bytes)):  # text is refused by parse.sympy_only, with its own message
        if not isinstance(coordinate, sp.Basic):
            raise SceneError(
                f"the coordinate of a contact must be a SymPy expression (a dynamicsymbol or a gap function), "
                f"not {type(coordinate).__name__} {shorten(coordinate)}."
            )
        finite_expression(coordinate, "the gap of a contact")
    if compliance is not None and not _has_methods(compliance, "phi_psi", "deformation", "reaction"):
        raise SceneError(
            f"compliance = {shorten(compliance)} is not a law; use Generic(), KelvinVoigt(...) or Law(...)."
        )
    if friction is not None and not _has_methods(friction, "magnitude"):
        raise SceneError(f"friction = {shorten(friction)} is not a friction law; use Coulomb(...) or Viscous(...).")
    if not isinstance(unilateral, (bool, np.bool_)):
        raise SceneError(f"unilateral = {shorten(unilateral)} must be True or False.")


def _has_methods(value, *names: str) -> bool:
    """A law recognised by what it does (laws.py imports this module, so it cannot be imported here):
    a compliance law gives Phi, Psi, the deformation and the reaction; a friction law its magnitude."""
    return not isinstance(value, type) and all(callable(getattr(value, name, None)) for name in names)


def reactions_act(accelerations: dict, contacts: Sequence) -> None:
    """Every contact's reaction appears in some acceleration (else its claims would be empty)."""
    for index, contact in enumerate(contacts):
        if not any(g.has(contact.reaction) for g in accelerations.values()):
            raise SceneError(
                f"the reaction {contact.reaction} of contact {index} (gap {shorten(contact.coordinate)}) appears in "
                "no acceleration, so the contact does not act; add it to the accelerations or remove the contact."
            )


def sign_pattern(signs) -> tuple[int, ...]:
    """A sign pattern as a tuple of Python ints +1 / -1 (length is checked by the scene)."""
    if isinstance(signs, np.ndarray):
        signs = signs.tolist()
    signs = _sequence(signs, "a sign pattern", "write e.g. (1, -1)", SignPatternError)
    out = []
    for position, value in enumerate(signs):
        exact = isinstance(value, (int, np.integer, sp.Integer)) and not isinstance(value, (bool, np.bool_))
        if not exact or value not in (1, -1):
            raise SignPatternError(
                f"sign {shorten(value)} at position {position} must be +1 or -1; write e.g. (1, -1)."
            )
        out.append(int(value))
    return tuple(out)


# --- numerics ---------------------------------------------------------------------------------


def solver_method(method, allowed: Sequence[str] = ("Radau", "BDF", "LSODA", "RK45", "RK23", "DOP853")) -> str:
    """The name of a ``solve_ivp`` method."""
    if method not in allowed:
        raise NumericsError(f"method = {shorten(method)} is not a solver; use one of {', '.join(allowed)}.")
    return method


def real_array(values, what: str) -> np.ndarray:
    """Real floats from numbers or arrays; complex values are an error, not cut to their real part.

    A float64 array comes back as a read-only view (no copy: a classifier reads its inputs
    once, and nothing downstream can write into the caller's data).
    """
    if isinstance(values, (str, bytes)):
        raise NumericsError(f"{what} = {shorten(values)} is text; pass numbers.")
    try:
        array = np.asarray(values)
    except (ValueError, TypeError) as error:
        raise NumericsError(f"{what} is not an array of numbers: {shorten(error)}.") from error
    if np.iscomplexobj(array):
        raise NumericsError(f"complex values in {what}; pass real numbers (the imaginary parts would be lost).")
    if array.dtype.kind not in "biuf":
        raise NumericsError(f"{what} must hold real numbers, not {array.dtype} values.")
    if array.dtype != np.float64:
        return array.astype(float)
    view = array.view()  # the caller's float64 data, not copied and not writable through the result
    view.flags.writeable = False
    return view


def output_times(t_eval, span: tuple[float, float]) -> np.ndarray | None:
    """Output times: finite, inside the span and in its direction."""
    if t_eval is None:
        return None
    times = real_array(t_eval, "t_eval").ravel()
    if not np.all(np.isfinite(times)):
        raise NumericsError("t_eval contains nan or infinite times; pass finite times.")
    start, end = span
    if times.size and (times.min() < min(start, end) or times.max() > max(start, end)):
        raise NumericsError(
            f"t_eval runs from {times.min():g} to {times.max():g}, outside the span ({start:g}, {end:g}); "
            "keep the output times inside the span."
        )
    if np.any(np.diff(times) * (end - start) < 0):
        raise NumericsError("t_eval is not sorted in the direction of integration; sort it, e.g. numpy.sort(t_eval).")
    return times


def chunk_size(chunk) -> int:
    """A positive whole number of points per chunk."""
    if isinstance(chunk, (bool, np.bool_)) or not isinstance(chunk, (int, np.integer)) or chunk < 1:
        raise NumericsError(f"chunk = {shorten(chunk)} must be a whole number >= 1 (points per chunk).")
    return int(chunk)


def finite_number(value, what: str) -> float:
    """A finite float from a real number."""
    if isinstance(value, NUMBER_TYPES) and not isinstance(value, (bool, np.bool_)):
        if math.isfinite(float(value)):
            return float(value)
    raise NumericsError(f"{what} = {shorten(value)} must be a finite number.")
