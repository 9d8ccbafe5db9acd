"""Sequence fidelity: does a simulated trace realise the declared sequence?

The declared interactions must occur in the recognised trace in their order (a
subsequence: other interactions may happen in between, e.g. the bird bouncing on
the ground after its work is done). An occurrence matches when the term and its
objects are the same and its direction is one the scenario allows after
narrowing by the restrictions (`fall` also accepts any direction, since the
recognised fall names where it landed, not where it came from). The trace must
also break no restriction while the solution runs (from the shot until the declared
sequence is complete: the paper's restrictions "only apply to the solution
interaction sequence"), and meet the domain's goal (`Trace.solved`; Angry Birds: every
pig destroyed). Nothing here depends on a domain: it reads the scenario and a trace.

The scenario is the front end's checked IR (physc.dsl.scenario.ScenarioIR); this layer
imports nothing of the front end, and reads only what `Declared` and `DeclaredTerm` name.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Protocol

import attrs
import numpy as np

from physc.simulation.trace import Interaction, Trace


class DeclaredTerm(Protocol):
    """A declared interaction as the front end checked it (physc.dsl.scenario.TermIR): its
    term, objects, the directions it may be realised in (narrowed), and its text."""

    @property
    def name(self) -> str: ...
    @property
    def objects(self) -> tuple[str, ...]: ...
    @property
    def directions(self) -> tuple[str, ...]: ...
    @property
    def text(self) -> str: ...


class Declared(Protocol):
    """What a trace is held against: the declared sequence of a scenario (a
    physc.dsl.scenario.ScenarioIR), in order."""

    @property
    def interactions(self) -> Sequence[DeclaredTerm]: ...


@attrs.frozen
class Fidelity:
    matched: int  # how many declared interactions, from the first, occur in order
    total: int
    violations: tuple[str, ...]
    solved: bool
    times: tuple[float, ...]  # when each matched interaction happened
    progress: float = 0.0  # towards the first unmatched interaction (higher is nearer)

    @property
    def complete(self) -> bool:
        return self.matched == self.total

    @property
    def valid(self) -> bool:
        return self.complete and not self.violations and self.solved

    @property
    def score(self) -> tuple:
        """Higher is better: more of the sequence, then fewer broken restrictions, then
        solved, then nearer to the next interaction. (A pig destroyed by a forbidden hit
        is no progress.)"""
        return (self.matched, -len(self.violations), self.solved, round(self.progress, 3))


def matches(declared: DeclaredTerm, found: Interaction) -> bool:
    if declared.name != found.name or tuple(declared.objects) != found.objects[: len(declared.objects)]:
        return False
    if declared.name == "fall" or not declared.directions:  # a fall names where it landed; destroy, touch have none
        return True
    return found.direction in declared.directions


def fidelity(scenario: Declared, trace: Trace) -> Fidelity:
    matched, times = 0, []
    for found in trace.interactions:
        if matched < len(scenario.interactions) and matches(scenario.interactions[matched], found):
            times.append(found.time)
            matched += 1
    # Restrictions hold "during the solution": from the shot until the declared
    # sequence is complete (what happens after the last pig is gone is not the solution).
    until = times[-1] if matched == len(scenario.interactions) and times else float("inf")
    progress = (
        0.0
        if matched == len(scenario.interactions)
        else _progress(scenario.interactions[matched], trace, times[-1] if times else 0.0)
    )
    return Fidelity(
        matched,
        len(scenario.interactions),
        tuple(v.text() for v in trace.violations if v.interaction.time <= until),
        trace.solved,
        tuple(times),
        progress,
    )


def _progress(declared: DeclaredTerm, trace: Trace, since: float) -> float:
    """How near the trace came to the interaction it did not realise, after `since`."""
    start = int(since / trace.dt)
    if declared.name == "destroy":
        target = declared.objects[1]
        return sum(
            d.amount for d in trace.damage if d.target == target and d.by == declared.objects[0] and d.time >= since
        )
    actor = declared.objects[0]
    if actor not in trace.names:
        return 0.0
    path = trace.states[start:, trace.index(actor), :2]
    path = path[~np.isnan(path[:, 0])]
    if not len(path):
        return 0.0
    if declared.name in ("roll", "slide"):
        return float(np.hypot(*(path[-1] - path[0])))
    other = declared.objects[1] if len(declared.objects) > 1 else None
    if other in trace.names:
        target = trace.states[start:, trace.index(other), :2][: len(path)]
        gaps = np.hypot(*(path[: len(target)] - target).T)
        gaps = gaps[~np.isnan(gaps)]
        return -float(gaps.min()) if len(gaps) else 0.0
    return 0.0
