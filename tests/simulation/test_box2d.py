"""The Box2D backend: the target worlds' engine, run with the domain's settings natively; its
contacts from Box2D's own events; concave and many-cornered bodies split into convex parts."""

from __future__ import annotations

import math

import attrs
import Box2D
import numpy as np
import pytest

from physc.backends import BackendError, BodySpec, Circle, Compound, Polygon, installed_backends, load_backend
from physc.backends.convex import convex_parts, hull, is_convex, signed_area
from physc.backends.settings import EngineSettings
from physc.domains.angrybirds.worlds import PHYQ, SCIENCE_BIRDS_ENGINE

BOX2D = load_backend("box2d")
FLOOR = Polygon(((-5, -0.5), (5, -0.5), (5, 0.5), (-5, 0.5)))
BOX = Polygon(((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)))


def world(settings: EngineSettings = SCIENCE_BIRDS_ENGINE, gravity: float = PHYQ.gravity):
    made = BOX2D.create_world(gravity, settings)
    made.add(BodySpec("floor", FLOOR, 0.0, -0.5, static=True))
    return made


def drop(height: float, bounciness: float) -> float:
    """The highest the box climbs again after falling `height` onto the floor."""
    w = world()
    w.add(BodySpec("box", BOX, 0.0, 0.2 + 0.01 + height, bounciness=bounciness))
    landed, peak = False, 0.0
    for _ in range(200):
        w.step(PHYQ.engine.dt)
        y, vy = w.state("box")[1], w.state("box")[4]
        landed = landed or bool(w.touching("box"))
        if landed and vy > 0:
            peak = max(peak, y - 0.21)
    return peak


def test_box2d_is_an_installed_backend_and_the_default():
    from physc.backends import DEFAULT_BACKEND

    assert "box2d" in installed_backends() and DEFAULT_BACKEND == "box2d"
    assert BOX2D.package == "box2d" and set(BOX2D.honours) == set(attrs.fields_dict(EngineSettings))


def test_the_science_birds_settings_are_box2ds_compiled_constants_and_others_are_refused():
    world()  # every compiled-in constant is the game's
    with pytest.raises(BackendError, match="b2_velocityThreshold"):
        BOX2D.create_world(1.0, attrs.evolve(SCIENCE_BIRDS_ENGINE, restitution_threshold=0.5))
    with pytest.raises(BackendError, match="b2_timeToSleep"):
        BOX2D.create_world(1.0, attrs.evolve(SCIENCE_BIRDS_ENGINE, time_to_sleep=1.0))


def test_nothing_bounces_below_the_restitution_threshold():
    # A fall of h lands at √(2gh): 0.05 units land at 0.69 units/s (no bounce), 1 unit at 3.1.
    assert drop(0.05, 0.5) < 0.01
    assert drop(1.0, 0.5) > 0.1


def test_the_iterations_are_the_settings_own(monkeypatch):
    calls = []
    w = world(attrs.evolve(SCIENCE_BIRDS_ENGINE, velocity_iterations=7, position_iterations=5))
    original = w.world.Step
    monkeypatch.setattr(w, "world", type("Spy", (), {"Step": lambda self, dt, v, p: calls.append((dt, v, p)) or original(dt, v, p)})())
    w.step(0.02)
    assert calls == [(0.02, 7, 5)]


def test_contacts_begin_with_the_speed_before_the_impact_and_end_when_a_body_goes():
    w = world()
    w.add(BodySpec("box", BOX, 0.0, 1.21, bounciness=0.5))
    begun = []
    for step in range(100):
        w.step(PHYQ.engine.dt)
        begun += [(step, e) for e in w.begun()]
    first = begun[0][1]
    assert {first.a, first.b} == {"box", "floor"}
    assert abs(first.relative_velocity[1]) == pytest.approx(math.sqrt(2 * PHYQ.gravity * 1.0), rel=0.05)
    w.ended()
    assert "floor" in w.touching("box")
    w.remove("box")
    assert {frozenset(p) for p in w.ended()} == {frozenset(("box", "floor"))}
    assert w.touching("floor") == set()


@pytest.mark.parametrize("backend", ["box2d", "pymunk"])
def test_each_pair_of_colliders_begins_a_contact_and_the_bodies_first_is_first(backend):
    """A body of two colliders (Compound.colliders) landing flat on both: one event per pair
    of colliders, the first of them marked first (Unity calls OnCollisionEnter2D for each);
    two parts of one collider make one."""
    left = Polygon(((-0.4, -0.2), (0.0, -0.2), (0.0, 0.2), (-0.4, 0.2)))
    right = Polygon(((0.0, -0.2), (0.4, -0.2), (0.4, 0.2), (0.0, 0.2)))
    firsts = {}
    for colliders in ((0, 1), (0, 0)):
        w = load_backend(backend).create_world(PHYQ.gravity, SCIENCE_BIRDS_ENGINE)
        w.add(BodySpec("floor", FLOOR, 0.0, -0.5, static=True))
        w.add(BodySpec("slab", Compound((left, right), colliders), 0.0, 0.5))
        events = []
        for _ in range(60):
            w.step(PHYQ.engine.dt)
            events += w.begun()
        assert all({e.a, e.b} == {"slab", "floor"} for e in events)
        firsts[colliders] = [e.first for e in events]
    assert firsts[(0, 1)] == [True, False]
    assert firsts[(0, 0)] == [True]


@pytest.mark.parametrize("backend", ["box2d", "pymunk"])
def test_a_collider_taken_out_ends_its_contacts_and_its_mass(backend):
    left = Polygon(((-0.4, -0.2), (0.0, -0.2), (0.0, 0.2), (-0.4, 0.2)))
    right = Polygon(((0.0, -0.2), (0.4, -0.2), (0.4, 0.2), (0.0, 0.2)))
    w = load_backend(backend).create_world(PHYQ.gravity, SCIENCE_BIRDS_ENGINE)
    w.add(BodySpec("floor", FLOOR, 0.0, -0.5, static=True))
    w.add(BodySpec("slab", Compound((left, right), (0, 1)), 0.0, 0.21, density=1.0))
    for _ in range(20):
        w.step(PHYQ.engine.dt)
    w.begun(), w.ended()
    whole = w.mass("slab")
    w.disable_collider("slab", 0)
    assert w.mass("slab") == pytest.approx(whole / 2, rel=0.02) and "floor" in w.touching("slab")  # its other collider still rests
    w.disable_collider("slab", 1)
    for _ in range(2):
        w.step(PHYQ.engine.dt)
    assert {frozenset(p) for p in w.ended()} == {frozenset(("slab", "floor"))}


def test_the_same_bodies_and_steps_give_the_same_run_byte_for_byte():
    def run():
        w = world()
        for k in range(6):
            w.add(BodySpec(f"b{k}", BOX, 0.3 * k - 0.8, 0.21 + 0.45 * k, angle=0.1 * k, friction=0.6))
        rows = [w.states([f"b{k}" for k in range(6)]).copy() for _ in range(150) if w.step(PHYQ.engine.dt) is None]
        return np.array(rows)

    assert run().tobytes() == run().tobytes()


def test_a_sleeping_bodys_row_is_its_last_and_a_velocity_wakes_it():
    w = world()
    w.add(BodySpec("box", BOX, 0.0, 0.21))
    for _ in range(60):
        w.step(PHYQ.engine.dt)
    assert not w.bodies["box"].awake
    assert tuple(w.states(["box", "gone"])[0]) == w.state("box")
    assert np.isnan(w.states(["box", "gone"])[1]).all()
    w.set_velocity("box", 1.0, 0.0)
    w.step(PHYQ.engine.dt)
    assert w.states(["box"])[0][3] > 0.5


def test_a_concave_polygon_with_a_hole_collides_as_its_convex_parts_and_weighs_its_area():
    outline = ((-1, -1), (1, -1), (1, 1), (0, 0.2), (-1, 1))  # a notch at the top
    hole = ((-0.3, -0.6), (0.3, -0.6), (0.3, -0.3), (-0.3, -0.3))
    parts = convex_parts(outline, [hole])
    assert all(is_convex(p) and len(p) <= 8 and signed_area(p) > 0 for p in parts)
    assert sum(signed_area(p) for p in parts) == pytest.approx(signed_area(outline) - 0.18)
    w = world()
    w.add(BodySpec("notched", Compound(tuple(Polygon(p) for p in parts)), 0.0, 1.02, density=2.0))
    assert w.mass("notched") == pytest.approx(2.0 * (signed_area(outline) - 0.18))
    w.add(BodySpec("pellet", Circle(0.1), 0.0, 3.0))
    for _ in range(150):
        w.step(PHYQ.engine.dt)
    assert w.state("pellet")[1] < 1.02 + 0.2 + 0.1 + 0.05  # it fell into the notch, below its rim



def test_a_polygon_of_more_corners_than_unitys_eight_is_split_and_a_hull_wraps_points():
    gon = [(math.cos(2 * math.pi * k / 24), math.sin(2 * math.pi * k / 24)) for k in range(24)]
    parts = convex_parts(gon)
    assert len(parts) > 1 and all(len(p) <= 8 for p in parts)
    assert sum(signed_area(p) for p in parts) == pytest.approx(signed_area(gon))
    wrapped = hull(gon + [(0.0, 0.0), (0.5, 0.1)])
    assert len(wrapped) == 24 and signed_area(wrapped) == pytest.approx(signed_area(gon))


def test_a_continuous_body_does_not_pass_through_a_thin_moving_one():
    def passes(continuous: bool) -> bool:
        w = BOX2D.create_world(0.0, SCIENCE_BIRDS_ENGINE)
        w.add(BodySpec("wall", Polygon(((-0.02, -1), (0.02, -1), (0.02, 1), (-0.02, 1))), 0.0, 0.0))
        w.add(BodySpec("shot", Circle(0.05), -1.0, 0.0, continuous=continuous))
        w.set_velocity("shot", 90.0, 0.0)
        w.set_velocity("wall", -0.01, 0.0)  # a dynamic body, awake
        for _ in range(5):
            w.step(PHYQ.engine.dt)
        return w.state("shot")[0] > w.state("wall")[0]  # it went through, not along with the wall

    assert passes(False) and not passes(True)


def test_pybox2d_is_box2d_2_3():
    assert Box2D.__version__.startswith("2.3")


def test_physc_backends_lists_the_engines_their_versions_and_what_each_honours():
    import json

    from conftest import run_physc

    run = run_physc("backends")
    assert run.status == 0
    lines = run.stdout.splitlines()
    assert lines[0].startswith("box2d (default): box2d 2.3.10: ") and any(line.startswith("pymunk: pymunk ") for line in lines)
    verbose = run_physc("backends", "pymunk", "-v").stdout
    assert "restitution_threshold" in verbose and "emulated" in verbose and "not honoured" in verbose
    data = json.loads(run_physc("backends", "--json").stdout)
    assert [d["name"] for d in data] == ["box2d", "bullet", "pymunk"] and all(d["installed"] and d["version"] for d in data)
    assert data[0]["honours"]["velocity_iterations"].startswith("native")
    wrong = run_physc("backends", "box2e")
    assert wrong.status == 2 and "did you mean 'box2d'?" in wrong.stderr
