"""The engine settings of a target world: what its own physics engine is configured with.

A task must work where the user plays it, so the *domain* states its world's engine settings
(Science Birds: Unity's Physics2DSettings.asset and TimeManager.asset; PHYRE: its simulator's
Box2D call), and every backend honours them as far as its engine can. Box2D, the engine of
both worlds, honours every one natively: the step and the iterations are arguments of its
step, and the rest are the constants it was compiled with, which a Box2D world checks against
these (physc.backends.box2d). What each other backend does with each setting is listed in
its `honours` (`physc backends` prints it).
"""

from __future__ import annotations

import math

import attrs


@attrs.frozen
class EngineSettings:
    """A world's engine settings, in the domain's units (a Box2D world's meaning of each)."""

    dt: float = 1 / 60  # seconds of one step
    velocity_iterations: int = 8  # the solver's velocity iterations per step
    position_iterations: int = 3  # the solver's position iterations per step
    restitution_threshold: float = 1.0  # units/s: slower approaches do not bounce
    linear_slop: float = 0.005  # overlap the solver leaves alone; polygons keep 2 × this apart
    baumgarte: float = 0.2  # share of an overlap corrected per position iteration
    toi_baumgarte: float = 0.75  # the same in a time-of-impact sub-step
    max_linear_correction: float = 0.2  # units a position iteration may move a body
    max_angular_correction: float = math.radians(8.0)
    max_translation: float = 2.0  # units a body may move in one step
    time_to_sleep: float = 0.5  # seconds at rest before a body sleeps
    linear_sleep_tolerance: float = 0.01  # units/s below which a body counts as at rest
    angular_sleep_tolerance: float = math.radians(2.0)  # rad/s below which a body counts as at rest

    @property
    def contact_offset(self) -> float:
        """Unity's name for the skin polygons keep apart (Box2D's polygon radius)."""
        return 2 * self.linear_slop


BOX2D_DEFAULTS = EngineSettings()
"""Box2D 2.3's own defaults (b2Settings.h; the testbed's 8/3 iterations at 60 Hz)."""
