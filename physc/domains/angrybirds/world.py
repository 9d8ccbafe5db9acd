"""The Science Birds world: level bounds, the slingshot, and the bird's reach.

Facts from shared/design/sciencebirds-facts.md: a `width="2"` level spans x in
[-17.5, 17.5]; the ground's top is at y = -3.5; the slingshot stands at
(-12, -2.5) and the bird rests at (-12.15, -1.7); gravity is 9.81 with a gravity
scale of 0.48; a full-stretch launch has speed 10.
"""

from __future__ import annotations

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


def discriminant(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> float:
    """v⁴ − g(g·dx² + 2·dy·v²) for the point (x, y) seen from the bird's rest point:
    the launch equation has a real root (the point is in reach) exactly when it is ≥ 0."""
    dx, dy = x - BIRD_REST[0], y - BIRD_REST[1]
    return speed**4 - gravity * (gravity * dx * dx + 2 * dy * speed * speed)


def reachable(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> bool:
    """Whether a full-stretch shot from the bird's rest point can pass through (x, y)."""
    return discriminant(x, y, speed, gravity) >= 0
