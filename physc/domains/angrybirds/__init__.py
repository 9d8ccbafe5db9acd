"""The angrybirds domain: Science Birds levels (the paper's demonstration domain).

It has every capability of the domain interface (physc.domains.base.Domain) and
overrides every default: the bird must reach the first hit's target, a point is in
reach when a full-stretch shot can pass through it, and a solution is put through 6
noisy replays.
"""

from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.layout_rules import LayoutRules
from physc.domains.angrybirds import world
from physc.domains.angrybirds.concretize import concretize
from physc.domains.angrybirds.level import Camera, Level, LevelObject
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.vocabulary import VOCABULARY
from physc.domains.base import Domain

REPLAY_SECONDS = 10.0  # a replay's simulated time at most (the evaluation's)


class AngryBirds(Domain):
    name = "angrybirds"
    description = "Angry Birds levels in the Science Birds format (the paper's domain)"
    vocabulary = VOCABULARY
    layout_rules = LayoutRules(player="bird", flat="flatPlatform", ground="ground", player_heading="right")
    robustness_replays = ROBUSTNESS_REPLAYS  # noisy replays a generated solution is put through
    level_classes = (Level, Camera, LevelObject)
    level_suffix = "xml"  # Science Birds level files
    layout_parameters = LayoutParameters(
        clearance=0.1,
        far=1.5,
        left=world.PLACEMENT_AREA.left,
        right=world.PLACEMENT_AREA.right,
        bottom=world.PLACEMENT_AREA.bottom,
        top=world.PLACEMENT_AREA.top,
    )

    @staticmethod
    def concretize(graph, scenario, rng):
        return concretize(graph, scenario, rng)

    @staticmethod
    def reach_targets(scenario) -> list[str]:
        """The objects the bird must hit directly: the first interaction's target."""
        first = scenario.interactions[0]
        return [first.objects[1]] if first.name == "hit" else []

    @staticmethod
    def reachable(x: float, y: float) -> bool:
        return world.reachable(x, y)

    @staticmethod
    def emit_level(level) -> str:
        from physc.domains.angrybirds.level_xml import emit_level

        return emit_level(level)

    @staticmethod
    def picture(task, fmt: str = "png") -> bytes:
        """The task's level with the paths its solution makes, like the paper's figure; a
        placed layout (`--emit layout --png`) as the level it becomes."""
        from physc.compiler.concrete_layout import ConcreteLayout
        from physc.domains.angrybirds.game import Game
        from physc.domains.angrybirds.launch import Shot
        from physc.domains.angrybirds.picture import draw_level, render, save

        if isinstance(task, ConcreteLayout):
            return render(task, fmt)
        shot = Shot(target=task.solution.target, trajectory=task.solution.trajectory)
        trace = Game(task.level).simulate(shot, 9.0, settle_after_solved=0.5)
        supports = frozenset(o.name for o in task.level.objects if o.name.startswith(("support_", "obstacle")))
        title = f"{task.scenario} (seed {task.seed}): {task.solution.aimed_at}"
        return save(draw_level(task.level, title, trace.paths(), supports), fmt)

    @staticmethod
    def replay(level, solution, scenario, rng=None):
        """The solution's shot (or, with `rng`, the evaluation's noise: release angle and
        object positions jittered), played with the scenario's restrictions and declared
        bounces."""
        from physc.domains.angrybirds.game import Game
        from physc.domains.angrybirds.launch import Shot
        from physc.domains.angrybirds.noise import ANGLE_SIGMA, jitter

        if rng is None:
            shot = Shot(target=tuple(solution.target), trajectory=solution.trajectory)
        else:
            shot = Shot(angle=solution.release_angle + rng.gauss(0.0, ANGLE_SIGMA))
            level = jitter(level, rng)
        redirects = {tuple(t.objects) for t in scenario.interactions if t.name == "bounce"}
        return Game(level).play(shot, REPLAY_SECONDS, restrictions=scenario.restrictions, redirects=redirects, settle_after_solved=0.3)

    @staticmethod
    def stability(level) -> tuple[bool, float]:
        """10 s with no action: no object moves more than 0.05 units, nothing is destroyed."""
        from physc.domains.angrybirds.stability import stability

        return stability(level)

    @staticmethod
    def accidental(level, scenario, solution, rng) -> dict:
        """The paper's heuristic agent (agent.py): it shoots at everything but the first target."""
        from physc.domains.angrybirds.agent import accidental

        fraction, plays = accidental(level, scenario.interactions[0].objects[1])
        return {"accidental": None if fraction is None else round(fraction, 5), "agent_plays": plays}

    def satisfy(self, scenario, layout, rng, validate: bool = True, accept: int | None = None):
        """Simulation-based satisfaction, distractions and validation of one layout; the
        solution must pass `accept` of the noisy replays (default: all of them)."""
        from physc.domains.angrybirds.generate import satisfy

        return satisfy(self, scenario, layout, rng, validate, accept)


DOMAIN = AngryBirds()
