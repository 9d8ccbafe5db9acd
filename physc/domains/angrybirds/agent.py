"""The paper's heuristic agent, the evaluation's measure of accidental solvability in
angrybirds: it shoots at every block, pig and TNT except the solution's target, at its
points of interest, on both trajectories; a task's value is the fraction of those plays
that solve it. In a level of several birds, a play shoots each of them at the same point,
in turn (language version 2)."""

from __future__ import annotations

from physc.domains.angrybirds.actions import agent_targets, points_of_interest
from physc.domains.angrybirds.launch import Shot, Shots

AGENT_POINTS = ("ll", "ul", "ur", "lr", "c")


def plays(domain, level, solution_target: str | None) -> list[tuple[str, Shot | Shots]]:
    """The heuristic agent's plays of one level, (label, shot): each point of interest within
    reach of every object it shoots at, on both trajectories; in a level of several birds, each
    bird shot at the same point in turn."""
    found: list[tuple[str, Shot | Shots]] = []
    for obj in agent_targets(level, solution_target):
        points = points_of_interest(obj)
        for name in AGENT_POINTS:
            x, y = points[name]
            if not domain.world.reachable(x, y):
                continue
            for trajectory in ("low", "high"):
                shot: Shot | Shots = Shot(target=(x, y), trajectory=trajectory)
                if len(level.birds) > 1:
                    shot = Shots(
                        tuple(
                            Shot(target=(x, y), trajectory=trajectory, bird="bird" if k == 0 else f"bird{k + 1}")
                            for k in range(len(level.birds))
                        )
                    )
                found.append((f"agent: {obj.name}.{name}, {trajectory}", shot))
    return found


def accidental(domain, level, solution_target: str | None) -> tuple[float | None, int]:
    """The paper's AS for one level: the fraction of the heuristic agent's plays that solve it
    (each an outcome playout in the domain's world and backend), and the number of plays. None
    when the agent found no play (no point of interest within reach): a fraction of nothing is
    not 0, and must not pull a mean down."""
    shots = plays(domain, level, solution_target)
    solved = sum(domain.playout(level, shot).solved for _, shot in shots)
    return (solved / len(shots) if shots else None), len(shots)
