"""Outcome playouts (physc.simulation.run.run_to_outcome) say what the full run says of the outcome,
bit for bit: on every golden task, its shot and noisy replays of it, in Angry Birds' game."""

from __future__ import annotations

import random

import numpy as np
import pytest
from conftest import GOLDEN

from physc.api import domain_of, load_task
from physc.simulation.ending import Ending

TASKS = sorted((GOLDEN / "task").glob("*.json"))


def same_outcome(trace, playout) -> bool:
    """Whether a playout says what the full run's trace says of the outcome and the end."""
    return (
        (trace.solved, trace.goal_met, trace.steps, trace.destructions, trace.damage) ==
        (playout.solved, playout.goal_met, playout.steps, playout.destructions, playout.damage)
        and np.array_equal(trace.states[-1], playout.final, equal_nan=True)
    )


@pytest.mark.parametrize("path", TASKS, ids=lambda p: p.stem)
def test_a_playout_of_a_golden_task_is_its_full_run_bit_for_bit(path):
    task = load_task(path)
    domain = domain_of(task)
    rng = random.Random(0)
    shots = [domain.actions.action_of(task.solution)] + [domain.actions.noisy(task.level, domain.actions.action_of(task.solution), rng)[1] for _ in range(2)]
    for shot in shots:
        assert same_outcome(domain.play(task.level, shot, ending=Ending.OUTCOME), domain.playout(task.level, shot))
        assert same_outcome(domain.play(task.level, shot, ending=Ending.WHOLE), domain.playout(task.level, shot, ending=Ending.WHOLE))
    assert domain.playout(task.level, shots[0]).solved


def test_a_playout_keeps_no_states_over_time():
    task = load_task(TASKS[0])
    playout = domain_of(task).playout(task.level, domain_of(task).actions.action_of(task.solution))
    assert playout.final.shape == (len(playout.names), 6)
    assert not hasattr(playout, "states") and not hasattr(playout, "contacts")
