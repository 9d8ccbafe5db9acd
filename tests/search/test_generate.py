"""physc compile, end to end: a validated task whose solution realises the sequence."""

from __future__ import annotations

import json

import attrs
import pytest
from conftest import EXAMPLES, run_physc
from middle_end import DOMAIN, paper_scenarios

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import LevelObject
from physc.domains.angrybirds.level_xml import read_level
from physc.domains.angrybirds.worlds import PHYQ
from physc.driver.pipeline import Pipeline
from physc.simulation.fidelity import fidelity

# A fixed seed per scenario that generation handles today in the game's physics (docs/results.md
# has the rates of all 16): seed 0 of the 2- and 4-interaction scenarios but R, and B seed 2 (seed 0
# gives no task that holds under both readings of the game). A scenario with a
# roll (R and the chains that contain one) rarely generates since the game's own flat-footed
# circles hop where true circles rolled (docs/results.md), and a task that does takes minutes,
# too long for a test: the evaluation measures them.
GENERATED = {"SF": 0, "SFTB": 0, "SFLB": 0, "S": 0, "B": 2, "F": 0}


BOX2D = load_backend("box2d")

@pytest.mark.parametrize("name", GENERATED)
def test_paper_scenario_compiles_and_validates(name):
    scenario = paper_scenarios()[name]
    task = Pipeline(DOMAIN, scenario, seed=GENERATED[name]).task
    assert task.validated
    # Replay the written level independently: the solution realises the sequence.
    written = read_level(DOMAIN.files.emit_level(task.level).encode())
    # Level files carry no names; objects keep their order.
    level = attrs.evolve(written, objects=tuple(attrs.evolve(o, name=n.name) for o, n in zip(written.objects, task.level.objects)))
    assert level == task.level
    numbers = [getattr(o, f) for o in task.level.objects for f in ("x", "y", "rotation", "scale_x", "scale_y")]
    assert {type(n) for n in numbers} <= {float, type(None)}  # as the model says: no numpy scalars
    shot = Shot(target=tuple(task.solution.target), trajectory=task.solution.trajectory)
    redirects = {tuple(t.objects) for t in scenario.interactions if t.name == "bounce"}
    trace = Game(level, PHYQ, BOX2D).play(shot, 9.0, restrictions=scenario.restrictions, redirects=redirects)
    result = fidelity(scenario, trace)
    assert result.valid, (result, trace.sequence())
    assert DOMAIN.stability(level)[0]  # left alone, it stands


def test_stability_sees_a_rolling_circle():
    task = Pipeline(DOMAIN, paper_scenarios()["SF"], seed=0).task
    assert DOMAIN.stability(task.level)[0]
    ramp = LevelObject("Platform", "Platform", 6.0, -1.0, 20.0, scale_x=4.0, scale_y=0.5, name="ramp")
    ball = LevelObject("Block", "Circle", 6.0, -0.4, 0.0, "wood", name="ball")
    stable, shift = DOMAIN.stability(attrs.evolve(task.level, objects=task.level.objects + (ramp, ball)))
    assert not stable and shift > 0.05


def test_compile_writes_level_task_and_picture(tmp_path):
    level, task, png = tmp_path / "sf.xml", tmp_path / "sf.json", tmp_path / "sf.png"
    run = run_physc("compile", EXAMPLES / "paper" / "01_SF.phys", "-o", level, "--task", task, "--png", png)
    assert run.status == 0, run.stderr
    assert "SF: validated" in run.stderr
    data = json.loads(task.read_text())
    assert data["scenario"] == "SF" and data["seed"] == 0 and data["validated"] is True
    assert data["trace"].startswith("hit(bird, pig, left) > destroy(bird, pig)")
    seconds = data["seconds"]
    assert list(seconds) == ["layout", "satisfy", "distract", "validate", "total"]
    assert sum(seconds.values()) - seconds["total"] == pytest.approx(seconds["total"], abs=1e-3)
    assert read_level(level.read_bytes()).objects
    assert png.read_bytes().startswith(b"\x89PNG")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["sf.json", "sf.png", "sf.xml"]


def test_same_seed_same_level_bytes():
    first = run_physc("compile", EXAMPLES / "paper" / "05_F.phys", "--seed", "2", "-q")
    second = run_physc("compile", EXAMPLES / "paper" / "05_F.phys", "--seed", "2", "-q")
    assert first.status == 0 and first.stdout == second.stdout


def test_no_validate_marks_the_task(tmp_path):
    task = tmp_path / "t.json"
    assert run_physc("compile", EXAMPLES / "paper" / "01_SF.phys", "--no-validate", "--task", task, "-o", tmp_path / "l.xml", "-q").status == 0
    assert json.loads(task.read_text())["validated"] is None


def test_several_scenarios_into_folders(tmp_path):
    run = run_physc("compile", EXAMPLES / "paper" / "all.paper.phys", "-s", "SF", "-s", "SFLB", "-o", tmp_path / "levels", "--task", tmp_path / "tasks", "-q")
    assert run.status == 0, run.stderr
    assert sorted(p.name for p in (tmp_path / "levels").iterdir()) == ["SF.xml", "SFLB.xml"]
    assert sorted(p.name for p in (tmp_path / "tasks").iterdir()) == ["SF.json", "SFLB.json"]


def test_infeasible_scenario_exits_3():
    run = run_physc("compile", EXAMPLES / "infeasible" / "E0801_fall_from_below.phys", "-q", "--color", "never")
    assert run.status == 3 and run.stdout == "" and "error[E0801]" in run.stderr


def test_the_task_says_why_earlier_layouts_were_given_up(tmp_path):
    # S seed 2: its first layouts do not realise the sequence (or too fragilely); a later one works.
    task = tmp_path / "s.json"
    run = run_physc("compile", EXAMPLES / "paper" / "all.paper.phys", "-s", "S", "--seed", "2", "--no-validate", "--task", task, "-o", tmp_path / "l.xml")
    assert run.status == 0, run.stderr
    data = json.loads(task.read_text())
    given_up = data["given_up"]
    assert data["layouts_tried"] >= 2 and "the sequence was not realised" in given_up
    assert sum(why["layouts"] for why in given_up.values()) == data["layouts_tried"] - 1
    assert 0 < sum(why["simulations"] for why in given_up.values()) < data["simulations"]
    summary = ", ".join(f"{why['layouts']} × {reason}" for reason, why in sorted(given_up.items(), key=lambda item: (-item[1]["layouts"], item[0])))
    assert f"{data['layouts_tried']} layouts (given up: {summary})" in run.stderr


def test_a_failure_says_why_its_layouts_were_given_up():
    run = run_physc("compile", EXAMPLES / "paper" / "all.paper.phys", "-s", "RRR", "--layouts", "2", "-q", "--color", "never")
    assert run.status == 3
    assert "within the budget (2 layouts)" in run.stderr and "; given up: 2 × the sequence was not realised" in run.stderr
    assert "in order (never `" in run.stderr  # how far the best simulation got, and where it stopped


def test_the_searchs_parts_are_the_tasks_own_fields():
    """One record from the search to the task: every field of Parts is the Task's field of the
    same name, passed on whole (physc.driver.pipeline)."""
    import attrs

    from physc.compiler.task import Task
    from physc.search.outcome import Parts

    task_fields = {f.name: f for f in attrs.fields(Task)}
    assert {f.name for f in attrs.fields(Parts)} <= set(task_fields)
