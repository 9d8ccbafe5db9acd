"""A pybullet world confined to the level's plane, behind physc's backend interface.

pybullet is a 3-D engine with no planar joint and no linear or angular factors. Each dynamic
body is therefore a multibody of its own: a fixed, massless base at the origin, a prismatic
joint along x, one along y and a revolute joint about z, with the body's shape on the last
link (the mechanism of bullet3's biped2d example). The joints' coordinates *are* the body's
x, y and angle, so no body can leave the plane or turn out of it, and a state read is one
`getJointStates` call. The joints' motors are switched off; Box2D's angular damping is the
revolute joint's damping. Static bodies are plain fixed bodies.

Shapes are extrusions (bodies.py): boxes for rectangles, convex hulls for other polygons,
spheres for circles (a sphere's single contact point rolls on a platform as the game's
circle does; see docs/performance.md for the calibration). Mass is set from the *area* (a
polygon's with its skin, as pymunk counts it), and the inertia about z from the 2-D shape, so
they mean what they mean in pymunk whatever the depth. Bullet multiplies the friction of two bodies and multiplies
their restitution; each body gets the square root of its friction (the pair's product is the geometric mean, as
Box2D's), and its own bounciness against a static body of restitution 1 (exact against the
static world); a game step in which two dynamic bodies strike each other is taken again, from
the bodies' poses and velocities at its start (Bullet keeps its own contact caches), with Box2D's
larger-of-two for them (physc.backends.bullet.restitution).

Bullet reports no contact events, only the contact points after a step. Contacts begun and
ended are the difference of the touching pairs between two steps; a contact's relative
velocity is taken from the two bodies' velocities read before the step, so it is the
velocity before the collision was resolved. Two differences of the engines are bridged where
they would change what a task's solution does: bodies that start overlapping are pushed
apart without speed (`_separate`), and a body set moving flies as it does in pymunk
(`set_velocity`). Each world has its own DIRECT client, with deterministic overlapping
pairs: same bodies, same steps, same result.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import attrs
import numpy as np
import pybullet

from physc.backends import BackendError, BodySpec, ContactEvent, ContactLog
from physc.backends.bullet.bodies import BODY_LINK, JOINTS, SKIN, collision_shape, planar_body, static_body
from physc.backends.bullet.restitution import raised
from physc.backends.bullet.shapes import area, centroid, polar_moment
from physc.backends.settings import EngineSettings

SUBSTEPS = 2  # Bullet steps per game step
ITERATIONS = 10  # the solver's iterations per Bullet step (calibrated: docs/performance.md, "Two engines")
SEPARATION = 50  # Bullet steps at most that push initial overlaps apart (see _separate)
SLOP = 0.005  # overlap left alone before the first step (pymunk's and Box2D's linear slop)
TOUCH = 0.005  # contact points this near (or nearer: negative is overlap) count as touching
HONOURS = {
    "dt": "native (two Bullet sub-steps per step)",
    "velocity_iterations": "not honoured (10 per sub-step, calibrated against pymunk)",
    "position_iterations": "not honoured (Bullet corrects positions by ERP)",
    "restitution_threshold": "native (restitutionVelocityThreshold)",
    "linear_slop": "native (contactSlop)",
    "baumgarte": "native (erp, contactERP, frictionERP)",
    "toi_baumgarte": "not honoured (no continuous collision in the planar bodies)",
    "max_linear_correction": "not honoured",
    "max_angular_correction": "not honoured",
    "max_translation": "not honoured",
    "time_to_sleep": "not honoured (Bullet's own deactivation)",
    "linear_sleep_tolerance": "not honoured",
    "angular_sleep_tolerance": "not honoured",
}


@attrs.frozen
class Dynamic:
    """What the world keeps of a dynamic body (Bullet keeps the rest)."""

    mass: float
    inertia: float  # about z, through the centre of mass
    centre: tuple[float, float]  # the centre of mass in the body's frame (a polygon's centroid; pymunk's too)
    bounciness: float
    damping: float  # Box2D's angular damping (1/s)
    gravity_scale: float


class BulletWorld(ContactLog):
    def __init__(self, gravity: float, settings: EngineSettings):
        super().__init__()
        self.settings = settings
        self.client = pybullet.connect(pybullet.DIRECT)
        if self.client < 0:
            raise BackendError("pybullet could not start a physics client (DIRECT)")
        self.gravity = gravity
        pybullet.setGravity(0.0, -gravity, 0.0, physicsClientId=self.client)
        self.names: list[str] = []
        self._id: dict[str, int] = {}  # name → Bullet body id
        self._name_of: dict[int, str] = {}  # Bullet id → name (Bullet gives a freed id to the next body)
        self._dynamic: dict[str, Dynamic] = {}
        self._groups: dict[str, list[str]] = {}  # BodySpec.group → its bodies so far
        self._pairs: dict[tuple[int, int], tuple] = {}  # touching pairs after the last step
        self._dt: float | None = None
        self._unlagged: set[str] = set()  # bodies set moving before the first step (set_velocity)

    def __del__(self):
        try:
            pybullet.disconnect(physicsClientId=self.client)
        except Exception:  # already gone (interpreter shutdown)
            pass

    # ---- building --------------------------------------------------------------
    def add(self, spec: BodySpec) -> None:
        shape = collision_shape(self.client, spec)
        if spec.static:
            body = static_body(self.client, spec, shape)
        else:
            mass = spec.mass if spec.mass is not None else spec.density * area(spec.shape, SKIN)
            centre = centroid(spec.shape, SKIN)
            inertia = polar_moment(spec.shape, mass, SKIN) - mass * (centre[0] ** 2 + centre[1] ** 2)
            body = planar_body(self.client, spec, shape, mass, inertia, centre)
            self._dynamic[spec.name] = Dynamic(
                mass, inertia, centre, spec.bounciness, spec.angular_damping, spec.gravity_scale
            )
            if self._dt is not None:
                self._set_damping(spec.name, body, self._dt)
        if spec.group and not spec.static:  # no collision with the group's other bodies (Bullet filters pairs of links)
            for other in self._groups.setdefault(spec.group, []):
                pybullet.setCollisionFilterPair(
                    body, self._id[other], BODY_LINK, BODY_LINK, 0, physicsClientId=self.client
                )
            self._groups[spec.group].append(spec.name)
        self.names.append(spec.name)
        self._id[spec.name] = body
        self._name_of[body] = spec.name

    def remove(self, name: str) -> None:
        """Take a body out. Its contacts end now, as in pymunk (reported by the next `ended`):
        Bullet gives a removed body's id to the next body added."""
        body = self._id.pop(name)
        for key in sorted(k for k in self._pairs if body in k):
            self._parted(*self._names(self._pairs.pop(key)))
        self._gone(name)
        pybullet.removeBody(body, physicsClientId=self.client)
        self.names.remove(name)
        self._dynamic.pop(name, None)

    # ---- running -----------------------------------------------------------------
    def _configure(self, dt: float) -> None:
        """The engine's settings for a game step of `dt`, set at the first step."""
        self._dt = dt
        pybullet.setPhysicsEngineParameter(
            fixedTimeStep=dt / SUBSTEPS,
            numSubSteps=0,
            numSolverIterations=ITERATIONS,
            erp=self.settings.baumgarte,
            contactERP=self.settings.baumgarte,
            frictionERP=self.settings.baumgarte,
            contactSlop=self.settings.linear_slop,
            restitutionVelocityThreshold=self.settings.restitution_threshold,
            deterministicOverlappingPairs=1,
            physicsClientId=self.client,
        )
        for name in self._dynamic:
            self._set_damping(name, self._id[name], dt)
        self._separate()
        for name in sorted(self._unlagged & self._dynamic.keys()):
            self._unlag(name, dt)
        self._unlagged.clear()

    def _separate(self) -> None:
        """Push apart the bodies that start overlapping by more than SLOP, without giving them
        speed: Bullet's multibody solver corrects an overlap with a velocity that stays (a
        level's touching blocks would jump apart), where pymunk and Box2D move the bodies
        apart and keep their velocities. So before the first step, the overlaps are solved
        in up to SEPARATION Bullet steps without gravity, each begun with every dynamic
        body still; then each gets back the velocity it had (a bird already
        fired). Levels whose bodies do not overlap are not touched."""
        c = self.client
        pybullet.performCollisionDetection(physicsClientId=c)
        if not self._overlapping():
            return
        speeds = {name: self.state(name)[3:] for name in self._dynamic}  # a shot already fired keeps its speed
        pybullet.setGravity(0.0, 0.0, 0.0, physicsClientId=c)
        for _ in range(SEPARATION):
            for name in self._dynamic:
                self._velocity(name, 0.0, 0.0, 0.0)
            pybullet.stepSimulation(physicsClientId=c)
            if not self._overlapping():
                break
        for name, (vx, vy, w) in speeds.items():
            self._velocity(name, vx, vy, w)
        pybullet.setGravity(0.0, -self.gravity, 0.0, physicsClientId=c)

    def _overlapping(self) -> bool:
        """Whether two bodies overlap by more than SLOP (as Bullet's last collision detection found)."""
        return any(point[8] < -SLOP for point in pybullet.getContactPoints(physicsClientId=self.client))

    def _set_damping(self, name: str, body: int, dt: float) -> None:
        """Box2D's ω ← ω / (1 + dt·c) each game step, as the revolute joint's damping: Bullet
        applies ω ← ω (1 − h·d/I) each of its SUBSTEPS steps of h."""
        dynamic = self._dynamic[name]
        if not dynamic.damping:
            return
        h = dt / SUBSTEPS
        rate = (1.0 - (1.0 + dt * dynamic.damping) ** (-1.0 / SUBSTEPS)) / h
        pybullet.changeDynamics(body, BODY_LINK, jointDamping=rate * dynamic.inertia, physicsClientId=self.client)

    def step(self, dt: float) -> None:
        if self._dt != dt:
            self._configure(dt)
        before = {name: self.state(name) for name in self._dynamic}
        pairs = self._substeps(before)
        events = self._new_contacts(pairs, before)
        bouncing = self._bouncing(pairs, events)
        if bouncing:  # once more from the start, with Box2D's restitution for those pairs
            for name, state in before.items():
                self.restore(name, state)
            self._restitution(bouncing)
            pairs = self._substeps(before)
            self._restitution({name: self._dynamic[name].bounciness for name in bouncing})
            events = self._new_contacts(pairs, before)
        self._contacts(pairs, events)

    def _substeps(self, before: dict[str, tuple]) -> dict[tuple[int, int], tuple]:
        """The Bullet steps of one game step; the pairs that touched in them."""
        c = self.client
        pairs: dict[tuple[int, int], tuple] = {}
        for _ in range(SUBSTEPS):
            for name, dynamic in self._dynamic.items():
                if dynamic.gravity_scale != 1.0:
                    # The force that makes its gravity scale true, at the centre of mass: given in
                    # the body's own frame (Bullet's world-frame point is the last step's, and
                    # would give a moving body a lever arm).
                    pull = -dynamic.mass * self.gravity * (dynamic.gravity_scale - 1.0)
                    angle = self.state(name)[2]
                    force = (pull * math.sin(angle), pull * math.cos(angle), 0.0)
                    pybullet.applyExternalForce(
                        self._id[name], BODY_LINK, force, (0.0, 0.0, 0.0), pybullet.LINK_FRAME, physicsClientId=c
                    )
            pybullet.stepSimulation(physicsClientId=c)
            self._touched(pairs)
        return pairs

    def _bouncing(self, pairs: dict, events: list[ContactEvent]) -> dict[str, float]:
        """The restitution, for the step again, of each body that began touching a dynamic
        body of less bounciness, fast, and touched nothing else (physc.backends.bullet.restitution)."""
        partners: dict[str, list[str]] = {}
        for point in pairs.values():
            a, b = self._names(point)
            partners.setdefault(a, []).append(b)
            partners.setdefault(b, []).append(a)
        raised_to: dict[str, float] = {}
        for event in events:
            a, b = event.a, event.b
            if (
                a not in self._dynamic
                or b not in self._dynamic
                or self._dynamic[a].bounciness == self._dynamic[b].bounciness
            ):
                continue
            approach = event.relative_velocity[0] * event.normal[0] + event.relative_velocity[1] * event.normal[1]
            high, low = (a, b) if self._dynamic[a].bounciness > self._dynamic[b].bounciness else (b, a)
            if approach > self.settings.restitution_threshold and partners[high] == [low]:
                raised_to[high], kept = raised(self._dynamic[high].bounciness, self._dynamic[low].bounciness)
                if kept != self._dynamic[low].bounciness:
                    raised_to[low] = max(raised_to.get(low, 0.0), kept)
        return raised_to

    def _restitution(self, values: dict[str, float]) -> None:
        for name, value in values.items():
            pybullet.changeDynamics(self._id[name], BODY_LINK, restitution=value, physicsClientId=self.client)

    def restore(self, name: str, state: tuple) -> None:
        """Put a body back where and as it was (a step taken again, a snapshot)."""
        self._set_joints(name, state[:3], state[3:])

    def _touched(self, pairs: dict[tuple[int, int], tuple]) -> None:
        """Add the pairs touching in the last Bullet step to `pairs`: a contact point at most
        TOUCH apart, or one that pushed (Bullet's speculative contacts stop a body short of
        the other in the step it arrives, and it may bounce off before it ever overlaps)."""
        for point in pybullet.getContactPoints(physicsClientId=self.client):
            if point[8] > TOUCH and point[9] <= 0.0:
                continue
            key = (point[1], point[2]) if point[1] < point[2] else (point[2], point[1])
            if key not in pairs:
                pairs[key] = point

    def _new_contacts(self, pairs: dict[tuple[int, int], tuple], before: dict[str, tuple]) -> list[ContactEvent]:
        """The contacts of `pairs` that the last game step did not have, in a fixed order."""
        return [self._event(pairs[key], before) for key in sorted(pairs.keys() - self._pairs.keys())]

    def _contacts(self, pairs: dict[tuple[int, int], tuple], events: list[ContactEvent]) -> None:
        """The pairs touching in a game step's Bullet steps: those new to it began (`events`),
        those gone from it ended."""
        for event in events:
            self._began(event)
        for key in sorted(self._pairs.keys() - pairs.keys()):
            self._parted(*self._names(self._pairs[key]))
        self._pairs = pairs

    def _names(self, point: tuple) -> tuple[str, str]:
        """The two bodies of a contact point, in Bullet's order (A, B)."""
        return self._name_of[point[1]], self._name_of[point[2]]

    def _event(self, point: tuple, before: dict[str, tuple]) -> ContactEvent:
        a, b = self._names(point)
        px, py = point[5][0], point[5][1]
        va = self._point_velocity(a, before.get(a), px, py)
        vb = self._point_velocity(b, before.get(b), px, py)
        normal = point[7]  # on B, pointing from B to A
        return ContactEvent(a, b, (px, py), (-normal[0], -normal[1]), (va[0] - vb[0], va[1] - vb[1]), va, vb)

    def state(self, name: str):
        """(x, y, angle, vx, vy, ω): the origin's position and the centre of mass's velocity,
        as pymunk gives them (Bullet's joints move with the origin)."""
        (x, vx, *_), (y, vy, *_), (angle, w, *_) = pybullet.getJointStates(
            self._id[name], JOINTS, physicsClientId=self.client
        )
        rx, ry = self._arm(name, angle)
        return (x, y, angle, vx - w * ry, vy + w * rx, w)

    def _arm(self, name: str, angle: float) -> tuple[float, float]:
        """From the body's origin to its centre of mass, in the world's axes."""
        cx, cy = self._dynamic[name].centre
        if not cx and not cy:
            return 0.0, 0.0
        cos, sin = math.cos(angle), math.sin(angle)
        return cx * cos - cy * sin, cx * sin + cy * cos

    def _centre_of_mass(self, name: str, state: tuple) -> tuple[float, float]:
        rx, ry = self._arm(name, state[2])
        return state[0] + rx, state[1] + ry

    def _point_velocity(self, name: str, state: tuple | None, px: float, py: float) -> tuple[float, float]:
        """The velocity of the body's point (px, py): v + ω × r from its centre of mass; zero
        for a static body."""
        if state is None:
            return (0.0, 0.0)
        x, y = self._centre_of_mass(name, state)
        vx, vy, w = state[3:]
        return (vx - w * (py - y), vy + w * (px - x))

    def states(self, names: Sequence[str], out: np.ndarray | None = None) -> np.ndarray:
        if out is None:
            out = np.empty((len(names), 6))
        for row, name in enumerate(names):
            out[row] = self.state(name) if name in self._dynamic else np.nan
        return out

    def set_velocity(self, name: str, vx: float, vy: float, angular: float = 0.0) -> None:
        """Set a body moving, as pymunk means it: Chipmunk moves a body with its velocity
        before gravity changes it, Bullet (as Box2D) after, so a body set moving at v flies
        a little lower in Bullet, more with every second (0.07 units/s: the bird lands 0.2
        units short). Setting Bullet's velocity lower by gravity's change over the game step
        in which it would act before the move, G·dt·(k+1)/(2k) for k Bullet steps, makes the
        flight the same, step for step, until the body touches something."""
        self._velocity(name, vx, vy, angular)
        if self._dt is None:
            self._unlagged.add(name)  # done at the first step, when dt is known
        else:
            self._unlag(name, self._dt)

    def _unlag(self, name: str, dt: float) -> None:
        vx, vy, w = self.state(name)[3:]
        lag = self.gravity * self._dynamic[name].gravity_scale * dt * (SUBSTEPS + 1) / (2 * SUBSTEPS)
        self._velocity(name, vx, vy + lag, w)

    def _velocity(self, name: str, vx: float, vy: float, angular: float) -> None:
        """Set a body's velocity (its centre of mass's, and ω) in Bullet, as it stands."""
        self._set_joints(name, self.state(name)[:3], (vx, vy, angular))

    def _set_joints(self, name: str, pose, velocity) -> None:
        """Bullet's joints of a body: the pose (x, y, angle of its origin) and the velocity
        (vx, vy of its centre of mass, ω), turned into the origin's."""
        rx, ry = self._arm(name, pose[2])
        vx, vy, w = velocity
        body = self._id[name]
        for joint, value, speed in zip(JOINTS, pose, (vx + w * ry, vy - w * rx, w), strict=False):
            pybullet.resetJointState(body, joint, value, speed, physicsClientId=self.client)

    def mass(self, name: str) -> float:
        return self._dynamic[name].mass
