"""Parts of the public boundary: what :mod:`contactsym.arguments`, :mod:`contactsym.validate`
and :mod:`contactsym.parse` are built from.

Those top-level modules are the interface, and each imports the names of its parts from here;
this subpackage exports nothing of its own. Its modules are leaves below every other part of
contactsym (they import only :mod:`contactsym.errors` and each other):

- :mod:`~contactsym.boundary.plain_values`: user text cut short for messages, and checks of
  flags, paths and plain-typed dataclass fields, for ``contactsym.validate``;
- :mod:`~contactsym.boundary.hints`: one value against one type hint (``fits``), and what a
  hint asks for in words (``describe``), for ``contactsym.arguments.checked``;
- :mod:`~contactsym.boundary.formula_text`: the names and tokens of a formula, for
  ``contactsym.parse``, and ``sympy_only``, which keeps text out of the Python API.
"""

__all__: list[str] = []
