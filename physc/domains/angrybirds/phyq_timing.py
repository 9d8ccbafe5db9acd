"""When a dataset's timed shots are taken, for `replay_shots.py` to take them then by the clock.

A timed shot (a `wait`) is taken `wait` seconds after its bird came onto the slingshot, which the
game does when the bird before first struck something or used its power (ABGameWorld.KillBird;
flight.py). The replay script cannot see that moment, but it knows when it sent the shot before:
so shots.csv gives, for each shot of a level with a timed shot, its `launch_gap`, the seconds
from the shot before's launch to its own in physc's play of the level, with the shots as
Phy-Q's agents send them (agent_shots.py), in the world and engine the task was made in. The
script sends the shot that long after the shot before's launch, less the game's drag
(docs/angrybirds.md, "Playing a task in Phy-Q's game").
"""

from __future__ import annotations

import math


def launch_gaps(text: str, solution: dict, world: str | None, backend: str | None = None) -> list[float | None]:
    """For each shot of `solution` (a manifest row's: a ShotsSolution's `shots`, or version 1's
    record alone), the seconds from the shot before's launch to its own in physc's play of the
    level `text`, rounded to the step; None for the first shot, and for every shot of a level
    without a timed shot (it is not played then: a shot once the level rests is taken when the
    game rests, whenever that is), a level with fewer birds than shots, a shot without its agent
    action, or a bird the play never launched."""
    shots = solution.get("shots") or [solution]
    gaps: list[float | None] = [None] * len(shots)
    if not any(s.get("wait") is not None for s in shots) or any(not s.get("agent_action") for s in shots):
        return gaps
    from physc.domains import bound, load_domain
    from physc.domains.angrybirds.agent_shots import agent_shot, bird_names
    from physc.domains.angrybirds.launch import Shots
    from physc.domains.angrybirds.level_xml import parse_level
    from physc.domains.simulated import SimulatedDomain
    from physc.simulation.ending import Ending

    level = parse_level(text)
    if len(level.birds) < len(shots):
        return gaps
    names = [s.get("bird") or default for s, default in zip(shots, bird_names(len(shots)), strict=True)]
    played = Shots(tuple(agent_shot(level, s["agent_action"], names[k], s.get("wait")) for k, s in enumerate(shots)))
    domain = bound(load_domain("angrybirds"), world or level.world, backend)
    assert isinstance(domain, SimulatedDomain)  # Science Birds plays its levels
    trace = domain.play(level, played, None, domain.seconds, ending=Ending.WHOLE)  # as physc.simulate plays it
    launched = [_launched(trace, name) for name in names]
    for k in range(1, len(shots)):
        before, now = launched[k - 1], launched[k]
        if before is not None and now is not None:
            gaps[k] = round((now - before) * trace.dt, 4)
    return gaps


def _launched(trace, name: str) -> int | None:
    """The first step at which the trace has the bird `name` (None: never launched)."""
    if name not in trace.names:
        return None
    column = trace.names.index(name)
    return next((i for i in range(trace.steps) if not math.isnan(trace.states[i, column, 0])), None)
