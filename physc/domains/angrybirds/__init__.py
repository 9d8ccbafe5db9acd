"""The angrybirds domain: Science Birds levels (the paper's demonstration domain).

A one-action simulated domain (physc.domains.simulated.SimulatedDomain): the generation
search is physc's own (physc.generation.search); what this package writes is what differs
in Science Birds: its shot and candidate actions (the paper's points of interest), the game
played with its rules (game.py), its catalogue, masses and frictions, its noise model, its
obstacles (a platform) and distractors, its level file and picture.
"""

from __future__ import annotations


import attrs

from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.vocabulary import VOCABULARY
from physc.domains.angrybirds.worlds import PHYQ, WORLDS
from physc.domains.angrybirds.evaluation import ScienceBirdsEvaluation
from physc.domains.angrybirds.level_files import ScienceBirdsFiles
from physc.domains.angrybirds.search_hooks import ScienceBirdsSearch
from physc.domains.angrybirds.shooting import ScienceBirdsActions
from physc.domains.part import part
from physc.domains.simulated import SimulatedDomain

REPLAY_SECONDS = 10.0  # a replay's simulated time at most (the evaluation's)
PLAY_SECONDS = 9.0  # a play's simulated time at most while generating


class AngryBirds(SimulatedDomain):
    name = "angrybirds"
    description = "Angry Birds levels in the Science Birds format (the paper's domain)"
    vocabulary = VOCABULARY
    worlds = WORLDS
    default_world = PHYQ.name
    capabilities = SimulatedDomain.capabilities | {
        "layout_rules", "layout_parameters", "concretize", "level_from_layout", "play", "actions", "distractors",
        "emit_level", "picture", "read_level", "draw",
    }
    @property
    def layout_rules(self):
        """The layout graph's rules in Science Birds (the compiler loads when a scenario is compiled)."""
        from physc.compiler.layout_rules import LayoutRules

        return LayoutRules(player="bird", flat="flatPlatform", ground="ground", player_heading="right", inclined="inclinedPlatform")

    robustness_replays = ROBUSTNESS_REPLAYS  # noisy replays a generated solution is put through
    files = part(ScienceBirdsFiles)  # its level XML, pictures and Phy-Q's level set (level_files.py)
    actions = part(ScienceBirdsActions)  # the birds' shots: candidates, noise, records (shooting.py)
    evaluation = part(ScienceBirdsEvaluation)  # the paper's heuristic agent (evaluation.py)
    seconds = PLAY_SECONDS

    @property
    def playing(self):
        """How agents play its levels (playing.py; physc/AngryBirds-v0)."""
        from physc.domains.angrybirds.playing import PLAYING

        return PLAYING

    @property
    def layout_parameters(self):
        """The QSRs' distances, and the world's placement area."""
        from physc.compiler.dimension_graphs import LayoutParameters

        area = self.world.frame.placement
        return LayoutParameters(clearance=0.1, far=1.5, left=area.left, right=area.right, bottom=area.bottom, top=area.top)

    search = part(ScienceBirdsSearch)  # the search's hooks: bodies, obstacles, distractors (search_hooks.py)

    def concretize(self, graph, scenario, rng):
        from physc.domains.angrybirds.concretize import concretize

        return concretize(graph, scenario, rng, self.world)

    @staticmethod
    def reach_targets(scenario) -> list[str]:
        """The objects the birds must hit directly: what each bird's shot starts by hitting."""
        from physc.domains.angrybirds.shots import birds, first_hit, shot_starts

        order, starts = birds(scenario, VOCABULARY.player), (0, *shot_starts(scenario, VOCABULARY.player))
        return [t for t in (first_hit(scenario, name, start) for name, start in zip(order, starts)) if t is not None]

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
        return attrs.evolve(level_from_layout(layout), birds=birds, world=self.world.name, generator=f"physc {__version__}")

    def game(self, level):
        """`level` as the game plays it in this domain's world and engine."""
        from physc.domains.angrybirds.game import Game

        return Game(level, self.world, self.backend)

    def play(self, level, action, scenario=None, seconds=None, recognise: bool = True, resume=None, whole: bool = False):
        """The level played with the shot `action` (None: no shot), judged against the
        scenario's restrictions and declared bounces; from the snapshot `resume`, if given.
        With `whole`, played out as the game plays it (until everything rests, not stopping
        soon after the last pig goes: `physc simulate`)."""
        restrictions = scenario.restrictions if scenario is not None else ()
        redirects = {tuple(t.objects) for t in scenario.interactions if t.name == "bounce"} if scenario is not None else None
        game = self.game(level)
        if whole:
            return game.play(action, seconds or self.seconds, restrictions=restrictions, redirects=redirects)
        if not recognise:
            return game.simulate(action, seconds or self.seconds, settle_after_solved=0.0, resume=resume)
        return game.play(action, seconds or self.seconds, restrictions=restrictions, redirects=redirects, settle_after_solved=0.3, resume=resume)

    def playout(self, level, action, seconds=None, whole: bool = False, to_end: bool = True):
        """The shot's outcome alone (physc.simulation.run.play_out), as `play` with `recognise`
        False (or `whole`) would run it (the game's rules settle nothing before they finish, so
        `to_end` changes nothing)."""
        game = self.game(level)
        settle = {} if whole else {"settle_after_solved": 0.0}
        return game.simulate(action, seconds or self.seconds, record=False, **settle)

    # ---- files, pictures, evaluation ------------------------------------------------------

    @staticmethod
    def shot(point: tuple[float, float, str] | None = None, angle: float | None = None):
        """The shot at a target point (x, y, trajectory) or at a release angle; None for neither."""
        from physc.domains.angrybirds.launch import Shot

        if point is None:
            return None if angle is None else Shot(angle=angle)
        x, y, trajectory = point
        return Shot(target=(x, y), trajectory=trajectory)

    def replay(self, level, solution, scenario, rng=None):
        """The solution's shots (or, with `rng`, the evaluation's noise: the recorded release angles
        jittered, then the objects: noise.py), played with the scenario's restrictions and declared
        bounces for REPLAY_SECONDS. The same noise as `actions.noisy`, drawn from the task file's
        record in the order its replays have always drawn it (a verification stays what it was)."""
        from physc.domains.angrybirds import shots
        from physc.domains.angrybirds.noise import ANGLE_SIGMA, jitter

        if rng is None:
            shot = shots.action_of(solution)
        else:
            shot = shots.action_of(solution, (rng, ANGLE_SIGMA))
            level = jitter(level, rng)
        return self.play(level, shot, scenario, REPLAY_SECONDS)

    def stability(self, level) -> tuple[bool, float]:
        """10 s with no action: no object moves more than 0.05 units, nothing is destroyed."""
        from physc.domains.angrybirds.stability import stability

        return stability(self.game(level))



DOMAIN = AngryBirds()
