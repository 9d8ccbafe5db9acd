"""The Science Birds world: level bounds, the slingshot, and the bird's reach.

Facts from shared/design/sciencebirds-facts.md: a `width="2"` level spans x in
[-17.5, 17.5]; the ground's top is at y = -3.5; the slingshot stands at
(-12, -2.5) and the bird rests at (-12.15, -1.7); gravity is 9.81 with a gravity
scale of 0.48; a full-stretch launch has speed 10.

The game launches the bird from where it was dragged to, not from its rest point
(ABBird.cs `LaunchBird`): the rest point pulled back along the shot by the stretch times
the drag radius (1 unit at full stretch), its collider 0.05 right and 0.03 below that
(BirdRed.prefab). So a shot at an angle starts up to a unit behind and below the rest
point, and the angle that passes through a point is found from that start (`aim`).
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
DRAG_RADIUS = 1.0  # BirdRed.prefab `_dragRadius`: a full stretch pulls the bird back this far
BIRD_COLLIDER_OFFSET = (0.05, -0.03)  # BirdRed.prefab CircleCollider2D `m_Offset`


@attrs.frozen
class Area:
    """Where generated objects may be placed."""

    left: float = -10.0  # clear of the slingshot
    right: float = 17.0
    bottom: float = GROUND_TOP
    top: float = 7.0  # keep the level inside the camera's view


PLACEMENT_AREA = Area()


def launch_point(angle: float, stretch: float = 1.0) -> tuple[float, float]:
    """Where the bird's centre starts a shot released at `angle` degrees: the rest point
    pulled back along the shot by `stretch` × the drag radius, plus the collider's offset."""
    theta = math.radians(angle)
    pull = DRAG_RADIUS * min(max(stretch, 0.0), 1.0)
    return (BIRD_REST[0] - pull * math.cos(theta) + BIRD_COLLIDER_OFFSET[0], BIRD_REST[1] - pull * math.sin(theta) + BIRD_COLLIDER_OFFSET[1])


def discriminant(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY, origin: tuple[float, float] = BIRD_REST) -> float:
    """v⁴ − g(g·dx² + 2·dy·v²) for the point (x, y) seen from `origin`: the launch equation
    has a real root (the point is in reach from there) exactly when it is ≥ 0."""
    dx, dy = x - origin[0], y - origin[1]
    return speed**4 - gravity * (gravity * dx * dx + 2 * dy * speed * speed)


def _angle_from(origin, x: float, y: float, trajectory: str, speed: float, gravity: float) -> float | None:
    dx = x - origin[0]
    disc = discriminant(x, y, speed, gravity, origin)
    if disc < 0:
        return None
    if dx == 0:
        return 90.0
    root = math.sqrt(disc)
    tangent = (speed**2 - root) / (gravity * dx) if trajectory == "low" else (speed**2 + root) / (gravity * dx)
    angle = math.degrees(math.atan(tangent))
    return angle if dx > 0 else angle + 180.0


def aim(x: float, y: float, trajectory: str = "low", speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> float | None:
    """The release angle (degrees) of the full-stretch shot whose flight, started where the
    game starts it (`launch_point`), passes through (x, y) on the low or high trajectory;
    None when no such shot reaches the point. The start depends on the angle, so the angle is
    found from the rest point first, then from the start it gives, until it settles."""
    angle = _angle_from(BIRD_REST, x, y, trajectory, speed, gravity)
    for _ in range(50):
        if angle is None:
            return None
        again = _angle_from(launch_point(angle), x, y, trajectory, speed, gravity)
        if again is not None and abs(again - angle) < 1e-9:
            return again
        angle = again
    return angle


def reachable(x: float, y: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> bool:
    """Whether a full-stretch shot, launched as the game launches it, can pass through (x, y)."""
    return aim(x, y, "high", speed, gravity) is not None
