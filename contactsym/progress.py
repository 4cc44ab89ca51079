"""Progress reports and wall-clock limits for long work (stiff simulations, exact classification).

A long computation takes ``progress=`` (a callable receiving the fraction done, 0 to 1,
and a short message) and ``max_seconds=``. :class:`Budget` throttles the reports to a
few per second and says when the time is up. A plain callable keeps contactsym free of
a progress-bar dependency; a tqdm bar fits in it directly::

    bar = tqdm.tqdm(total=1.0)
    progress = lambda fraction, message: bar.update(fraction - bar.n)

Examples
--------
>>> seen = []
>>> budget = Budget(lambda fraction, message: seen.append(round(fraction, 2)), every=0.0)
>>> budget.report(0.5, "half"); budget.report(1.0, "done")
False
False
>>> seen
[0.5, 1.0]
>>> Budget(max_seconds=0.0).report(0.1)
True
"""

from __future__ import annotations

import time
from collections.abc import Callable

from .errors import NumericsError
from .validate import finite_number

__all__ = ["Budget", "Progress"]

#: A progress callback: ``progress(fraction_done, message)``.
Progress = Callable[[float, str], None]


class Budget:
    """Throttled progress reports and a wall-clock limit, from the moment it is made.

    Parameters
    ----------
    progress : callable, optional
        ``progress(fraction, message)``, called at most once per ``every`` seconds (and
        always for fraction 1).
    max_seconds : float, optional
        The time after which :meth:`report` returns True.
    """

    def __init__(self, progress: Progress | None = None, max_seconds: float | None = None, every: float = 0.25):
        self.progress = progress
        self.max_seconds = None if max_seconds is None else finite_number(max_seconds, "max_seconds")
        if self.max_seconds is not None and self.max_seconds < 0:
            raise NumericsError(f"max_seconds = {max_seconds} must be >= 0.")
        self.every = every
        self.started = time.perf_counter()
        self._last = -float("inf")

    @property
    def elapsed(self) -> float:
        return time.perf_counter() - self.started

    def report(self, fraction: float, message: str = "") -> bool:
        """Pass on the progress (throttled); True when the time limit has passed."""
        now = time.perf_counter()
        if self.progress is not None and (fraction >= 1 or now - self._last >= self.every):
            self._last = now
            self.progress(min(max(fraction, 0.0), 1.0), message)
        return self.max_seconds is not None and now - self.started > self.max_seconds
