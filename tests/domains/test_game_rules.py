"""Science Birds' rules and bodies as the game's own files give them (docs/angrybirds.md,
"The game's engine and rules, from its own files"): each departure physc had is fixed here
or kept as a named parameter, and each has a test."""

from __future__ import annotations

import math

import attrs
import numpy as np
import pytest

from physc.backends import Compound, Polygon, load_backend
from physc.backends.convex import signed_area
from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.catalogue import MATERIAL
from physc.domains.angrybirds.game import BIRD, GROUND, Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.rules import Rules
from physc.domains.angrybirds.worlds import PHYQ, SCIENCE_BIRDS_ENGINE

BOX2D = load_backend("box2d")

GROUND_TOP = PHYQ.frame.ground_top
RULES, MODEL = PHYQ.rules, PHYQ.bodies
from physc.simulation.trace import ContactRecord

PIG = LevelObject("Pig", "BasicSmall", 0.0, GROUND_TOP + 0.236, 0.0, name="pig")


def test_the_engine_settings_are_unitys_physics2d_and_time_settings():
    e = SCIENCE_BIRDS_ENGINE
    assert (e.dt, e.velocity_iterations, e.position_iterations) == (0.02, 100, 100)
    assert (e.restitution_threshold, e.contact_offset, e.time_to_sleep, e.linear_sleep_tolerance) == (1.0, 0.01, 0.5, 0.01)
    assert e.angular_sleep_tolerance == pytest.approx(math.radians(2)) and e.max_translation == pytest.approx(2.0)
    assert PHYQ.engine is e and PHYQ.engine.dt == 0.02


def test_masses_follow_the_first_collider_rule_and_equal_the_saved_auto_masses():
    saved = {name: p["rigidbody"]["mass"] for name, p in prefabs.prefabs().items()}
    for name in ("Circle", "CircleSmall", "SquareHole", "TriangleHole", "BasicMedium", "BasicBig"):
        assert prefabs.body_mass(name, 1.0) == pytest.approx(saved[name], rel=1e-5), name  # Unity's own, at density 1
    # The density lands on the disabled circle: a Circle weighs the same in any material,
    # a pig its polygon's area (not twice it).
    assert prefabs.body_mass("Circle", MATERIAL["stone"].density) == prefabs.body_mass("Circle", MATERIAL["wood"].density)
    assert prefabs.body_mass("BasicSmall", MODEL.pig_density) == pytest.approx(0.1508, abs=1e-4)
    # SquareHole: its box takes the material's density, its holed polygon keeps 1.
    box = 0.7636**2
    assert prefabs.body_mass("SquareHole", 1.5) == pytest.approx(box * 1.5 + (saved["SquareHole"] - box), rel=1e-5)
    game = Game(Level(objects=(LevelObject("Block", "Circle", 0.0, 0.0, 0.0, "stone", name="c"), PIG)), PHYQ, BOX2D)
    world = game.build()
    assert world.mass("c") == pytest.approx(0.4277, abs=1e-3) and world.mass("pig") == pytest.approx(0.1508, abs=1e-3)


def test_the_games_colliders_are_its_polygons_with_holes_and_flat_feet():
    circle = prefabs.body_shape("Circle")
    assert isinstance(circle, Compound) and all(isinstance(p, Polygon) and len(p.points) <= 8 for p in circle.parts)
    lowest = min(y for p in circle.parts for _, y in p.points)
    assert lowest == pytest.approx(-0.375)  # the flat foot
    hole = prefabs.body_shape("TriangleHole")
    assert sum(signed_area(p.points) for p in hole.parts) == pytest.approx(prefabs.prefabs()["TriangleHole"]["rigidbody"]["mass"], rel=1e-5)
    assert len(prefabs.enabled("SquareHole")) == 2


def test_a_pig_struck_by_the_bird_takes_the_half_formula_and_a_block_the_full_one():
    block = LevelObject("Block", "SquareSmall", 3.0, GROUND_TOP + 0.2, 0.0, "wood", name="block")
    game = Game(Level(objects=(PIG, block)), PHYQ, BOX2D)
    world = game.build()
    game.launch(world, Shot(angle=10.0))
    game.kinds[BIRD] = "bird"
    bird_mass = world.mass(BIRD)
    for target, share, defence in (("pig", 0.5, 1.0), ("block", 1.0, 2.5)):
        contact = ContactRecord(3.0, BIRD, target, (0, 0), (1, 0), (8.0, 0.0), (8.0, 0.0), (0.0, 0.0))
        out = []
        game.life[target] = 1000.0
        game._damage(world, contact, out, 3.0)
        (record,) = out
        assert record.amount == pytest.approx(8.0 * bird_mass * 11.22 * share - defence)
        # The strike that would have destroyed it: its life and defence over the damage per unit of speed.
        assert record.attacker == BIRD
        assert record.needed == pytest.approx((1000.0 + defence) / (bird_mass * 11.22 * share))


def test_a_squarehole_hears_of_a_strike_once_per_collider():
    """SquareHole has two enabled colliders (a box and a holed polygon): Unity calls its
    OnCollisionEnter2D for each pair of colliders that begins touching, so a bird's strike on
    both deals the damage twice (and a blast reaches each: Physics2D.OverlapCircleAll)."""
    platform = LevelObject("Platform", "Platform", 2.0, -1.0, 0.0, scale_x=10 / 0.64, scale_y=0.5, name="platform")
    block = LevelObject("Block", "SquareHole", -1.5, -1.0 + 0.16 + 0.3918 + 0.01, 0.0, "ice", name="block")
    trace = Game(Level(objects=(platform, block)), PHYQ, BOX2D).play(Shot(target=(-1.9, -0.45)), 6.0)
    strikes = [d for d in trace.damage if d.target == "block" and d.by == BIRD]
    assert len(strikes) == 2 and strikes[0].time == strikes[1].time and strikes[0].amount == pytest.approx(strikes[1].amount)
    assert [d.name for d in trace.destructions] == ["block"]  # 2 × 54 of the ice's 70: once would leave it standing
    tnt = LevelObject("TNT", "TNT", 0.0, GROUND_TOP + 0.33, 0.0, name="tnt")
    holed = LevelObject("Block", "SquareHole", 1.0, GROUND_TOP + 0.42, 0.0, "stone", name="holed")
    game = Game(Level(objects=(tnt, holed)), PHYQ, BOX2D)
    world = game.build()
    damage = []
    game._explode(world, "tnt", {"tnt", "holed"}, damage, 3.0)
    distance = math.dist(world.state("holed")[:2], world.state("tnt")[:2])
    assert [d.amount for d in damage] == [pytest.approx(2 * 100 * (1 - distance / 2.5), rel=1e-3)]


def test_a_dying_object_stops_loses_its_first_collider_and_stays_its_lifetime():
    """ABGameObject.Die: velocity zeroed, GetComponent<Collider2D>() (the first collider,
    enabled or not) disabled, Destroy after the prefab's `_systemLifetime`. A pig's first
    collider is its disabled circle, so its polygon stays solid; a SquareHole keeps its holed
    polygon; a block of one collider has nothing left and goes at once."""
    assert (prefabs.lifetime("BasicSmall"), prefabs.lifetime("SquareHole"), prefabs.lifetime("RectFat")) == (0.2, 0.5, 0.5)
    holed = LevelObject("Block", "SquareHole", 2.0, GROUND_TOP + 0.42, 0.0, "wood", name="holed")
    fat = LevelObject("Block", "RectFat", 4.0, GROUND_TOP + 0.2, 0.0, "wood", name="fat")
    game = Game(Level(objects=(PIG, holed, fat)), PHYQ, BOX2D)
    world = game.build()
    world.set_velocity("pig", 1.0, 2.0, 0.5)
    mass = world.mass("holed")
    assert game.lingers(world, "pig", "damage") == pytest.approx(0.2)
    assert world.state("pig")[3:] == pytest.approx((0.0, 0.0, 0.5))
    assert game.lingers(world, "holed", "damage") == pytest.approx(0.5)
    assert world.mass("holed") < mass  # its box is gone, its holed polygon stays
    assert game.lingers(world, "fat", "damage") == 0.0
    # Every contact a dying object begins stops it again (OnCollisionEnter2D → DealDamage → Die).
    world.set_velocity("pig", 0.0, -3.0, 0.0)
    game._invulnerable = 10.0  # (the run's state, which `scene` sets)
    game.on_contact(world, ContactRecord(1.0, "pig", GROUND, (0, 0), (0, -1), (0.0, -3.0), (0.0, -3.0), (0.0, 0.0)), [], 1.0)
    assert world.state("pig")[3:5] == pytest.approx((0.0, 0.0))
    # In a run: the pig the bird kills leaves the level at once and the world 0.2 s later.
    trace = Game(Level(objects=(PIG,)), PHYQ, BOX2D).play(Shot(target=(0.0, GROUND_TOP + 0.25)), 6.0)
    (killed,) = [d for d in trace.destructions if d.name == "pig"]
    assert killed.until == pytest.approx(killed.time + 0.2)
    assert np.isnan(trace.states[int(round(killed.time / trace.dt)) - 1 :, trace.index("pig"), 0]).all()
    assert attrs.evolve(RULES, dying_lingers=False).dying_lingers is False


def test_tnt_falls_off_with_distance_and_spares_birds():
    tnt = LevelObject("TNT", "TNT", 0.0, GROUND_TOP + 0.33, 0.0, name="tnt")
    near = LevelObject("Block", "SquareSmall", 1.0, GROUND_TOP + 0.2, 0.0, "stone", name="near")
    far = LevelObject("Block", "SquareSmall", 2.0, GROUND_TOP + 0.2, 0.0, "stone", name="far")
    game = Game(Level(objects=(tnt, near, far)), PHYQ, BOX2D)
    world = game.build()
    game.launch(world, Shot(angle=80.0))
    game.kinds[BIRD] = "bird"
    damage = []
    game._explode(world, "tnt", {"tnt", "near", "far", BIRD}, damage, 3.0)
    by = {d.target: d.amount for d in damage}
    distance = math.dist(world.state("near")[:2], world.state("tnt")[:2])
    assert by["near"] == pytest.approx(100 * (1 - distance / 2.5), rel=1e-3)
    assert by["far"] < by["near"] and BIRD not in by
    assert world.state(BIRD)[3:5] == pytest.approx((10 * math.cos(math.radians(80)), 10 * math.sin(math.radians(80))), abs=1e-5)
    # TNT's own body: no material (0.4), angular drag 0.05, 0.64² × 1.
    assert (MODEL.tnt_friction, MODEL.tnt_angular_drag) == (0.4, 0.05)
    assert world.mass("tnt") == pytest.approx(0.64**2)


def test_the_bird_is_checked_three_seconds_after_its_first_collision_then_every_second():
    # A bird shot down into the ground by the slingshot comes to rest there.
    trace = Game(Level(objects=()), PHYQ, BOX2D).simulate(Shot(angle=-45.0), 20.0, stop_at_rest=False)
    first = min(c.time for c in trace.contacts if BIRD in (c.a, c.b))
    (gone,) = [d for d in trace.destructions if d.name == BIRD]
    after = gone.time - first
    assert gone.cause == "removed" and after >= 3.0 - 1e-9
    assert abs((after - 3.0) - round(after - 3.0)) < 0.021  # at a whole second's check
    still = Game(Level(objects=()), attrs.evolve(PHYQ, rules=Rules(bird_lifetime=2.0)), BOX2D).simulate(Shot(angle=45.0), 5.0, stop_at_rest=False)
    assert [d.time for d in still.destructions if d.name == BIRD] == [pytest.approx(2.0)]


def test_birds_and_pigs_collide_continuously_and_blocks_do_not():
    game = Game(Level(objects=(PIG, LevelObject("Block", "SquareSmall", 3.0, GROUND_TOP + 0.2, 0.0, "wood", name="block"))), PHYQ, load_backend("box2d"))
    world = game.build()
    game.launch(world, Shot(angle=20.0))
    assert world.bodies[BIRD].bullet and world.bodies["pig"].bullet and not world.bodies["block"].bullet
