"""Obstacles against random shots (physc.search.accidents): the plays of the evaluation's agent
that solve a task by accident are blocked while the intended solution holds, and the task file
says how many solved before and after, as the evaluation measures it."""

from __future__ import annotations

import json
import random

from conftest import EXAMPLES, SCIENCEBIRDS, run_physc

import physc
from physc.domains import bound, load_domain


def test_a_task_the_agent_solved_by_accident_gets_a_bar_and_says_so(tmp_path):
    # Phy-Q's falling, seed 1: five of the agent's thirty plays (high shots at the pig) solve the
    # task as first laid out; a bar in their flight stops them and leaves the intended fall.
    level, task_file = tmp_path / "f.xml", tmp_path / "f.json"
    run = run_physc("compile", EXAMPLES / "phyq" / "04_falling.phys", "--seed", "1", "-q", "-o", level, "--task", task_file)
    assert run.status == 0, run.stderr
    record = json.loads(task_file.read_text())
    accidental = record["accidental"]
    assert accidental["plays"] == 30 and accidental["solved_before"] > 0.05 >= accidental["solved"]
    assert accidental["obstacles"] == sum(1 for o in record["obstacles"] if o.startswith("accidental: "))
    assert accidental["obstacles"] >= 1
    task = physc.load_task(task_file)
    domain = bound(load_domain("angrybirds"), task.world, None)
    scenario = physc.api.compiling.selected(EXAMPLES / "phyq" / "04_falling.phys", None)[1]
    measured = domain.evaluation.accidental(task.level, scenario, task.solution, random.Random(0))
    assert measured["agent_plays"] == accidental["plays"] and measured["accidental"] <= 0.05  # the evaluation's measure


def test_the_agents_plays_are_what_the_evaluation_counts():
    """The search blocks the very plays the evaluation counts: agent_plays lists them, and the
    evaluation's accidental solvability is the share of them that solve."""
    domain = bound(load_domain("angrybirds"), "phyq", None)
    level = physc.read_level(SCIENCEBIRDS / "phyq-templates" / "1_1_1_1.xml")
    scenario = physc.api.compiling.selected(EXAMPLES / "paper" / "01_SF.phys", None)[1]
    plays = domain.evaluation.agent_plays(level, scenario)
    assert plays and all(label.startswith("agent: ") for label, _ in plays)
    solved = sum(domain.playout(level, action).solved for _, action in plays)
    measured = domain.evaluation.accidental(level, scenario, None, random.Random(0))
    assert measured == {"accidental": round(solved / len(plays), 5), "agent_plays": len(plays)}
