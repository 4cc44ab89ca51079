"""Old names kept for the users of contactsym 0.1: each works as before and warns, naming its successor.

Renamed functions stay callable under the old name (:func:`deprecated_alias`), renamed
attributes of the stage objects stay readable (:func:`deprecated_property`), and renamed
classes or functions of a module stay importable through the module's ``__getattr__``
(:func:`deprecated_names`). Each use raises a ``DeprecationWarning``.

Examples
--------
>>> import warnings
>>> def new(x):
...     return 2 * x
>>> old = deprecated_alias(new, "old")
>>> with warnings.catch_warnings(record=True) as caught:
...     warnings.simplefilter("always")
...     old(2)
4
>>> print(caught[0].message)
old is deprecated; use contactsym.deprecation.new (the same behaviour).
"""

from __future__ import annotations

import functools
import warnings
from collections.abc import Callable

__all__ = ["deprecated_alias", "deprecated_names", "deprecated_property"]


def _warn(old: str, new: str) -> None:
    # stacklevel 3: the warning points at the caller of the old name, not at this module
    warnings.warn(f"{old} is deprecated; use {new} (the same behaviour).", DeprecationWarning, stacklevel=3)


def deprecated_alias(function: Callable, old: str) -> Callable:
    """``function`` under its former name ``old``: the same call, with a DeprecationWarning."""
    new = f"{function.__module__}.{function.__qualname__}"

    @functools.wraps(function)
    def alias(*args, **kwargs):
        _warn(old, new)
        return function(*args, **kwargs)

    alias.__name__ = alias.__qualname__ = old
    alias.__doc__ = f"Deprecated name of :func:`{new}`."
    return alias


def deprecated_property(new: str, old: str) -> property:
    """A read-only attribute ``old`` that warns and returns the attribute ``new`` of the same object.

    Examples
    --------
    >>> class Stage:
    ...     jacobian = 1
    ...     matrix = deprecated_property("jacobian", "matrix")
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     Stage().matrix
    1
    >>> print(caught[0].message)
    Stage.matrix is deprecated; use Stage.jacobian (the same behaviour).
    """

    def getter(self):
        owner = type(self).__name__
        _warn(f"{owner}.{old}", f"{owner}.{new}")
        return getattr(self, new)

    return property(getter, doc=f"Deprecated name of :attr:`{new}`.")


def deprecated_names(module: str, renamed: dict[str, str], namespace: dict) -> Callable[[str], object]:
    """A module ``__getattr__`` that serves each old name of ``renamed`` (old -> new) with a warning.

    Examples
    --------
    >>> __getattr__ = deprecated_names("demo", {"Fraction": "TrigFraction"}, {"TrigFraction": float})
    >>> with warnings.catch_warnings(record=True) as caught:
    ...     warnings.simplefilter("always")
    ...     __getattr__("Fraction")
    <class 'float'>
    >>> print(caught[0].message)
    demo.Fraction is deprecated; use demo.TrigFraction (the same behaviour).
    """

    def __getattr__(name: str):
        if name in renamed:
            _warn(f"{module}.{name}", f"{module}.{renamed[name]}")
            return namespace[renamed[name]]
        raise AttributeError(f"module {module!r} has no attribute {name!r}")

    return __getattr__
