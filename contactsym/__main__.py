"""``python3 -m contactsym``: the command line (:mod:`contactsym.cli`)."""

import sys

from .cli import main

if __name__ == "__main__":  # importing the module (the docs build does) runs nothing
    sys.exit(main())
