"""The inequality engine bound to a scene's count presentation, and the sign cases counts enumerate.

The counts state their regions in the scene's ``count_presentation`` when it has one (the
guides use mu_j = ``|v_j|``/kappa, as the paper does for (5.8)-(5.10)), else in its
presentation. :func:`count_facts` gives the :class:`~contactsym.inequalities.Facts` that
try every condition in the scene's canonical form and in that presentation.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from ..arguments import checked
from ..inequalities import Facts

__all__ = ["count_facts", "count_presentation", "sign_choices"]


@checked(scene="Scene")
def count_presentation(scene) -> dict:
    """The presentation the counts use: the scene's ``count_presentation``, or its presentation.

    Examples
    --------
    The guides present the friction coefficients through the speeds, mu_j = |v_j|/kappa:

    >>> import sympy as sp
    >>> import contactsym as cs
    >>> presentation = count_presentation(cs.scene("painleve-klein-guides"))
    >>> presentation[sp.Symbol("mu_1", positive=True)]
    Abs(v_1)/kappa
    """
    return dict(getattr(scene, "count_presentation", None) or scene.presentation)


@checked(scene="Scene")
def count_facts(scene) -> Facts:
    """What the counts know about a scene: its positive expressions and its count presentation.

    Examples
    --------
    >>> import sympy as sp
    >>> import contactsym as cs
    >>> facts = count_facts(cs.scene("painleve-klein-guides"))
    >>> facts.condition(2 - sp.Symbol("mu_1", positive=True)).presented  # mu_j = |v_j|/kappa
    (2*kappa - Abs(v_1))/kappa
    """
    presentation = count_presentation(scene)
    return Facts(scene.positive_expressions, lambda expr: scene.present(expr, None, presentation))


@checked
def sign_choices(known: list, open_: list) -> Iterator[list]:
    """Every completion of the known signs: each open position takes +1 and -1.

    Examples
    --------
    >>> list(sign_choices([1, None, None], [1, 2]))
    [[1, 1, 1], [1, 1, -1], [1, -1, 1], [1, -1, -1]]
    """
    for choice in itertools.product((1, -1), repeat=len(open_)):
        signs = list(known)
        for i, s in zip(open_, choice):
            signs[i] = s
        yield signs
