"""Equilibrium counts: how many contact reactions a load can produce (piecewise-linear f on
orthants, corners for k = 1, thresholds, the one-sided Painlevé classification).
"""

from .conditions import count_facts, count_presentation, sign_choices
from .corners import CountCase, corner_cases, corner_regions, slope_count_name, uses_corners
from .one_sided import OneSidedCase, one_sided_cases
from .orthants import SceneMap, orthant_regions, scene_map
from .plmap import OrthantMap, count_label, k2_label, k2_quadrants, orthant_patterns
from .regions import COUNT_DESCRIPTIONS, count_regions
from .thresholds import Threshold, square_threshold, threshold_angle

__all__ = [
    "COUNT_DESCRIPTIONS",
    "CountCase",
    "OneSidedCase",
    "OrthantMap",
    "SceneMap",
    "Threshold",
    "corner_cases",
    "corner_regions",
    "count_facts",
    "count_label",
    "count_presentation",
    "count_regions",
    "k2_label",
    "k2_quadrants",
    "one_sided_cases",
    "orthant_patterns",
    "orthant_regions",
    "scene_map",
    "sign_choices",
    "slope_count_name",
    "square_threshold",
    "threshold_angle",
    "uses_corners",
]
