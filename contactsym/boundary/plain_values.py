"""Plain values at the boundary: user text cut short for messages (:func:`cut`, :func:`shorten`),
and checks of flags, paths, instances and the plain-typed fields of a dataclass.

Examples
--------
>>> shorten("ab" * 1000, limit=10)
"'ababababa... (2002 characters)"
>>> flag(True, "force"), path_text("out", "--out")
(True, 'out')
"""

from __future__ import annotations

import os
from fractions import Fraction

import numpy as np
import sympy as sp

from ..errors import ContactsymError

__all__ = ["NUMBER_TYPES", "SHOWN", "checked_fields", "cut", "flag", "instance_of", "path_text", "shorten"]

#: The most characters of user text that a message repeats.
SHOWN = 60

#: The types of a plain number a user may pass (not bool, which is a flag).
NUMBER_TYPES = (int, float, Fraction, np.integer, np.floating)


def cut(text: str, limit: int = SHOWN, *, count: bool = True) -> str:
    """``text`` cut to ``limit`` characters: the one text-cutting rule of contactsym.

    With ``count`` (messages) the first ``limit`` characters are kept and the message says how
    long the text was; without it (tables, summaries) the result, ``...`` included, fits in
    ``limit`` characters.

    Examples
    --------
    >>> cut("x" * 70)
    'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx... (70 characters)'
    >>> cut("mu <= Abs(cot(alpha))", 12, count=False)
    'mu <= Abs...'
    """
    if len(text) <= limit:
        return text
    return f"{text[:limit]}... ({len(text)} characters)" if count else text[: limit - 3] + "..."


def shorten(value, limit: int = SHOWN) -> str:
    """``repr`` of a string, ``str`` of anything else, cut to ``limit`` characters."""
    return cut(repr(value) if isinstance(value, str) else str(value), limit)


# --- flags, paths and types ---------------------------------------------------------------------


def flag(value, what: str, error=ContactsymError) -> bool:
    """A flag must be True or False: ``force="no"`` is text, and text is not a flag.

    Examples
    --------
    >>> flag(False, "force")
    False
    >>> flag("no", "force")
    Traceback (most recent call last):
    ...
    contactsym.errors.ContactsymError: force = 'no' must be True or False (a bool), not str.
    """
    if not isinstance(value, (bool, np.bool_)):
        raise error(f"{what} = {shorten(value)} must be True or False (a bool), not {type(value).__name__}.")
    return bool(value)


def path_text(value, what: str, error=ContactsymError) -> str:
    """A file or directory name: text or an ``os.PathLike``, not empty, without NUL characters."""
    if isinstance(value, os.PathLike):
        value = os.fspath(value)
    if not isinstance(value, str):
        raise error(f"{what} = {shorten(value)} must be a path (text or pathlib.Path), not {type(value).__name__}.")
    if not value.strip() or "\x00" in value:
        raise error(f"{what} = {shorten(value)} is not a usable path; name a file or directory.")
    return value


def instance_of(value, kinds, what: str, hint: str, error=ContactsymError, optional: bool = False):
    """``value`` if it is one of ``kinds`` (or None when ``optional``), else a clear error ending with ``hint``."""
    if (optional and value is None) or (isinstance(value, kinds) and not isinstance(value, bool)):
        return value
    raise error(f"{what} = {shorten(value)} ({type(value).__name__}) is not accepted; {hint}.")


_PLAIN_TYPES = {"str": str, "bool": bool, "int": int, "float": float, "tuple": tuple, "list": list, "dict": dict}


def _fits(value, hint: str) -> bool | None:
    """Whether ``value`` fits a plain type hint written as text (None: the hint is not a plain one)."""
    verdicts = []
    for part in (p.strip() for p in hint.split("|")):
        base = part.split("[")[0]
        if base == "None":
            verdicts.append(value is None)
        elif base in ("Path", "pathlib.Path"):
            verdicts.append(isinstance(value, (str, os.PathLike)))
        elif base in ("sp.Basic", "sp.Expr", "sympy.Basic"):
            verdicts.append(isinstance(value, (sp.Basic, *NUMBER_TYPES)) and not isinstance(value, bool))
        elif base in ("Mapping", "dict"):
            verdicts.append(isinstance(value, dict) or hasattr(value, "keys") and hasattr(value, "__getitem__"))
        elif base in _PLAIN_TYPES:
            kind = _PLAIN_TYPES[base]
            if kind is bool:
                verdicts.append(isinstance(value, (bool, np.bool_)))
            elif kind in (int, float):
                ok = isinstance(value, (int, np.integer) if kind is int else NUMBER_TYPES)
                verdicts.append(ok and not isinstance(value, (bool, np.bool_)))
            else:
                verdicts.append(isinstance(value, kind))
        else:
            return None
    return any(verdicts)


def checked_fields(record, error=ContactsymError) -> None:
    """Each field of a dataclass ``record`` whose hint is a plain type (text, number, flag, tuple, dict,
    SymPy object, path, or a union of these) must hold a value of that type; call it in ``__post_init__``."""
    for name, spec in getattr(type(record), "__dataclass_fields__", {}).items():
        hint = spec.type if isinstance(spec.type, str) else getattr(spec.type, "__name__", "")
        value = getattr(record, name)
        if _fits(value, hint) is False:
            raise error(
                f"{type(record).__name__}: {name} = {shorten(value)} must be {hint}, not {type(value).__name__}."
            )
