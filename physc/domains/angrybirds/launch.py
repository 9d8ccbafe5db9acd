"""The launch model: a full-stretch shot, as the game launches it.

The game launches the bird from where it was dragged to, not from its rest point
(ABBird.cs `LaunchBird`): the rest point pulled back along the shot by the stretch times
the drag radius (1 unit at full stretch), its collider 0.05 right and 0.03 below that
(BirdRed.prefab), with velocity = direction · 10 · min(stretch, 1). To pass through a
target point (dx, dy) from there, tan θ = (v² ± √(v⁴ − g(g dx² + 2 dy v²))) / (g dx): the
minus root is the low trajectory, the plus root the high one; no real root means the point
is out of reach. The start depends on the angle, so the angle is found from the rest point
first, then from the start it gives, until it settles. Gravity is the world's
(physc.domains.angrybirds.worlds): every aim is made in one world.
"""

from __future__ import annotations

import math

import attrs


class Unreachable(ValueError):
    pass


@attrs.frozen
class Launch:
    """The slingshot's launch: where the bird rests, how far a full stretch pulls it, its speed."""

    bird_rest: tuple[float, float] = attrs.field(
        default=(-12.15, -1.7), metadata={"source": "Phy-Q levels' bird (sciencebirds-facts §1)"}
    )
    speed: float = attrs.field(default=10.0, metadata={"source": "ABConstants.BIRD_MAX_LANUCH_SPEED"})
    drag_radius: float = attrs.field(default=1.0, metadata={"source": "BirdRed.prefab `_dragRadius`"})
    collider_offset: tuple[float, float] = attrs.field(
        default=(0.05, -0.03), metadata={"source": "BirdRed.prefab CircleCollider2D `m_Offset`"}
    )

    def point(self, angle: float, stretch: float = 1.0) -> tuple[float, float]:
        """Where the bird's centre starts a shot released at `angle` degrees: the rest point
        pulled back along the shot by `stretch` × the drag radius, plus the collider's offset."""
        theta = math.radians(angle)
        pull = self.drag_radius * min(max(stretch, 0.0), 1.0)
        rest, offset = self.bird_rest, self.collider_offset
        return (rest[0] - pull * math.cos(theta) + offset[0], rest[1] - pull * math.sin(theta) + offset[1])

    def discriminant(self, x: float, y: float, gravity: float, origin: tuple[float, float] | None = None) -> float:
        """v⁴ − g(g·dx² + 2·dy·v²) for (x, y) seen from `origin` (the rest point): the launch
        equation has a real root (the point is in reach from there) exactly when it is ≥ 0."""
        origin = origin or self.bird_rest
        dx, dy, v = x - origin[0], y - origin[1], self.speed
        return v**4 - gravity * (gravity * dx * dx + 2 * dy * v * v)

    def _angle_from(self, origin, x: float, y: float, trajectory: str, gravity: float) -> float | None:
        dx = x - origin[0]
        disc = self.discriminant(x, y, gravity, origin)
        if disc < 0:
            return None
        if dx == 0:
            return 90.0
        root, v2 = math.sqrt(disc), self.speed**2
        tangent = (v2 - root) / (gravity * dx) if trajectory == "low" else (v2 + root) / (gravity * dx)
        angle = math.degrees(math.atan(tangent))
        return angle if dx > 0 else angle + 180.0

    def aim(self, x: float, y: float, trajectory: str, gravity: float) -> float | None:
        """The release angle (degrees) of the full-stretch shot whose flight, started where the
        game starts it (`point`), passes through (x, y) on the low or high trajectory; None
        when no such shot reaches the point."""
        angle = self._angle_from(self.bird_rest, x, y, trajectory, gravity)
        for _ in range(50):
            if angle is None:
                return None
            again = self._angle_from(self.point(angle), x, y, trajectory, gravity)
            if again is not None and abs(again - angle) < 1e-9:
                return again
            angle = again
        return angle

    def reachable(self, x: float, y: float, gravity: float) -> bool:
        """Whether a full-stretch shot, launched as the game launches it, can pass through (x, y)."""
        return self.aim(x, y, "high", gravity) is not None


@attrs.frozen
class Shot:
    """A shot: at a target point on the low or high trajectory, or at a release angle. Where
    it flies depends on the world (its launch and gravity), so each question takes one.
    Version 2 (several shots, birds' powers): the bird it launches (the trace's name of it),
    when the player taps (its power: seconds after the launch, None: no tap), and, for a shot
    after the first, when it is shot (`wait`: seconds after the game brought its bird onto the
    slingshot, when the bird before first struck something or used its power, flight.py; None:
    once the level is at rest, as Phy-Q's agents wait). `stretch`: how far the bird is
    pulled, in drag radii (1: a full-stretch shot, as every shot physc makes; an agent's shorter
    drag launches nearer the rest point and slower, ABBird.cs `LaunchBird`)."""

    target: tuple[float, float] | None = None
    trajectory: str = "low"  # "low" | "high"
    angle: float | None = None  # degrees above the horizontal, counter-clockwise
    tap: float | None = None
    bird: str = "bird"
    wait: float | None = None
    stretch: float = 1.0

    def release_angle(self, world) -> float:
        """The release angle in degrees in `world` (physc.domains.angrybirds.worlds)."""
        if self.angle is not None:
            return self.angle
        assert self.target is not None, "a shot has a target point or a release angle"
        x, y = self.target
        angle = world.launch.aim(x, y, self.trajectory, world.gravity)
        if angle is None:
            raise Unreachable(f"({x:g}, {y:g}) is out of reach of a full-stretch shot")
        return angle

    def at_angle(self, angle: float, world) -> Shot | None:
        """The shot released at `angle` instead, named like this one: by the point of its
        flight above the same x as this shot's target, on the trajectory (low or high) whose aim
        at that point is this angle again (a shot turned far enough passes the point on the
        other branch); None when no point names it (the flight never gets there)."""
        assert self.target is not None, "a shot turned to another angle is named by its target's x"
        x = self.target[0]
        origin = world.launch.point(angle)
        speed, gravity = world.launch.speed, world.gravity
        dx = x - origin[0]
        theta = math.radians(angle)
        y = origin[1] + dx * math.tan(theta) - gravity * dx * dx / (2 * speed**2 * math.cos(theta) ** 2)
        target = (x, round(y, 6))
        other = "high" if self.trajectory == "low" else "low"
        for trajectory in (self.trajectory, other):
            aimed = world.launch.aim(*target, trajectory, gravity)
            if aimed is not None and abs(aimed - angle) < 1e-3:
                return attrs.evolve(self, target=target, trajectory=trajectory, angle=None)
        return None

    def origin(self, world) -> tuple[float, float]:
        """Where the bird's centre starts this shot (the game's dragged-to point)."""
        return self.start(world)[0]

    def start(self, world) -> tuple[tuple[float, float], tuple[float, float]]:
        """Where the bird starts this shot and its velocity there, from one release angle: at
        full stretch 10 units/s, at a shorter one that times the stretch (ABBird.cs `LaunchBird`:
        the drag's length over the drag radius times the top speed)."""
        angle = self.release_angle(world)
        theta = math.radians(angle)
        stretch = min(max(self.stretch, 0.0), 1.0)
        speed = world.launch.speed * stretch
        return world.launch.point(angle, stretch), (speed * math.cos(theta), speed * math.sin(theta))

    def velocity(self, world) -> tuple[float, float]:
        return self.start(world)[1]

    def text(self) -> str:
        if self.angle is not None:
            aim = f"angle {self.angle:g}°"
        else:
            assert self.target is not None, "a shot has a target point or a release angle"
            aim = f"({self.target[0]:g}, {self.target[1]:g}), {self.trajectory}"

        pulled = "" if self.stretch >= 1.0 else f", stretch {self.stretch:.3g}"
        timed = "" if self.wait is None else f", {self.wait:g} s after its bird came onto the slingshot"
        return aim + pulled + ("" if self.tap is None else f", tap at {self.tap:g} s") + timed

    @property
    def shots(self) -> tuple[Shot, ...]:
        return (self,)


@attrs.frozen
class Shots:
    """Several shots in turn, one bird each (language version 2): each is shot from the state
    the one before left (`Shot.wait`)."""

    shots: tuple[Shot, ...]

    def text(self) -> str:
        return "; ".join(f"{s.bird}: {s.text()}" for s in self.shots)

    def then(self, shot: Shot) -> Shots:
        return Shots(self.shots + (shot,))


def shots_of(action) -> tuple[Shot, ...]:
    """The shots of an action (a Shot or Shots; None: none)."""
    return () if action is None else action.shots
