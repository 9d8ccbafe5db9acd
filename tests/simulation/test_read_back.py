"""A realised trace reads back as the terms that made it: each golden task's solution, replayed in
its world, is recognised as the whole sequence its task file records (every declared term among
it, with the direction docs/language.md gives it: hit from a side, slide towards one, bounce to
where the bounce sends it, fall onto)."""

from __future__ import annotations

from pathlib import Path

import pytest

from physc.api.tasks import domain_of, load_task, scenario_of
from physc.simulation.fidelity import fidelity

TASKS = sorted((Path(__file__).parents[1] / "golden" / "task").glob("*.json"))


@pytest.mark.parametrize("path", TASKS, ids=lambda p: p.stem)
def test_the_solution_reads_back_as_its_sequence(path):
    task = load_task(path)
    scenario = scenario_of(task)
    domain = domain_of(task)  # in the world and engine the task was made in
    trace = domain.replay(task.level, task.solution, scenario)
    assert trace.sequence() == task.trace
    assert fidelity(scenario, trace).valid, f"{scenario.name}: {trace.sequence()}"


def test_the_golden_tasks_cover_the_paper_s_directed_terms():
    """hit, slide, bounce and fall are declared among them, each with its direction."""
    declared = {t.name for path in TASKS for t in scenario_of(load_task(path)).interactions}
    assert {"hit", "slide", "bounce", "fall", "destroy"} <= declared
