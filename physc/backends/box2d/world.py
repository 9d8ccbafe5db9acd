"""A Box2D world behind physc's backend interface: the target worlds' own engine.

Science Birds runs Unity's 2D physics, which is Box2D 2.x, and PHYRE runs Box2D 2.3; pybox2d
is Box2D 2.3.x. Everything the target world configures is honoured natively, nothing
emulated: the step, the velocity and position iterations are the arguments of `b2World.Step`,
and the thresholds (restitution, slop and polygon skin, Baumgarte factors, corrections,
sleeping) are the constants Box2D was compiled with, which a world checks against the
domain's settings at creation (a mismatch is a BackendError, not a silent difference). Box2D
mixes frictions by their geometric mean and restitutions by the larger, and damps rotation by
ω ← ω / (1 + dt · c), exactly as Unity states them, so a body's values go in as the game gives
them.

Contacts are Box2D's own events: `BeginContact` (called while the step finds new touching
pairs, before the solver, so the bodies' velocities are still those before the impact) and
`EndContact` (also called when a body is destroyed). A compound body begins a contact when
its first part touches and ends it when its last part parts; each pair of its colliders
(Compound.colliders) that begins touching after that is an event of its own (`first` False). A concave polygon, or
one with more than Unity's eight corners, is split into convex parts (physc.backends.convex). A
`continuous` body is a Box2D bullet (Unity's Continuous collision detection): swept against
moving bodies too, not only static ones.

Reading the world is most of the Python work per step, so `states` reads only the bodies that
are awake, and a sleeping one once after it fell asleep (Box2D zeroes its velocity then): it has
not moved since, and that row is reused.
The world is deterministic: same bodies, same steps, same result.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence

import Box2D
import Box2D._Box2D as _Box2D
import numpy as np

from physc.backends import BackendError, BodySpec, Circle, ContactEvent, ContactLog, colliders, group_number, parts
from physc.backends.convex import MAX_CORNERS, convex_parts, signed_area
from physc.backends.settings import EngineSettings

# pybox2d's C accessors, called directly: its Python properties add a call each (the states
# of every awake body are read every step).
_position = _Box2D.b2Body___GetPosition
_velocity = _Box2D.b2Body___GetLinearVelocity
_angle = _Box2D.b2Body___GetAngle
_spin = _Box2D.b2Body___GetAngularVelocity
_awake = _Box2D.b2Body___IsAwake
_x = _Box2D.b2Vec2_x_get
_y = _Box2D.b2Vec2_y_get

# Each setting, the Box2D constant it must equal (pybox2d exposes them), and how it is honoured.
COMPILED = {
    "restitution_threshold": "b2_velocityThreshold",
    "linear_slop": "b2_linearSlop",
    "baumgarte": "b2_baumgarte",
    "toi_baumgarte": "b2_toiBaugarte",
    "max_linear_correction": "b2_maxLinearCorrection",
    "max_angular_correction": "b2_maxAngularCorrection",
    "max_translation": "b2_maxTranslation",
    "time_to_sleep": "b2_timeToSleep",
    "linear_sleep_tolerance": "b2_linearSleepTolerance",
    "angular_sleep_tolerance": "b2_angularSleepTolerance",
}
HONOURS = {
    "dt": "native (b2World.Step)",
    "velocity_iterations": "native (b2World.Step)",
    "position_iterations": "native (b2World.Step)",
    **{setting: f"native ({constant}, compiled in; checked)" for setting, constant in COMPILED.items()},
}


def check_settings(settings: EngineSettings) -> None:
    """BackendError unless every compiled-in constant is the domain's setting."""
    for setting, constant in COMPILED.items():
        wanted, built = getattr(settings, setting), getattr(Box2D, constant)
        if not math.isclose(wanted, built, rel_tol=1e-6):
            raise BackendError(
                f"Box2D was compiled with {constant} = {built:g}, but the domain's world needs {setting} = {wanted:g}; "
                "pybox2d cannot change it at run time"
            )


class _Listener(Box2D.b2ContactListener):
    """Box2D's contact events, handed to the world."""

    def __init__(self, world: Box2DWorld):
        super().__init__()
        self.world = world

    def BeginContact(self, contact):  # Box2D's name
        self.world._on_begin(contact)

    def EndContact(self, contact):  # Box2D's name
        self.world._on_end(contact)


class Box2DWorld(ContactLog):
    def __init__(self, gravity: float, settings: EngineSettings):
        super().__init__()
        check_settings(settings)
        self.settings = settings
        self.gravity = gravity
        self.world = Box2D.b2World(gravity=(0.0, -gravity), doSleep=True)
        self._listener = _Listener(self)
        self.world.contactListener = self._listener
        self.names: list[str] = []
        self.bodies: dict[str, Box2D.b2Body] = {}
        self._asleep_in_table: set[str] = set()  # bodies whose row was read while they slept
        self._version = 0  # bumped by add and remove: `states` looks the bodies up again
        self._read_for: Sequence[str] | None = None  # the names of the last `states`, their bodies,
        self._read_bodies: list = []  # and the version they were looked up at
        self._read_version = -1
        self._table = np.empty((0, 6))
        self._moving_for: Sequence[str] | None = None  # the same for `moving`: the names asked,
        self._moving_bodies: list = []  # their bodies in the world,
        self._moving_version = -1  # and the version they were looked up at

    # ---- building --------------------------------------------------------------
    def add(self, spec: BodySpec) -> None:
        if spec.name in self.bodies:
            raise BackendError(f"a body named '{spec.name}' is already in the world")
        body_def, fixtures = _definitions(spec)
        body = self.world.CreateBody(body_def)
        for fixture in fixtures:
            body.CreateFixture(fixture)
        self.names.append(spec.name)
        self.bodies[spec.name] = body
        self._version += 1

    def disable_collider(self, name: str, collider: int) -> None:
        body = self.bodies[name]
        for fixture in [f for f in body.fixtures if f.userData == collider]:
            body.DestroyFixture(fixture)  # Box2D ends its contacts (EndContact) and resets the mass
        self._version += 1

    def remove(self, name: str) -> None:
        body = self.bodies.pop(name)
        self.world.DestroyBody(body)  # Box2D ends its contacts (EndContact) here
        self._version += 1
        self.names.remove(name)
        self._gone(name)

    # ---- running -----------------------------------------------------------------
    def step(self, dt: float) -> None:
        self.world.Step(dt, self.settings.velocity_iterations, self.settings.position_iterations)

    def state(self, name: str):
        body = self.bodies[name]
        p, v = _position(body), _velocity(body)
        return (_x(p), _y(p), _angle(body), _x(v), _y(v), _spin(body))

    def moving(self, names: Sequence[str], speed: float) -> bool:
        """Read from the awake bodies alone: Box2D zeroes a body's velocity as it falls asleep."""
        if self._moving_for is not names or self._moving_version != self._version:
            self._moving_for, self._moving_version = (
                names,
                self._version,
            )  # the bodies of `names`, looked up again after an add or a remove
            self._moving_bodies = [self.bodies[name] for name in names if name in self.bodies]
        for body in self._moving_bodies:
            if _awake(body):
                v = _velocity(body)
                if abs(_x(v)) + abs(_y(v)) + abs(_spin(body)) > speed:
                    return True
        return False

    def states(self, names: Sequence[str], out: np.ndarray | None = None) -> np.ndarray:
        if self._read_for is not names or self._read_version != self._version:
            # The bodies of `names`, and a table of their rows that only awake bodies rewrite.
            self._read_for, self._read_version = names, self._version
            self._read_bodies = [(row, name, self.bodies.get(name)) for row, name in enumerate(names)]
            self._table = np.full((len(names), 6), np.nan)
            self._asleep_in_table = set()
        table, asleep = self._table, self._asleep_in_table
        for row, name, body in self._read_bodies:
            if body is None:
                continue
            if _awake(body):
                asleep.discard(name)
            elif name in asleep:
                continue  # read since it fell asleep (Box2D zeroed its velocity then): unchanged
            else:
                asleep.add(name)
            p, v = _position(body), _velocity(body)
            table[row] = (_x(p), _y(p), _angle(body), _x(v), _y(v), _spin(body))
        if out is None:
            return table.copy()
        out[:] = table
        return out

    def set_velocity(self, name: str, vx: float, vy: float, angular: float = 0.0) -> None:
        body = self.bodies[name]
        body.awake = True
        body.linearVelocity = (vx, vy)
        body.angularVelocity = angular
        self._asleep_in_table.discard(name)

    def restore(self, name: str, state) -> None:
        """A body still in `state` was asleep (Box2D zeroes a sleeping body's velocity) and is
        put back asleep: the solver then skips it until something touches it, as it did."""
        x, y, angle, vx, vy, w = state
        body = self.bodies[name]
        body.transform = ((x, y), angle)
        if vx or vy or w:
            self.set_velocity(name, vx, vy, w)
        else:
            body.awake = False

    def mass(self, name: str) -> float:
        return self.bodies[name].mass

    def ended(self) -> list[tuple[str, str]]:
        return sorted(super().ended())

    # ---- contact events ------------------------------------------------------------
    def _on_begin(self, contact) -> None:
        fixture_a, fixture_b = contact.fixtureA, contact.fixtureB
        body_a, body_b = fixture_a.body, fixture_b.body
        a, b = body_a.userData, body_b.userData

        def event(first: bool) -> ContactEvent:
            manifold = contact.worldManifold
            count = contact.manifold.pointCount
            point = tuple(manifold.points[0]) if count else tuple(body_a.worldCenter)
            if count > 1:  # the middle of the two points of a face contact
                point = tuple((p + q) / 2 for p, q in zip(manifold.points[0], manifold.points[1], strict=False))
            va = body_a.GetLinearVelocityFromWorldPoint(point)
            vb = body_b.GetLinearVelocityFromWorldPoint(point)
            normal = tuple(manifold.normal)
            return ContactEvent(
                a, b, point, normal, (va[0] - vb[0], va[1] - vb[1]), (va[0], va[1]), (vb[0], vb[1]), first
            )

        self._part_began(a, fixture_a.userData, b, fixture_b.userData, event)

    def _on_end(self, contact) -> None:
        fixture_a, fixture_b = contact.fixtureA, contact.fixtureB
        self._part_ended(fixture_a.body.userData, fixture_a.userData, fixture_b.body.userData, fixture_b.userData)


@functools.lru_cache(maxsize=4096)
def _definitions(spec: BodySpec) -> tuple:
    """Box2D's definitions of a body and of its fixtures, made once per body (a search plays
    the same level's bodies thousands of times, with only the action's body new each time);
    Box2D copies a definition, and clones its shape, into each world it builds."""
    kind = Box2D.b2_staticBody if spec.static else Box2D.b2_dynamicBody
    body = Box2D.b2BodyDef(
        type=kind,
        position=(spec.x, spec.y),
        angle=spec.angle,
        angularDamping=spec.angular_damping,
        gravityScale=spec.gravity_scale,
        bullet=spec.continuous,
        userData=spec.name,
    )
    shapes = [
        (shape, collider)
        for part, collider in zip(parts(spec.shape), colliders(spec.shape), strict=False)
        for shape in _box2d_shapes(part)
    ]
    area = sum(_area(shape) for shape, _ in shapes)  # of the shapes as Box2D holds them (float32 corners)
    density = spec.density if spec.mass is None else spec.mass / max(area, 1e-12)
    fixtures = tuple(
        Box2D.b2FixtureDef(
            shape=shape,
            density=0.0 if spec.static else density,
            friction=spec.friction,
            restitution=spec.bounciness,
            userData=collider,
            **({"groupIndex": -group_number(spec.group)} if spec.group else {}),
        )
        for shape, collider in shapes
    )
    return body, _Fixtures(fixtures, tuple(shape for shape, _ in shapes))


class _Fixtures(tuple):
    """A body's fixture definitions, holding their shapes (a definition points at its shape
    without keeping it alive)."""

    shapes: tuple

    def __new__(cls, fixtures: tuple, shapes: tuple):
        made = super().__new__(cls, fixtures)
        made.shapes = shapes
        return made


@functools.lru_cache(maxsize=4096)
def _box2d_shapes(part) -> list:
    if isinstance(part, Circle):
        return [Box2D.b2CircleShape(radius=part.radius)]
    return [
        Box2D.b2PolygonShape(vertices=list(points)) for points in convex_parts(part.points, max_corners=MAX_CORNERS)
    ]


def _area(shape) -> float:
    if isinstance(shape, Box2D.b2CircleShape):
        return math.pi * shape.radius**2
    return abs(signed_area(shape.vertices))
