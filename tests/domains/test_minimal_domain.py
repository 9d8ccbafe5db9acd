"""A minimal domain that is not Angry Birds, defined here, compiled end to end.

"minimal": a ball on flat ground is pushed (the player's only action), hits a box, and
the box must touch a static goal pad; the goal is met when a box touches every pad. The
domain implements every generation capability (layout rules and parameters, concretize,
emit_level, picture as SVG) with the least code that is honest, and is a SimulatedDomain:
it writes the hooks of physc's one generation search (its level, its play, its candidate
pushes) and nothing of the search itself, which places the pad where the box's simulated
path takes it. It runs on the backend's world and the generic run loop, the generic
recogniser and sequence fidelity.

The tests check that the public pipeline and the command line make a real task of it:
its solution realises the declared sequence in a fresh simulation, the level stands,
the same seed gives the same bytes and another seed another layout.
"""

from __future__ import annotations

import json
import math
from importlib.metadata import EntryPoint

import attrs
from conftest import run_physc

from physc import domains
from physc.backends import BodySpec, Circle, Polygon, load_backend
from physc.backends.settings import EngineSettings
from physc.compiler.concrete_layout import Body
from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.geometry import Geometry
from physc.compiler.layout_graph import IN_DIRECTION, PLAYER, LayoutEdge, LayoutGraph, LayoutNode, Provenance
from physc.compiler.layout_graph import OBJECT as OBJECT_NODE
from physc.compiler.layout_rules import LayoutRules
from physc.diagnostics import SourceText
from physc.domains.actions import Actions
from physc.domains.base import MissingCapability, missing
from physc.domains.level_files import LevelFiles
from physc.domains.part import part
from physc.domains.simulated import SimulatedDomain
from physc.domains.vocabulary import (
    DIRECTION,
    INTERACTION,
    OBJECT,
    ConcreteObject,
    ObjectTerm,
    Parameter,
    TermSignature,
    Vocabulary,
)
from physc.driver.pipeline import Pipeline
from physc.driver.stages import NEEDS
from physc.dsl.check import check_file
from physc.dsl.parser import parse_source
from physc.dsl.vocabularies import Vocabularies
from physc.simulation.ending import Ending
from physc.simulation.fidelity import fidelity
from physc.simulation.recognise import Recogniser, approach, side
from physc.simulation.restrictions import violations
from physc.simulation.run import RunRules, run
from physc.simulation.stability import stable
from physc.simulation.trace import Interaction, Trace
from physc.worlds import Incline, World

# ---- the domain ---------------------------------------------------------------------------
SIDES = ("left", "right", "above", "below")
HEIGHT = 0.5  # every object is this tall; the placement area is one object high: all stand on the ground
GRAVITY, DT, SECONDS = 9.8, 0.02, 4.0
FRICTION = 0.3
SPEEDS = (4.0, 6.0, 8.0)  # units/s: the pushes the player may give the ball, towards the first hit's target
STILL = 0.02  # below this (units/s, rad/s) a body is at rest
# A level stands when, left alone, nothing moves further than this (the backend keeps polygons
# a skin of 0.01 apart: a box placed flush on the ground rises by about 0.013)
STANDS = 0.05
RECOGNISER = Recogniser(
    hit_speed=0.3, rehit=0.1, moving=0.15, roll_slip=0.3, slide_spin=0.3, motion_time=0.2, fall_time=0.2,
    fall_height=0.4, bounce_time=0.2, bounce_speed=1.0, surfaces=("ground", "pad"), background=("ground",), thrown=("ball",),
)

# The one world this domain simulates (physc.worlds): Box2D's own engine settings, at this step.
WORLD = World(
    name="flat", description="flat ground, gravity 9.8", engine=EngineSettings(dt=DT), gravity=GRAVITY, recogniser=RECOGNISER,
    incline=Incline(descending=(0.0, 0.0), other=(0.0, 0.0)),
)

VOCABULARY = Vocabulary(
    object_terms=(
        ObjectTerm("ball", ("ball",), noun="the player's ball"),
        ObjectTerm("box", ("box",), noun="a box"),
        ObjectTerm("goal", ("pad",), noun="a goal pad"),
        # Vocabulary.goal must name an object term, and every object of it must be destroyed
        # (E0404): this domain's goal is a touch, so it names a term that nothing can be.
        ObjectTerm("nothing", (), noun="nothing: this domain destroys nothing"),
    ),
    concrete_objects=(ConcreteObject("ball"), ConcreteObject("box"), ConcreteObject("pad", static=True)),
    terms=(
        TermSignature(
            "hit",
            INTERACTION,
            (Parameter("a", OBJECT, dynamic=True, acts=True), Parameter("b", OBJECT, moves=True), Parameter("d", DIRECTION, directions=SIDES)),
            "a collides with b on b's side d",
        ),
        TermSignature(
            "touch",
            INTERACTION,
            (
                Parameter("a", OBJECT, dynamic=True, acts=True),
                Parameter("b", OBJECT, fits="goal"),
                # Optional, but a direction it must have: fidelity matches a term without one
                # only if it is called destroy or fall.
                Parameter("d", DIRECTION, directions=SIDES, default=SIDES),
            ),
            "a comes to touch the goal pad b on its side d",
        ),
    ),
    direction_aliases={"any": SIDES},
    player="ball",
    goal="nothing",
)


@attrs.frozen
class Thing:
    name: str
    kind: str  # ball | box | pad
    x: float  # centre
    y: float
    width: float
    height: float

    def box(self, x: float | None = None, y: float | None = None) -> tuple[float, float, float, float]:
        """(left, right, bottom, top), centred at (x, y) if given."""
        x, y = self.x if x is None else x, self.y if y is None else y
        return x - self.width / 2, x + self.width / 2, y - self.height / 2, y + self.height / 2


@attrs.frozen
class Level:
    things: tuple[Thing, ...]

    def thing(self, name: str) -> Thing:
        return next(t for t in self.things if t.name == name)

    def moved(self, name: str, x: float) -> Level:
        return Level(tuple(attrs.evolve(t, x=round(float(x), 6)) if t.name == name else t for t in self.things))


@attrs.frozen
class PushLayout(LayoutRules):
    """`hit(a, b, d)` and `touch(a, b, d)`: a starts on side d of b (inDirection(a, b, d))."""

    player: str = "ball"
    flat: str = "pad"

    def infer(self, scenario, structure: str = "flat") -> LayoutGraph:
        nodes = tuple(
            LayoutNode(o.name, o.term, o.concrete, o.static, PLAYER if o.term == VOCABULARY.player else OBJECT_NODE)
            for o in scenario.objects
        )
        edges = tuple(
            LayoutEdge(IN_DIRECTION, t.objects[0], t.objects[1], t.directions, (Provenance("interaction", t.text, t.span),))
            for t in scenario.interactions
        )
        return LayoutGraph(scenario.name, scenario.domain, nodes, edges)


class Rules(RunRules):
    """Nothing is damaged or leaves; the run ends once everything has been at rest a while."""

    def __init__(self):
        self.resting_since = None

    def finished(self, values, alive, time) -> bool:
        if any(abs(vx) + abs(vy) + abs(w) > STILL for _, _, _, vx, vy, w in values):
            self.resting_since = None
        elif self.resting_since is None:
            self.resting_since = time
        return self.resting_since is not None and time - self.resting_since >= 0.3


def _outline(width: float, height: float) -> Polygon:
    w, h = width / 2, height / 2
    return Polygon(((-w, -h), (w, -h), (w, h), (-w, h)))


def simulate(level: Level, push: float) -> Trace:
    """The level played with the ball pushed at `push` units/s (rolling, no slip; 0: no action),
    with the interactions recognised in it and whether a box touched every pad."""
    world = load_backend().create_world(GRAVITY)
    world.add(BodySpec("ground", _outline(100.0, 1.0), 0.0, -0.5, static=True, friction=FRICTION))
    kinds = {"ground": "ground"}
    for t in level.things:
        shape = Circle(t.width / 2) if t.kind == "ball" else _outline(t.width, t.height)
        world.add(BodySpec(t.name, shape, t.x, t.y, static=t.kind == "pad", friction=FRICTION))
        kinds[t.name] = t.kind
    balls = [t for t in level.things if t.kind == "ball"]
    if push:
        world.set_velocity(balls[0].name, push, 0.0, -push / (balls[0].width / 2))
    dynamic = [t.name for t in level.things if t.kind != "pad"]
    recorded = run(world, dynamic, Rules(), SECONDS, DT)
    pads = tuple(t.name for t in level.things if t.kind == "pad")
    trace = Trace(DT, tuple(dynamic), kinds, recorded.states, recorded.contacts, recorded.separations, goal=pads)
    touches = []
    for c in trace.contacts:
        for mover, pad in ((c.a, c.b), (c.b, c.a)):
            if kinds.get(pad) == "pad" and mover in trace.names:
                vx, vy = approach(trace, c, mover, pad)
                touches.append(Interaction("touch", (mover, pad), side(-vx, -vy), c.time))
    found = RECOGNISER.recognise(trace, {t.name: t.width / 2 for t in balls}) + tuple(touches)
    found = tuple(sorted(found, key=lambda i: (round(i.time, 6), i.name)))
    touched = {i.objects[1] for i in touches if kinds[i.objects[0]] == "box"}
    return attrs.evolve(trace, interactions=found, violations=violations(found, ()), solved=bool(pads) and touched >= set(pads))


@attrs.frozen
class Push:
    """A task's solution in this domain: the push, in its own record (not another domain's)."""

    aimed_at: str
    speed: float


class MinimalFiles(LevelFiles):
    """Its level file, JSON, and a picture in SVG."""

    solution_class = Push

    @staticmethod
    def emit_level(level: Level) -> str:
        return json.dumps({"things": [attrs.asdict(t) for t in level.things]}, indent=2) + "\n"

    def picture(self, task, fmt: str = "png") -> bytes:
        if fmt != "svg":
            raise MissingCapability(self.domain.name, ("picture",), f"a {fmt} picture (it draws SVG only)")
        if not hasattr(task, "solution"):
            raise MissingCapability(self.domain.name, ("picture",), "a picture of a layout (it draws tasks only)")
        trace = simulate(task.level, task.solution.speed)
        flip = lambda y: 2 - y  # noqa: E731
        shapes = [
            f'<circle cx="{t.x}" cy="{flip(t.y)}" r="{t.width / 2}"/>' if t.kind == "ball"
            else f'<rect x="{t.x - t.width / 2}" y="{flip(t.y + t.height / 2)}" width="{t.width}" height="{t.height}"/>'
            for t in task.level.things
        ]
        paths = [
            '<polyline fill="none" stroke="red" stroke-width="0.02" points="' + " ".join(f"{x:.3f},{flip(y):.3f}" for x, y in points) + '"/>'
            for points in trace.paths().values()
        ]
        body = "".join(shapes + paths)
        return f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 8 2">{body}</svg>\n'.encode()



class MinimalActions(Actions):
    """Its actions: pushes of the ball."""

    resumable = False  # its play starts from the start every time

    @staticmethod
    def candidates(level, scenario) -> list[tuple[str, float]]:
        """Pushes of the ball towards the first hit's target, if both have entered the scene."""
        first = scenario.interactions[0]
        names = {t.name for t in level.things}
        if not set(first.objects) <= names:
            return []
        ball, target = level.thing(first.objects[0]), level.thing(first.objects[1])
        return [(f"{ball.name} pushed at {speed:g} units/s", math.copysign(speed, target.x - ball.x)) for speed in SPEEDS]

    @staticmethod
    def solution(label: str, push: float) -> Push:
        return Push(label, push)

    @staticmethod
    def action_of(solution: Push) -> float:
        return solution.speed


class Minimal(SimulatedDomain):
    """What differs in this domain, as hooks of physc's one search (SimulatedDomain)."""

    name = "minimal"
    description = "a ball pushed on flat ground, a box, goal pads a box must touch (physc's test domain)"
    vocabulary = VOCABULARY
    worlds = (WORLD,)
    layout_rules = PushLayout()
    layout_parameters = LayoutParameters(clearance=0.1, far=1.0, left=0.0, right=8.0, bottom=0.0, top=HEIGHT)
    seconds = SECONDS
    files = part(MinimalFiles)
    capabilities = SimulatedDomain.capabilities | {"layout_rules", "layout_parameters", "concretize", "level_from_layout", "play", "actions", "emit_level", "picture"}
    actions = part(MinimalActions)

    @staticmethod
    def concretize(graph, scenario, rng) -> dict[str, Body]:
        widths = {"ball": (HEIGHT,), "box": (0.4, 0.5, 0.6), "pad": (0.2, 0.3)}
        bodies = {}
        for node in graph.nodes:
            concrete = rng.choice(node.concrete)
            bodies[node.name] = Body(node.name, node.role, concrete, Geometry(rng.choice(widths[concrete]), HEIGHT))
        return bodies

    @staticmethod
    def level_from_layout(layout, scenario=None) -> Level:
        return Level(tuple(Thing(o.name, o.concrete, o.x, o.y, o.width, o.height) for o in layout.objects))

    def play(self, level, action, scenario=None, seconds=None, ending=Ending.READ, resume=None) -> Trace:
        return simulate(level, action or 0.0)

    @staticmethod
    def stability(level) -> tuple[bool, float]:
        return stable(simulate(level, 0.0), STANDS)






DOMAIN = Minimal()

SOURCE = """\
scenario Push "A ball pushes a box against the goal" {
    domain minimal

    interactions {
        hit(ball, box, left)
        > touch(box, goal, left)
    }
}
"""


def scenario_ir():
    """The checked scenario, with this module's domain as the one `domain minimal` selects."""
    parsed = parse_source(SourceText("push.phys", SOURCE))
    checked = check_file(parsed.file, "push.phys", vocabularies=Vocabularies(lambda name: DOMAIN.vocabulary, "minimal"))
    assert not parsed.diagnostics and not checked.diagnostics, [d.message for d in checked.diagnostics]
    (ir,) = checked.scenarios
    return ir


def compiled(seed: int):
    return Pipeline(DOMAIN, scenario_ir(), seed).task


def positions(level: Level) -> dict[str, tuple[float, float, float]]:
    return {t.name: (t.x, t.y, t.width) for t in level.things}


# ---- the tests -------------------------------------------------------------------------------
def test_the_domain_has_every_capability_generation_asks_for():
    assert missing(DOMAIN, NEEDS["level"] + ("picture",)) == ()
    ir = scenario_ir()
    assert [t.text for t in ir.interactions] == ["hit(ball, box, left)", "touch(box, goal, left)"]
    assert ir.object("goal").static and not ir.object("box").static


def test_a_task_is_compiled_and_its_solution_realises_the_sequence_in_a_fresh_simulation():
    ir = scenario_ir()
    task = compiled(0)
    assert (task.domain, task.scenario, task.seed, task.validated) == ("minimal", "Push", 0, True)
    assert task.simulations > 0 and task.layouts_tried >= 1
    # Built stage by stage: the goal pad was placed on the box's simulated path.
    assert any("goal on its path" in step for step in task.repairs), task.repairs
    level = task.level
    assert sorted(t.kind for t in level.things) == ["ball", "box", "pad"]
    ball, box, goal = level.thing("ball"), level.thing("box"), level.thing("goal")
    # The ball and the box are where the pipeline's placement put them (the first layout gave
    # the task); the goal moved along the box's path.
    assert task.layouts_tried == 1
    placed = {o.name: o for o in Pipeline(DOMAIN, ir, 0).placed.layout.objects}
    assert [(t.x, t.width) for t in (ball, box)] == [(placed[n].x, placed[n].width) for n in ("ball", "box")]
    assert goal.x != placed["goal"].x
    # The layout's relations hold in the task: the ball left of the box, the box left of the goal,
    # all standing on the ground, apart.
    clearance = DOMAIN.layout_parameters.clearance
    assert ball.box()[1] + clearance <= box.box()[0] + 1e-9 and box.box()[1] + clearance <= goal.box()[0] + 1e-9
    assert all(math.isclose(t.y, HEIGHT / 2) for t in level.things)
    # A fresh simulation of the solution realises the declared sequence, meets the goal, and
    # recognises exactly what the task says.
    push = task.solution.speed
    assert push > 0 and task.solution.aimed_at == f"ball pushed at {push:g} units/s"
    trace = simulate(level, push)
    realised = fidelity(ir, trace)
    assert realised.valid and realised.matched == 2 and trace.solved
    assert trace.sequence() == task.trace
    texts = [i.text() for i in trace.interactions]
    assert texts.index("hit(ball, box, left)") < texts.index("touch(box, goal, left)")
    # Without the push nothing happens: the level stands, the goal is not met.
    still = simulate(level, 0.0)
    assert stable(still, STANDS)[0] and not still.solved and not fidelity(ir, still).matched
    # The level file and the picture.
    assert json.loads(DOMAIN.files.emit_level(level)) == {"things": [attrs.asdict(t) for t in level.things]}
    assert DOMAIN.files.picture(task, "svg").startswith(b"<svg") and b"polyline" in DOMAIN.files.picture(task, "svg")


def test_the_same_seed_gives_the_same_task_and_another_seed_another_layout():
    first, again, other = compiled(0), compiled(0), compiled(1)
    same = ("solution", "trace", "repairs", "layouts_tried", "simulations", "conjunctions_tried")
    assert DOMAIN.files.emit_level(first.level) == DOMAIN.files.emit_level(again.level)
    assert [getattr(first, f) for f in same] == [getattr(again, f) for f in same]
    assert positions(other.level) != positions(first.level)
    assert other.validated and fidelity(scenario_ir(), simulate(other.level, other.solution.speed)).valid


def test_the_command_line_compiles_it_as_an_installed_plugin(tmp_path, monkeypatch):
    """Registered like a third-party plugin (an entry point of physc.domains), the domain is
    found by `domain minimal` and `physc compile` writes the level, the task and the picture."""
    installed = dict(domains.installed_domains())
    installed["minimal"] = EntryPoint("minimal", f"{__name__}:DOMAIN", domains.ENTRY_POINT_GROUP)
    monkeypatch.setattr(domains, "installed_domains", lambda: installed)
    domains.load_domain.cache_clear()
    try:
        source = tmp_path / "push.phys"
        source.write_text(SOURCE)
        assert run_physc("check", "-q", source).status == 0
        out = run_physc(
            "compile", "-q", "--seed", "0", source,
            "-o", tmp_path / "push.json", "--task", tmp_path / "task.json", "--png", tmp_path / "push.svg",
        )
        assert (out.status, out.stderr) == (0, "")
        expected = compiled(0)
        assert (tmp_path / "push.json").read_text() == DOMAIN.files.emit_level(expected.level)
        task = json.loads((tmp_path / "task.json").read_text())
        assert (task["domain"], task["trace"], task["validated"]) == ("minimal", expected.trace, True)
        assert (tmp_path / "push.svg").read_bytes().startswith(b"<svg")
        # What the domain cannot draw is refused as such (E0703), not an internal error.
        for extra in (["--png", tmp_path / "push.png"], ["--emit", "layout", "--png", tmp_path / "layout.svg"]):
            out = run_physc("compile", "-q", "--color", "never", source, "-o", tmp_path / "again.json", *extra)
            assert out.status == 2, out.stderr
            assert "error[E0703]: the domain 'minimal' cannot do what a" in out.stderr and "Traceback" not in out.stderr
            assert not (tmp_path / "push.png").exists() and not (tmp_path / "layout.svg").exists()
    finally:
        domains.load_domain.cache_clear()
