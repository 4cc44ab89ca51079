"""Ctrl-C while the command line is still importing: a quiet stop with exit code 130.

``python -m contactsym`` and the ``contactsym`` script import the whole package before
:func:`contactsym.cli.main` can install its signal handlers; a SIGINT in that second
would print a traceback. When this process is the command line (and only then), SIGINT
ends it at once: nothing has been written yet. ``main()`` replaces the handler with its
own for the run. A library user's ``import contactsym`` changes no handler.
"""

from __future__ import annotations

import atexit
import os
import signal
import sys

__all__ = ["is_command_line"]


def is_command_line(argv: list[str], script: str) -> bool:
    """Whether the interpreter was started as ``python -m contactsym`` or as the ``contactsym`` script.

    Examples
    --------
    >>> is_command_line(["python3", "-m", "contactsym", "list"], "-m"), is_command_line(["python3", "x.py"], "x.py")
    (True, False)
    """
    if "-m" in argv[:-1] and argv[argv.index("-m") + 1] == "contactsym":
        return True
    return os.path.basename(script) == "contactsym"


def _stop_quietly(signum, frame):
    os.write(2, b"contactsym: interrupted\n")
    os._exit(128 + signum)


_IGNORED = signal.getsignal(signal.SIGINT) == signal.SIG_IGN  # e.g. started in the background by a shell: keep it so


def _ignore_interrupts() -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)


if not _IGNORED and is_command_line(list(getattr(sys, "orig_argv", [])), sys.argv[0] if sys.argv else ""):
    signal.signal(signal.SIGINT, _stop_quietly)
    # Python's shutdown puts SIGINT back to the system default, so a Ctrl-C in the last milliseconds, after
    # the run, killed the process (exit -2, seen once in the suite's SIGINT trials); an ignored signal stays
    # ignored, and atexit runs before that reset: the exit code then says how the run went
    atexit.register(_ignore_interrupts)
