"""Worlds (issue 52): one value per world, a variant as a derivation, the world and the engine
bound to the domain and passed down to every simulation, and the rolling world's bodies."""

from __future__ import annotations

import json
import math

import pytest
from conftest import EXAMPLES, run_physc

from physc.backends import Circle, load_backend
from physc.domains import load_domain
from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ, ROLLING, catalogue_model
from physc.worlds import WorldError

BOX2D = load_backend("box2d")


def test_the_rolling_world_is_phyq_with_two_settings_changed_and_says_what_they_read():
    assert ROLLING.parent == "phyq" and set(ROLLING.changed) == {
        "bodies.circle_colliders", "bodies.angular_drag",  # its bodies
        "recogniser.roll_slip", "recogniser.slide_spin", "recogniser.travel", "recogniser.hop_rise", "recogniser.round_slides", "recogniser.bounce_walls",  # the paper's words
    }
    ours = {s.path: s for s in ROLLING.settings()}
    theirs = {s.path: s for s in PHYQ.settings()}
    assert ours.keys() == theirs.keys()
    differ = {path for path in ours if ours[path].value != theirs[path].value}
    assert differ == set(ROLLING.changed)
    assert all(ours[path].source.startswith("rolling: physc's reading") for path in differ)
    assert (ROLLING.bodies.angular_drag, ROLLING.bodies.bird_angular_drag, ROLLING.bodies.tnt_angular_drag) == (0.05, 2.0, 0.05)


def test_every_setting_of_every_world_says_where_it_comes_from():
    for world in (PHYQ, ROLLING, load_domain("phyre").world):
        settings = world.settings()
        assert len(settings) > 10
        assert all(s.source for s in settings), [s.path for s in settings if not s.source]
    sources = {s.path: s.source for s in PHYQ.settings()}
    assert "TimeManager.asset" in sources["engine.dt"] and "Physics2DSettings.asset" in sources["engine.velocity_iterations"]
    assert sources["rules.damage_factor"] == "ABConstants.DAMAGE_CONSTANT_MULTIPLIER"


def test_a_domain_bound_to_a_world_and_an_engine_is_a_copy():
    domain = load_domain("angrybirds")
    assert (domain.world.name, domain.backend.name) == ("phyq", "box2d")
    rolling = domain.at("rolling", "pymunk")
    assert (rolling.world, rolling.backend.name) == (ROLLING, "pymunk")
    assert (domain.world.name, domain.backend.name) == ("phyq", "box2d")
    assert rolling.at(backend="box2d").world is ROLLING  # None keeps the bound world
    with pytest.raises(WorldError, match="no world 'rollin'; did you mean 'rolling'"):
        domain.at("rollin")
    with pytest.raises(WorldError, match="no world 'rolling'"):
        load_domain("phyre").at("rolling")


def test_rolling_bodies_are_the_circles_phyq_ships_disabled_with_the_density_on_them():
    assert {p for p in prefabs.prefabs() if prefabs.circle_first(p)} == {"Circle", "CircleSmall", "BasicSmall", "BasicMedium", "BasicBig"}
    assert prefabs.body_shape("Circle", True) == Circle(0.36)
    assert not isinstance(prefabs.body_shape("Circle", False), Circle)  # Phy-Q's flat-footed polygon
    wood = PHYQ.bodies.materials["wood"].density
    assert prefabs.body_mass("Circle", wood, True) == pytest.approx(math.pi * 0.36**2 * wood)
    assert prefabs.body_mass("BasicSmall", 2.0, True) == pytest.approx(math.pi * 0.215**2 * 2.0)
    assert prefabs.body_mass("RectFat", wood, True) == prefabs.body_mass("RectFat", wood, False)  # a box has no circle
    level = Level(objects=(LevelObject("Block", "Circle", 0.0, -3.5 + 0.36, 0.0, "wood", name="c"),))
    assert Game(level, ROLLING, BOX2D).radii()["c"] == 0.36
    assert Game(level, PHYQ, BOX2D).radii()["c"] == 0.375  # the flat foot's height


def test_a_struck_circle_rolls_far_in_the_rolling_world_and_not_in_phyq():
    """Phy-Q's flat-footed circle with angular drag 2 stops soon; the same strike sends the
    rolling world's circle to the end of a 30-unit platform (sciencebirds-facts §6)."""
    top = -2.0
    platform = LevelObject("Platform", "Platform", 8.0, top - 0.16, 0.0, scale_x=30 / 0.64, scale_y=0.5, name="platform")
    circle = LevelObject("Block", "Circle", -6.0, top + 0.38, 0.0, "wood", name="c")
    shot = Shot(target=(-6.3, top + 0.475))
    travelled = {}
    for world in (PHYQ, ROLLING):
        trace = Game(Level(objects=(platform, circle)), world, BOX2D).simulate(shot, 10.0)
        xs = trace.states[:, trace.names.index("c"), 0]
        travelled[world.name] = float(max(x for x in xs if x == x)) + 6.0
    assert travelled["phyq"] < 10.0 and travelled["rolling"] > 20.0, travelled


def test_a_shot_is_aimed_with_the_worlds_gravity():
    heavy = PHYQ.derive("heavy", "more gravity", "a test", gravity=1.3 * PHYQ.gravity)
    shot = Shot(target=(-4.0, -2.0))
    assert shot.release_angle(heavy) > shot.release_angle(PHYQ) + 2
    assert heavy.changed == ("gravity",)


def test_the_catalogue_models_are_worlds_of_their_own():
    assert catalogue_model("game") is PHYQ
    assert catalogue_model("round").bodies.colliders == "round" and catalogue_model("round").changed == ("bodies.colliders",)


def test_physc_worlds_lists_each_domains_worlds_and_with_v_every_setting(tmp_path):
    run = run_physc("worlds")
    assert run.status == 0
    assert "angrybirds/phyq (default):" in run.stdout and "phyre/phyre (default):" in run.stdout
    assert "bodies.circle_colliders = True, bodies.angular_drag = 0.05" in run.stdout.split("derived from phyq: ")[1].splitlines()[0]
    listed = json.loads(run_physc("worlds", "-v", "angrybirds", "--format", "json").stdout)
    assert [w["world"] for w in listed] == ["phyq", "rolling"]
    assert listed[0]["concerns"] is None and listed[1]["concerns"] == ["roll", "slide", "bounce"]
    assert "its changes concern links of: roll, slide, bounce" in run.stdout
    settings = {s["setting"]: s for s in listed[1]["settings"]}
    assert settings["bodies.angular_drag"]["value"] == 0.05 and settings["gravity"]["value"] == pytest.approx(4.7088)
    assert run_physc("worlds", "marbles").status == 2


def test_world_option_is_checked_and_a_task_records_its_world(tmp_path):
    run = run_physc("compile", EXAMPLES / "paper" / "05_F.phys", "--world", "rollin")
    assert run.status == 2 and "did you mean 'rolling'" in run.stderr
    run = run_physc("compile", "plugins/physc-phyre/examples/01_ledge.phys", "--world", "rolling", "--emit", "layout")
    assert run.status == 2 and "the domain 'phyre' has no world 'rolling'" in run.stderr
    level, task = tmp_path / "f.xml", tmp_path / "f.json"
    run = run_physc("compile", EXAMPLES / "paper" / "05_F.phys", "--world", "rolling", "--seed", "1", "-q", "-o", level, "--task", task)
    assert run.status == 0, run.stderr
    made = json.loads(task.read_text())
    assert (made["world"], made["backend"]) == ("rolling", "box2d")
    # Replayed in the task's world unless told otherwise, and said so when told.
    run = run_physc("verify", level, "--task", task, "--replays", "0", "--format", "json")
    assert run.status == 0 and json.loads(run.stdout)["world"] == "rolling" and "note" not in run.stderr
    shot = f"--angle={made['solution']['release_angle']}"
    run = run_physc("simulate", level, "--task", task, shot)
    assert run.status == 0 and "world rolling" in run.stdout and "note" not in run.stderr
    run = run_physc("simulate", level, "--task", task, "--world", "phyq", shot)
    assert "world phyq" in run.stdout
    assert "note: the task was made in the world 'rolling'; replaying it in 'phyq' (--world)" in run.stderr
