"""A world: everything one target world's physics is, as one value.

A task is only useful where the user plays it, so a domain simulates in a *world* that
describes its target as LLVM's `TargetMachine` describes a target: the engine settings,
gravity, the incline rule of its surfaces, the recognition thresholds, and whatever the
domain adds (Science Birds: level bounds, launch, body models, game rules). A domain owns
its worlds and names one as its default (`Domain.worlds`, `Domain.default_world`); a
command picks one with `--world NAME`, and the world passes down to the simulation with the
domain (`Domain.at`), never through a module-level value.

A variant is a small derivation of another world (`derive`), not a copy: it names its
parent, what it changes and what the change is a reading of, and `settings()` reports each
changed setting with that reading as its source (`physc worlds -v`).
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterator, Mapping

import attrs

from physc.backends.settings import EngineSettings
from physc.simulation.recognise import Recogniser
from physc.simulation.trace import Trace


class WorldError(Exception):
    """A world name the domain does not have (a usage error: exit status 2)."""


@attrs.frozen
class Incline:
    """The incline rule: the angles (degrees from the horizontal) an inclined surface is drawn
    at, for one that a body rolls or slides down (`descending`) and for any other (`other`,
    a bounce surface, tilted either way). Data of the world: how steep a slope its bodies
    still rest on, and carry a chain down, is its physics'."""

    descending: tuple[float, float] = attrs.field(metadata={"source": "physc: drawn, then chosen by simulation"})
    other: tuple[float, float] = attrs.field(metadata={"source": "physc: drawn, then chosen by simulation"})
    # A ramp of the ramp structure (a mover comes down it from a ledge at its head to the
    # target at its foot): its angle and length. None: as `descending`, and the domain's length.
    ramp: tuple[float, float] | None = attrs.field(default=None, metadata={"source": "the world's own ramps"})
    ramp_length: tuple[float, float] | None = attrs.field(default=None, metadata={"source": "the world's own ramps"})


@attrs.frozen
class OpenPoint:
    """A point the target world's files leave open: one setting of the world (`setting`, a
    dotted path such as "rules.platform_mass") and the values the files allow it (`readings`,
    the world's own value first). A task counts only where it holds under each reading."""

    setting: str
    readings: tuple
    question: str  # what is open, in words
    source: str  # where the files leave it open
    label: str = "{value}"  # one reading in words, for messages: "platform mass {value:g}"

    def describe(self, value) -> str:
        return self.label.format(value=value)


@attrs.frozen
class Setting:
    """One setting of a world as `physc worlds -v` lists it."""

    path: str  # dotted: "engine.dt", "bodies.angular_drag"
    value: object
    source: str  # the target world's file it is read from, or physc's reason


@attrs.frozen(kw_only=True)
class World:
    """A world a domain simulates (module docstring). A domain's subclass adds its own
    settings as attrs fields; each field's `metadata["source"]` (or the world's `sources`,
    by dotted prefix) says where its value comes from."""

    name: str = attrs.field(metadata={"meta": True})
    description: str = attrs.field(metadata={"meta": True})
    engine: EngineSettings
    gravity: float  # downwards, in the domain's units per second²
    recogniser: Recogniser
    incline: Incline
    parent: str | None = attrs.field(default=None, metadata={"meta": True})
    reading: str = attrs.field(default="", metadata={"meta": True})  # a variant: what its changes are a reading of
    changed: tuple[str, ...] = attrs.field(default=(), metadata={"meta": True})  # a variant: the settings it changes
    # A variant: the kinds of interaction (`roll`, `bounce`: the terms' names) its changes are
    # made for, as its author declares them; empty: not said, so any kind. Exit 3 proposes,
    # and tries, another world only for a scenario with a link of a kind the worlds differ in
    # (`differing_kinds`).
    concerns: tuple[str, ...] = attrs.field(default=(), metadata={"meta": True})
    sources: Mapping[str, str] = attrs.field(factory=dict, eq=False, metadata={"meta": True})

    def derive(self, name: str, description: str, reading: str, concerns: tuple[str, ...] = (), **changes) -> World:
        """A variant of this world: `changes` by setting (a whole part, e.g. `bodies=`);
        `reading` says what the changes are a reading of (the source of each changed setting);
        `concerns`, the kinds of interaction the changes are made for (empty: any kind)."""
        variant = attrs.evolve(
            self,
            name=name,
            description=description,
            parent=self.name,
            reading=reading,
            changed=(),
            concerns=tuple(concerns),
            **changes,
        )
        ours = dict(_walk(self, "", self.sources))
        changed = tuple(s.path for s in variant.settings() if ours.get(s.path, _MISSING) != s.value)
        return attrs.evolve(variant, changed=changed)

    def open_points(self) -> tuple[OpenPoint, ...]:
        """What the target world's files leave open (the default: nothing). Declared once, by
        the domain's world; `physc worlds -v` lists them with their sources."""
        return ()

    def open_values(self) -> tuple:
        """This world's value of each open point, in `open_points` order."""
        return tuple(_get(self, point.setting) for point in self.open_points())

    def read_as(self, values: tuple) -> World:
        """This world with its open points set to `values` (in `open_points` order): itself when
        they are its own, else a variant named for the readings that differ."""
        points = self.open_points()
        own = self.open_values()
        if tuple(values) == own:
            return self
        world = self
        for point, value in zip(points, values, strict=False):  # values may come from elsewhere: as many as both
            world = _set(world, point.setting, value)
        changed = [
            point.describe(value) for point, value, mine in zip(points, values, own, strict=False) if value != mine
        ]
        return attrs.evolve(
            world,
            name=f"{self.name}, {', '.join(changed)}",
            parent=self.name,
            reading="a reading of what the world's files leave open",
            changed=tuple(
                point.setting for point, value, mine in zip(points, values, own, strict=False) if value != mine
            ),
        )

    def readings(self) -> tuple[World, ...]:
        """This world under every combination of readings of its open points, itself first: a
        task counts only when its solution holds under every one that can change its outcome
        (`under_readings` runs just those). A world whose files leave nothing open: itself.

        >>> from physc.domains.angrybirds.worlds import PHYQ
        >>> [point.setting for point in PHYQ.open_points()]
        ['rules.relative_velocity', 'rules.platform_mass', 'rules.near_tie']
        >>> readings = PHYQ.readings()
        >>> len(readings), readings[0] is PHYQ
        (8, True)
        >>> readings[1].name, readings[1].changed
        ('phyq, near ties: other attacks', ('rules.near_tie',))
        """
        points = self.open_points()
        own = self.open_values()
        combos = itertools.product(
            *(sorted(p.readings, key=lambda v, mine=mine: v != mine) for p, mine in zip(points, own, strict=True))
        )
        return tuple(self.read_as(values) for values in combos)

    def settings(self) -> list[Setting]:
        """Every setting, in declaration order, with its source; a variant's changed settings
        cite its reading."""
        out = []
        for path, value, source in _walk_sourced(self, "", self.sources):
            if path in self.changed:
                source = f"{self.name}: {self.reading}"
            out.append(Setting(path, value, source))
        return out


_MISSING = object()


def under_readings(
    world: World, run: Callable[[World], Trace], settled: Callable[[Trace], float] | None = None
) -> list[tuple[World, Trace]]:
    """(reading, its trace) for every reading of `world`'s open points that can make `run`
    (a play of one level and action in a given reading) go another way, `world` itself first.

    A run records which open points decided something in it (`Trace.decisive`); a reading
    that differs from it only in other points plays the same run. So, starting from the
    world's own reading, each decisive point is read the other ways in turn, and so on from
    each new run: every combination of readings plays the same run as one of those explored
    (at most every combination; usually the world's own and one or two more). `settled`: the
    time after which nothing a run's rules decide can change what the caller reads of it
    (a decision after it does not count); None: the whole run."""
    points = world.open_points()
    start = world.open_values()
    seen = {start: run(world)}
    queue = [start]
    while queue:
        values = queue.pop(0)
        trace = seen[values]
        until = settled(trace) if settled is not None else float("inf")
        decisive = {p for d in trace.depends if d.time <= until + 1e-9 for p in d.points}
        for i, point in enumerate(points):
            if point.setting not in decisive:
                continue
            for value in point.readings:
                other = values[:i] + (value,) + values[i + 1 :]
                if other not in seen:
                    seen[other] = run(world.read_as(other))
                    queue.append(other)
    return [(world.read_as(values), trace) for values, trace in seen.items()]


def _get(value, path: str):
    for part in path.split("."):
        value = getattr(value, part)
    return value


def _set(value, path: str, new):
    head, _, rest = path.partition(".")
    if not rest:
        return attrs.evolve(value, **{head: new})
    return attrs.evolve(value, **{head: _set(getattr(value, head), rest, new)})


def _source(path: str, field_source: str, sources: Mapping[str, str]) -> str:
    """The longest prefix of `path` that `sources` names, else the field's own metadata."""
    parts = path.split(".")
    for end in range(len(parts), 0, -1):
        prefix = ".".join(parts[:end])
        if prefix in sources:
            return sources[prefix]
    return field_source


def _walk_sourced(
    value, prefix: str, sources: Mapping[str, str], inherited: str = ""
) -> Iterator[tuple[str, object, str]]:
    for field in attrs.fields(type(value)):
        if field.metadata.get("meta"):
            continue
        path = f"{prefix}{field.name}"
        own = field.metadata.get("source", inherited)
        item = getattr(value, field.name)
        if attrs.has(type(item)):
            yield from _walk_sourced(item, path + ".", sources, _source(path, own, sources))
        else:
            yield path, item, _source(path, own, sources)


def _walk(value, prefix: str, sources: Mapping[str, str]) -> Iterator[tuple[str, object]]:
    for path, item, _ in _walk_sourced(value, prefix, sources):
        yield path, item


def differing_kinds(a: World, b: World, worlds: tuple[World, ...]) -> frozenset[str] | None:
    """The kinds of interaction the worlds `a` and `b` of one domain (`worlds`) differ in: what
    each variant between them declares it `concerns` (the variants on their lines of descent
    below the ancestor they share); None when one of those declares nothing, or the two share
    no ancestor (they may differ in any kind).

    >>> from physc.domains.angrybirds.worlds import PHYQ, ROLLING, WORLDS
    >>> sorted(differing_kinds(PHYQ, ROLLING, WORLDS))
    ['bounce', 'roll', 'slide']
    >>> differing_kinds(PHYQ, PHYQ, WORLDS)
    frozenset()
    """
    named = {w.name: w for w in worlds} | {a.name: a, b.name: b}

    def line(world: World) -> list[World]:
        out = [world]
        while out[-1].parent in named and named[str(out[-1].parent)] not in out:
            out.append(named[str(out[-1].parent)])
        return out

    ours, theirs = line(a), line(b)
    shared = {w.name for w in ours} & {w.name for w in theirs}
    if not shared:
        return None
    kinds: set[str] = set()
    for world in ours + theirs:
        if world.name in shared:
            continue
        if not world.concerns:
            return None
        kinds |= set(world.concerns)
    return frozenset(kinds)


def by_name(worlds: tuple[World, ...], name: str, domain: str) -> World:
    """The world `name` of a domain's `worlds`, or WorldError with "did you mean"."""
    from physc.suggest import did_you_mean

    for world in worlds:
        if world.name == name:
            return world
    names = [w.name for w in worlds]
    hint = did_you_mean(name, names) or "its worlds: " + (", ".join(names) or "none")
    raise WorldError(f"the domain '{domain}' has no world '{name}'; {hint} (`physc worlds` lists them)")
