"""The generic run loop: an engine world stepped for some seconds, recorded as a trace.

Every domain plays its worlds the same way: step the engine, record the contacts that
began (with their relative velocity before the collision) and ended, record every
dynamic body's pose and velocity, take out the bodies the rules say leave, and stop
when the rules say the run is over. What differs is the rules, so they are hooks of a
`RunRules` object (Scenic's simulators keep the same split: a generic loop, a few
hooks per simulator):

* `on_start`: the engine world is built and about to run (a rule that asks it who
  touches whom keeps it);
* `on_contact`: a contact began (Science Birds: damage);
* `removals_due` / `gone` / `on_removed`: whether anything may leave this step (cheap,
  every step), why a body leaves (the destruction's cause and author), and what its
  leaving does (a TNT's blast);
* `enter`: bodies that join the run now (Science Birds: the next bird launched, a blue
  bird's split), for rules that say `arrivals`;
* `finished`: the run is over before its time (everything at rest, the goal met);
* `solved`: whether the recorded run met the domain's goal;
* `completed` / `read`: what the rules add to the trace of their run, and how they name what
  the recogniser read in it (Science Birds: a split bird's parts are that bird);
* `resume`: the run continues from a snapshot (physc.simulation.snapshot): the rules'
  state as the events before it leave it (Science Birds: lives, the bird's checks).

The loop is generic and hot: it runs once per simulated step (0.02 s of game time), so
each hook is one call per step at most and the state rows are handed over as plain
lists. Ctrl-C and the time budget stop it between steps (`physc.budget`).
"""

from __future__ import annotations

from collections.abc import Sequence

import attrs
import numpy as np

from physc import budget
from physc.simulation.snapshot import Snapshot
from physc.simulation.trace import ContactRecord, DamageRecord, DestructionRecord, Interaction, SeparationRecord, Trace


class RunRules:
    """The hooks of a run; the defaults are a world where nothing is damaged, nothing
    leaves and the run lasts its whole time."""

    reads_states = True
    """Whether `removals_due` and `finished` read `values` (every dynamic body's state, each
    step). Rules that ask the world what they need instead (World.moving, World.touches) say
    False, and an outcome playout (`run_to_outcome`) then reads no state until the run ends."""

    arrivals = False
    """Whether bodies join the run after its start (`enter`): the dynamic bodies they will be
    are listed from the start, not yet in the world (their rows NaN until they enter)."""

    def on_start(self, engine) -> None:
        """The run is about to begin in `engine`: the dynamic bodies not in it yet are
        `arrivals`' (see `enter`)."""

    def enter(self, engine, values: list, alive: set[str], damage: list[DamageRecord], time: float) -> tuple[str, ...]:
        """The dynamic bodies that join the run now, added to `engine` by the rules (for rules
        that say `arrivals`; called every step after the removals)."""
        return ()

    def on_contact(self, engine, contact: ContactRecord, damage: list[DamageRecord], time: float) -> None:
        """A contact began at `time` (append what it damaged to `damage`): the two bodies'
        first, or another pair of their colliders (physc.backends.ContactEvent.first)."""

    def removals_due(self, values: list, alive: set[str], time: float) -> bool:
        """Whether any body may leave this step (`values`: each dynamic body's state row,
        NaN for the bodies gone). Called every step: keep it cheap; `gone` says which."""
        return False

    def gone(self, name: str, state: tuple, time: float, damage: list[DamageRecord]) -> tuple[str, str | None] | None:
        """Why `name` (its state: x, y, angle, vx, vy, ω) leaves now: (cause, by whom), or None."""
        return None

    def on_removed(
        self, engine, name: str, cause: str, alive: set[str], damage: list[DamageRecord], time: float
    ) -> None:
        """`name` is leaving (still in the engine): what its leaving does to the others."""

    def lingers(self, engine, name: str, cause: str) -> float:
        """`name` has left the level (`gone`, `on_removed` done): the seconds it stays in the
        engine before it is taken out (0: now), doing there what the rules leave it (they may
        change its state or colliders now). It is no longer recorded: its rows are NaN, and
        its contacts count for the rules alone."""
        return 0.0

    def finished(self, values: list, alive: set[str], time: float) -> bool:
        """Whether the run is over at `time`, before its end."""
        return False

    def settled(self, time: float, end: float) -> bool:
        """Whether the outcome (`solved`, `goal_met`) can no longer change between `time` and
        the run's `end`: an outcome playout that need not play to the end stops here (the
        default: it plays until `finished`)."""
        return False

    def solved(self, recording: Recording) -> bool:
        """Whether the run met the domain's goal (read once, after the run)."""
        return False

    def goal_met(self, recording: Recording) -> float | None:
        """When the run met the domain's goal, for rules that time it (None: untimed, or not
        met). The recogniser's `touch` is then the rules' own verdict, even where they judge
        touching by more than the engine's contacts (PHYRE's two balls)."""
        return None

    def resume(self, engine, snapshot: Snapshot) -> None:
        """The run goes on from `snapshot` (after `on_start`): set the state the events
        before it leave (the default: the rules keep none)."""

    def completed(self, trace: Trace) -> Trace:
        """The trace of the run with what the rules kept while it ran (read once, after the run,
        before recognition; Science Birds: the decisions another reading of its open points would
        have made, the bodies that came in). The default adds nothing."""
        return trace

    def read(self, interactions: tuple[Interaction, ...]) -> tuple[Interaction, ...]:
        """The interactions recognised in the run, as the scenario names them (Science Birds: what
        a blue bird's other birds did, its own; a tap that fired a power). The default: as recognised."""
        return interactions


@attrs.frozen
class Recording:
    """What a run recorded: the states (steps, bodies, 6: x y angle vx vy ω; NaN once
    gone) of the dynamic bodies in `names` order, and the events in time order. An outcome
    playout's (`run_to_outcome`) holds the last step's states alone, and no contacts."""

    states: np.ndarray
    contacts: tuple[ContactRecord, ...]
    separations: tuple[SeparationRecord, ...]
    damage: tuple[DamageRecord, ...]
    destructions: tuple[DestructionRecord, ...]
    played: int | None = None  # steps run, where `states` does not hold them all

    @property
    def steps(self) -> int:
        """The steps the run lasted."""
        return self.played if self.played is not None else len(self.states)


def run(
    engine, dynamic: Sequence[str], rules: RunRules, seconds: float, dt: float, resume: Snapshot | None = None
) -> Recording:
    """Step `engine` for `seconds` (or until `rules.finished`), recording the bodies in
    `dynamic` and every contact, damage and destruction; from `resume`'s step on, if given
    (physc.simulation.snapshot)."""
    index = {name: i for i, name in enumerate(dynamic)}
    steps = int(round(seconds / dt))
    states = np.full((steps, len(dynamic), 6), np.nan)
    contacts, separations, damage, destructions = [], [], [], []
    alive = set(dynamic)
    lingering: dict[str, float] = {}  # bodies gone from the level but still in the engine → when they leave it
    arrivals = rules.arrivals
    unrecorded: set[str] = set()  # bodies that lingered: their contacts are no longer recorded
    parting: list[
        tuple[str, str]
    ] = []  # their contacts when they left the level: ended for the record next step, as a removal's are
    rules.on_start(engine)
    if arrivals:
        alive &= set(engine.names)  # the bodies still to come are not alive yet
    first, already = 0, set()
    if resume is not None:
        first, already = _continued(engine, dynamic, rules, resume, states, alive), set(resume.touching)
        contacts, separations = list(resume.contacts), list(resume.separations)
        damage, destructions = list(resume.damage), list(resume.destructions)
    for step in range(first, steps):
        budget.check()  # Ctrl-C and the time budget stop a run between steps
        engine.step(dt)
        time = (step + 1) * dt
        resumed = set()
        for event in engine.begun():
            pair = frozenset((event.a, event.b))
            if pair in resumed or (event.first and pair in already):
                already.discard(pair)
                resumed.add(pair)
                continue  # touching at the snapshot already (reported when stepped, or woken): no new contact
            record = ContactRecord.of(time, event)
            # What touched what; another pair of the same bodies' colliders, and a body that
            # lingers after it left the level, are heard by the rules alone.
            if event.first and not pair & unrecorded:
                contacts.append(record)
            rules.on_contact(engine, record, damage, time)
        separations.extend(SeparationRecord(time, a, b) for a, b in parting)
        parting.clear()
        for a, b in engine.ended():
            if a not in unrecorded and b not in unrecorded:
                separations.append(SeparationRecord(time, a, b))
        for name in [n for n, until in lingering.items() if until <= time + 1e-9]:
            engine.remove(name)
            del lingering[name]
        row = _read(engine, dynamic, states[step], lingering, index)
        values = row.tolist()  # (plain floats are quicker to test than a small array)
        if rules.removals_due(values, alive, time):
            values = _removals(
                engine, dynamic, index, rules, row, time, alive, damage, destructions, lingering, (unrecorded, parting)
            )
        if arrivals and _entered(engine, rules, values, alive, damage, time, row, index):
            values = row.tolist()
        if rules.finished(values, alive, time):
            states = states[: step + 1]
            break
    return Recording(states, tuple(contacts), tuple(separations), tuple(damage), tuple(destructions))


def run_to_outcome(
    engine, dynamic: Sequence[str], rules: RunRules, seconds: float, dt: float, to_end: bool = True
) -> Recording:
    """`run` to the outcome, recording only what the rules' verdict reads: the same steps, the
    same hooks in the same order, so the same outcome, damage and destructions, bit for bit
    (the engine's state does not depend on what is read from it). It keeps no states but the
    last step's, no contacts and no separations; contacts are made into records only for
    rules that hear them (`on_contact`), and states are read each step only for rules that
    read them (`RunRules.reads_states`). Without `to_end` it stops once the rules say the
    outcome is `settled` (the last states are then those of that step, not the run's end).
    Whole traces stay for `run`."""
    steps = int(round(seconds / dt))
    damage, destructions = [], []
    alive = set(dynamic)
    lingering: dict[str, float] = {}
    index = {name: i for i, name in enumerate(dynamic)}
    hears = type(rules).on_contact is not RunRules.on_contact
    removes = type(rules).removals_due is not RunRules.removals_due
    reads = rules.reads_states
    step_world, finished, check = engine.step, rules.finished, budget.check
    settled = None if to_end or type(rules).settled is RunRules.settled else rules.settled
    arrivals = rules.arrivals
    end = steps * dt
    row = np.full((len(dynamic), 6), np.nan)
    values: list = []  # the rows the rules read: none for rules that read no states (`reads_states` False)
    engine.listen(hears)
    rules.on_start(engine)
    if arrivals:
        alive &= set(engine.names)
    step = -1
    for step in range(steps):
        check()
        step_world(dt)
        time = (step + 1) * dt
        if hears:
            engine.ended()  # (drained: only the rules read contacts here)
            for event in engine.begun():
                record = ContactRecord.of(time, event)
                rules.on_contact(engine, record, damage, time)
        if lingering:
            for name in [n for n, until in lingering.items() if until <= time + 1e-9]:
                engine.remove(name)
                del lingering[name]
        if reads:
            values = _read(engine, dynamic, row, lingering, index).tolist()
        if removes and rules.removals_due(values, alive, time):
            values = _removals(engine, dynamic, index, rules, row, time, alive, damage, destructions, lingering)
        if arrivals and _entered(engine, rules, values, alive, damage, time, row, index):
            values = row.tolist() if reads else values
        if finished(values, alive, time) or (settled is not None and settled(time, end)):
            break
    return Recording(
        _read(engine, dynamic, row, lingering, index)[None], (), (), tuple(damage), tuple(destructions), played=step + 1
    )


def _entered(
    engine, rules: RunRules, values, alive: set, damage: list, time: float, row: np.ndarray, index: dict
) -> bool:
    """The bodies the rules bring in now (`RunRules.enter`) made alive, their states read into
    `row`; whether any came."""
    new = rules.enter(engine, values, alive, damage, time)
    for name in new:
        alive.add(name)
        row[index[name]] = engine.state(name)
    return bool(new)


def _read(engine, dynamic: Sequence[str], out: np.ndarray, lingering: dict, index: dict) -> np.ndarray:
    """Every dynamic body's state into `out` (NaN for the bodies gone from the engine, and for
    those that linger after leaving the level)."""
    engine.states(dynamic, out=out)
    for name in lingering:
        out[index[name]] = np.nan
    return out


def _removals(
    engine,
    dynamic,
    index: dict,
    rules: RunRules,
    row: np.ndarray,
    time: float,
    alive: set,
    damage: list,
    destructions: list,
    lingering: dict,
    recording=None,
) -> list:
    """The bodies the rules say leave now taken out (or left to linger), in `dynamic` order: the
    order of removals must not depend on string hashing, and a removal (a blast) changes the
    state of what is read after it. `row` is written anew (each body still in the level read
    again, NaN for the others); the new values. `recording`: (the bodies no longer recorded,
    the contacts to end for the record), which a lingering body joins."""
    row[:] = np.nan
    for name in [n for n in dynamic if n in alive]:
        state = engine.state(name)
        gone = rules.gone(name, state, time, damage)
        if gone:
            rules.on_removed(engine, name, gone[0], alive, damage, time)
            alive.discard(name)
            touched = sorted(engine.touching(name))
            stay = rules.lingers(engine, name, gone[0])
            if stay > 0:  # its contacts end for the record now, and begin no more
                if recording is not None:
                    recording[1].extend((name, other) for other in touched)
                    recording[0].add(name)
                lingering[name] = time + stay
            else:
                engine.remove(name)
            destructions.append(DestructionRecord(time, name, gone[0], gone[1], time + stay if stay > 0 else None))
        else:
            row[index[name]] = state
    return row.tolist()


def _continued(
    engine, dynamic: Sequence[str], rules: RunRules, snapshot: Snapshot, states: np.ndarray, alive: set[str]
) -> int:
    """`engine` (built as at the start) put in `snapshot`'s state: its bodies restored, the
    ones gone by then removed, the rows before it filled in (a body the snapshot lacks:
    its pose at the start, at rest), the rules resumed. The step to go on from."""
    first = min(snapshot.step, len(states))
    gone = snapshot.gone
    present = set(engine.names)
    engine.assume_touching(tuple(p) for p in snapshot.touching if len(p) == 2 and p <= present and not p & gone)
    for i, name in enumerate(dynamic):
        if name in snapshot.names:
            states[:first, i] = snapshot.states[:first, snapshot.names.index(name)]
            if name in gone:
                engine.remove(name)
                alive.discard(name)
            else:
                engine.restore(name, snapshot.state(name))
        else:
            states[:first, i] = (*engine.state(name)[:3], 0.0, 0.0, 0.0)
    rules.resume(engine, snapshot)
    return first
