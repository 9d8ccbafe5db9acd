"""A run continued from a snapshot: the world as an earlier run left it at some step.

A search simulates the same prefix again and again: every variant of a stage adds new
objects to a scene whose run, until its bodies come near them, is the run already made
without them (the parent's). A `Snapshot` is that earlier run cut at a step: the states
of its bodies, the events recorded so far, who touches whom. `physc.simulation.run.run`
continues from it: the bodies are put back where they were (`World.restore`), the ones
already gone are taken out, the rules rebuild their state from the events
(`RunRules.resume`), and the loop goes on from the step, the rows and events before it
copied in. A body the earlier run did not have (a new object) stays where the scene put
it, and its rows before the step are that pose.

Continuing is not the same bytes as running from the start: the engine's contact caches
(warm starting) and its order of bodies differ. It is a quick look, so the search
confirms what passes with a full run (physc.search.search). It is deterministic:
the same snapshot and scene give the same run.
"""

from __future__ import annotations

import attrs
import numpy as np

from physc.simulation.trace import (
    ContactRecord,
    DamageRecord,
    DependenceRecord,
    DestructionRecord,
    SeparationRecord,
    Trace,
)


@attrs.frozen
class Snapshot:
    """The run of `trace` cut after `step` steps: `names`' states (steps, bodies, 6) up to
    there, the events up to its time, and the pairs touching then."""

    step: int
    dt: float
    names: tuple[str, ...]
    states: np.ndarray = attrs.field(eq=False, repr=False)
    contacts: tuple[ContactRecord, ...]
    separations: tuple[SeparationRecord, ...]
    damage: tuple[DamageRecord, ...]
    destructions: tuple[DestructionRecord, ...]
    touching: frozenset[frozenset[str]]
    depends: tuple[DependenceRecord, ...] = ()

    @property
    def time(self) -> float:
        return self.step * self.dt

    @classmethod
    def of(cls, trace: Trace, step: int) -> Snapshot:
        """`trace` cut after `step` steps (1 ≤ step < trace.steps)."""
        if not 1 <= step < trace.steps:
            raise ValueError(
                f"a snapshot of a {trace.steps}-step run must be cut after 1 to {trace.steps - 1} steps, not {step}"
            )
        if cls.latest_cut(trace, step) != step:
            raise ValueError(
                f"a snapshot cannot be cut after {step} steps: a body that left the level is still in the world there"
            )
        time = step * trace.dt + 1e-9

        def until(records):
            return tuple(r for r in records if r.time <= time)

        contacts, separations = until(trace.contacts), until(trace.separations)
        touching: dict[frozenset[str], int] = {}
        events = sorted([(c.time, 0, c.a, c.b) for c in contacts] + [(s.time, 1, s.a, s.b) for s in separations])
        for _, parted, a, b in events:
            pair = frozenset((a, b))
            touching[pair] = 0 if parted else 1
        return cls(
            step,
            trace.dt,
            trace.names,
            trace.states[:step].copy(),
            contacts,
            separations,
            until(trace.damage),
            until(trace.destructions),
            frozenset(p for p, t in touching.items() if t),
            until(trace.depends),
        )

    @staticmethod
    def latest_cut(trace: Trace, step: int) -> int:
        """The latest cut at or before `step` at which no body that left the level still
        lingers in the world (DestructionRecord.until): its state there is not recorded, so a
        run cannot go on from inside that while. Below 1: there is none."""
        dt = trace.dt
        moved = True
        while moved:
            moved = False
            for d in trace.destructions:
                if d.until is not None and d.time <= step * dt + 1e-9 < d.until - 1e-9:
                    step, moved = int(round(d.time / dt)) - 1, True
        return step

    def state(self, name: str) -> tuple | None:
        """`name`'s state at the cut (None: gone by then, or not in the run)."""
        if name not in self.names:
            return None
        row = self.states[-1, self.names.index(name)]
        return None if np.isnan(row[0]) else tuple(float(v) for v in row)

    @property
    def gone(self) -> set[str]:
        """The bodies of the run that had left by the cut."""
        return {n for i, n in enumerate(self.names) if np.isnan(self.states[-1, i, 0])}
