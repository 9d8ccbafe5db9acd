"""A release angle as Phy-Q's agents send it, and a level set the game loads (agent_action.py, phyq_levels.py)."""

import ast
import csv
import io
import json
import math

import pytest
from conftest import EXAMPLES, run_physc

from physc.domains.angrybirds import agent_action as aa
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level_xml import parse_level
from physc.domains.angrybirds.phyq_levels import benchmark_files
from physc.domains.angrybirds.worlds import PHYQ, SCIENCE_BIRDS_ENGINE

SLINGSHOT, CAMERA_Y, MAX_WIDTH = (-12.0, -2.5), -1.0, 35.0  # every Phy-Q level's


def game_launch(pixel):
    """The game's launch of an agent's release point (TapShoot → DragBird → LaunchBird): the
    point read into the world, the bird dragged there from its rest point within the drag
    radius, launched away from it at 10 units/s a unit of stretch."""
    released = aa.to_world(pixel, CAMERA_Y, MAX_WIDTH)
    rest = aa.rest_point(SLINGSHOT)
    pull = (rest[0] - released[0], rest[1] - released[1])
    length = math.hypot(*pull)
    if length > aa.DRAG_RADIUS:
        released = (rest[0] - pull[0] / length * aa.DRAG_RADIUS, rest[1] - pull[1] / length * aa.DRAG_RADIUS)
        pull = (rest[0] - released[0], rest[1] - released[1])
    speed = min(length, aa.DRAG_RADIUS) / aa.DRAG_RADIUS * PHYQ.launch.speed
    direction = math.atan2(pull[1], pull[0])
    return released, (speed * math.cos(direction), speed * math.sin(direction))


@pytest.mark.parametrize("angle", [-20.0, 0.0, 12.5, 33.3, 45.0, 55.9004, 70.0, 84.0])
def test_the_drag_launches_what_physc_simulates(angle):
    # angle → the agent's drag (exact pixels) → the game's launch: the start and velocity of
    # physc's full-stretch shot at that angle (the collider's offset aside), within 0.01°.
    ref = aa.reference_point(SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    dx, dy = aa.drag(angle, SLINGSHOT, CAMERA_Y, MAX_WIDTH, 100.0)
    released, velocity = game_launch((ref[0] + dx, ref[1] - dy))
    start, physc_velocity = Shot(angle=angle).start(PHYQ)
    offset = PHYQ.launch.collider_offset
    assert released[0] + offset[0] == pytest.approx(start[0], abs=1e-9) and released[1] + offset[1] == pytest.approx(start[1], abs=1e-9)
    launched = math.degrees(math.atan2(velocity[1], velocity[0]))
    assert abs(launched - angle) < 0.01
    assert math.hypot(*velocity) == pytest.approx(math.hypot(*physc_velocity))


@pytest.mark.parametrize("angle", [x * 2.5 for x in range(-8, 33)])
def test_the_whole_pixel_action_is_the_agents_200_pixel_drag_nearest_the_angle(angle):
    action, launched = aa.agent_action(angle, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    ref = aa.reference_point(SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    pixel = (ref[0] + action[0], ref[1] - action[1])
    assert all(isinstance(v, int) for v in action) and action[2] == 0
    # DQNDiscreteAgent's drag: 200 pixels from the reference point (within a pixel, once whole);
    # at low angles the release point is left of the screen, as the DQN agent's own drags are.
    assert abs(math.hypot(action[0], action[1]) - aa.AGENT_DRAG) < math.sqrt(2)
    _, velocity = game_launch(pixel)
    assert math.hypot(*velocity) == pytest.approx(PHYQ.launch.speed)  # full stretch
    assert math.degrees(math.atan2(velocity[1], velocity[0])) == pytest.approx(launched, abs=1e-9)
    # the nearest of the whole pixels around the exact drag there (floor and ceiling of each):
    # the point on the ray at θ + 180° from the rest point 200 pixels from the reference point
    low, high = 100.0, 300.0
    for _ in range(60):
        middle = (low + high) / 2
        low, high = (middle, high) if math.hypot(*aa.drag(angle, SLINGSHOT, CAMERA_Y, MAX_WIDTH, middle)) < 200 else (low, middle)
    dx, dy = aa.drag(angle, SLINGSHOT, CAMERA_Y, MAX_WIDTH, low)
    around = [
        abs(aa.launch_angle((x, y), SLINGSHOT, CAMERA_Y, MAX_WIDTH)[0] - angle)
        for x in (math.floor(dx), math.ceil(dx))
        for y in (math.floor(dy), math.ceil(dy))
    ]
    assert abs(launched - angle) == pytest.approx(min(around)) and abs(launched - angle) < 0.15


def test_the_drag_is_the_dqn_agents():
    # DQNDiscreteAgent.__degToShot: [200·cos(deg), 200·sin(deg)] for deg 90..269, truncated by
    # the wrapper's step (int()); at 180° the release point is 200 pixels left of the reference.
    assert aa.AGENT_DRAG == 200
    sent = [int(aa.AGENT_DRAG * math.cos(math.radians(180.0))), int(aa.AGENT_DRAG * math.sin(math.radians(180.0)))]
    assert sent == [-200, 0]
    launched, stretch = aa.launch_angle(sent, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert stretch == 1.0 and abs(launched) < 0.5  # about level: the rest point is not the reference point
    action, _ = aa.agent_action(0.0, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert aa.reference_point(SLINGSHOT, CAMERA_Y, MAX_WIDTH)[0] + action[0] < 0  # off the screen, as the DQN's own


def find_release_point(sling, theta):
    """Utils/trajectory_planner.py (phy-q/benchmark 514491c), transcribed: `sling` is the
    framework's box (X, Y, width, height) after the wrapper's swap."""
    x, y, width, height = sling
    mag = height * 5
    ref = (int(x + 0.45 * width), int(y + 0.35 * width))  # get_reference_point
    return int(ref[0] - mag * math.cos(theta)), int(ref[1] + mag * math.sin(theta))


@pytest.mark.parametrize("angle", [-15.0, 0.0, 12.3, 30.0, 45.0, 61.7, 80.0])
def test_the_planner_release_is_find_release_point_from_the_reference_point(angle):
    sling = aa.sling_box(SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert sling == (120, 251, 17, 49) and aa.PLANNER_STRETCH == 5  # the box's edges rounded: 2.055 units high
    ref = aa.reference_point(SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    action = aa.planner_release(angle, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert (ref[0] + action[0], ref[1] - action[1]) == find_release_point(sling, math.radians(angle))
    assert action[2] == 0
    launched, stretch = aa.launch_angle(action, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    # aimed from the reference point, not the rest point, and truncated: a little low, under 0.7°
    assert stretch == 1.0 and -0.7 < launched - angle < 0


def test_the_neighbours_are_the_8_pixels_around():
    around = aa.neighbours([-120, -45, 560])
    assert len(around) == len({tuple(p) for p in around}) == 8 and [-120, -45, 560] not in around
    assert all(max(abs(p[0] + 120), abs(p[1] + 45)) == 1 and p[2] == 560 for p in around)


def test_the_reference_point_is_the_frameworks():
    # The ground truth's slingshot box at 24 pixels a unit: x 120–137, top 251; X + 0.45·17, Y + 0.35·17.
    assert aa.reference_point(SLINGSHOT, CAMERA_Y, MAX_WIDTH) == (127, 256)
    assert aa.to_screen(aa.rest_point(SLINGSHOT), CAMERA_Y, MAX_WIDTH) == pytest.approx((128.4, 256.8))


def test_a_task_records_and_verifies_its_agent_action(tmp_path):
    level, task = tmp_path / "sf.xml", tmp_path / "sf.json"
    assert run_physc("compile", EXAMPLES / "paper" / "01_SF.phys", "-o", level, "--task", task, "-q").status == 0
    solution = json.loads(task.read_text())["solution"]
    action, angle = aa.agent_action(solution["release_angle"], SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert solution["agent_action"] == action and solution["agent_angle"] == pytest.approx(angle, abs=1e-5)
    run = run_physc("verify", level, "--task", task)
    assert run.status == 0 and f"env.step({action})" in run.stdout


def test_a_dataset_holds_a_level_set_the_game_loads(tmp_path):
    level = (EXAMPLES.parent / "tests" / "data" / "sciencebirds" / "phyq-templates").glob("*.xml")
    text = next(iter(sorted(level))).read_text(encoding="utf-8-sig")
    rows = [({"scenario": "SF", "seed": seed, "solution": {"release_angle": 40.0 + seed}}, text) for seed in (3, 4)]
    files = benchmark_files(rows)
    assert files["phyq/Levels/SF_3_1.xml"] == text.encode("utf-8") and "phyq/Levels/SF_4_2.xml" in files
    shots = list(csv.DictReader(io.StringIO(files["phyq/shots.csv"].decode())))
    assert [s["level"] for s in shots] == ["1", "2"] and shots[1]["release_angle"] == "44.0"
    assert abs(float(shots[0]["agent_angle"]) - 43.0) < 0.1
    config = files["phyq/config.xml"].decode()
    listed = [line for line in config.splitlines() if "game_levels " in line]
    assert len(listed) == 3 and listed[-1] == listed[-2] and "SF_4_2.xml" in listed[-1]  # the last twice, as Phy-Q's scripts do
    script = files["phyq/replay_shots.py"].decode()
    tree = ast.parse(script)
    assert {"agent_action", "launch_angle", "main"} <= {node.name for node in tree.body if isinstance(node, ast.FunctionDef)}
    assert "import physc" not in script  # it runs in the agents' own Python
    assert parse_level(text).world is None


def test_a_level_names_its_world_and_the_level_commands_play_it_there(tmp_path):
    level = tmp_path / "sf.xml"
    assert run_physc("compile", EXAMPLES / "paper" / "01_SF.phys", "--world", "rolling", "-o", level, "-q").status == 0
    text = level.read_text()
    assert '<Level width="2" world="rolling" generator="physc ' in text
    assert parse_level(text).world == "rolling"
    played = run_physc("simulate", level, "--angle", "40", "--format", "json")
    assert played.status == 0 and json.loads(played.stdout)["world"] == "rolling" and not played.stderr
    other = run_physc("simulate", level, "--angle", "40", "--world", "phyq", "--format", "json")
    assert json.loads(other.stdout)["world"] == "phyq" and "made for the world 'rolling'" in other.stderr
    bad = tmp_path / "bad.xml"
    bad.write_text(text.replace('world="rolling"', 'world="rollng"'))
    run = run_physc("trace", bad, "--angle", "40")
    assert run.status == 2 and "did you mean 'rolling'" in run.stderr


def test_the_level_set_carries_the_shot_the_task_recorded():
    text = next(iter(sorted((EXAMPLES.parent / "tests" / "data" / "sciencebirds" / "phyq-templates").glob("*.xml")))).read_text(encoding="utf-8-sig")
    recorded = {"release_angle": 43.0, "agent_action": [-100, -93, 0], "agent_angle": 42.98}
    shots = list(csv.DictReader(io.StringIO(benchmark_files([({"scenario": "SF", "seed": 0, "solution": recorded}, text)])["phyq/shots.csv"].decode())))
    assert (shots[0]["dx"], shots[0]["dy"], shots[0]["agent_angle"]) == ("-100", "-93", "42.98")  # what physc verify replayed


def test_the_level_set_carries_every_shot_of_a_task_of_several_in_turn():
    text = next(iter(sorted((EXAMPLES.parent / "tests" / "data" / "sciencebirds" / "phyq-templates").glob("*.xml")))).read_text(encoding="utf-8-sig")
    recorded = {"shots": [
        {"release_angle": 43.0, "agent_action": [-100, -93, 0], "agent_angle": 42.98},
        {"release_angle": 20.0, "agent_action": [-120, -40, 560], "agent_angle": 20.01},
    ]}
    files = benchmark_files([({"scenario": "Two", "seed": 0, "solution": recorded}, text)])
    shots = list(csv.DictReader(io.StringIO(files["phyq/shots.csv"].decode())))
    assert [(s["level"], s["shot"], s["tap_time"]) for s in shots] == [("1", "1", "0"), ("1", "2", "560")]
    assert files["phyq/config.xml"].decode().count("Two_0_1.xml") == 2  # the level once (and the last again, as Phy-Q lists it)


def test_the_agents_other_actions_are_the_planners_release_the_8_pixels_and_the_tap_off_by_a_step():
    from types import SimpleNamespace

    from physc.domains.angrybirds.launch import Shots
    from physc.domains.angrybirds.shots import TAP_LEAST, TAP_OFF, BirdShot, ShotsSolution, Solution, agent_variants, played_as

    level = SimpleNamespace(slingshot=SLINGSHOT, camera=SimpleNamespace(y=CAMERA_Y, max_width=MAX_WIDTH))
    one = played_as(level, Solution("pig", (5.0, -2.0), "low", 20.0))
    variants = agent_variants(level, one)
    assert len(variants) == 9 and all(isinstance(action, Shot) for _, action in variants)
    planner = aa.planner_release(20.0, SLINGSHOT, CAMERA_Y, MAX_WIDTH)
    assert variants[0][0].startswith(f"the planner's release: env.step({planner})")
    assert variants[0][1].angle == pytest.approx(aa.launch_angle(planner, SLINGSHOT, CAMERA_Y, MAX_WIDTH)[0], abs=1e-5)
    pixels = [aa.launch_angle(p, SLINGSHOT, CAMERA_Y, MAX_WIDTH)[0] for p in aa.neighbours(one.agent_action)]
    assert [action.angle for _, action in variants[1:]] == pytest.approx(pixels, abs=1e-5)
    assert agent_variants(level, Solution("pig", (5.0, -2.0), "low", 20.0)) == []  # a record from before agent actions
    # Two shots, the second tapped: each shot's variants with the other as sent; the tap 20 ms off.
    assert TAP_OFF == 20 and TAP_OFF / 1000 == SCIENCE_BIRDS_ENGINE.dt  # a frame steps the game's physics once at most
    two = played_as(level, ShotsSolution("two", (
        BirdShot("bird", "pig", (5.0, -2.0), "low", 20.0),
        BirdShot("blue", "pig", (6.0, -2.0), "low", 35.0, tap=0.54),
    )))
    variants = agent_variants(level, two)
    assert len(variants) == 9 + 9 + 2 and all(isinstance(action, Shots) for _, action in variants)
    first, second = (s.agent_angle for s in two.shots)
    assert all(action.shots[1].angle == second for _, action in variants[:9])
    assert all(action.shots[0].angle == first for _, action in variants[9:])
    early, late = variants[-2:]
    assert [early[1].shots[1].tap, late[1].shots[1].tap] == pytest.approx([0.52, 0.56])
    assert early[1].shots[1].angle == second and "shot 2 (blue): the tap 20 ms early: env.step(" in early[0]
    assert early[0].endswith(f"{list(two.shots[1].agent_action[:2]) + [520]})")
    # A tap sooner than 20 ms is tapped at 1 ms at the earliest (HUD.cs taps only at a tap time above 0).
    soon = played_as(level, ShotsSolution("soon", (BirdShot("blue", "pig", (6.0, -2.0), "low", 35.0, tap=0.012),)))
    early = agent_variants(level, soon)[-2][1]
    assert TAP_LEAST == 1 and early.tap == 0.001 and "the tap 20 ms early" in agent_variants(level, soon)[-2][0]
