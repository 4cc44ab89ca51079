"""The paper's equation numbers of a scene's formulas.

The general theory's numbers (by the number of contacts) come first, then those of the paper's
example that the scene reproduces.
"""

from __future__ import annotations

from ..arguments import checked, require
from ..printing.latex_output import Numbering
from ..stages import equilibria as _equilibria
from ..stages import fast as _fast
from ..stages import linear as _linear
from ..stages import regularize as _regularize
from ..stages import stability as _stability

__all__ = ["GENERAL_NUMBERS", "NUMBERS", "paper_equations"]

#: The scene's own formulas: the accelerations (1.4), for any number of contacts.
NUMBERS = Numbering({"accelerations": (("1.4",),) * 3, "contact accelerations": (("1.4",),) * 3})

#: The general theory's numbers of every stage's formulas.
GENERAL_NUMBERS = (
    NUMBERS | _regularize.NUMBERS | _fast.NUMBERS | _equilibria.NUMBERS | _linear.NUMBERS | _stability.NUMBERS
)


@checked
def paper_equations(scene, key: str, detail: str | None = None) -> tuple[tuple, str]:
    """The paper's equation numbers and a note for a formula of ``scene`` (any object with ``k``).

    The general theory's numbers (by the number of contacts k) come first, then the numbers
    of the paper's example that the scene reproduces (its ``equations``).

    Examples
    --------
    >>> import contactsym as cs
    >>> paper_equations(cs.scene("painleve-klein-guides"), "A")
    (('4.3', '5.4'), '')
    >>> paper_equations(cs.scene("brake"), "stable for every law")
    (('4.4', '6.3'), 'Proposition 6; with equality allowed: erratum 12')
    """
    k, equations = getattr(scene, "k", 2), getattr(scene, "equations", None)
    usable = isinstance(k, int) and not isinstance(k, bool) and k >= 1 and isinstance(equations, (dict, type(None)))
    require(usable, "paper_equations", "scene", scene, "a scene (an object with k contacts)")
    return GENERAL_NUMBERS(key, k, equations, detail)
