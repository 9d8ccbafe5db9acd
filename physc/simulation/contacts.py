"""What a trace's contact records say, before any interaction is named: when each pair touched
(`contact_intervals`), which bodies touch anything at each step, and the way one body came at
another (`approach`, `side`). The recogniser (physc.simulation.recognise) and the margins
(physc.simulation.margins) read them.
"""

from __future__ import annotations

import math

import numpy as np

from physc.simulation.trace import ContactRecord, Trace


def side(dx: float, dy: float) -> str:
    """The side (of a target) that a direction from its contact towards the actor points to."""
    if abs(dx) >= abs(dy):
        return "right" if dx > 0 else "left"
    return "above" if dy > 0 else "below"


def contact_intervals(trace: Trace) -> dict[frozenset, list[list[float]]]:
    """Contact intervals per pair: [begin, end] (end = separation, destruction or the end)."""
    ends = {d.name: d.time for d in trace.destructions}
    open_: dict[frozenset, list[float]] = {}
    out: dict[frozenset, list[list[float]]] = {}
    events = [(c.time, 0, c.a, c.b) for c in trace.contacts] + [(s.time, 1, s.a, s.b) for s in trace.separations]
    for time, kind, a, b in sorted(events, key=lambda e: (e[0], e[1])):
        pair = frozenset((a, b))
        if kind == 0 and pair not in open_:
            open_[pair] = [time, math.inf]
            out.setdefault(pair, []).append(open_[pair])
        elif kind == 1 and pair in open_:
            open_.pop(pair)[1] = time
    for pair, interval in open_.items():
        interval[1] = min([trace.duration] + [ends[n] for n in pair if n in ends])
    return out


def approach(trace: Trace, contact: ContactRecord, actor: str, target: str) -> tuple[float, float]:
    """The actor's velocity relative to the target's, of their centres, in the step
    before the contact began. Not the contact points' velocities: the front of a
    rolling ball turns downwards, so a ball rolling into a block at its side would
    seem to come from above. (The contact points' when a body's state is unknown.)"""
    step = int(round(contact.time / trace.dt)) - 2  # state row k holds the time (k + 1) · dt
    velocities = []
    for name in (actor, target):
        if name not in trace.names:
            velocities.append((0.0, 0.0))  # a platform or the ground: static
            continue
        row = trace.states[step, trace.index(name)] if step >= 0 else None
        if row is None or math.isnan(row[3]):
            rv = contact.relative_velocity
            return rv if actor == contact.a else (-rv[0], -rv[1])
        velocities.append((float(row[3]), float(row[4])))
    (ax, ay), (tx, ty) = velocities
    return ax - tx, ay - ty


def touching_steps(trace: Trace, intervals) -> np.ndarray:
    """(steps, bodies): whether each dynamic body touches anything at each step (what a fall
    is read from: a spell of touching nothing)."""
    touching = np.zeros((trace.steps, len(trace.names)), dtype=bool)
    index = {name: i for i, name in enumerate(trace.names)}
    for pair, spans in intervals.items():
        for name in pair:
            if name in index:
                for begin, end in spans:
                    first = max(int(round(begin / trace.dt)) - 1, 0)
                    last = min(int(math.ceil(end / trace.dt)) - 1, trace.steps)
                    touching[first:last, index[name]] = True
    return touching
