"""Parts of the command line, :mod:`contactsym.cli`: what it reads and what it prints.

:mod:`contactsym.cli` is the interface (``main``, the ``contactsym`` script) and imports the
names of its parts from here; this subpackage exports nothing of its own.

- :mod:`~contactsym.command_line.options`: the argument parser, ``--limit`` and ``--set``,
  sign patterns, the exit codes;
- :mod:`~contactsym.command_line.output`: the text the commands print (the derivation chain,
  the conditions as text or LaTeX).
"""

__all__: list[str] = []
