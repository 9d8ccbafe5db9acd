"""The core a second domain is written on: compound bodies in both engines, the touch
goal recognised, PHYRE's AUCCESS, the generic goal check (E0404), and the liesOnPath
placing of a stage's new objects by the one search."""

from __future__ import annotations

import attrs
import pytest

from physc.backends import BodySpec, Circle, Compound, Polygon, load_backend
from physc.backends.settings import EngineSettings
from physc.compiler.concrete_layout import ChosenRelation, ConcreteLayout, PlacedObject
from physc.compiler.dimension_graphs import LayoutParameters
from physc.simulation.fidelity import Fidelity
from physc.simulation.recognise import Recogniser
from physc.simulation.run import RunRules
from physc.simulation.scene import Scene, play_scene


def rectangle(cx, cy, w, h):
    return Polygon(((cx - w / 2, cy - h / 2), (cx + w / 2, cy - h / 2), (cx + w / 2, cy + h / 2), (cx - w / 2, cy + h / 2)))


CUP = Compound((rectangle(0, 0, 3, 0.3), rectangle(-1.35, 1, 0.3, 2), rectangle(1.35, 1, 0.3, 2)))
FLOOR = BodySpec("floor", rectangle(0, 0, 40, 1), 0, -0.65, static=True)


@pytest.mark.parametrize("backend", ["pymunk", "bullet"])
def test_a_compound_body_holds_a_ball_and_touches_it_once(backend):
    world = load_backend(backend).create_world(9.8)
    world.add(FLOOR)
    world.add(BodySpec("cup", CUP, 0, 0, density=0.25))
    world.add(BodySpec("ball", Circle(0.5), 0.3, 4, density=0.25))
    begun = []
    for _ in range(300):
        world.step(1 / 60)
        begun += [frozenset((e.a, e.b)) for e in world.begun()]
    x, y = world.state("ball")[:2]
    assert abs(x) < 1.2 and 0.3 < y < 1.0  # inside the cup, on its base
    assert world.touching("ball") == {"cup"}
    # The mass is the parts' (0.25 × area, with each engine's polygon skin).
    assert world.mass("cup") == pytest.approx(0.25 * (3 * 0.3 + 2 * 0.3 * 2), rel=0.1)
    if backend == "pymunk":  # one contact began, though the ball touched two of the cup's parts
        assert begun.count(frozenset(("ball", "cup"))) == 1


def test_bullet_wraps_a_compound_of_other_polygons_in_its_hull():
    # pybullet's compounds take no meshes: a compound with a part that is not a circle or a
    # rectangle (a game collider split into convex parts) collides as the hull of its parts.
    world = load_backend("bullet").create_world(9.8)
    world.add(BodySpec("floor", rectangle(0, -0.5, 10, 1), 0, 0, static=True))
    triangle = Polygon(((0, 0), (1, 0), (0, 1)))
    world.add(BodySpec("odd", Compound((triangle, rectangle(0.5, -0.5, 1, 1))), 0, 1.02))
    for _ in range(60):
        world.step(1 / 60)
    assert world.state("odd")[1] == pytest.approx(1.02, abs=0.03)  # resting on its hull's foot


class Held(RunRules):
    """Ends the run once the goal bodies have touched for 1 s."""

    def __init__(self, goal=("ball", "shelf")):
        self.goal = goal
        self.held, self.met = 0, False

    def on_start(self, world):
        self.world = world

    def finished(self, values, alive, time):
        self.held = self.held + 1 if self.goal[1] in self.world.touching(self.goal[0]) else 0
        self.met = self.held >= 60
        return self.met

    def solved(self, recording):
        return self.met


RECOGNISER = Recogniser(
    hit_speed=0.5, rehit=0.1, moving=0.3, roll_slip=0.3, slide_spin=0.3, motion_time=0.2, fall_time=0.2, fall_height=0.5,
    bounce_time=0.2, bounce_speed=1.0, surfaces=("surface",), touch_time=1.0,
)


def test_touch_is_recognised_for_the_goal_bodies_once_held():
    shelf = BodySpec("shelf", rectangle(0, 0, 6, 0.5), 0, 0, static=True, friction=0.9)
    ball = BodySpec("ball", Circle(0.5), 0, 3, density=0.25, friction=0.9)
    scene = Scene((shelf, ball), {"shelf": "surface", "ball": "object"}, 9.8, EngineSettings(dt=1 / 60, velocity_iterations=15, position_iterations=20), {"ball": 0.5}, goal=("ball", "shelf"))
    trace = play_scene(scene, load_backend(), Held(), 10.0, RECOGNISER)
    assert trace.solved and trace.duration < 3.0  # ended by the goal, not by the time
    assert [i.text() for i in trace.interactions][-1] == "touch(ball, shelf)"
    fell = play_scene(attrs.evolve(scene, goal=("ball", "nothing")), load_backend(), Held(("ball", "nothing")), 2.0, RECOGNISER)
    assert not fell.solved and "touch" not in fell.sequence()


def test_the_goal_check_speaks_the_domains_words(tmp_path):
    from conftest import run_physc

    path = tmp_path / "s.phys"
    path.write_text("scenario P {\n    domain phyre\n    interactions { hit(red, green, above) > fall(green, target) }\n}\n")
    run = run_physc("check", "--color", "never", path)
    assert run.status == 1
    assert "error[E0404]: the greenObject 'green' never touches its target (a task is solved when the green object touches the target for 3 s)" in run.stderr
    assert "help: add `> touch(green, target)` at the end of the interactions" in run.stderr


def _placed(name, x, y, w, h, role="object", concrete="thing"):
    return PlacedObject(name, role, concrete, None, x, y, 0.0, w, h)


def test_the_next_target_goes_with_its_support_onto_the_actors_path():
    """A ball (the actor, rObj) falls at x = 2; the target resting on its ledge at x = 8 is moved,
    ledge and all, so that its top is under the path; the actor's own ledge does not move."""
    import numpy as np

    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze_text
    from physc.simulation.trace import Trace

    scenario = analyze_text("s.phys", "scenario P { domain phyre interactions { hit(red, rObj, above) > hit(rObj, green, above) > touch(green, target) } }", INSTALLED).scenarios[0]
    objects = (
        _placed("rObj", 2, 5.5, 1, 1), _placed("ledge", 2, 4.9, 3, 0.2, "support"),
        _placed("green", 8, 2.5, 1, 1), _placed("support_green", 8, 1.9, 3, 0.2, "support"),
    )
    conjunction = (
        ChosenRelation("MeetN", "rObj", "ledge", "onLocation(rObj, ledge)"),
        ChosenRelation("MeetN", "green", "support_green", "onLocation(green, support_green)"),
    )
    layout = ConcreteLayout("P", "phyre", 1, objects, conjunction, (), (), 1, 0, 0)
    steps = 120
    states = np.zeros((steps, 1, 6))
    states[:, 0, 0] = 2.0
    states[:, 0, 1] = np.linspace(5.5, 1.0, steps)
    trace = Trace(1 / 60, ("rObj",), {"rObj": "object"}, states)
    fidelity = Fidelity(1, 3, (), False, (0.1,))
    from physc_phyre import PhyreSearch

    from physc.domains import load_domain
    from physc.domains.part import part
    from physc.search.attempt import Attempt
    from physc.search.placing import consistent
    from physc.search.problem import Problem
    from physc.search.variants import on_path

    class UnscaledSearch(PhyreSearch):
        trace_scale = 1.0

    class Unscaled(type(load_domain("phyre"))):
        layout_parameters = LayoutParameters(clearance=0.05, far=1.0, left=0, right=12, bottom=0, top=10)
        search = part(UnscaledSearch)

    search = Problem.of(Unscaled(), scenario, layout, 0)
    stage = search.plan[1]
    assert stage.start == 1 and set(stage.new) == {"green", "support_green"}
    proposals = list(on_path(search, layout, scenario.interactions[1], stage, Attempt("", None, trace, fidelity)))
    assert proposals
    description, moved = proposals[0]
    assert description.startswith("hit(rObj, green, above): green on its path")
    after = {o.name: o for o in moved.objects}
    assert after["green"].x == pytest.approx(2.0) and after["support_green"].x == pytest.approx(2.0)
    assert after["green"].y - after["support_green"].y == pytest.approx(0.6)  # still resting on it
    assert after["rObj"] == objects[0] and after["ledge"] == objects[1]  # the prefix never moves
    assert all(consistent(m, search.parameters, {"green", "support_green"}) for _, m in proposals)


def test_the_backend_handed_over_plays_a_scene():
    shelf = BodySpec("shelf", rectangle(0, 0, 6, 0.5), 0, 0, static=True)
    ball = BodySpec("ball", Circle(0.5), 0, 3, density=0.25)
    scene = Scene((shelf, ball), {"shelf": "surface", "ball": "object"}, 9.8, EngineSettings(dt=1 / 60, velocity_iterations=15, position_iterations=20), {"ball": 0.5})
    trace = play_scene(scene, load_backend("bullet"), RunRules(), 1.5, RECOGNISER)
    assert trace.states[-1, 0, 1] == pytest.approx(0.75, abs=0.05)  # came to rest on the shelf
