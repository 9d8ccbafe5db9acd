"""The launch model: a full-stretch shot, as the game launches it.

velocity = direction · 10 · min(stretch, 1), set on the bird where it was dragged to
(physc.domains.angrybirds.world.launch_point); to pass through a target point (dx, dy)
from there, tan θ = (v² ± √(v⁴ − g(g dx² + 2 dy v²))) / (g dx): the minus root is the low
trajectory, the plus root the high one; no real root means the point is out of reach.
"""

from __future__ import annotations

import math

import attrs

from physc.domains.angrybirds.world import (
    GRAVITY,
    LAUNCH_SPEED,
    aim,
    launch_point,
)


class Unreachable(ValueError):
    pass


@attrs.frozen
class Shot:
    """A shot: at a target point on the low or high trajectory, or at a release angle."""

    target: tuple[float, float] | None = None
    trajectory: str = "low"  # "low" | "high"
    angle: float | None = None  # degrees above the horizontal, counter-clockwise

    def release_angle(self, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> float:
        """The release angle in degrees."""
        if self.angle is not None:
            return self.angle
        x, y = self.target
        angle = aim(x, y, self.trajectory, speed, gravity)
        if angle is None:
            raise Unreachable(f"({x:g}, {y:g}) is out of reach of a full-stretch shot")
        return angle

    def at_angle(self, angle: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> Shot:
        """The shot released at `angle` instead, named like this one: by the point of its
        flight above the same x as this shot's target, on the same trajectory."""
        x = self.target[0]
        origin = launch_point(angle)
        dx = x - origin[0]
        theta = math.radians(angle)
        y = origin[1] + dx * math.tan(theta) - gravity * dx * dx / (2 * speed**2 * math.cos(theta) ** 2)
        return Shot(target=(x, round(y, 6)), trajectory=self.trajectory)

    def origin(self, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> tuple[float, float]:
        """Where the bird's centre starts this shot (the game's dragged-to point)."""
        return self.start(speed, gravity)[0]

    def start(self, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> tuple[tuple[float, float], tuple[float, float]]:
        """Where the bird starts this shot and its velocity there, from one release angle
        (finding it from a target point iterates: `aim`)."""
        angle = self.release_angle(speed, gravity)
        theta = math.radians(angle)
        return launch_point(angle), (speed * math.cos(theta), speed * math.sin(theta))

    def velocity(self, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> tuple[float, float]:
        return self.start(speed, gravity)[1]

    def text(self) -> str:
        if self.angle is not None:
            return f"angle {self.angle:g}°"
        return f"({self.target[0]:g}, {self.target[1]:g}), {self.trajectory}"
