"""Bounds on polynomials in sin, cos and symbols of known sign, term by term (exact fractions).

The last test of :func:`contactsym.algebra.reductions.known_sign`: each monomial of the other
symbols gets a range ``centre -+ spread`` from its trigonometric factors (``|sin|, |cos| <= 1``,
``sin, cos in [0, 1]`` where declared positive); when every such range times its monomial's sign
lies on one side of zero, one of them strictly, the polynomial has that sign. A sufficient test,
never a refutation: None means not proved.
"""

from __future__ import annotations

from fractions import Fraction


def as_fraction(c) -> Fraction:
    """A rational ground element (SymPy's QQ or ZZ) as an exact Python fraction."""
    return Fraction(int(c.numerator), int(c.denominator))


def plain_term_range(monom: tuple, coeff: Fraction, trig: list, unit: set) -> tuple:
    """(rest, centre, spread): the monomial's range is centre -+ spread, with |sin|, |cos| <= 1 and
    sin, cos in [0, 1] where declared positive (an even power, or only such factors: in [0, 1])."""
    rest = tuple(0 if i in trig else e for i, e in enumerate(monom))
    powers = [(i, monom[i]) for i in trig if monom[i]]
    if not powers:
        return rest, coeff, 0
    if all(e % 2 == 0 or i in unit for i, e in powers):
        return rest, coeff / 2, abs(coeff) / 2
    return rest, 0, abs(coeff)


def group_ranges(terms, bounded: set) -> dict:
    """{monomial of the other symbols: [centre, spread]}; an odd power of a sign symbol makes a term symmetric."""
    groups: dict = {}
    for rest, centre, spread in terms:
        centre, spread = Fraction(centre), Fraction(spread)
        if any(rest[i] % 2 for i in bounded):
            centre, spread = Fraction(0), abs(centre) + spread
        key = tuple(0 if i in bounded else e for i, e in enumerate(rest))
        entry = groups.setdefault(key, [Fraction(0), Fraction(0)])
        entry[0] += centre
        entry[1] += spread
    return groups


def ranges_sign(groups: dict, scale: dict, real: dict) -> int | None:
    """+1 (-1) when each group's monomial times its range is >= 0 (<= 0), one of them strictly.

    ``groups`` maps exponent tuples to ``[centre, spread]``; ``scale`` gives the known sign of a
    symbol (by index) and ``real`` whether it is real (an even power of a real symbol is >= 0).

    Examples
    --------
    3 -+ 1 plus x with x > 0 is positive; x - 2 (x of unknown sign) is not proved:

    >>> from fractions import Fraction as F
    >>> ranges_sign({(0,): [F(3), F(1)], (1,): [F(1), F(0)]}, {0: 1}, {0: True})
    1
    >>> ranges_sign({(0,): [F(-2), F(0)], (1,): [F(1), F(0)]}, {0: None}, {0: True}) is None
    True
    """
    for target in (1, -1):
        strict, holds = False, True
        for key, (centre, spread) in groups.items():
            if centre == spread == 0:
                continue
            sign, nonzero = 1, True
            for i, e in enumerate(key):
                if e == 0:
                    continue
                if scale.get(i) is not None:
                    sign *= scale[i] ** (e % 2)
                elif e % 2 == 0 and real[i]:
                    nonzero = False  # an even power of a real symbol: >= 0, possibly 0
                else:
                    holds = False
            low = sign * target * centre - spread
            if not holds or low < 0:
                holds = False
                break
            strict = strict or (low > 0 and nonzero)
        if holds and strict:
            return target
    return None
