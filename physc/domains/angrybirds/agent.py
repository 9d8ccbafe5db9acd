"""The paper's heuristic agent, the evaluation's measure of accidental solvability in
angrybirds: it shoots at every block, pig and TNT except the solution's target, at its
points of interest, on both trajectories; a task's value is the fraction of those plays
that solve it."""

from __future__ import annotations

from physc.domains.angrybirds import REPLAY_SECONDS
from physc.domains.angrybirds.actions import agent_targets, points_of_interest
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot

AGENT_POINTS = ("ll", "ul", "ur", "lr", "c")


def accidental(game: Game, solution_target: str) -> tuple[float | None, int]:
    """The paper's AS for one level: the fraction of the heuristic agent's plays that solve it,
    and the number of plays. None when the agent found no play (no point of interest within
    reach): a fraction of nothing is not 0, and must not pull a mean down."""
    plays = solved = 0
    for obj in agent_targets(game.level, solution_target):
        points = points_of_interest(obj)
        for name in AGENT_POINTS:
            x, y = points[name]
            if not game.world.reachable(x, y):
                continue
            for trajectory in ("low", "high"):
                plays += 1
                trace = game.simulate(Shot(target=(x, y), trajectory=trajectory), REPLAY_SECONDS, settle_after_solved=0.0)
                solved += trace.solved
    return (solved / plays if plays else None), plays
