"""Questions about a scenario's declared sequence of interactions, asked by the layout rules,
the search and the domains' preferences: which way a declared hit pushes its target, and where
in the sequence an object was last hit or last rolled or slid.

They read the terms alone (TermIR: name, objects, directions), never a layout or a trace.
"""

from __future__ import annotations

from collections.abc import Set

from physc.dsl.scenario import TermIR

OPPOSITE = {"left": "right", "right": "left", "above": "below", "below": "above"}


def falls_between(interactions, mover: str, first: str, second: str) -> bool:
    """Whether `mover` falls after it last moves on `first` and before it first moves on `second`."""
    on = [k for k, t in enumerate(interactions) if t.name in ("roll", "slide") and t.objects == (mover, first)]
    onto = [k for k, t in enumerate(interactions) if t.name in ("roll", "slide") and t.objects == (mover, second)]
    if not onto:
        return False
    start = on[-1] if on else -1
    return any(t.name == "fall" and t.objects[0] == mover for t in interactions[start + 1 : onto[0]])


def pushes(interactions, position: int, players: Set[str], heading: str | None = "right") -> str | None:
    """The way (left or right) that the hit `interactions[position]` pushes its target, if
    known: away from the one side it is declared from (from the left: to the right). A hit
    declared otherwise (`left ∨ above`, `any`) pushes the way its actor flies, if that is
    known: the player's object flies `heading` until it has bounced (Angry Birds' bird,
    launched from the slingshot at the left edge of the level, to the right)."""
    hit, before = interactions[position], interactions[:position]
    if len(hit.directions) == 1 and hit.directions[0] in ("left", "right"):
        return OPPOSITE[hit.directions[0]]
    actor = hit.objects[0]
    if (
        heading is not None
        and actor in players
        and not any(t.name == "bounce" and t.objects[0] == actor for t in before)
    ):
        return heading
    return None


def last_hit_at(interactions, name: str) -> int | None:
    """The position of the last declared hit on `name` among `interactions` (those before
    some point)."""
    return next(
        (
            i
            for i in reversed(range(len(interactions)))
            if interactions[i].name == "hit" and interactions[i].objects[1] == name
        ),
        None,
    )


def last_hit_on(interactions, name: str) -> TermIR | None:
    """The last declared hit on `name` among `interactions` (those before some point)."""
    at = last_hit_at(interactions, name)
    return None if at is None else interactions[at]


def last_motion(interactions, name: str) -> int | None:
    """The position of the last roll or slide of `name` among `interactions`."""
    return next(
        (
            i
            for i in reversed(range(len(interactions)))
            if interactions[i].name in ("roll", "slide") and interactions[i].objects[0] == name
        ),
        None,
    )
