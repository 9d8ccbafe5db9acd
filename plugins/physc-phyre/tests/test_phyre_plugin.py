"""The PHYRE-like plugin end to end, as its users run it: check, compile (task file in
PHYRE's structure, picture, the intended action), verify in both engines, eval."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import attrs
import pytest

from physc.cli import main

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
LEDGE = EXAMPLES / "01_ledge.phys"


def physc(*args) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            status = main([str(a) for a in args])
        except SystemExit as exit_:
            status = exit_.code if isinstance(exit_.code, int) else 1
    return status, out.getvalue(), err.getvalue()


@pytest.fixture(scope="module")
def ledge(tmp_path_factory):
    folder = tmp_path_factory.mktemp("ledge")
    status, _, err = physc(
        "compile",
        LEDGE,
        "--seed",
        "1",
        "-q",
        "--no-acceptance",
        "-o",
        folder / "level.json",
        "--task",
        folder / "task.json",
        "--png",
        folder / "level.png",
    )
    assert status == 0, err
    return folder


def test_every_example_checks_clean():
    examples = sorted(EXAMPLES.rglob("*.phys"))  # the templates in phyre/ too
    assert len(examples) >= 6
    for path in examples:
        assert physc("check", "-q", path)[0] == 0, path


def test_the_domain_is_listed():
    status, out, _ = physc("domains", "phyre")
    assert status == 0 and out.startswith("phyre: PHYRE-like tasks") and "touch(a, b)" in out


def test_the_level_is_a_task_in_phyres_structure(ledge):
    task = json.loads((ledge / "level.json").read_text())
    bodies = task["scene"]["bodies"]
    assert task["scene"]["width"] == task["scene"]["height"] == 256
    assert [b["shapeType"] for b in bodies[:4]] == [0, 0, 0, 0]  # the walls first
    green, target = bodies[task["bodyId1"]], bodies[task["bodyId2"]]
    assert (green["color"], green["bodyType"], green["shapeType"]) == (2, 2, 1)  # a green dynamic ball
    assert (target["color"], target["bodyType"]) == (4, 1)  # purple, static
    assert task["relationships"] == [6] and task["tier"] == "BALL"
    assert task["description"] == "Make sure the green ball is touching the purple bar."
    (ball,) = task["solutions"][0]["balls"]
    assert 2 <= ball["radius"] <= 32 and ball["position"]["x"] == int(ball["position"]["x"])
    x, y, r = task["physc"]["actions"][0]
    assert all(0 <= v <= 1 for v in (x, y, r))
    assert (ledge / "level.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_task_file_holds_the_intended_action_and_its_trace(ledge):
    task = json.loads((ledge / "task.json").read_text())
    assert task["domain"] == "phyre" and task["solution"]["node"] == "BallAction"
    assert task["trace"].endswith("touch(green, target)")
    assert task["robustness"] == [6, 6] and task["validated"] is True


def test_same_seed_same_bytes(ledge, tmp_path):
    assert physc("compile", LEDGE, "--seed", "1", "-q", "--no-acceptance", "-o", tmp_path / "again.json")[0] == 0
    assert (tmp_path / "again.json").read_bytes() == (ledge / "level.json").read_bytes()


@pytest.mark.parametrize("backend", ["pymunk", "bullet"])
def test_the_solution_replays_in_both_engines(ledge, backend):
    status, out, err = physc(
        "verify", ledge / "level.json", "--task", ledge / "task.json", "--backend", backend, "--replays", "2"
    )
    assert status == 0, out + err
    assert "passes" in out


@pytest.mark.parametrize(
    "damage, message",
    [
        (lambda t: t["solution"].update(radius="big"), "radius must be a finite number"),
        (lambda t: t["solution"].update(radius=0), "radius must be from 2 to 32 px"),
        (lambda t: t["level"]["bodies"][0].update(size=0), "size must be more than 0"),
        (lambda t: t["level"]["bodies"][0].update(shape="cloud"), "'shape' must be in"),
        (lambda t: t["level"].update(goal=["green"]), "the goal must name two of the level's bodies"),
        (lambda t: t["level"].update(goal=["green", "wall_bottom"]), "the goal must name two of the level's bodies"),
        # A task file of an older plugin (one `player`, before the two-ball tier): refused, not misread.
        (lambda t: t["level"].update(player=t["level"].pop("players")[0]), "a 'PhyreLevel' has no field 'player'"),
        (lambda t: t.update(solution={"node": "TwoBallAction", "first": 1, "second": 2}), "'first' must be"),
    ],
)
def test_a_damaged_task_file_is_a_usage_error(ledge, tmp_path, damage, message):
    task = json.loads((ledge / "task.json").read_text())
    damage(task)
    damaged = tmp_path / "task.json"
    damaged.write_text(json.dumps(task))
    status, _, err = physc("verify", ledge / "level.json", "--task", damaged)
    assert status == 2 and message in err and "internal error" not in err, err


def test_the_goal_pair_is_the_scenarios_touch(tmp_path):
    """A blue ball declared before the purple floor is not the target: touch says which is."""
    path = tmp_path / "s.phys"
    text = LEDGE.read_text().replace(
        "target: targetObject = purpleFloor",
        "decoy: targetObject = blueBall\n        target: targetObject = purpleFloor",
    )
    path.write_text(
        text.replace(
            "        > touch(green, target)\n    }",
            "        > touch(green, target)\n    }\n    restrictions { cannotHit(red, decoy, any) }",
        )
    )
    status, out, err = physc("compile", path, "--seed", "1", "-q", "--emit", "layout")
    assert status == 0, err
    from physc_phyre import DOMAIN

    from physc.compiler.concrete_layout import ConcreteLayout
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze
    from physc.serialize import from_data

    scenario = analyze(str(path), INSTALLED).scenarios[0]
    layout = from_data(json.loads(out), {cls.__name__: cls for cls in (ConcreteLayout,)} | _layout_classes())
    assert "decoy" in {o.name for o in layout.objects}
    assert DOMAIN.level_from_layout(layout, scenario).goal == ("green", "target")


def _layout_classes():
    from physc.compiler.concrete_layout import ChosenRelation, PlacedObject

    return {"ChosenRelation": ChosenRelation, "PlacedObject": PlacedObject}


@pytest.fixture
def tenth_of_phyres_pool(monkeypatch):
    """PHYRE's acceptance at a tenth of its pool (chunks of 1,000, ten times the threshold, so
    that the same binomial tests decide), for tests: the full rule costs a minute a task."""
    from physc_phyre.evaluation import PhyreEvaluation

    rule = attrs.evolve(PhyreEvaluation.ball_rule, threshold=1e-4, chunk=1000, min_valid=1000, screen=100)
    monkeypatch.setattr(PhyreEvaluation, "ball_rule", rule)
    return rule


def test_eval_measures_the_random_agent_and_phyres_acceptance(tmp_path, tenth_of_phyres_pool):
    """A task of PHYRE's template 00009 kept by PHYRE's acceptance rule (GOOD_STABLE, not
    TRIVIAL, its solution stable under half-pixel moves), with the figures in the record and
    the report."""
    status, _, err = physc(
        "eval",
        EXAMPLES / "phyre" / "task00009.phys",
        "--seed",
        "1",
        "--tasks",
        "1",
        "--jobs",
        "1",
        "--out",
        tmp_path / "eval",
        "-q",
    )
    assert status == 0, err
    (record,) = [json.loads(line) for line in (tmp_path / "eval" / "records.jsonl").read_text().splitlines()]
    assert record["generated"] and record["stable"] and record["intended_exact"]
    assert record["agent_plays"] == 100 and 0 <= record["accidental"] <= 1 and 0 <= record["auccess"] <= 1
    assert record["good_stable"] is True and record["trivial"] is False and record["solution_stable"] is True
    assert 0 < record["solve_rate"] < 0.5
    report = (tmp_path / "eval" / "results.md").read_text()
    assert "AUCCESS" in report and "GOOD_STABLE" in report
    assert list((tmp_path / "eval").glob("task_*.png"))


def test_the_scene_runs_in_box2d_with_phyres_step_and_iterations():
    from physc_phyre import world

    from physc.backends import DEFAULT_BACKEND, load_backend

    assert (world.ENGINE.dt, world.ENGINE.velocity_iterations, world.ENGINE.position_iterations) == (1 / 60, 15, 20)
    assert DEFAULT_BACKEND == "box2d"
    created = load_backend("box2d").create_world(world.GRAVITY, world.ENGINE)  # Box2D's compiled constants are PHYRE's
    assert created.settings is world.ENGINE


def test_every_pixel_and_radius_survives_phyres_scaling():
    """An exported action read the way PHYRE's ball tier reads it (action_mappers.py:
    x = int(a·255), y likewise, r = round(2 + a·30), bounds tested on a·255) is the same
    ball, for every whole pixel and radius."""
    from physc_phyre.level import BallAction

    for p in range(256):
        for r in (2, 17, 32):
            a = BallAction(p, 255 - p, r).unit()
            assert all(0.0 <= v <= 1.0 for v in a)
            x, y, radius = a[0] * 255, a[1] * 255, 2 + a[2] * 30
            assert (int(x), int(y), round(radius)) == (p, 255 - p, r)
            assert (x, y) == (p, 255 - p)  # PHYRE's bounds test sees the pixel itself


def _pipeline(name):
    from physc.domains import load_domain
    from physc.domains.words import INSTALLED
    from physc.driver.pipeline import Pipeline
    from physc.dsl.frontend import analyze

    (scenario,) = analyze(str(EXAMPLES / "phyre" / name), INSTALLED).scenarios
    return Pipeline(load_domain("phyre"), scenario, 0)


def test_a_ball_rolled_along_the_floor_rests_on_it():
    """PHYRE's template 00000: the floor spans the scene, so a ball that rolls along it rests
    on it anywhere; nothing places it beside the floor (was E0801)."""
    run = _pipeline("task00000.phys")
    texts = {e.text() for e in run.layout_graph.edges}
    assert "onLocation(green, floor, centre ∨ left ∨ right)" in texts or any(
        t.startswith("onLocation(green, floor,") for t in texts
    )
    assert not any(t.startswith("inDirection(green, floor") for t in texts)
    objects = {o.name: o for o in run.placed.layout.objects}
    assert objects["green"].y - objects["green"].height / 2 == pytest.approx(0.0, abs=0.5)  # on the floor's top


def test_a_path_broken_by_a_fall_need_not_be_continuous_and_a_wall_stands_where_the_ball_heads():
    """PHYRE's template 00001: the ball rolls off its shelf, falls, and rolls on along the floor
    to the purple wall: the shelf need not touch the floor (was E0801), and the wall stands at
    the right edge, where the ball heads."""
    run = _pipeline("task00001.phys")
    assert not any(e.term == "touching" and "floor" in (e.a, e.b) for e in run.layout_graph.edges)
    wall = next(o for o in run.placed.layout.objects if o.name == "wall")
    assert (wall.rotation, wall.x) == (90.0, pytest.approx(256 - 5.12 / 2))


def test_an_upright_stick_gets_a_ledge_a_few_of_its_thicknesses_long():
    run = _pipeline("task00009.phys")
    objects = {o.name: o for o in run.placed.layout.objects}
    assert objects["green"].rotation == 90.0 and objects["support_green"].width < 100


def test_shapes_that_cannot_fit_the_scene_are_drawn_again_not_an_internal_error(monkeypatch):
    import physc_phyre

    from physc.compiler.concrete_layout import Body
    from physc.compiler.geometry import Geometry
    from physc.compiler.infeasible import Infeasible

    def too_big(graph, scenario, rng):
        return {n.name: Body(n.name, n.role, "blackBar", Geometry(1000.0, 5.12)) for n in graph.nodes}

    monkeypatch.setattr(physc_phyre.Phyre, "concretize", staticmethod(too_big))
    with pytest.raises(Infeasible):
        _ = _pipeline("task00000.phys").placed  # placing raises


def test_distractors_are_static_bars_and_balls_or_gray_balls_on_the_floor(tmp_path, tenth_of_phyres_pool):
    import random

    from physc_phyre.distract import distractors

    seen = [obj for index in range(1, 30) for obj in distractors(None, index, random.Random(index))]
    assert {o.concrete for o in seen} == {"blackBar", "blackBall", "ball"}
    assert all(0 < o.x < 256 and 0 < o.y < 256 for o in seen)
    assert all(o.y == o.height / 2 for o in seen if o.concrete == "ball")  # on the floor
    # Template 00009, seed 1: three kept; in the task file, a black (static) or gray body each.
    status, _, err = physc(
        "compile",
        EXAMPLES / "phyre" / "task00009.phys",
        "--seed",
        "1",
        "-q",
        "-o",
        tmp_path / "t.json",
        "--task",
        tmp_path / "task.json",
    )
    assert status == 0, err
    task = json.loads((tmp_path / "task.json").read_text())
    assert task["distractors"] and task["acceptance"]["accepted"]
    level = json.loads((tmp_path / "t.json").read_text())
    names = level["physc"]["names"]
    for name in task["distractors"]:
        body = level["scene"]["bodies"][names.index(name)]
        assert (body["color"], body["bodyType"]) in ((6, 1), (5, 2))


def test_a_scene_may_move_at_the_start_but_not_solve_itself():
    """PHYRE's rule, not the paper's stillness: a green ball falling onto a bar is an acceptable
    scene; one falling onto its purple target is not (the empty action solves it)."""
    from physc_phyre import DOMAIN, PhyreLevel, SceneBody

    bar = SceneBody("bar", "bar", 128.0, 60.0, 0.0, 120.0, "black", False)
    target = SceneBody("target", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)
    falling = SceneBody("green", "ball", 128.0, 200.0, 0.0, 12.5, "green", True)
    onto_the_bar = PhyreLevel((bar, target, falling), ("green", "target"))
    assert DOMAIN.stability(onto_the_bar)[0] is True
    assert DOMAIN.stability(onto_the_bar)[1] > 10  # it did move: the ball fell 120 px
    past_the_bar = PhyreLevel((target, falling), ("green", "target"))
    assert DOMAIN.stability(past_the_bar)[0] is False


def test_may_be_trivial_reaches_the_level_and_its_rule(tmp_path):
    """PHYRE's template 00024 keeps TRIVIAL tasks (its script excludes no flag): the scenario
    says `mayBeTrivial()`, its level keeps it, and its acceptance excludes nothing."""
    from physc_phyre import DOMAIN

    from physc.api import load_task

    status, _, err = physc(
        "compile",
        EXAMPLES / "phyre" / "task00024.phys",
        "--seed",
        "0",
        "-q",
        "--no-acceptance",
        "-o",
        tmp_path / "t.json",
        "--task",
        tmp_path / "task.json",
    )
    assert status == 0, err
    level = load_task(tmp_path / "task.json").level
    assert level.may_be_trivial and DOMAIN.evaluation.rule(level).excluded == ()


def test_a_solution_the_finished_level_makes_invalid_is_not_kept(tmp_path, monkeypatch):
    """The finished level (obstacles, distractors, objects moved) may occlude the intended
    ball: the search checks the action on it, with or without PHYRE's acceptance."""
    from physc_phyre import PhyreActions

    monkeypatch.setattr(PhyreActions, "valid", lambda self, level, action: False)
    status, _, err = physc(
        "compile", LEDGE, "--seed", "1", "--no-acceptance", "--layouts", "2", "-o", tmp_path / "t.json"
    )
    assert status == 3 and "the solution is not a valid action in the finished level" in err
