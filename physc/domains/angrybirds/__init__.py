"""The angrybirds domain: Science Birds levels (the paper's demonstration domain).

A one-action simulated domain (physc.domains.simulated.SimulatedDomain): the generation
search is physc's own (physc.search.search); what this package writes is what differs
in Science Birds: its shot and candidate actions (the paper's points of interest), the game
played with its rules (game.py), its catalogue, masses and frictions, its noise model, its
obstacles (a platform) and distractors, its level file and picture.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import attrs

from physc.domains.angrybirds.evaluation import ScienceBirdsEvaluation
from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.level_files import ScienceBirdsFiles
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.search_hooks import ScienceBirdsSearch
from physc.domains.angrybirds.shooting import ScienceBirdsActions
from physc.domains.angrybirds.vocabulary import VOCABULARY
from physc.domains.angrybirds.worlds import PHYQ, WORLDS, ScienceBirdsWorld
from physc.domains.part import part
from physc.domains.simulated import SimulatedDomain
from physc.simulation.ending import Ending

if TYPE_CHECKING:
    from physc.compiler.dimension_graphs import LayoutParameters
    from physc.compiler.layout_rules import LayoutRules
    from physc.domains.angrybirds.game import Game
    from physc.domains.playing import Playing

PLAY_SECONDS = 10.0  # a play's simulated time at most, each shot's (the evaluation's replays; the paper's stability)
READ_SETTLE = 0.3  # seconds a play for reading the chain goes on after the last pig goes, once nothing falls

# How the game's run ends for each ending of a play (Game.scene): a play read for the chain goes on
# READ_SETTLE after the last pig, so that a fall that began while the chain ran lands; an outcome
# alone ends once the last pig goes and nothing falls; the whole play and stability do not stop for the pigs, and
# stability not for rest either.
ENDINGS = {
    Ending.READ: {"settle_after_solved": READ_SETTLE},
    Ending.OUTCOME: {"settle_after_solved": 0.0},
    Ending.SETTLED: {"settle_after_solved": 0.0},
    Ending.WHOLE: {},
    Ending.STILL: {"stop_at_rest": False},
}


class AngryBirds(SimulatedDomain):
    name = "angrybirds"
    description = "Angry Birds levels in the Science Birds format (the paper's domain)"
    vocabulary = VOCABULARY
    worlds = WORLDS
    default_world = PHYQ.name
    capabilities = SimulatedDomain.capabilities | {
        "layout_rules",
        "layout_parameters",
        "concretize",
        "level_from_layout",
        "simulation",
        "actions",
        "distractors",
        "emit_level",
        "picture",
        "read_level",
        "draw",
    }

    @property
    def world(self) -> ScienceBirdsWorld:
        """The Science Birds world it simulates in (`Domain.world`): one of WORLDS, or a variant
        derived from one, so a ScienceBirdsWorld."""
        world = super().world
        assert isinstance(world, ScienceBirdsWorld), world
        return world

    @property
    def layout_rules(self) -> LayoutRules:
        """The layout graph's rules in Science Birds (the compiler loads when a scenario is compiled)."""
        from physc.compiler.layout_rules import LayoutRules

        # continuous_paths: a mover's platforms make one top edge, as Phy-Q's rolling and sliding
        # levels build them (docs/qsr.md, "Continuous paths").
        return LayoutRules(
            player="bird",
            flat="flatPlatform",
            ground="ground",
            player_heading="right",
            inclined="inclinedPlatform",
            continuous_paths=True,
        )

    robustness_replays = ROBUSTNESS_REPLAYS  # noisy replays a generated solution is put through
    files = part(ScienceBirdsFiles)  # its level XML, pictures and Phy-Q's level set (level_files.py)
    actions = part(ScienceBirdsActions)  # the birds' shots: candidates, noise, records (shooting.py)
    evaluation = part(ScienceBirdsEvaluation)  # the paper's heuristic agent (evaluation.py)
    seconds = PLAY_SECONDS

    @property
    def playing(self) -> Playing:
        """How agents play its levels (playing.py; physc/AngryBirds-v0)."""
        from physc.domains.angrybirds.playing import PLAYING

        return PLAYING

    @property
    def layout_parameters(self) -> LayoutParameters:
        """The QSRs' distances, and the world's placement area."""
        from physc.compiler.dimension_graphs import LayoutParameters

        area = self.world.frame.placement
        return LayoutParameters(
            clearance=0.1, far=1.5, left=area.left, right=area.right, bottom=area.bottom, top=area.top
        )

    search = part(ScienceBirdsSearch)  # the search's hooks: bodies, obstacles, distractors (search_hooks.py)

    def concretize(self, graph, scenario, rng):
        from physc.domains.angrybirds.concretize import concretize

        return concretize(graph, scenario, rng, self.world)

    def reach_targets(self, scenario) -> list[str]:
        """The objects the birds must hit directly: what each bird's shot starts by hitting."""
        from physc.domains.angrybirds.shots import birds, first_hit, shot_starts

        order, starts = birds(scenario, VOCABULARY.player), (0, *shot_starts(scenario, VOCABULARY.player))
        return [
            t
            for t in (first_hit(scenario, name, start) for name, start in zip(order, starts, strict=False))
            if t is not None
        ]

    def reachable(self, x: float, y: float) -> bool:
        return self.world.reachable(x, y)

    # ---- the search's hooks ------------------------------------------------------------
    def level_from_layout(self, layout, scenario=None) -> Level:
        """The placed layout as a level that names this world and the physc that made it."""
        from physc import __version__
        from physc.domains.angrybirds.catalogue import shape
        from physc.domains.angrybirds.shots import level_birds
        from physc.domains.angrybirds.to_level import level_from_layout

        birds = level_birds(layout, scenario, VOCABULARY.player, lambda concrete: shape(concrete).prefab)
        return attrs.evolve(
            level_from_layout(layout), birds=birds, world=self.world.name, generator=f"physc {__version__}"
        )

    def game(self, level: Level) -> Game:
        """`level` as the game plays it in this domain's world and engine."""
        from physc.domains.angrybirds.game import Game

        return Game(level, self.world, self.backend)

    def simulation(self, level, action, ending):
        """The level as the game plays it with the shot `action` (None: no shot), the game its
        rules (game.py), ending as `ending` asks (ENDINGS)."""
        game = self.game(level)
        return game.scene(action, **ENDINGS[ending]), game


DOMAIN = AngryBirds()
