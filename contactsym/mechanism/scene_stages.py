"""The stages of a scene, computed on first request and cached with it (:class:`SceneStages`).

Each stage is built from the one before (``Linearization(fast, signs)``, ``Stability(lin)``,
``Equilibria(fast)``); the scene keeps them by key, validated sign pattern included.
"""

from __future__ import annotations

from ..arguments import checked
from ..counts.regions import count_regions
from ..errors import SignPatternError
from ..stages.equilibria import Equilibria
from ..stages.fast import FastSubsystem
from ..stages.linear import Linearization, linearization_of
from ..stages.regions import scene_regions
from ..stages.regularize import ReducedSystem, Regularized
from ..stages.stability import Stability, stability_of
from ..validate import shorten, sign_pattern

__all__ = ["SceneStages"]


class SceneStages:
    """The sign patterns and the cached stages of a :class:`~contactsym.mechanism.scene.Scene`
    (the scene's ``_stage_cache`` holds them).

    Examples
    --------
    >>> import contactsym as cs
    >>> brake = cs.scene("brake")
    >>> isinstance(brake, SceneStages), brake.stability() is brake.stability()
    (True, True)
    """

    # --- sign patterns ------------------------------------------------------------

    @property
    def fixed_signs(self) -> dict:
        """Switching functions whose sign the scene fixes (unilateral contacts: u_j > 0)."""
        return self.fast_subsystem().fixed_signs

    @checked
    def sign_patterns(self) -> list[tuple[int, ...]]:
        """All admissible sign patterns of the switching functions (fixed ones kept)."""
        return self.fast_subsystem().sign_patterns()

    @checked
    def check_signs(self, signs) -> tuple:
        """Validate a sign pattern against the switching functions of the fast subsystem."""
        switching = self.fast_subsystem().switching
        signs = sign_pattern(signs)
        if len(signs) != len(switching):
            raise SignPatternError(
                f"the sign pattern {signs} has length {len(signs)}, but scene {shorten(self.name)} has "
                f"{len(switching)} switching functions {list(switching)}; give one sign (+1 or -1) each."
            )
        for value, s in zip(signs, switching):
            if isinstance(value, bool) or value not in (1, -1):
                raise SignPatternError(f"sign {value!r} for {s} must be +1 or -1.")
            if self.fixed_signs.get(s, value) != value:
                raise SignPatternError(f"{s} > 0 on the unilateral contact; its sign must be +1.")
        return signs

    # --- stages -------------------------------------------------------------------

    @checked(key="tuple | str", build="Callable")
    def cached(self, key, build):
        """``build()``, computed once per ``key`` and kept with the scene: the stages and what is derived
        from them (counts, thresholds) share the scene's cache through this method."""
        if key not in self._stage_cache:
            self._stage_cache[key] = build()
        return self._stage_cache[key]

    @checked
    def regularized(self) -> Regularized:
        """The system (1.7)/(1.9) in slow and fast variables (see :mod:`contactsym.stages.regularize`)."""
        return self.cached("regularized", lambda: Regularized(self))

    @checked
    def fast_subsystem(self) -> FastSubsystem:
        """The associated system (2.1): ``u' = Phi v + Psi f(u)``, ``v' = f(u)``."""
        return self.cached("fast", lambda: FastSubsystem(self))

    @checked
    def equilibria(self, signs=None) -> Equilibria:
        """Equilibria of the fast subsystem, one branch per sign pattern (4.2)."""
        key = None if signs is None else self.check_signs(signs)
        return self.cached(("equilibria", key), lambda: Equilibria(self.fast_subsystem(), key))

    @checked
    def linearization(self, signs=None) -> Linearization:
        """Jacobian A (4.3), the matrix (4.5) and the characteristic polynomial (4.6)."""
        key = None if signs is None else self.check_signs(signs)
        return self.cached(("linear", key), lambda: linearization_of(self.fast_subsystem(), key))

    @checked
    def stability(self, signs=None) -> Stability:
        """Hurwitz conditions (4.7) and the robustness classification (Props. 3-8)."""
        key = None if signs is None else self.check_signs(signs)
        return self.cached(("stability", key), lambda: stability_of(self.fast_subsystem(), key))

    @checked
    def regions(self, signs=None) -> dict:
        """Named closed-form regions: stable / unstable for every law, law-dependent, Hopf line."""
        key = None if signs is None else self.check_signs(signs)
        return self.cached(("regions", key), lambda: scene_regions(self, key))

    @checked
    def equilibrium_counts(self) -> dict:
        """Named closed-form regions by the number of equilibria (see :mod:`contactsym.counts.regions`)."""
        return self.cached("counts", lambda: count_regions(self))

    @checked
    def reduced_system(self, signs=None) -> ReducedSystem:
        """The comparison system (2.2): slow motion with reactions from f(u*) = 0."""
        key = None if signs is None else self.check_signs(signs)
        return self.cached(("reduced", key), lambda: ReducedSystem(self, key))
