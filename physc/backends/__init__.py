"""Physics backends are plugins (entry-point group `physc.backends`), the built-in
pymunk one included.

A backend is thin (docs/plugins.md): it turns bodies into an engine world and
offers primitives — add and remove bodies, step, read poses and velocities (one body
or all at once), set a velocity, and report the contacts that began or ended. Game rules and the
recognition of interactions are domain code over the backend-neutral values
defined here, so every engine is judged by the same rules.
"""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

import attrs

from physc.backends.settings import BOX2D_DEFAULTS, EngineSettings
from physc.suggest import did_you_mean

if TYPE_CHECKING:  # numpy and the entry points load with the engines, not with the command line
    from importlib.metadata import EntryPoint

    import numpy as np

ENTRY_POINT_GROUP = "physc.backends"
DEFAULT_BACKEND = "box2d"  # the engine of both target worlds (README, "The reference engine")


@attrs.frozen
class Circle:
    radius: float


@attrs.frozen
class Polygon:
    points: tuple[
        tuple[float, float], ...
    ]  # convex, counter-clockwise, about the body's origin (x, y); the mass sits at their centroid


@attrs.frozen
class Compound:
    """A body of several convex parts, rigidly joined (PHYRE's jar: a base and two walls).
    Each part is about the body's origin; the body's contacts are the union of its parts'
    (two bodies touch while any of their parts do). `colliders` names the collider each part
    belongs to, where the target world has several on one body and its scripts hear of a
    contact once per pair of colliders (Unity's OnCollisionEnter2D: Science Birds' SquareHole,
    a box and a holed polygon); None: the body is one collider."""

    parts: tuple[Circle | Polygon, ...]
    colliders: tuple[int, ...] | None = None


def parts(shape: Circle | Polygon | Compound) -> tuple[Circle | Polygon, ...]:
    """The convex parts of a body's shape (a single shape is its own one part)."""
    return shape.parts if isinstance(shape, Compound) else (shape,)


def colliders(shape: Circle | Polygon | Compound) -> tuple[int, ...]:
    """The collider of each of the shape's parts (Compound.colliders; one collider if none said)."""
    if isinstance(shape, Compound) and shape.colliders is not None:
        return shape.colliders
    return (0,) * len(parts(shape))


def half_extents(shape: Circle | Polygon | Compound) -> tuple[float, float]:
    """The half-width and half-height of a shape's box about the body's origin, in its own frame."""
    w = h = 0.0
    for part in parts(shape):
        if isinstance(part, Circle):
            w, h = max(w, part.radius), max(h, part.radius)
        else:
            w = max([w] + [abs(x) for x, _ in part.points])
            h = max([h] + [abs(y) for _, y in part.points])
    return w, h


@attrs.frozen
class BodySpec:
    name: str
    shape: Circle | Polygon | Compound
    x: float
    y: float
    angle: float = 0.0  # radians, counter-clockwise
    static: bool = False
    mass: float | None = None  # None: density × area
    density: float = 1.0
    friction: float = 0.5  # as the game states it; the backend combines pairs like Box2D
    bounciness: float = 0.0
    gravity_scale: float = 1.0  # relative to the world's gravity
    angular_damping: float = 0.0  # Box2D-style: ω ← ω / (1 + dt · damping) each step
    continuous: bool = False  # swept against moving bodies too (Box2D's bullet; Unity's Continuous detection)
    group: str = (
        ""  # bodies of one named group never collide with each other (Unity's layer matrix; Box2D's negative group)
    )

    @property
    def outline(self) -> tuple[float, float, float, float, float]:
        """(x, y, angle, half-width, half-height): the body's box where it starts (Trace.outlines)."""
        return (self.x, self.y, self.angle, *half_extents(self.shape))


_GROUPS: dict[str, int] = {}


def group_number(group: str) -> int:
    """The positive number an engine knows a `BodySpec.group` by (the same in every world of
    a process; only equality matters, so the order groups are first met in does not)."""
    return _GROUPS.setdefault(group, len(_GROUPS) + 1)


@attrs.frozen
class ContactEvent:
    """Two bodies began touching. `normal` points from `a` to `b`; `relative_velocity`
    is a's velocity minus b's at the contact point, before the collision is resolved.
    `first`: whether the two bodies touched nothing of each other before; False when another
    pair of their colliders (Compound.colliders) began touching while they already touched,
    which a world's rules hear of as a contact of its own (Science Birds' damage) and the
    recording of what touched what does not."""

    a: str
    b: str
    point: tuple[float, float]
    normal: tuple[float, float]
    relative_velocity: tuple[float, float]
    velocity_a: tuple[float, float]
    velocity_b: tuple[float, float]
    first: bool = True


class EngineWorld(Protocol):
    """An engine's world: the bodies of one play in one engine (not the target world,
    physc.worlds.World, whose settings it is built with)."""

    names: list[str]

    def add(self, spec: BodySpec) -> None: ...
    def remove(self, name: str) -> None: ...
    def step(self, dt: float) -> None: ...
    def state(self, name: str) -> tuple[float, float, float, float, float, float]: ...
    def states(self, names: Sequence[str], out: np.ndarray | None = None) -> np.ndarray:
        """`state` of every named body, a row each (NaN for a body not in the world),
        written into `out` (shape (len(names), 6)) if given: the game reads the whole world
        once per step through this, into the trace's row for the step."""
        ...

    def set_velocity(self, name: str, vx: float, vy: float, angular: float = 0.0) -> None: ...
    def restore(self, name: str, state: tuple[float, float, float, float, float, float]) -> None:
        """Put a body back in `state` (x, y, angle, vx, vy, ω, as `state` reads it) and wake
        it: a run continued from a snapshot (physc.simulation.snapshot)."""
        ...

    def mass(self, name: str) -> float: ...
    def disable_collider(self, name: str, collider: int) -> None:
        """Take the parts of `name`'s collider `collider` (Compound.colliders) out of the
        world: their contacts end, the body's mass is what is left (Unity's
        `Collider2D.enabled = false` on an auto-mass body). Optional: a backend without it
        leaves a world's rules to take the whole body out instead."""
        ...

    def begun(self) -> list[ContactEvent]: ...
    def ended(self) -> list[tuple[str, str]]: ...
    def touching(self, name: str) -> set[str]: ...
    def touches(self, a: str, b: str) -> bool:
        """Whether `a` and `b` touch now (`b in touching(a)`, without a copy: rules ask it every step)."""
        ...

    def moving(self, names: Sequence[str], speed: float) -> bool:
        """Whether any of the bodies `names` still in the world moves faster than `speed` by
        |vx| + |vy| + |ω| (a sleeping body does not move): what rules that end a run once all
        is still ask every step instead of reading every state."""
        ...

    def listen(self, details: bool) -> None:
        """Whether the contacts begun and ended are reported (`begun`, `ended`) with their
        details; False: only who touches whom is kept (an outcome playout whose rules hear no
        contacts, physc.simulation.run.run_to_outcome)."""
        ...


def _count(table: dict, key, change: int) -> int:
    """`table[key]` moved by `change`, the key dropped at zero: the parts in contact of a pair."""
    count = table.get(key, 0) + change
    if count > 0:
        table[key] = count
    else:
        table.pop(key, None)
    return count


class ContactLog:
    """The contact bookkeeping a world reports through, the same for every engine: the
    contacts begun and ended since the last call, and who touches whom now. A world
    subclasses it and tells it what its engine saw (`_began`, `_parted`, `_gone`)."""

    def __init__(self):
        self._begun: list[ContactEvent] = []
        self._ended: list[tuple[str, str]] = []
        self._touching: dict[str, set[str]] = {}
        self._part_contacts: dict[tuple[str, str], int] = {}  # a pair of bodies → their parts in contact
        self._collider_contacts: dict[tuple, int] = {}  # a pair of (body, collider) → their parts in contact
        self._details = True  # whether begun and ended contacts are reported (`listen`)

    def listen(self, details: bool) -> None:
        self._details = details

    def _counted(self, a: str, b: str, change: int) -> int:
        """The parts of `a` and `b` in contact after `change` (+1 a pair of parts began
        touching, -1 one parted): a compound body's parts each begin and end their own
        contacts, and the bodies touch while any do."""
        return _count(self._part_contacts, (a, b) if a < b else (b, a), change)

    def _part_began(self, a: str, a_collider: int, b: str, b_collider: int, event) -> None:
        """A part of `a`'s collider `a_collider` began touching a part of `b`'s `b_collider`:
        the event (`event(first)` makes it, so that a world reads velocities only when one is
        due) when that pair of colliders touched nothing of each other before, `first` when
        the two bodies did not either."""
        bodies = self._counted(a, b, 1)
        if self._counted_colliders(a, a_collider, b, b_collider, 1) == 1:
            if self._details:
                self._began(event(bodies == 1))
            elif bodies == 1:
                self._touch(a, b)

    def _part_ended(self, a: str, a_collider: int, b: str, b_collider: int) -> None:
        """A part of `a`'s collider `a_collider` parted from a part of `b`'s `b_collider`."""
        self._counted_colliders(a, a_collider, b, b_collider, -1)
        if self._counted(a, b, -1) == 0:
            self._parted(a, b)

    def _counted_colliders(self, a: str, a_collider: int, b: str, b_collider: int, change: int) -> int:
        key = ((a, a_collider), (b, b_collider)) if a < b else ((b, b_collider), (a, a_collider))
        return _count(self._collider_contacts, key, change)

    def _began(self, event: ContactEvent) -> None:
        if self._details:
            self._begun.append(event)
        self._touch(event.a, event.b)

    def _touch(self, a: str, b: str) -> None:
        self._touching.setdefault(a, set()).add(b)
        self._touching.setdefault(b, set()).add(a)

    def _parted(self, a: str, b: str) -> None:
        if self._details:
            self._ended.append((a, b))
        if a in self._touching:
            self._touching[a].discard(b)
        if b in self._touching:
            self._touching[b].discard(a)

    def _gone(self, name: str) -> None:
        """`name` left the world: it touches nothing any more."""
        self._part_contacts = {pair: n for pair, n in self._part_contacts.items() if name not in pair}
        self._collider_contacts = {
            pair: n for pair, n in self._collider_contacts.items() if name not in (pair[0][0], pair[1][0])
        }
        for other in self._touching.pop(name, ()):
            self._touching.get(other, set()).discard(name)

    def assume_touching(self, pairs) -> None:
        """Count `pairs` as touching now (a run continued from a snapshot, whose engine reports
        their contact only once it steps them, and a sleeping body not until it wakes)."""
        for a, b in pairs:
            self._touching.setdefault(a, set()).add(b)
            self._touching.setdefault(b, set()).add(a)

    def begun(self) -> list[ContactEvent]:
        events, self._begun = self._begun, []
        return events

    def ended(self) -> list[tuple[str, str]]:
        events, self._ended = self._ended, []
        return events

    def touching(self, name: str) -> set[str]:
        return set(self._touching.get(name, ()))

    def touches(self, a: str, b: str) -> bool:
        return b in self._touching.get(a, ())

    def states(self, names: Sequence[str], out: np.ndarray | None = None) -> np.ndarray:
        """Each body's (x, y, angle, vx, vy, ω), a row each (EngineWorld.states): the engine's
        world that subclasses this reads them."""
        raise NotImplementedError

    def moving(self, names: Sequence[str], speed: float) -> bool:
        """From the bodies' states (`states`, which a world subclassing this has); a world whose
        engine says which bodies sleep reads only the others."""
        return any(abs(r[3]) + abs(r[4]) + abs(r[5]) > speed for r in self.states(list(names)).tolist())


@attrs.frozen
class Backend:
    """A physics backend: its name, one line for people, and the EngineWorld class it builds
    (`world(gravity, settings)`, settings: physc.backends.settings.EngineSettings). A plugin
    registers one under `physc.backends`. `honours` says, setting by setting, what its engine
    does with the target world's engine settings (`physc backends` prints it); `package` is
    the distribution whose version `physc backends` reports."""

    name: str
    description: str
    world: type
    package: str = ""
    honours: dict[str, str] = attrs.field(factory=dict)

    def create_world(self, gravity: float, settings: EngineSettings | None = None) -> EngineWorld:
        return self.world(gravity, settings or BOX2D_DEFAULTS)


class BackendError(Exception):
    pass


def installed_backends() -> dict[str, EntryPoint]:
    from importlib.metadata import entry_points

    return dict(sorted((ep.name, ep) for ep in entry_points(group=ENTRY_POINT_GROUP)))


@functools.cache
def load_backend(name: str = DEFAULT_BACKEND) -> Backend:
    installed = installed_backends()
    if name not in installed:
        hint = did_you_mean(name, installed) or "installed backends: " + (", ".join(installed) or "none")
        raise BackendError(f"the physics backend '{name}' is not installed; {hint}")
    try:
        return installed[name].load()
    except Exception as error:  # a broken third-party plugin must not crash physc
        raise BackendError(
            f"the plugin of backend '{name}' ({installed[name].value}) fails to load: {error}"
        ) from error
