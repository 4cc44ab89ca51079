"""Equilibrium counts for piecewise-linear f: how many reactions a load can produce.

f is affine on each piece of a sign pattern; the slopes (k = 1) or the orthant
determinants (k >= 2) decide how many roots f(u) = 0 can have, for every load.

k = 1 (§3). The corners c_i are the roots of the switching functions sigma_i (each
oriented increasing in u). For each ordering of the corners (a condition on the
parameters, e.g. Y*_1 + Y*_2 < 0, = 0, > 0) the pieces, from left to right, start with
every sign -1 and flip the signs of the switching functions that vanish at each corner.
With the signs of the slopes f' on the pieces:

- all f' > 0: a unique root, stable for every contact law (Propositions 3, 4);
- c <= 3 sign changes: f has c local extrema; when the outer slopes differ in sign the count
  is even (c = 1: a fold, two roots or none, none being an impact-type catastrophe),
  when they agree it is odd (c = 2: a cusp, one root or three; c = 3: none, two or four);
- four or more sign changes: the values at the extrema, not the signs, decide which
  counts occur: undecided.

Orthant maps (k >= 2, and any unilateral contact, lift-off included): see
:mod:`contactsym.counts.orthants` and :mod:`contactsym.counts.plmap`. With the orthant determinants
(principal minors of A with lift-off):

- all of one sign (coherent orientation): a unique solution for every load;
- k = 2, otherwise: the degree of the map decides, and it follows from the signs and
  one cross determinant (:func:`contactsym.counts.plmap.k2_label`): two or none, one or
  three, or none, two or four;
- k >= 3, otherwise: undecided in closed form; :func:`contactsym.plotting.counts.decide_counts`
  decides at numeric points.

Determinants and slopes of known sign are not enumerated, and sign combinations that a
short exact argument excludes (a sum of the conditions of known non-positive sign) are
dropped; conditions implied by the others are removed. Each region is then written in the
scene's presentation variables by the inequality engine (:mod:`contactsym.inequalities`,
shared with :mod:`contactsym.stages.regions`), with ``x < c, -x < c`` merged into ``|x| < c`` and
``x > c or -x > c`` into ``|x| > c``. A scene may carry ``count_presentation``, a
presentation used for the counts only (the guides use mu_j = ``|v_j|``/kappa, as the paper does
for (5.8)-(5.10)); see :mod:`contactsym.counts.conditions`. Boundaries (a slope or a
determinant equal to 0, two corners meeting where the scene leaves that open) belong to no
region.

The work is split by job: :mod:`contactsym.counts.corners` (k = 1, bilateral),
:mod:`contactsym.counts.orthants` (orthant maps), :mod:`contactsym.counts.thresholds` (5.9); this module
names the counts and gathers the regions.

:func:`square_threshold` finds where the unique region stops lying inside the region
"stable for every law": for the guides, phi = arctan(sqrt(2)) (5.9);
:func:`threshold_angle` returns that angle.
"""

from __future__ import annotations

import sympy as sp

from ..arguments import checked
from ..inequalities import merge_or as _merge_or  # noqa: F401  (tests use the counts' name)
from ..stages.regions import Region
from .corners import CountCase, corner_cases, corner_regions, uses_corners
from .orthants import orthant_regions
from .thresholds import Threshold, square_threshold, threshold_angle

__all__ = [
    "COUNT_DESCRIPTIONS",
    "CountCase",
    "Threshold",
    "corner_cases",
    "count_regions",
    "square_threshold",
    "threshold_angle",
]

#: What each count region means.
#:
#: >>> from contactsym.counts import COUNT_DESCRIPTIONS
#: >>> COUNT_DESCRIPTIONS['unique stable'].split(' (')[0]
#: 'one root for every load, stable for every contact law'
COUNT_DESCRIPTIONS = {
    "unique stable": "one root for every load, stable for every contact law (f' > 0 on every piece; Props. 3-4)",
    "unique unstable": "one root for every load, unstable for every contact law (f' < 0 on every piece)",
    "unique": "one solution for every load (coherent orientation: all orthant determinants of one sign)",
    "two or none": "degree 0: two solutions or none, by the load (a fold; none is an impact-type catastrophe)",
    "one or three": "degree +-1 with mixed orientation: one solution or three, by the load (a cusp)",
    "none, two or four": "degree 0, orthant determinant signs alternating: none, two or four, by the load",
    "undecided": (
        "orthant determinants of mixed signs: the count follows the degree of the map, which their signs "
        "do not fix; decide it at numeric points with contactsym.plotting.counts.decide_counts"
    ),
}


@checked(scene="Scene")
def count_regions(scene) -> dict[str, Region]:
    """Named closed-form regions by the number of equilibria, for piecewise-linear f.

    Parameters
    ----------
    scene : Scene
        A built-in or user scene with k = 1 (corners and slopes) or k >= 2 (orthant
        determinants; for k >= 3 only "unique" is decided).

    Returns
    -------
    dict of str to Region
        Keys among :data:`COUNT_DESCRIPTIONS`; regions that are empty are left out.

    Examples
    --------
    >>> import contactsym as cs
    >>> for name, region in count_regions(cs.scene("painleve-klein-guides")).items():
    ...     print(f"{name}: {region.condition}")
    unique: Abs(v_1) + Abs(v_2) < 2*kappa**2
    one or three: (Abs(v_1) + Abs(v_2) > 2*kappa**2) & (Abs(Abs(v_1) - Abs(v_2)) < 2*kappa**2)
    two or none: Abs(Abs(v_1) - Abs(v_2)) > 2*kappa**2
    >>> count_regions(cs.scene("painleve-klein-rod"))["two or none"]
    Region(two or none: Abs(mu_-) > 2)
    >>> count_regions(cs.scene("brake"))
    {'unique': Region(unique: True)}
    """
    raw = corner_regions(scene) if uses_corners(scene) else orthant_regions(scene)
    regions = {}
    for name, condition in raw.items():
        if condition == sp.false:
            continue
        description = COUNT_DESCRIPTIONS.get(name, f"{name} solutions, by the load")
        regions[name] = Region(condition, name=name, description=f"{scene.name}: {description}")
    return regions
