"""Simulation traces: what happened in a run, as backend-neutral data.

A trace holds the poses and velocities of every dynamic body at every step, the
contacts that began and ended (with relative velocity), damage, destructions,
and the interactions a domain recognised from all that, printable in `.phys`
syntax. Traces are values: domain rules and recognisers read them; they never
reach into an engine.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import attrs
import numpy as np

if TYPE_CHECKING:
    from physc.backends import ContactEvent


@attrs.frozen
class ContactRecord:
    time: float
    a: str
    b: str
    point: tuple[float, float]
    normal: tuple[float, float]  # from a to b
    relative_velocity: tuple[float, float]  # a's minus b's, before the collision
    velocity_a: tuple[float, float]
    velocity_b: tuple[float, float]

    @classmethod
    def of(cls, time: float, event: ContactEvent) -> ContactRecord:
        """The record of a contact the engine reported beginning (`event`) at `time`."""
        return cls(
            time,
            event.a,
            event.b,
            event.point,
            event.normal,
            event.relative_velocity,
            event.velocity_a,
            event.velocity_b,
        )

    @property
    def speed(self) -> float:
        return float(np.hypot(*self.relative_velocity))


@attrs.frozen
class SeparationRecord:
    time: float
    a: str
    b: str


@attrs.frozen
class DamageRecord:
    time: float
    target: str
    amount: float
    life: float  # left after the damage
    by: str
    # The body whose mass set the damage (a domain's rule may make it the target itself), and
    # the contact speed that would have destroyed the target with that attacker: what a link
    # that was to destroy it needed (physc.simulation.stopped). None where no rule says.
    attacker: str | None = None
    needed: float | None = None
    # The least and the most damage any reading of what the world's files leave open would
    # have dealt in the same contact (World.open_points; None where the rules say nothing of
    # readings): the worst reading for a link that must destroy, and for one that must survive.
    # A contact that deals nothing in the run's own reading but would in another is recorded
    # with `amount` 0.
    least: float | None = None
    most: float | None = None


@attrs.frozen
class DependenceRecord:
    """A decision of the rules at `time`, about `target`, that another reading of the world's
    open points (`points`: their setting paths, physc.worlds.OpenPoint) would have made
    otherwise: under such a reading the run may go another way (physc.worlds.under_readings)."""

    time: float
    target: str
    points: tuple[str, ...]


@attrs.frozen
class DestructionRecord:
    time: float
    name: str
    cause: str  # "damage" | "out of world" | "removed"
    by: str | None = None
    # When the body left the world, where its rules kept it there a while after it left the
    # level (Science Birds: a dying object until its Destroy): None, at `time`.
    until: float | None = None


@attrs.frozen
class Interaction:
    """A recognised interaction, as a term of the `.phys` language."""

    name: str
    objects: tuple[str, ...]
    direction: str | None
    time: float

    def text(self) -> str:
        arguments = list(self.objects) + ([self.direction] if self.direction else [])
        return f"{self.name}({', '.join(arguments)})"


@attrs.frozen
class Violation:
    restriction: str
    interaction: Interaction

    def text(self) -> str:
        return f"{self.restriction} violated at t = {self.interaction.time:.2f} s by {self.interaction.text()}"


class Run:
    """What a whole trace and an outcome playout both tell of a run: how long it lasted, what
    was destroyed, where a body's column is (each has `steps`, `dt`, `names`, `destructions`)."""

    __slots__ = ()

    @property
    def duration(self: RunFacts) -> float:
        return self.steps * self.dt

    @property
    def destroyed(self: RunFacts) -> set[str]:
        return {d.name for d in self.destructions}

    def index(self: RunFacts, name: str) -> int:
        return self.names.index(name)


class RunFacts(Protocol):
    """What `Run`'s methods read of the run they are of: a field or a property of each kind of run."""

    @property
    def steps(self) -> int: ...
    @property
    def dt(self) -> float: ...
    @property
    def names(self) -> tuple[str, ...]: ...
    @property
    def destructions(self) -> tuple[DestructionRecord, ...]: ...


@attrs.frozen
class Trace(Run):
    dt: float
    names: tuple[str, ...]  # the dynamic bodies, in the order of the state arrays
    kinds: dict = attrs.field(eq=False)  # name → kind (bird, pig, block, platform, tnt)
    states: np.ndarray = attrs.field(
        eq=False, repr=False, metadata={"dump": False}
    )  # (steps, bodies, 6): x y angle vx vy w; NaN once gone
    contacts: tuple[ContactRecord, ...] = ()
    separations: tuple[SeparationRecord, ...] = ()
    damage: tuple[DamageRecord, ...] = ()
    destructions: tuple[DestructionRecord, ...] = ()
    goal: tuple[str, ...] = ()  # the bodies the domain's goal is about (angrybirds: the pigs)
    solved: bool = False  # whether the domain's goal was met (angrybirds: every pig destroyed)
    interactions: tuple[Interaction, ...] = ()
    violations: tuple[Violation, ...] = ()
    goal_met: float | None = None  # when the rules judged the goal met, where they time it (PHYRE: the touch held 3 s)
    depends: tuple[
        DependenceRecord, ...
    ] = ()  # the rules' decisions another reading of the world would have made otherwise
    # Every body's box where it starts: name → (x, y, angle in radians, half-width, half-height)
    # in its own frame; a static body stays there, a dynamic one moves as `states` say (margins
    # read how far a landing or a clearance was from failing from it).
    outlines: dict = attrs.field(factory=dict, eq=False, repr=False)
    radii: dict = attrs.field(
        factory=dict, eq=False, repr=False
    )  # name → rolling radius of a round body (the recogniser's)
    # Bodies that are part of another as the scenario names it (Science Birds: a blue bird's
    # other two birds after its split are that bird): name → the whole's name.
    parts: dict = attrs.field(factory=dict, eq=False, repr=False, metadata={"dump": False})

    @property
    def decisive(self) -> frozenset[str]:
        """The open points of the world (setting paths) whose reading decided something in this
        run: a reading that differs from this run's only in other points plays the same run."""
        return frozenset(p for d in self.depends for p in d.points)

    @property
    def steps(self) -> int:
        return self.states.shape[0]

    def paths(self, threshold: float = 0.1, every: float = 0.1) -> dict[str, list[tuple[float, float]]]:
        """Sampled paths (every `every` seconds) of the bodies that moved more than `threshold`."""
        stride = max(int(round(every / self.dt)), 1)
        out = {}
        for index, name in enumerate(self.names):
            points = self.states[:, index, :2]
            points = points[~np.isnan(points[:, 0])]
            if len(points) and np.max(np.hypot(*(points - points[0]).T)) > threshold:
                out[name] = [tuple(p) for p in points[::stride]] + [tuple(points[-1])]
        return out

    def sequence(self) -> str:
        """The recognised interactions in `.phys` syntax: `hit(bird, pig, left) > destroy(bird, pig)`."""
        return " > ".join(i.text() for i in self.interactions)


@attrs.frozen
class Playout(Run):
    """What an outcome playout tells of a run (physc.simulation.run.run_to_outcome): whether the
    domain's goal was met and when, how many steps the run lasted, the damage and
    destructions, and the dynamic bodies' states (x y angle vx vy ω; NaN once gone) at its
    end. The same as the full run's Trace in all of these, bit for bit; it has no states
    over time, no contacts and no recognised interactions, which nobody reading an outcome
    reads (a solved verdict, a reward, the level as the run leaves it)."""

    dt: float
    names: tuple[str, ...]
    final: np.ndarray = attrs.field(eq=False, repr=False)
    steps: int
    damage: tuple[DamageRecord, ...] = ()
    destructions: tuple[DestructionRecord, ...] = ()
    goal: tuple[str, ...] = ()
    solved: bool = False
    goal_met: float | None = None
