"""The block on two legs that can lift off (unilateral contacts): see :mod:`.two_leg_block`."""

from __future__ import annotations

from .two_leg_block import build as _build


def build():
    return _build(unilateral=True)
