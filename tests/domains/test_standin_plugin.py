"""A third domain, written in this test against physc's public plugin API alone and with no
physics engine, installed as a plugin and compiled from `.phys` text to a task by `physc.compile`:
the whole way of a compile (docs/architecture.md) runs on a domain's hooks.

The stand-in's world is one line: the player pushes a ball from x = 0 at a speed (its action);
friction slows it by 1 unit/s²; a ball that reaches the pig strikes it at the speed it has left,
and a strike of at least 1 unit/s destroys it. Its plays are formulas, written as the traces the
generic recognition reads; its level is where the pig is, its level file a line of JSON."""

from __future__ import annotations

import sys
from importlib.metadata import EntryPoint

import pytest

from physc import domains

PLUGIN = '''
import json
import math

import attrs
import numpy as np
from physc.backends import EngineSettings
from physc.compiler.concrete_layout import Body
from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.geometry import Geometry
from physc.compiler.layout_rules import LayoutRules
from physc.domains.actions import Actions
from physc.domains.level_files import LevelFiles
from physc.domains.part import part
from physc.domains.simulated import SimulatedDomain
from physc.domains.vocabulary import (
    DIRECTION, INTERACTION, OBJECT, ConcreteObject, ObjectTerm, Parameter, TermSignature, Vocabulary,
)
from physc.simulation.ending import Ending
from physc.simulation.recognise import Recogniser
from physc.simulation.trace import ContactRecord, DamageRecord, DestructionRecord, Trace
from physc.worlds import Incline, World

DT, FRICTION, LIFE, REACH = 0.01, 1.0, 1.0, 0.3
LINE = World(
    name="line", description="a ball on a line", engine=EngineSettings(dt=DT), gravity=0.0,
    recogniser=Recogniser(
        hit_speed=0.3, rehit=0.1, moving=0.15, roll_slip=0.3, slide_spin=0.3, motion_time=0.2, fall_time=0.2,
        fall_height=0.4, bounce_time=0.2, bounce_speed=1.0, surfaces=("bar",), background=("bar",),
    ),
    incline=Incline(descending=(10.0, 20.0), other=(10.0, 20.0)),
)


@attrs.frozen
class Push:
    speed: float


@attrs.frozen
class LineLevel:
    pig: float  # the pig's centre, from the ball's start


class LineFiles(LevelFiles):
    level_classes = (LineLevel,)
    solution_class = Push

    def emit_level(self, level):
        return json.dumps({"pig": level.pig}) + "\\n"


class LineActions(Actions):
    resumable = False  # its play starts from the start every time

    def candidates(self, level, scenario):
        return [(f"push {speed:g}", Push(speed)) for speed in (1.0, 2.0, 3.0, 4.0)]

    def nudged(self, action, step):
        return Push(round(action.speed + 0.05 * step, 6))

    def noisy(self, level, action, rng):
        return level, Push(action.speed + rng.gauss(0.0, 0.02))


class Line(SimulatedDomain):
    name = "line"
    description = "a ball pushed along a line at a pig (a test's stand-in)"
    vocabulary = Vocabulary(
        object_terms=(
            ObjectTerm("ball", ("redBall",), noun="the player's ball"),
            ObjectTerm("pig", ("pig",), noun="a pig"),
            ObjectTerm("bar", ("bar",), noun="a bar"),
        ),
        concrete_objects=(ConcreteObject("redBall"), ConcreteObject("pig"), ConcreteObject("bar", static=True)),
        terms=(
            TermSignature("hit", INTERACTION, (
                Parameter("a", OBJECT, dynamic=True, acts=True), Parameter("b", OBJECT, moves=True),
                Parameter("d", DIRECTION, directions=("left", "right")),
            )),
            TermSignature("destroy", INTERACTION, (
                Parameter("a", OBJECT, dynamic=True, acts=True), Parameter("b", OBJECT, fits="pig", destroys=True, completes=True),
            ), requires="hit"),
        ),
        player="ball",
        goal="pig",
    )
    worlds = (LINE,)
    capabilities = SimulatedDomain.capabilities | {"layout_rules", "layout_parameters", "concretize", "level_from_layout", "play", "actions", "emit_level"}
    layout_rules = LayoutRules(player="ball", flat="bar", ground=None)
    layout_parameters = LayoutParameters(clearance=0.1, far=1.0, left=-1.0, right=6.0, bottom=0.0, top=2.0)
    files = part(LineFiles)
    actions = part(LineActions)
    robustness_replays = 4

    def concretize(self, graph, scenario, rng):
        sizes = {"redBall": (0.2, 0.2), "pig": (0.4, 0.4), "bar": (round(rng.uniform(1.0, 2.0), 2), 0.1)}
        return {
            node.name: Body(node.name, node.role, node.concrete[0], Geometry(*sizes[node.concrete[0]]),
                            fixed=(0.0, 0.5) if node.concrete[0] == "redBall" else None)
            for node in graph.nodes
        }

    def level_from_layout(self, layout, scenario=None):
        return LineLevel(round(layout.object("pig").x, 6))

    def stability(self, level):
        return True, 0.0

    def play(self, level, action, scenario=None, seconds=None, ending=Ending.READ, resume=None):
        v, gap = max(action.speed, 1e-6), level.pig - REACH
        meets = v * v - 2 * FRICTION * gap
        met = None if meets < 0 or gap < 0 else (v - math.sqrt(meets)) / FRICTION
        end = v / FRICTION if met is None else met + 0.3
        steps = int(end / DT) + 2
        times = (np.arange(steps) + 1) * DT
        t = np.minimum(times, met if met is not None else v / FRICTION)
        states = np.zeros((steps, 2, 6))
        states[:, 0, 0] = v * t - FRICTION * t * t / 2
        states[:, 0, 3] = np.where(times < (met if met is not None else v / FRICTION), v - FRICTION * t, 0.0)
        states[:, 1, 0] = level.pig
        kinds = {"ball": "ball", "pig": "pig"}
        outlines = {"ball": (0.0, 0.0, 0.0, 0.1, 0.1), "pig": (level.pig, 0.0, 0.0, 0.2, 0.2)}
        if met is None:
            trace = Trace(DT, ("ball", "pig"), kinds, states, goal=("pig",), outlines=outlines)
        else:
            strike = v - FRICTION * met
            states[int(met / DT):, 1, 0] = np.nan if strike >= LIFE else level.pig
            contact = ContactRecord(met, "ball", "pig", (level.pig - 0.2, 0.0), (1.0, 0.0), (strike, 0.0), (strike, 0.0), (0.0, 0.0))
            damage = (DamageRecord(met, "pig", strike, LIFE - strike, "ball"),)
            destroyed = (DestructionRecord(met, "pig", "damage", "ball"),) if strike >= LIFE else ()
            trace = Trace(DT, ("ball", "pig"), kinds, states, (contact,), (), damage, destroyed, ("pig",), bool(destroyed), outlines=outlines)
        if not ending.recognised:
            return trace
        return attrs.evolve(trace, interactions=self.recogniser.recognise(trace, {}))


DOMAIN = Line()
'''

SCENARIO = """scenario Push "The ball rolls along its line into the pig" {
    domain line
    interactions {
        hit(ball, pig, left) > destroy(ball, pig)
    }
}
"""


@pytest.fixture
def line_domain(tmp_path, monkeypatch):
    """The stand-in installed as a plugin (its package on the path, its entry point listed)."""
    package = tmp_path / "line_physc"
    package.mkdir()
    (package / "__init__.py").write_text(PLUGIN)
    monkeypatch.syspath_prepend(str(tmp_path))
    installed = dict(domains.installed_domains())
    installed["line"] = EntryPoint("line", "line_physc:DOMAIN", domains.ENTRY_POINT_GROUP)
    monkeypatch.setattr(domains, "installed_domains", lambda: installed)
    domains.load_domain.cache_clear()
    yield
    domains.load_domain.cache_clear()
    sys.modules.pop("line_physc", None)


def test_a_plugin_written_in_the_test_compiles_a_scenario_to_a_task(line_domain, tmp_path):
    import physc

    source = tmp_path / "push.phys"
    source.write_text(SCENARIO)
    task = physc.compile(source, seed=0, time_budget=60)
    assert task.domain == "line" and task.trace == "hit(ball, pig, left) > destroy(ball, pig)"
    assert task.validated and task.robustness[0] == task.robustness[1] > 0
    level = task.level
    strike = (task.solution.speed ** 2 - 2 * (level.pig - 0.3)) ** 0.5  # the formulas of the plugin
    assert strike >= 1.0
    assert physc.level_text(task) == f'{{"pig": {level.pig}}}\n'
