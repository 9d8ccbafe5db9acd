"""A pymunk world behind physc's backend interface.

Box2D (the engine of Science Birds) and Chipmunk combine contact properties
differently: Box2D takes the geometric mean of two frictions and the larger of
two restitutions; Chipmunk multiplies. Each shape therefore gets the square root
of its friction (the product is then the geometric mean, exactly), and the
pair's restitution is set to the larger of the two when the contact begins,
which is when an impact's bounce is computed. Box2D's angular damping is a
damped rotary spring of no stiffness to the static body (C, not Python). Contacts
are reported from pymunk 7's `Space.on_collision` begin and separate callbacks.
The target world's engine settings are honoured as far as Chipmunk can (HONOURS): the
solver's iterations are the velocity iterations, the collision slop and the polygons' skin
are Box2D's (levels saved from the game keep stacked blocks 0.015 apart: Box2D's 0.01
polygon skin on each, less its slop), sleeping follows the time and the linear tolerance,
and an impact slower than the restitution threshold does not bounce (set when the contact
begins, as Box2D decides it). The game steps
and reads the world hundreds of times per simulation, so both are kept lean: `states` reads every
body in one batched call (pymunk.batch) through numpy views of its buffer, and `step` calls
Chipmunk's step directly unless bodies were added or removed since the last step (then pymunk's
own `Space.step` does its bookkeeping). The world is deterministic: same bodies, same steps, same
result.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import pymunk
import pymunk.batch
from pymunk._chipmunk_cffi import ffi, lib
from pymunk.constraints import Constraint, DampedRotarySpring

from physc.backends import BodySpec, Circle, ContactEvent, ContactLog, colliders, group_number, parts
from physc.backends.settings import EngineSettings

HONOURS = {
    "dt": "native (Space.step)",
    "velocity_iterations": "native (Space.iterations; Chipmunk has one solver loop)",
    "position_iterations": "not honoured (Chipmunk corrects positions by bias velocities, no iterations)",
    "restitution_threshold": "emulated (no bounce for a slower approach, set when the contact begins)",
    "linear_slop": "native (Space.collision_slop; polygons' skin 2 × slop)",
    "baumgarte": "not honoured (Chipmunk's collision_bias)",
    "toi_baumgarte": "not honoured (Chipmunk has no continuous collision)",
    "max_linear_correction": "not honoured",
    "max_angular_correction": "not honoured",
    "max_translation": "not honoured",
    "time_to_sleep": "native (Space.sleep_time_threshold)",
    "linear_sleep_tolerance": "native (Space.idle_speed_threshold)",
    "angular_sleep_tolerance": "not honoured (Chipmunk's idle test is linear)",
}
# What one batched read returns per body: id; x, y, angle, vx, vy, ω (in this order).
BATCH_FIELDS = (
    pymunk.batch.BodyFields.BODY_ID
    | pymunk.batch.BodyFields.POSITION
    | pymunk.batch.BodyFields.ANGLE
    | pymunk.batch.BodyFields.VELOCITY
    | pymunk.batch.BodyFields.ANGULAR_VELOCITY
)


def _velocity_function(scale: float):
    def update(body, gravity, damping, dt):
        pymunk.Body.update_velocity(body, (gravity[0] * scale, gravity[1] * scale), damping, dt)

    return update


class PymunkWorld(ContactLog):
    def __init__(self, gravity: float, settings: EngineSettings):
        super().__init__()
        self.settings = settings
        self.space = pymunk.Space()
        self.space.gravity = (0.0, -gravity)
        self.space.iterations = settings.velocity_iterations
        self.space.collision_slop = settings.linear_slop
        self.space.sleep_time_threshold = settings.time_to_sleep
        self.space.idle_speed_threshold = settings.linear_sleep_tolerance
        self._skin = settings.contact_offset
        self.gravity = gravity
        self.names: list[str] = []
        self.bodies: dict[str, pymunk.Body] = {}
        self.shapes: dict[str, tuple[pymunk.Shape, ...]] = {}
        self._name_of: dict[int, str] = {}
        self._collider_of: dict[int, int] = {}  # a shape → the collider of its body it belongs to (Compound.colliders)
        self._bounciness: dict[int, float] = {}
        self._drags: dict[str, Constraint] = {}
        # One batched read of every body per step (pymunk.batch's own call, without
        # building its request anew each time): the buffer, the request, the reader, and
        # numpy views of the buffer's two arrays (`_ids`, `_floats`; renewed when one grows).
        self._buffer = pymunk.batch.Buffer()
        self._request = ffi.new("pmBatchedData *")
        self._request.fields = BATCH_FIELDS.value
        self._request.floatArray = self._buffer._float_arr
        self._request.intArray = self._buffer._int_arr
        self._reader = ffi.addressof(lib, "pmSpaceBodyGetIteratorFuncBatched")
        self._capacity = (-1, -1)  # the arrays' capacities when the views were made
        self._ids = self._floats = np.empty(0)
        self._read_order: tuple | None = None  # (body ids as read, names asked, a copy) of the last read,
        self._rows: tuple = ()  # and where the names' rows are in it: `_arrange`'s result
        # Chipmunk's step, called directly once pymunk's own bookkeeping (checking new
        # bodies, releasing removed shapes) has nothing to do: after the first step
        # following an `add` or a `remove`. The callbacks never add or remove bodies.
        self._cp_space = self.space._space
        self._cp_step = lib.cpSpaceStep
        self._changed = True
        self.space.on_collision(begin=self._on_begin, separate=self._on_separate)

    # ---- building --------------------------------------------------------------
    def add(self, spec: BodySpec) -> None:
        if spec.static:
            body = pymunk.Body(body_type=pymunk.Body.STATIC)
        else:
            body = pymunk.Body()
        body.position = (spec.x, spec.y)
        body.angle = spec.angle
        shapes = tuple(
            pymunk.Circle(body, s.radius) if isinstance(s, Circle) else pymunk.Poly(body, s.points, radius=self._skin)
            for s in parts(spec.shape)
        )
        total = sum(shape.area for shape in shapes)
        for shape in shapes:
            if not spec.static:
                if spec.mass is not None:  # a given mass spread over the parts by area
                    shape.mass = spec.mass if len(shapes) == 1 else spec.mass * shape.area / total
                else:
                    shape.density = spec.density
            shape.friction = math.sqrt(max(spec.friction, 0.0))
            shape.elasticity = spec.bounciness
            if spec.group:
                shape.filter = pymunk.ShapeFilter(group=group_number(spec.group))
        self.space.add(body, *shapes)
        self._changed = True
        if not spec.static and spec.gravity_scale != 1.0:
            body.velocity_func = _velocity_function(spec.gravity_scale)
        if not spec.static and spec.angular_damping:
            # Box2D's angular damping, dω/dt = −c·ω, is the torque −c·I·ω: a rotary
            # spring of no stiffness to the static body applies it, in C.
            drag = DampedRotarySpring(body, self.space.static_body, 0.0, 0.0, spec.angular_damping * body.moment)
            self.space.add(drag)
            self._drags[spec.name] = drag
        self.names.append(spec.name)
        self.bodies[spec.name] = body
        self.shapes[spec.name] = shapes
        for shape, collider in zip(shapes, colliders(spec.shape), strict=False):
            self._name_of[id(shape)] = spec.name
            self._collider_of[id(shape)] = collider
            self._bounciness[id(shape)] = spec.bounciness

    def disable_collider(self, name: str, collider: int) -> None:
        shapes = self.shapes[name]
        going = [shape for shape in shapes if self._collider_of[id(shape)] == collider]
        self.space.remove(*going)  # Chipmunk separates their arbiters; the body's mass is the rest's
        self.shapes[name] = tuple(shape for shape in shapes if shape not in going)
        self._changed = True

    def remove(self, name: str) -> None:
        body, shapes = self.bodies.pop(name), self.shapes.pop(name)
        if name in self._drags:
            self.space.remove(self._drags.pop(name))
        self.space.remove(body, *shapes)
        self._changed = True
        self.names.remove(name)
        self._gone(name)

    # ---- running -----------------------------------------------------------------
    def step(self, dt: float) -> None:
        if self._changed:
            self.space.step(dt)
            self._changed = False
        else:
            self._cp_step(self._cp_space, dt)

    def state(self, name: str):
        body = self.bodies[name]
        (x, y), (vx, vy) = body.position, body.velocity
        return (x, y, body.angle, vx, vy, body.angular_velocity)

    def states(self, names: Sequence[str], out: np.ndarray | None = None) -> np.ndarray:
        """`state` of every named body at once, a row per name (NaN for a body not in the
        world), from one batched read of the space; into `out` if given."""
        floats, ints = self._buffer._float_arr, self._buffer._int_arr
        floats.num = ints.num = 0
        lib.cpSpaceEachBody(self._cp_space, self._reader, self._request)
        if (ints.max, floats.max) != self._capacity:  # an array grew (was reallocated): view them anew
            self._capacity = (ints.max, floats.max)
            self._ids = np.frombuffer(ffi.buffer(ints.arr, ffi.sizeof("uintptr_t") * ints.max), dtype=np.uintp)
            self._floats = np.frombuffer(ffi.buffer(floats.arr, ffi.sizeof("cpFloat") * floats.max), dtype=np.float64)
        count = ints.num
        ids = self._ids[:count].tobytes()
        order = self._read_order
        if order is None or order[0] != ids or (order[1] is not names and order[2] != tuple(names)):
            self._read_order = (ids, names, tuple(names))
            self._rows = self._arrange(self._ids[:count], names)
        rows, absent = self._rows
        table = self._floats[: count * 6].reshape(-1, 6)
        if out is None:
            out = table[rows]
        else:
            table.take(rows, 0, out)  # positional: numpy's keywords cost more than the copy here
        if absent is not None:
            out[absent] = np.nan
        return out

    def _arrange(self, ids: np.ndarray, names: Sequence[str]):
        """Where each named body is in a batched read; which names have no body."""
        row_of = {int(i): r for r, i in enumerate(ids)}
        rows = [row_of.get(self.bodies[n].id, -1) if n in self.bodies else -1 for n in names]
        absent = np.array([r < 0 for r in rows], dtype=bool)
        return np.array([max(r, 0) for r in rows], dtype=np.intp), (absent if absent.any() else None)

    def set_velocity(self, name: str, vx: float, vy: float, angular: float = 0.0) -> None:
        body = self.bodies[name]
        body.velocity = (vx, vy)
        body.angular_velocity = angular
        body.activate() if body.body_type == pymunk.Body.DYNAMIC else None

    def restore(self, name: str, state) -> None:
        x, y, angle, vx, vy, w = state
        body = self.bodies[name]
        body.position, body.angle = (x, y), angle
        self.space.reindex_shapes_for_body(body)
        self.set_velocity(name, vx, vy, w)

    def mass(self, name: str) -> float:
        return self.bodies[name].mass

    def ended(self) -> list[tuple[str, str]]:
        # Chipmunk reports separations while walking a hash set keyed by memory addresses:
        # their order within a step would vary from process to process.
        return sorted(super().ended())

    # ---- collision callbacks -------------------------------------------------------
    def _pair(self, arbiter):
        first, second = arbiter.shapes
        return self._name_of.get(id(first)), self._name_of.get(id(second))

    def _on_begin(self, arbiter, space, data):
        a, b = self._pair(arbiter)
        if a is None or b is None:
            return
        points = arbiter.contact_point_set.points
        point = points[0].point_a if points else arbiter.bodies[0].position
        body_a, body_b = arbiter.bodies
        va = body_a.velocity_at_world_point(point)
        vb = body_b.velocity_at_world_point(point)
        normal = arbiter.normal
        # Box2D's restitution of a pair is the larger one, and none below its threshold
        # speed of approach. Chipmunk takes the product every step, but the bounce of an
        # impact is computed in the step the contact begins, right after this callback.
        approach = (va.x - vb.x) * normal.x + (va.y - vb.y) * normal.y
        bounces = approach > self.settings.restitution_threshold
        arbiter.restitution = (
            max(self._bounciness[id(arbiter.shapes[0])], self._bounciness[id(arbiter.shapes[1])]) if bounces else 0.0
        )
        first, second = arbiter.shapes
        self._part_began(
            a,
            self._collider_of[id(first)],
            b,
            self._collider_of[id(second)],
            lambda new: ContactEvent(
                a,
                b,
                (point.x, point.y),
                (normal.x, normal.y),
                (va.x - vb.x, va.y - vb.y),
                (va.x, va.y),
                (vb.x, vb.y),
                new,
            ),
        )

    def _on_separate(self, arbiter, space, data):
        a, b = self._pair(arbiter)
        if a is None or b is None:
            return
        first, second = arbiter.shapes
        self._part_ended(a, self._collider_of[id(first)], b, self._collider_of[id(second)])
