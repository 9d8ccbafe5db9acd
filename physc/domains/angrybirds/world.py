"""The Science Birds world: level bounds, the slingshot, and the bird's reach.

Facts from shared/design/sciencebirds-facts.md: a `width="2"` level spans x in
[-17.5, 17.5]; the ground's top is at y = -3.5; the slingshot stands at
(-12, -2.5) and the bird rests at (-12.15, -1.7); gravity is 9.81 with a gravity
scale of 0.48; a full-stretch launch has speed 10.
"""

from __future__ import annotations

import math

import attrs

LEVEL_LEFT = -17.5
LEVEL_RIGHT = 17.5
GROUND_TOP = -3.5
SLINGSHOT = (-12.0, -2.5)
BIRD_REST = (-12.15, -1.7)
GRAVITY = 9.81 * 0.48
LAUNCH_SPEED = 10.0


@attrs.frozen
class Area:
    """Where generated objects may be placed."""

    left: float = -10.0  # clear of the slingshot
    right: float = 17.0
    bottom: float = GROUND_TOP
    top: float = 7.0  # keep the level inside the camera's view


PLACEMENT_AREA = Area()


def reachable(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> bool:
    """Whether a full-stretch shot from the bird's rest point can pass through (x, y).

    The launch equation tan θ = (v² ± √(v⁴ − g(g dx² + 2 dy v²))) / (g dx) has a
    real root exactly when the discriminant is not negative.
    """
    dx, dy = x - BIRD_REST[0], y - BIRD_REST[1]
    return speed**4 - gravity * (gravity * dx * dx + 2 * dy * speed * speed) >= 0


def launch_angles(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY):
    """The (low, high) release angles in radians that pass through (x, y), or None."""
    dx, dy = x - BIRD_REST[0], y - BIRD_REST[1]
    disc = speed**4 - gravity * (gravity * dx * dx + 2 * dy * speed * speed)
    if disc < 0 or dx == 0:
        return None
    root = math.sqrt(disc)
    low = math.atan((speed**2 - root) / (gravity * dx))
    high = math.atan((speed**2 + root) / (gravity * dx))
    return low, high
