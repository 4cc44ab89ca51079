"""The printer: LaTeX through SymPy's printer and the :class:`Formula` rows the stages print as,
and plain text with Unicode mathematics as LaTeX. Imports no stage.
"""

from .glyphs import OwnLetters, look_alike, spelled_apart
from .latex_output import Formula, LatexReprMixin, Numbering, formulas, latex, prime, signs_latex, tex
from .unicode_math import text_to_latex

__all__ = [
    "Formula",
    "LatexReprMixin",
    "Numbering",
    "OwnLetters",
    "formulas",
    "latex",
    "look_alike",
    "prime",
    "signs_latex",
    "spelled_apart",
    "tex",
    "text_to_latex",
]
