"""The stages of a chain: which objects enter the scene at which interaction.

The search builds a task along its causal sequence. An object enters the scene at the
first interaction that names it; what it rests on enters with it (or earlier), and
platforms joined edge to edge enter together, so a shelf that several bodies move
along is there from the first of them. The player's object, the ground and what no
interaction names enter at the start or, for objects no interaction needs, last.

A term of the player's objects alone (a tap of the bird) brings in what the term after it
brings in. A *stage* runs from an interaction that brings objects in to the next such one. A
stage's scene holds only what has entered by its start, so what the chain has not
reached yet can neither help nor get in the way, and a simulation says exactly how far
the prefix gets.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import attrs

from physc.compiler.qsr import joined

WHOLLY_ON = ("MeetN", "MeetDuringW", "MeetDuringE")  # the QSRs of an object resting wholly on another
RESTS_ON = WHOLLY_ON + ("MeetOver",)  # and of one resting with its centre over it (version 2's structures)
ALWAYS = ("player", "ground")  # roles and concretes present from the start


@attrs.frozen
class ChainStage:
    """Interactions `start` .. `end` - 1 of the sequence, realised by the scene that has
    the objects brought in at `start` (`new`) and before."""

    index: int
    start: int
    end: int
    new: tuple[str, ...]

    @property
    def span(self) -> tuple[int, int]:
        """(start, end): the interactions it realises, by which a funnel names it across layouts
        (physc.search.funnel), whose plans may number their stages apart."""
        return (self.start, self.end)


def supports(layout) -> dict[str, str]:
    """What each object of the layout rests on, by name."""
    return {r.a: r.b for r in layout.conjunction if r.relation in RESTS_ON}


def introduced(layout, interactions: Sequence, carried: Sequence[tuple[str, str]] = ()) -> dict[str, int]:
    """The interaction at which each object of `layout` enters the scene (module docstring);
    `carried`: (a, b) pairs of the scenario's structures (version 2: a rests on or in b), where a
    enters with b, being there when b is."""
    total = len(interactions)
    entry = {}
    for o in layout.objects:
        entry[o.name] = 0 if o.role in ALWAYS or o.concrete in ALWAYS else total
    players = {o.name for o in layout.objects if o.role == "player"}
    pending = None  # a run of terms of the player's objects alone (a tap): what comes next enters with them
    for k, term in enumerate(interactions):
        if term.objects and set(term.objects) <= players:
            pending = k if pending is None else pending
            continue
        for name in term.objects:
            if name in entry:
                entry[name] = min(entry[name], k if pending is None else pending)
        pending = None
    before = [(support, a) for a, support in supports(layout).items()]
    before += [(a, b) for a, b in carried]
    before += [pair for a, b in map(tuple, joined(layout.conjunction)) for pair in ((a, b), (b, a))]
    before = [(x, y) for x, y in before if x in entry and y in entry]
    changed = True
    while changed:
        changed = False
        for earlier, later in before:
            if entry[earlier] > entry[later]:
                entry[earlier], changed = entry[later], True
    return entry


def stages(interactions: Sequence, entry: Mapping[str, int], action_starts: Sequence[int] = ()) -> list[ChainStage]:
    """The stages of `interactions` whose objects enter at the interaction `entry` says
    (objects brought in by no interaction: at len(interactions), a last stage that
    realises nothing new but must keep the rest); a later action of the player (`action_starts`)
    starts a stage too, where the search chooses it."""
    total = len(interactions)
    starts = sorted({0, *(k for k in (*entry.values(), *action_starts) if 0 < k < total)})
    if any(k >= total for k in entry.values()):
        starts.append(total)
    out = []
    for i, start in enumerate(starts):
        end = starts[i + 1] if i + 1 < len(starts) and starts[i + 1] < total else total
        new = tuple(sorted(n for n, k in entry.items() if k == start))
        out.append(ChainStage(i, start, max(end, start), new))
    return out


def prefix(layout, entry: Mapping[str, int], start: int):
    """The layout of a stage beginning at interaction `start`: what has entered by then (an
    object the search added, an obstacle, is there from when it was added)."""
    return attrs.evolve(layout, objects=tuple(o for o in layout.objects if entry.get(o.name, 0) <= start))
