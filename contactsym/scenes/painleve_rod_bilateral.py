"""The Painlevé rod with its end held to the floor (bilateral contact): see :mod:`.painleve_rod`."""

from __future__ import annotations

from .painleve_rod import build_bilateral as build

__all__ = ["build"]
