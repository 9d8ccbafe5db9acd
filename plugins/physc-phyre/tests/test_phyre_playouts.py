"""Outcome playouts of PHYRE-like tasks: the same verdict as the full run, bit for bit, for
PHYRE's own pool of random actions, in Box2D and through the generic world queries of another
engine; and one that stops once the verdict is settled says the same."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from physc_phyre.pool import acceptance_chunk

from physc.api import domain_of, load_task
from physc.simulation.ending import Ending

DATA = Path(__file__).parent / "data"
TASKS = [
    DATA / "balls_00000.json",
    DATA / "ramp_00011.json",
]  # two balls by PHYRE's distance rule; a ball and a bar by contact


def _actions(domain, level, count):
    _, placed = acceptance_chunk(1, 0)
    return [a for a in placed[: 6 * count] if domain.actions.valid(level, a)][:count]


@pytest.mark.parametrize("path", TASKS, ids=lambda p: p.stem)
def test_playouts_of_the_pool_say_what_the_full_runs_say(path):
    task = load_task(path)
    domain = domain_of(task)
    actions = _actions(domain, task.level, 60) + [domain.actions.action_of(task.solution)]
    solved = 0
    for action in actions:
        trace = domain.play(task.level, action, ending=Ending.OUTCOME)
        playout = domain.playout(task.level, action)
        assert (trace.solved, trace.goal_met, trace.steps) == (playout.solved, playout.goal_met, playout.steps)
        assert np.array_equal(trace.states[-1], playout.final, equal_nan=True)
        settled = domain.playout(task.level, action, ending=Ending.SETTLED)
        assert (settled.solved, settled.goal_met) == (trace.solved, trace.goal_met) and settled.steps <= trace.steps
        solved += trace.solved
    assert 0 < solved < len(actions)  # both verdicts are among them


def test_in_another_engine_the_generic_queries_give_the_same_outcome():
    task = load_task(TASKS[1])
    domain = domain_of(task, backend="pymunk")
    for action in _actions(domain, task.level, 20):
        trace = domain.play(task.level, action, ending=Ending.OUTCOME)
        playout = domain.playout(task.level, action)
        assert (trace.solved, trace.steps) == (playout.solved, playout.steps)
