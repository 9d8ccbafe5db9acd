"""Every shot the player could send next, and a timed shot retimed: what the checks of
language version 2's properties play (`nonGreedy`, `blocks`, `timed`: physc.search.properties).

Phy-Q's agents send a release point 200 pixels from the slingshot's reference point at a
whole degree `deg` in 90…269 (phy-q/benchmark `LearningAgents/DQNDiscreteAgent.py`
`__degToShot`): the game launches the bird away from it, at `deg − 180`, so the release angles
the player can send span −90° to 90°. A sweep plays that span every SWEEP_STEP degrees (issue
73: half a degree), untapped, each shot taken once the level rests after the one before; the
paper's candidate shots at the object the check is about come first (tapped, for a bird the
scenario taps, as the search's candidates are), then the sweep from coarse to fine, so that a
shot that breaks a property is met after few plays.
"""

from __future__ import annotations

import attrs

from physc.domains.angrybirds.launch import Shot, Shots, shots_of
from physc.domains.angrybirds.shots import birds, tap_variants, tapped, where_left

SWEEP_RANGE = (-90.0, 90.0)  # release angles Phy-Q's agents can send (module docstring), the upper one excluded
SWEEP_STEP = 0.5  # degrees between two shots of a sweep (issue 73)


def sweep_angles(low: float = SWEEP_RANGE[0], high: float = SWEEP_RANGE[1], step: float = SWEEP_STEP) -> list[float]:
    """The release angles of a sweep, coarse to fine: every 16 steps first, then the ones
    halfway between, and so on, each angle once."""
    count = int(round((high - low) / step))
    order = sorted(range(count), key=lambda k: (-_depth(k), k))
    return [round(low + k * step, 6) for k in order]


def _depth(k: int) -> int:
    """How many times 2 divides k, at most 4 (0 counts as divisible every time)."""
    depth = 0
    while depth < 4 and k % 2 == 0:
        k //= 2
        depth += 1
    return depth


def sweep(domain, level, scenario, before=None, after=None, at: str | None = None) -> list[tuple[str, object]]:
    """The next bird's shots after `before` (module docstring): the candidates aimed at `at`
    in the level as `after` (the play of `before`) left it, then the sweep; [] when no bird is
    left."""
    order = birds(scenario, domain.vocabulary.player)
    done = shots_of(before)
    if len(done) >= len(order):
        return []
    name = order[len(done)]
    shots: list[tuple[str, Shot]] = []
    if at is not None:
        aimed = level if after is None else where_left(level, after)
        for label, shot in domain.search.actions_at(aimed, at):
            shot = attrs.evolve(shot, bird=name)
            if tapped(scenario, name):
                shots += tap_variants(label, shot, domain.world)
            shots.append((label, shot))
    shots += [(f"{angle:g}°", Shot(angle=angle, bird=name)) for angle in sweep_angles()]
    if before is None:
        return [(f"{name}: {label}", shot) for label, shot in shots]
    return [(f"{name}: {label}", Shots((*done, shot))) for label, shot in shots]


def timing(action, actor: str) -> float | None:
    """The wait of `actor`'s shot in `action` (None: not timed, or no such shot)."""
    return next((s.wait for s in shots_of(action) if s.bird == actor), None)


def retimed(action, actor: str, wait: float | None, earliest: float = 0.0):
    """`action` with `actor`'s shot taken `wait` seconds after the bird before it (None: once
    the level rests), or at `earliest` where the game can release it no sooner (the game plays
    it then); None when `action` has no later shot of `actor`'s."""
    shots = list(shots_of(action))
    index = next((k for k, s in enumerate(shots) if s.bird == actor), None)
    if index is None or index == 0:
        return None
    shots[index] = attrs.evolve(shots[index], wait=None if wait is None else max(wait, earliest))
    return Shots(tuple(shots))
