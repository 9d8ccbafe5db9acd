"""How a shot action moves (`AngryBirds.actions`): each shot's release angle jittered for a
noisy replay, and the lines the search's raising moves it along (each shot's release angle, its
tap, its wait: physc.search.coordinates)."""

from __future__ import annotations

import attrs

from physc.domains.angrybirds.launch import shots_of
from physc.domains.angrybirds.shots import as_action


def noisy(action, world, rng, sigma: float):
    """Each shot's release angle jittered (in the order shot), the rest of it as it was (its
    stretch, tap, bird and wait)."""
    return as_action(attrs.evolve(s, angle=s.release_angle(world) + rng.gauss(0.0, sigma)) for s in shots_of(action))


def lines(action) -> list[tuple[str, int, str]]:
    """The lines an action is moved along, as (name, shot, what): each shot's release angle,
    its tap where it is tapped, its wait where it is timed, in the order shot."""
    out = []
    for k, shot in enumerate(shots_of(action)):
        out.append((f"{shot.bird}'s angle", k, "angle"))
        if shot.tap is not None:
            out.append((f"{shot.bird}'s tap", k, "tap"))
        if shot.wait is not None:
            out.append((f"{shot.bird}'s wait", k, "wait"))
    return out


def nudged(action, world, step: int, degrees: float, line: int | None = None, seconds: float = 0.005):
    """The action with one of its `lines` moved `step` steps: a release angle by `degrees` a
    step, a tap or a wait by `seconds` (a tap stays after the launch, a wait not before the
    bird is on the slingshot); `line` None: the last shot (the one the search chooses now)
    turned. None where the moved shot has no such flight."""
    shots = list(shots_of(action))
    k, what = (len(shots) - 1, "angle") if line is None else lines(action)[line][1:]
    shot = shots[k]
    if what == "angle":
        moved = shot.at_angle(shot.release_angle(world) + step * degrees, world)
    elif what == "tap":
        tap = round((shot.tap or 0.0) + step * seconds, 3)
        moved = attrs.evolve(shot, tap=tap) if tap > 0 else None
    else:
        wait = round((shot.wait or 0.0) + step * seconds, 3)
        moved = attrs.evolve(shot, wait=wait) if wait >= 0 else None
    if moved is None:
        return None
    shots[k] = moved
    return as_action(shots)
