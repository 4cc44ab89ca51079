"""All-or-nothing output directories, and signals that clean up.

:func:`replaced_directory` lets a writer fill a hidden sibling of the target
directory; only when the writer finishes is the sibling renamed into place (the old
directory, if any, is renamed aside first and removed last). A failure or an
interrupt removes the sibling and leaves the old directory whole, so a reader finds
either the old output or the new one, never a mix. Each directory written this way
holds a :data:`MARKER` file listing what contactsym wrote there; a directory that
holds anything else (a user's file) is replaced only with ``force=True`` (a bool: text
such as ``"no"`` is an error). The temporary siblings carry the host and process id in
their names: a run killed with SIGKILL leaves them, and the next run into the same
place removes them (:func:`remove_leftovers`). New folders get the umask's permissions.

:func:`signals_as_exceptions` turns SIGINT, SIGTERM and SIGHUP into :class:`Interrupted`,
so that ``finally`` blocks and context managers, temporary directories among them, run
when the command line is stopped, also when the signal lands in a finalizer.

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
contactsym.errors.ContactsymError: ... exists and was not written by contactsym (it has no .contactsym file listing what contactsym wrote); choose another directory, or force the replacement (--force).
>>> _ = (root / "out" / "thesis.tex").write_text("mine")
>>> with replaced_directory(root / "out", force="no") as work:  # doctest: +ELLIPSIS
...     pass
Traceback (most recent call last):
...
contactsym.errors.ContactsymError: force = 'no' must be True or False (a bool), not str.
>>> with replaced_directory(root / "out") as work:  # doctest: +ELLIPSIS
...     pass
Traceback (most recent call last):
...
contactsym.errors.ContactsymError: ... holds 'thesis.tex' (and 0 more), which contactsym did not write; ...
"""

from __future__ import annotations

import _thread
import os
import shutil
import signal
import socket
import sys
import tempfile
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

from .errors import ContactsymError
from .validate import flag, path_text, shorten

__all__ = [
    "MARKER",
    "Interrupted",
    "fresh_directory",
    "last_signal",
    "process_tag",
    "remove_leftovers",
    "replaced_directory",
    "scratch_directory",
    "signals_as_exceptions",
    "umask_bits",
]

#: The file that marks a directory as written by contactsym (and so replaceable).
MARKER = ".contactsym"

#: The first line of a marker; the lines after it list what contactsym wrote in the directory.
_HEADER = "Written by contactsym; the next run replaces this directory if it holds only the entries listed below."

_CAUGHT = tuple(s for s in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)) if s is not None)


class Interrupted(KeyboardInterrupt):
    """A terminating signal arrived; ``exit_code`` is 128 + the signal number."""

    def __init__(self, signum: int):
        super().__init__(signum)
        self.exit_code = 128 + signum


def _manifest(directory: Path) -> set[str] | None:
    """The entries the marker of ``directory`` lists as written by contactsym (None: no list in it)."""
    try:
        lines = (directory / MARKER).read_text(errors="replace").splitlines()
    except OSError:
        return None
    if not lines or lines[0] != _HEADER:
        return None
    return set(lines[1:])


def _entries(directory: Path) -> list[str]:
    """Every file, folder and link below ``directory`` (links not followed), relative, sorted."""
    found = []
    for root, folders, files in os.walk(directory):
        for name in folders + files:
            found.append(os.path.relpath(os.path.join(root, name), directory))
    return sorted(found)


def _check_replaceable(target: Path, force: bool, error: type[ContactsymError]) -> None:
    if not os.path.lexists(target):
        return
    if Path.cwd().resolve().is_relative_to(target.resolve()):
        raise error(f"{shorten(str(target))} is or contains the current directory; name a new subdirectory.")
    if target.is_symlink() or not target.is_dir():
        raise error(f"{shorten(str(target))} exists and is not a directory; choose another directory.")
    if force or not any(target.iterdir()):
        return
    listed = _manifest(target)
    if listed is None:
        raise error(
            f"{shorten(str(target))} exists and was not written by contactsym (it has no {MARKER} file listing "
            "what contactsym wrote); choose another directory, or force the replacement (--force)."
        )
    foreign = [entry for entry in _entries(target) if entry != MARKER and entry not in listed]
    if foreign:
        raise error(
            f"{shorten(str(target))} holds {shorten(foreign[0])} (and {len(foreign) - 1} more), which contactsym did "
            "not write; move it away, choose another directory, or force the replacement (--force)."
        )


def process_tag() -> str:
    """This process's part of a temporary name: host and process id, so that a later run can tell it is gone."""
    host = "".join(c for c in socket.gethostname() if c.isalnum())[:32] or "host"
    return f"{host}-{os.getpid()}-"


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:  # another user's process, or no way to ask: assume it is running
        return True
    return True


def remove_leftovers(folder: Path | str, prefix: str) -> list[Path]:
    """Remove ``folder/PREFIX<host>-<pid>-*`` left by a run of this host that was killed (its process is gone).

    Returns what was removed. Entries of runs still going, or of other hosts, stay.
    """
    folder, host = Path(folder), process_tag().split("-")[0]
    removed = []
    try:
        names = [p.name for p in folder.iterdir() if p.name.startswith(prefix)]
    except OSError:
        return removed
    for name in names:
        parts = name[len(prefix) :].split("-")
        if len(parts) < 3 or parts[0] != host or not parts[1].isdigit() or _alive(int(parts[1])):
            continue
        path = folder / name
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path, ignore_errors=True)
        else:
            path.unlink(missing_ok=True)
        removed.append(path)
    return removed


def umask_bits() -> int:
    """The process's umask (read, not changed, where /proc allows)."""
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("Umask:"):
                return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    current = os.umask(0o022)  # no /proc: read it by setting it (and set it back at once)
    os.umask(current)
    return current


def fresh_directory(folder: Path, prefix: str) -> Path:
    """A new directory ``folder/PREFIX<host>-<pid>-XXXX`` with the permissions the umask gives a new folder."""
    made = Path(tempfile.mkdtemp(prefix=prefix + process_tag(), dir=folder))
    os.chmod(made, 0o777 & ~umask_bits())  # mkdtemp makes 0700; an output folder follows the umask like mkdir
    return made


@contextmanager
def scratch_directory(prefix: str = "contactsym-figures-") -> Iterator[Path]:
    """A temporary directory in the system's temporary folder, removed at the end; a killed run's is
    removed by the next run (see :func:`remove_leftovers`)."""
    folder = Path(tempfile.gettempdir())
    remove_leftovers(folder, prefix)
    made = fresh_directory(folder, prefix)
    try:
        yield made
    finally:
        shutil.rmtree(made, ignore_errors=True)


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
        old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-{process_tag()}", dir=target.parent))
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
    target = Path(os.path.abspath(path_text(target, "the directory", error)))  # '.' and 'a/..' get a name
    force = flag(force, "force", error)
    _check_replaceable(target, force, error)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        for kind in ("new", "old"):  # what a killed run into the same place left behind
            remove_leftovers(target.parent, f".{target.name}.{kind}-")
        work = fresh_directory(target.parent, f".{target.name}.new-")
    except OSError as failure:
        raise error(f"cannot create {shorten(str(target))}: {failure.strerror or failure}.") from failure
    try:
        yield work
        written = [entry for entry in _entries(work) if entry != MARKER]
        (work / MARKER).write_text("\n".join([_HEADER, *written]) + "\n")
        _swap(work, target)
    except BaseException:
        shutil.rmtree(work, ignore_errors=True)
        raise


_STATE = {"active": False, "signal": None}


def last_signal() -> int | None:
    """The signal that arrived in the last :func:`signals_as_exceptions` block (None: none did)."""
    return _STATE["signal"]


def _again(signum: int) -> None:
    """Deliver ``signum`` to the main thread once more, from outside the finalizer that swallowed it."""
    if not _STATE["active"]:
        return
    if hasattr(signal, "pthread_kill"):  # a real signal to the main thread: it also ends a sleep or a wait there
        signal.pthread_kill(threading.main_thread().ident, signum)
    elif signum == signal.SIGINT:  # no pthread_kill (Windows): noticed once the blocking call returns
        _thread.interrupt_main()
    else:
        signal.raise_signal(signum)


@contextmanager
def signals_as_exceptions() -> Iterator[None]:
    """Within the block SIGINT, SIGTERM and SIGHUP raise :class:`Interrupted` (main thread only).

    A signal can arrive while Python runs a finalizer (``__del__``, a weakref callback); the
    exception raised there is printed as "Exception ignored" and the run would go on. Here
    it is not printed: the signal is noted (:func:`last_signal`) and delivered again, so the
    block stops; a caller whose block still finished sees it in :func:`last_signal`.
    """
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _STATE["signal"] = None

    def stop(signum, frame):
        _STATE["signal"] = signum
        raise Interrupted(signum)

    def unraisable(info):
        if isinstance(info.exc_value, KeyboardInterrupt):  # swallowed in a finalizer: raise it again, outside
            signum = getattr(info.exc_value, "exit_code", 128 + signal.SIGINT) - 128
            threading.Timer(0.01, _again, (signum,)).start()
            return
        hook(info)

    hook, sys.unraisablehook = sys.unraisablehook, unraisable
    caught = [s for s in (signal.SIGINT, *_CAUGHT) if signal.getsignal(s) != signal.SIG_IGN]  # ignored stays ignored
    previous = {s: signal.signal(s, stop) for s in caught}
    _STATE["active"] = True
    try:
        yield
    finally:
        _STATE["active"] = False
        for s, handler in previous.items():
            signal.signal(s, handler)
        sys.unraisablehook = hook
