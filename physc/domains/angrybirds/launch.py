"""The launch model: a full-stretch shot from the bird's rest point.

velocity = direction · 10 · min(stretch, 1); to pass through a target point
(dx, dy) from the launch point, tan θ = (v² ± √(v⁴ − g(g dx² + 2 dy v²))) / (g dx):
the minus root is the low trajectory, the plus root the high one; no real root
means the point is out of reach.
"""

from __future__ import annotations

import math

import attrs

from physc.domains.angrybirds.world import (
    BIRD_REST,
    GRAVITY,
    LAUNCH_SPEED,
    discriminant,
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
        dx = x - BIRD_REST[0]
        disc = discriminant(x, y, speed, gravity)
        if disc < 0:
            raise Unreachable(f"({x:g}, {y:g}) is out of reach of a full-stretch shot")
        if dx == 0:
            return 90.0
        root = math.sqrt(disc)
        tangent = (speed**2 - root) / (gravity * dx) if self.trajectory == "low" else (speed**2 + root) / (gravity * dx)
        angle = math.degrees(math.atan(tangent))
        return angle if dx > 0 else angle + 180.0

    def at_angle(self, angle: float, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> Shot:
        """The shot released at `angle` instead, named like this one: by the point of its
        flight above the same x as this shot's target, on the same trajectory."""
        x = self.target[0]
        dx = x - BIRD_REST[0]
        theta = math.radians(angle)
        y = BIRD_REST[1] + dx * math.tan(theta) - gravity * dx * dx / (2 * speed**2 * math.cos(theta) ** 2)
        return Shot(target=(x, round(y, 6)), trajectory=self.trajectory)

    def velocity(self, speed: float = LAUNCH_SPEED, gravity: float = GRAVITY) -> tuple[float, float]:
        angle = math.radians(self.release_angle(speed, gravity))
        return speed * math.cos(angle), speed * math.sin(angle)

    def text(self) -> str:
        if self.angle is not None:
            return f"angle {self.angle:g}°"
        return f"({self.target[0]:g}, {self.target[1]:g}), {self.trajectory}"
