"""Shots from what Phy-Q's agents send: `env.step([dx, dy, tap_time])` played as the game plays it.

An agent's action is a release point in whole screen pixels from the slingshot's reference point
and a tap time in milliseconds after the launch (0: no tap); the game reads the point back into
the world with the level's camera and launches the bird away from it, at the angle and stretch
agent_action.py's `launch_angle` gives (docs/angrybirds.md, "Playing a task in Phy-Q's game").
`agent_shot` makes that the Shot physc plays, for one of a level's birds; `bird_names` names a
level's birds as traces name them.
"""

from __future__ import annotations

import math

from physc.domains.angrybirds import agent_action
from physc.domains.angrybirds.launch import Shot, Shots

FIRST = "bird"  # the first bird's name in a trace (flight.py's FIRST): the others are bird2, bird3, …


def bird_names(count: int, named: tuple[str, ...] | list[str] = ()) -> list[str]:
    """The names of a level's `count` birds in the order they are shot: `named` first (a task's
    scenario names its own), then bird, bird2, bird3, … for the place of each in the level.

    >>> bird_names(3)
    ['bird', 'bird2', 'bird3']
    >>> bird_names(2, ["blue"])
    ['blue', 'bird2']
    """
    return [named[k] if k < len(named) else (FIRST if k == 0 else f"{FIRST}{k + 1}") for k in range(count)]


def agent_values(action) -> list[int]:
    """[dx, dy, tap_ms] of an agent's action `[dx, dy]` or `[dx, dy, tap_time]`, each truncated to
    a whole number as the framework sends it (SBEnvironmentWrapper.py `step`: `int(action[0])`,
    …, `int(tap_time)`); ValueError for anything else."""
    values = list(action)
    if len(values) not in (2, 3):
        raise ValueError(f"an agent's action is [dx, dy] or [dx, dy, tap_time], not {values!r}")
    try:
        numbers = [float(v) for v in values]
    except (TypeError, ValueError):
        raise ValueError(f"an agent's action holds numbers, not {values!r}") from None
    if not all(math.isfinite(v) for v in numbers):
        raise ValueError(f"an agent's action holds finite numbers, not {values!r}")
    return [int(v) for v in numbers] + ([0] if len(numbers) == 2 else [])


def agent_shot(level, action, bird: str = FIRST, wait: float | None = None) -> Shot:
    """The shot the game launches for Phy-Q's agent action `action` ([dx, dy] or [dx, dy,
    tap_time], whole pixels and milliseconds, truncated as the framework truncates them) in
    `level` (its slingshot and camera): at the angle and stretch `launch_angle` gives, tapped
    tap_time / 1000 s after the launch (a tap time of 0 or less: no tap, as HUD.cs does not tap
    then), shooting `bird` (its name in the trace), `wait` as Shot's. ValueError for an action
    that is not one, or one that releases the bird where it rests (no direction to launch it)."""
    dx, dy, tap = agent_values(action)
    angle, stretch = agent_action.launch_angle([dx, dy], level.slingshot, level.camera.y, level.camera.max_width)
    if stretch <= 1e-9:
        raise ValueError(f"env.step([{dx}, {dy}, {tap}]) releases the bird where it rests: it is not launched")
    return Shot(angle=angle, tap=tap / 1000 if tap > 0 else None, bird=bird, wait=wait, stretch=stretch)


def agent_shots(level, actions, names: tuple[str, ...] | list[str] = ()) -> Shot | Shots:
    """The shots of `actions`, one agent action a bird, in the order the level's birds are
    shot (named by `bird_names`), each later one once the level rests as Phy-Q's agents shoot;
    ValueError for more actions than the level has birds."""
    actions = list(actions)
    if not actions:
        raise ValueError("no agent action to play")
    if len(actions) > len(level.birds):
        raise ValueError(f"{len(actions)} agent actions for a level of {len(level.birds)} bird(s)")
    birds = bird_names(len(level.birds), names)
    shots = tuple(agent_shot(level, a, birds[k]) for k, a in enumerate(actions))
    return shots[0] if len(shots) == 1 else Shots(shots)
