"""All-or-nothing output directories, and signals that clean up.

:func:`replaced_directory` lets a writer fill a hidden sibling of the target
directory; only when the writer finishes is the sibling renamed into place (the old
directory, if any, is renamed aside first and removed last). A failure or an
interrupt removes the sibling and leaves the old directory whole, so a reader finds
either the old output or the new one, never a mix. Each directory written this way
holds a :data:`MARKER` file; a directory without one was not written by contactsym
and is not replaced unless ``force`` is given.

:func:`signals_as_exceptions` turns SIGTERM and SIGHUP into an exception (SIGINT
already is one, KeyboardInterrupt), so that ``finally`` blocks and context managers,
temporary directories among them, run when the command line is killed.

Examples
--------
>>> import tempfile, pathlib
>>> root = pathlib.Path(tempfile.mkdtemp())
>>> with replaced_directory(root / "out") as work:
...     _ = (work / "a.txt").write_text("new")
>>> sorted(p.name for p in (root / "out").iterdir())
['.contactsym', 'a.txt']
>>> (root / "mine").mkdir(); _ = (root / "mine" / "notes.txt").write_text("keep")
>>> with replaced_directory(root / "mine") as work:  # doctest: +ELLIPSIS
...     pass
Traceback (most recent call last):
...
contactsym.errors.ContactsymError: ... exists and was not written by contactsym (it has no .contactsym file); choose another directory, or force the replacement (--force).
"""

from __future__ import annotations

import os
import shutil
import signal
import tempfile
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from .errors import ContactsymError
from .validate import shorten

__all__ = ["MARKER", "Interrupted", "replaced_directory", "signals_as_exceptions"]

#: The file that marks a directory as written by contactsym (and so replaceable).
MARKER = ".contactsym"

_CAUGHT = tuple(s for s in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)) if s is not None)


class Interrupted(KeyboardInterrupt):
    """A terminating signal arrived; ``exit_code`` is 128 + the signal number."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.exit_code = 128 + signum


def _check_replaceable(target: Path, force: bool, error: type[ContactsymError]) -> None:
    if not os.path.lexists(target):
        return
    if Path.cwd().resolve().is_relative_to(target.resolve()):
        raise error(f"{shorten(str(target))} is or contains the current directory; name a new subdirectory.")
    if target.is_symlink() or not target.is_dir():
        raise error(f"{shorten(str(target))} exists and is not a directory; choose another directory.")
    if force or (target / MARKER).is_file() or not any(target.iterdir()):
        return
    raise error(
        f"{shorten(str(target))} exists and was not written by contactsym (it has no {MARKER} file); "
        "choose another directory, or force the replacement (--force)."
    )


@contextmanager
def _signals_blocked() -> Iterator[None]:
    """Hold SIGINT/SIGTERM/SIGHUP back for a few system calls; they arrive right after."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    held = {signal.SIGINT, *_CAUGHT}
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, held)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def _swap(work: Path, target: Path) -> None:
    """Rename ``work`` to ``target``; an old ``target`` is renamed aside first and removed after."""
    with _signals_blocked():
        if not os.path.lexists(target):
            os.rename(work, target)
            return
        old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=target.parent))
        os.rmdir(old)  # only its (unique) name is wanted
        os.rename(target, old)
        try:
            os.rename(work, target)
        except OSError:
            os.rename(old, target)
            raise
    shutil.rmtree(old, ignore_errors=True)


@contextmanager
def replaced_directory(
    target: Path | str, *, force: bool = False, error: type[ContactsymError] = ContactsymError
) -> Iterator[Path]:
    """A fresh directory beside ``target`` that becomes ``target`` when the block succeeds.

    Parameters
    ----------
    target : path
        The directory to write. Its parent is created if needed.
    force : bool
        Replace ``target`` even when contactsym did not write it (no :data:`MARKER`).
    error : ContactsymError subclass
        The exception raised when ``target`` may not be replaced or cannot be created.
    """
    target = Path(os.path.abspath(target))  # '.' and 'a/..' get a name and a parent
    _check_replaceable(target, force, error)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        work = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=target.parent))
    except OSError as failure:
        raise error(f"cannot create {shorten(str(target))}: {failure.strerror or failure}.") from failure
    try:
        yield work
        (work / MARKER).write_text("Written by contactsym; the next report replaces this directory.\n")
        _swap(work, target)
    except BaseException:
        shutil.rmtree(work, ignore_errors=True)
        raise


@contextmanager
def signals_as_exceptions() -> Iterator[None]:
    """Within the block, SIGTERM and SIGHUP raise :class:`Interrupted` (main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def stop(signum, frame):
        raise Interrupted(signum)

    previous = {s: signal.signal(s, stop) for s in _CAUGHT}
    try:
        yield
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)
