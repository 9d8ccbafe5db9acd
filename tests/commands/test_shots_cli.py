"""`physc simulate`, `trace` and `render` replay what Phy-Q's agents send (`--action dx,dy[,tap]`),
taps (`--tap`), several birds in turn (a --shot, --angle or --action each) and timed shots
(`--wait`), as the Python API does (`physc.simulate(level, [dx, dy, tap])`, `physc.agent_shot`);
every mistake is a usage error (exit 2) that says what to write (physc/commands/aiming.py)."""

from __future__ import annotations

import json
import math

import pytest
from conftest import SCIENCEBIRDS, run_physc

import physc
from physc.domains.angrybirds import agent_action as aa
from physc.domains.angrybirds.agent_shots import agent_shot, bird_names
from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.worlds import PHYQ

ONE_PIG = SCIENCEBIRDS / "phyq-templates" / "1_1_1_1.xml"
SPLIT = """scenario Split {
    objects { bird: bird = blueBird  pig2: pig }
    interactions { tap(bird) > hit(bird, pig, left) > destroy(bird, pig) > hit(bird, pig2, left) > destroy(bird, pig2) }
}
"""
TWO = """scenario TwoShots {
    objects { bird2: bird  pig2: pig }
    interactions { hit(bird, pig, left) > destroy(bird, pig) > hit(bird2, pig2, left) > destroy(bird2, pig2) }
}
"""


def compiled(folder, text: str, name: str):
    """(the level's path, the task file's path, the task's shots) of `text` compiled."""
    source, level, task = folder / f"{name}.phys", folder / f"{name}.xml", folder / f"{name}.json"
    source.write_text(text)
    run = run_physc("compile", source, "-q", "--seed", "0", "-o", level, "--task", task)
    assert run.status == 0, run.stderr
    return level, task, json.loads(task.read_text())["solution"]["shots"]


@pytest.fixture(scope="module")
def split(tmp_path_factory):
    return compiled(tmp_path_factory.mktemp("split"), SPLIT, "split")


@pytest.fixture(scope="module")
def two(tmp_path_factory):
    return compiled(tmp_path_factory.mktemp("two"), TWO, "two")


def action_text(values) -> str:
    return ",".join(str(v) for v in values)


def test_a_tapped_shot_replays_from_the_action_the_agents_send(split):
    """A blue bird's split destroys both pigs: its task's env.step([dx, dy, tap]) splits the bird and its
    pieces destroy them; untapped, the bird stays whole."""
    level, task, (shot,) = split
    dx, dy, tap = shot["agent_action"]
    assert tap > 0
    played = run_physc("simulate", level, "--action", action_text([dx, dy, tap]))
    assert played.status == 0, played.stderr
    assert "2 of 2 pigs destroyed: solved" in played.stdout and f"env.step([{dx}, {dy}, {tap}])" in played.stdout
    assert "(damage, by bird~" in played.stdout  # the split's pieces
    untapped = run_physc("simulate", level, "--action", action_text([dx, dy]))
    assert untapped.status == 0 and "by bird~" not in untapped.stdout and "env.step([" in untapped.stdout
    by_angle = run_physc("simulate", level, "--angle", str(shot["agent_angle"]), "--tap", str(tap / 1000))
    assert "2 of 2 pigs destroyed: solved" in by_angle.stdout
    data = json.loads(run_physc("simulate", level, "--action", action_text([dx, dy, tap]), "--format", "json").stdout)
    (listed,) = data["shots"]
    assert listed["agent_action"] == [dx, dy, tap] and listed["tap"] == tap / 1000 and listed["stretch"] == 1.0
    assert listed["release_angle"] == pytest.approx(shot["agent_angle"], abs=1e-4) and data["solved"]
    traced = run_physc("trace", level, "--task", task, "--action", action_text([dx, dy, tap]))
    assert traced.stdout.splitlines()[1].startswith("tap(bird)") and ": solved" in traced.stdout.splitlines()[0]


def test_render_draws_the_paths_of_an_agents_action(split, tmp_path):
    level, _, (shot,) = split
    out = tmp_path / "split.svg"
    run = run_physc("render", level, "-o", out, "--action", action_text(shot["agent_action"]), "--format", "json")
    assert run.status == 0, run.stderr
    assert "bird" in json.loads(run.stdout)["paths"] and out.read_text().startswith("<?xml")


def test_each_bird_is_shot_in_turn_and_a_wait_times_the_later_one(two):
    level, task, shots = two
    actions = [a for s in shots for a in ("--action", action_text(s["agent_action"]))]
    data = json.loads(run_physc("simulate", level, *actions, "--format", "json").stdout)
    assert [s["bird"] for s in data["shots"]] == ["bird", "bird2"] and data["solved"]
    assert [s["agent_action"] for s in data["shots"]] == [s["agent_action"] for s in shots]
    rested = next(d["time"] for d in data["destroyed"] if d["by"] == "bird2")
    timed = json.loads(run_physc("simulate", level, *actions, "--wait", "0.5", "--format", "json").stdout)
    assert timed["shots"][1]["wait"] == 0.5 and timed["shots"][0]["wait"] is None
    sooner = next(d["time"] for d in timed["destroyed"] if d["by"] == "bird2")
    assert sooner < rested - 1.0  # shot while the level still moved, not once it rested
    mixed = run_physc(
        "simulate", level, "--action", action_text(shots[0]["agent_action"]), "--angle", str(shots[1]["agent_angle"])
    )
    assert mixed.status == 0 and "2 of 2 pigs destroyed: solved" in mixed.stdout
    judged = run_physc("trace", level, "--task", task, *actions)
    assert "destroy(bird2, pig2)" in judged.stdout and ": solved" in judged.stdout.splitlines()[0]


@pytest.mark.parametrize(
    ("arguments", "said"),
    [
        (["--action", "1.5,2"], "takes whole numbers, as env.step sends them"),
        (["--action", "-100"], "takes DX,DY or DX,DY,TAP"),
        (["--action", "a,b"], "'a' is not one"),
        (["--action", "-100,-93,-5"], "takes a tap time in ms from 0 (no tap)"),
        (["--action", "-100,-93,0,4"], "takes DX,DY or DX,DY,TAP"),
        (
            ["--action", "-100,-93", "--angle", "30"],
            "2 shots asked for (--action -100,-93,0, --angle 30), but the level has 1 bird",
        ),
        (["--action", "-100,-93", "--action", "-90,-93"], "but the level has 1 bird"),
        (["--tap", "0.5", "--angle", "30"], "--tap 0.5 comes before any shot: put it after"),
        (["--angle", "30", "--tap", "0.5", "--tap", "0.6"], "--tap is given twice for the shot of --angle 30"),
        (["--action", "-100,-93,500", "--tap", "0.3"], "taps its bird already (500 ms after the launch)"),
        (["--angle", "30", "--wait", "1"], "--wait 1 follows the first shot (--angle 30), which is taken at once"),
        (["--angle", "30", "--tap", "0"], "takes seconds after the launch, more than 0"),
        (["--angle", "30", "--tap", "nan"], "is not a finite number"),
    ],
)
def test_a_mistake_is_a_usage_error_that_says_what_to_write(arguments, said):
    for command in ("simulate", "trace"):
        run = run_physc(command, str(ONE_PIG), *arguments)
        assert run.status == 2 and said in run.stderr, (command, run.stderr)
        assert "Traceback" not in run.stderr and not run.stdout


def test_a_level_without_birds_still_says_so_for_an_action(tmp_path):
    text = ONE_PIG.read_text(encoding="utf-8-sig")
    start, end = text.index("<Birds>"), text.index("</Birds>") + len("</Birds>")
    bare = tmp_path / "nobird.xml"
    bare.write_text(text[:start] + "<Birds></Birds>" + text[end:], encoding="utf-8")
    run = run_physc("simulate", bare, "--action", "-100,-93")
    assert run.status == 1 and "E0907" in run.stderr and "--action" in run.stderr


def test_an_action_is_launched_at_the_angle_and_stretch_the_game_reads_from_it():
    level = Level()
    view = (level.slingshot, level.camera.y, level.camera.max_width)
    shot = agent_shot(level, [-100, -93, 560], "bird2", wait=1.0)
    angle, stretch = aa.launch_angle([-100, -93], *view)
    assert (shot.angle, shot.stretch, shot.tap, shot.bird, shot.wait) == (angle, stretch, 0.56, "bird2", 1.0)
    assert agent_shot(level, [-100.9, -93.2, 0]).angle == angle and agent_shot(level, [-100, -93]).tap is None
    short = agent_shot(level, [-10, -5])  # a drag shorter than the drag radius: a slower launch, nearer the rest point
    assert 0 < short.stretch < 1 and "stretch" in short.text() and short.angle is not None
    (x, y), (vx, vy) = short.start(PHYQ)
    assert math.hypot(vx, vy) == pytest.approx(PHYQ.launch.speed * short.stretch)
    assert (x, y) == pytest.approx(PHYQ.launch.point(short.angle, short.stretch))
    assert PHYQ.launch.point(short.angle, short.stretch) != pytest.approx(PHYQ.launch.point(short.angle))
    assert bird_names(3) == ["bird", "bird2", "bird3"] and bird_names(2, ("blue",)) == ["blue", "bird2"]
    for bad in ([1], [1, 2, 3, 4], ["a", 2], [math.inf, 0]):
        with pytest.raises(ValueError):
            agent_shot(level, bad)


def test_the_python_api_plays_what_the_agents_send(split, two):
    level_path, task_path, (shot,) = split
    level = physc.read_level(level_path)
    dx, dy, tap = shot["agent_action"]
    sent = physc.simulate(level, [dx, dy, tap])
    assert sent.solved and "bird~1" in sent.names and "bird~1" not in physc.simulate(level, [dx, dy]).names
    same = physc.simulate(level, physc.Shot(angle=physc.agent_shot(level, [dx, dy]).angle, tap=tap / 1000))
    assert same.solved and same.sequence() == sent.sequence()
    assert physc.render(level, [dx, dy, tap], fmt="svg").startswith(b"<?xml")
    level_path, task_path, shots = two
    task = physc.load_task(task_path)
    # One action a bird, the birds named as the scenario names them.
    both = physc.simulate(task, [s["agent_action"] for s in shots])
    assert both.solved and "destroy(bird2, pig2)" in both.sequence()
    with pytest.raises(ValueError, match="3 agent actions for a level of 2"):
        physc.simulate(task, [shots[0]["agent_action"]] * 3)
