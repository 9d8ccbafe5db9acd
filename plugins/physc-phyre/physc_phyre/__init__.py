"""PHYRE-like tasks for physc: the agent places a red ball (or two, PHYRE's two-ball tier);
the green object must touch the blue or purple one for 3 s.

A domain plugin written against physc's public API only (physc.domains.simulated,
physc.compiler, physc.backends, physc.simulation): it says what its world is (world.py,
level.py), what its actions are (actions.py), what its goal is (rules.py, the `touch`
term of vocabulary.py) and how to write its files (task_file.py, picture.py). physc's
generic search, robustness replays, stability and evaluation do the rest.
"""

from __future__ import annotations

import functools
import random
from collections.abc import Sequence

from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.layout_rules import LayoutRules
from physc.domains.actions import Actions
from physc.domains.part import part
from physc.domains.playing import Playing
from physc.domains.search_hooks import SearchHooks
from physc.domains.simulated import SimulatedDomain
from physc.simulation.scene import Scene
from physc_phyre import actions, two_balls, world
from physc_phyre.concretize import concretize
from physc_phyre.evaluation import PhyreEvaluation
from physc_phyre.files import PhyreFiles
from physc_phyre.level import BallAction, PhyreLevel, SceneBody, TwoBallAction, level_from_layout
from physc_phyre.rules import GoalRules
from physc_phyre.vocabulary import VOCABULARY
from physc_phyre.worlds import PHYRE

__all__ = ["DOMAIN", "Phyre", "BallAction", "TwoBallAction", "PhyreLevel", "SceneBody"]


LAYOUT_RULES = LayoutRules(
    player="redBall",
    flat="blackBar",
    ground="floor",
    player_placed=False,
    continuous_paths=True,
    fall_ahead_after_motion=True,
)
LAYOUT_PARAMETERS = LayoutParameters(clearance=2.0, far=25.0, left=0.0, right=world.SCENE, bottom=0.0, top=world.SCENE)


class PhyreSearch(SearchHooks):
    """PHYRE's hooks of the search: paths read in pixels, and distractors."""

    trace_scale = world.PIXELS_PER_METRE

    def distractors(self, layout, index: int, rng: random.Random):
        """Static bars and balls, and gray balls on the floor, that play no part (distract.py)."""
        from physc_phyre.distract import distractors

        return distractors(layout, index, rng)


class PhyreActions(Actions):
    """PHYRE's actions: one red ball placed, or two (actions.py, two_balls.py)."""

    def candidates(
        self, level: PhyreLevel, scenario, start: int = 0, before=None, after=None
    ) -> Sequence[tuple[str, BallAction | TwoBallAction]]:
        """Every valid drop onto the first target's points of interest (actions.py); in the
        two-ball tier, pairs of such drops (two_balls.py)."""
        if len(level.players) == 2:
            return two_balls.candidate_pairs(level, scenario)
        return actions.drops(level, scenario.interactions[0])

    def noisy(self, level: PhyreLevel, action, rng: random.Random):
        return level, actions.noisy(action, rng)

    def nudged(self, action, step: int, line: int | None = None):
        """The balls `step` whole pixels sideways."""
        return actions.moved(action, lambda ball: (step, 0))

    def random_action(self, level: PhyreLevel, rng: random.Random):
        return actions.random_action(level, rng)

    def neighbours(self, action) -> list:
        return actions.neighbours(action)

    def valid(self, level: PhyreLevel, action) -> bool:
        return actions.valid(level, action)


class Phyre(SimulatedDomain):
    name = "phyre"
    description = (
        "PHYRE-like tasks: the agent places a red ball (or two); the green object must touch the target for 3 s"
    )
    vocabulary = VOCABULARY
    worlds = (PHYRE,)
    capabilities = SimulatedDomain.capabilities | {
        "layout_rules",
        "layout_parameters",
        "concretize",
        "level_from_layout",
        "scene",
        "actions",
        "distractors",
        "random_action",
        "emit_level",
        "picture",
        "score_agent",
    }

    @property
    def layout_rules(self) -> LayoutRules:
        """PHYRE's layout inference: the red ball is dropped, not placed; paths are continuous."""
        return LAYOUT_RULES

    @property
    def layout_parameters(self) -> LayoutParameters:
        """The QSRs' distances and the whole scene as the placement area, in pixels."""
        return LAYOUT_PARAMETERS

    seconds = world.MAX_STEPS / world.FPS

    @property
    def playing(self) -> Playing:
        """How agents play its tasks (playing.py; physc/PhyreLike-v0)."""
        from physc_phyre.playing import PLAYING

        return PLAYING

    actions = part(PhyreActions)  # the red balls placed: candidates, noise, the random agent's draw
    search = part(PhyreSearch)  # the search's hooks: the trace's scale, distractors
    files = part(PhyreFiles)  # PHYRE's task structure, its benchmark files, pictures (files.py)
    evaluation = part(PhyreEvaluation)  # PHYRE's acceptance, random agent and AUCCESS, agents scored (evaluation.py)
    stable_limit = 0.5 / world.PIXELS_PER_METRE  # half a pixel, in metres: the trace's unit
    still_start = False  # PHYRE's scenes may move before the action; one left alone must not solve itself

    def concretize(self, graph, scenario, rng):
        return concretize(graph, scenario, rng, self.world.incline)

    def level_from_layout(self, layout, scenario) -> PhyreLevel:
        return level_from_layout(layout, scenario)

    def scene(self, level: PhyreLevel, action: BallAction | TwoBallAction | None) -> Scene:
        specs, kinds, radii = _level_scene(level)
        specs, kinds, radii = list(specs), dict(kinds), dict(radii)
        balls = action.balls if action is not None else ()
        if len(balls) > len(level.players):  # (fewer: the ball tier's actions on a two-ball task, as PHYRE judges it)
            raise ValueError(
                f"the level's tier ({level.tier}) places {len(level.players)} red balls, but the action has "
                f"{len(balls)}"
            )
        for name, ball in zip(level.players, balls, strict=False):
            specs.append(world.body_spec(name, world.outline("ball", ball.radius), ball.x, ball.y, 0.0, True))
            kinds[name] = "agent"
            radii[name] = ball.radius / world.PIXELS_PER_METRE
        return Scene(tuple(specs), kinds, self.world.gravity, self.world.engine, radii, goal=level.goal)

    def rules(self, level: PhyreLevel) -> GoalRules:
        """PHYRE's goal: two balls touch by its distance rule, other pairs by contact (rules.py)."""
        return GoalRules.of(level)


@functools.lru_cache(maxsize=64)
def _level_scene(level: PhyreLevel) -> tuple[tuple, dict, dict]:
    """(bodies, kinds, rolling radii) of the level without the agent's balls: the same for
    every action played on it (acceptance plays thousands)."""
    specs = world.walls(level.floor)
    kinds = {spec.name: "wall" for spec in specs} | {level.floor: "floor"}
    radii = {}
    for body in level.bodies:
        specs.append(
            world.body_spec(body.name, world.outline(body.shape, body.size), body.x, body.y, body.angle, body.dynamic)
        )
        kinds[body.name] = "object" if body.dynamic else "surface"
        if body.shape == "ball":
            radii[body.name] = body.size / world.PIXELS_PER_METRE
    return tuple(specs), kinds, radii


DOMAIN = Phyre()
