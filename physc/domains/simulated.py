"""A domain whose task is one action of the player in a scene that simulation judges.

Most physical-reasoning benchmarks are of this kind (PHYRE: place a ball; a marble run:
drop a marble): the player acts once, the world runs, a goal is met or not. Such a
domain subclasses `SimulatedDomain` and writes only what differs, as a sqlglot dialect
does:

* `level_from_layout(layout, scenario)`: the placed layout as the domain's level;
* `scene(level, action)`: the level as physics (a physc.simulation.scene.Scene), the
  action taken (None: no action);
* `rules(level)`: the run's rules (physc.simulation.run.RunRules: when the goal is met,
  when the run is over), and `seconds`, `stable_limit`;
* its parts (physc.domains.part), each a small base class with defaults: `actions`
  (physc.domains.actions: the candidate actions, their noise, the line the search moves one
  along, their record in a task file, the random agent's draw), `search`
  (physc.domains.search_hooks: the bodies a new object may take and their physics, the static
  bar that blocks forbidden hits, distractors, the search's settings) and, as every domain,
  `files` (physc.domains.level_files) and `evaluation` (physc.domains.evaluation: a benchmark's
  acceptance rule, the agent of accidental solvability). A domain whose rules are made
  with its scene (angrybirds: the game keeps the level's lives and birds) writes
  `simulation(level, action, ending)`, the two at once, instead, and declares it.

Everything else is physc's: every play through the generic loop (`play`, `playout`, each
ending as physc.simulation.ending.Ending says), the search that makes a placed layout a task
(physc.search.search, which the layout loop runs for a domain that declares
`satisfy`), the robustness replays, stability, the replays of `physc verify` and the
evaluation's measurements of intended solvability and fidelity.
"""

from __future__ import annotations

from typing import Any

import attrs

from physc.domains.actions import Actions
from physc.domains.base import Domain, MissingCapability
from physc.domains.part import part
from physc.domains.search_hooks import SearchHooks
from physc.simulation.ending import Ending
from physc.simulation.recognise import Recogniser
from physc.simulation.run import RunRules
from physc.simulation.scene import Scene, play_scene, playout
from physc.simulation.stability import stable
from physc.simulation.trace import Playout, Trace

# What a simulated domain must write for generation (checked before `satisfy` runs).
HOOKS = ("level_from_layout", "scene", "actions")


def search_needs(domain: SimulatedDomain) -> tuple[str, ...]:
    """The hooks the search needs that a simulated domain must write (E0703 before any work if it
    lacks one): a domain that writes `simulation` (its scene made with its rules), or `play` (a
    world with no physics engine of physc's), needs no `scene`."""
    own = {"simulation", "play"} & domain.capabilities
    return tuple(h for h in HOOKS if not (own and h == "scene"))


class SimulatedDomain(Domain):
    """The base class of a one-action domain (module docstring): the generation, replay and
    measurement hooks of `Domain` from a few of its own."""

    @property
    def recogniser(self) -> Recogniser:
        """The recognition of interactions in the domain's world (thresholds in its units, its kinds)."""
        return self.world.recogniser

    @property
    def margin_reader(self):
        """How the domain reads each link's margin from a trace (physc.simulation.margins): the
        generic reader, which a domain whose physics says more about a link extends."""
        from physc.simulation.margins import MarginReader

        return MarginReader

    def margins(self, scenario, trace: Trace, through: int | None = None, ahead: bool = False):
        """How far each declared link and restriction of `scenario` was from failing in `trace`
        (with `through`: of the first `through` links, and the restrictions until the last of them;
        with `ahead` too, what the link after them needs of the play, MarginReader.ahead: a
        stage that ends where the player acts again)."""
        reader = self.margin_reader(self.recogniser)
        margins = reader.read(scenario, trace, through)
        needed = reader.ahead(scenario, trace, through) if ahead and through is not None else None
        return margins if needed is None else attrs.evolve(margins, links=margins.links + (needed,))

    seconds: float = 10.0
    """A play's simulated time at most."""

    stable_limit: float = 0.05
    """How far (in the domain's units) a body may move, left alone for `seconds`, in a level
    that stands."""

    still_start: bool = True
    """Whether a scene must stand still before the action (the paper's physical stability). A
    world whose scenes may already move (PHYRE: a ball falling onto a shelf, a stick toppling)
    sets False: its scene is acceptable when, left alone, it does not solve itself (PHYRE's rule:
    no action at all must not solve a task)."""

    robustness_replays = 6  # noisy replays a generated solution must pass

    capabilities = frozenset({"satisfy", "replay", "stability"})
    """physc's search makes its tasks, replays its solutions and measures its levels' stability;
    a subclass adds what it writes (`Domain.capabilities`), and for the search declares
    `level_from_layout`, `actions`, and `scene` (with `rules`), or `simulation` (the two made
    together), or `play` (a world no physc engine runs); optionally `distractors` and
    `random_action` (the evaluation's random agent)."""

    # ---- what the domain writes ---------------------------------------------------------
    def level_from_layout(self, layout, scenario) -> Any:
        """The placed layout (a ConcreteLayout) of `scenario` as the domain's level."""
        raise MissingCapability(self.name, ("level_from_layout",), "generating a task")

    def scene(self, level, action) -> Scene:
        """The level as physics, with `action` taken (None: the level left alone)."""
        raise MissingCapability(self.name, ("scene",), "simulating a level")

    def rules(self, level) -> RunRules:
        """The rules of a run in `level` (when the goal is met, when the run is over): a new
        object per run, as rules keep the run's state."""
        return RunRules()

    # ---- what the search asks, with defaults ----------------------------------------------
    actions = part(Actions)
    """The player's actions (physc.domains.actions): the candidates, their noise, the line the
    search moves one along, their record in a task file."""

    search = part(SearchHooks)
    """What the search may ask beyond levels and actions (physc.domains.search_hooks): bodies and
    their physics, obstacles, distractors, the domain's own local changes, budgets."""

    # ---- what physc does with them --------------------------------------------------------
    def simulation(self, level, action, ending: Ending) -> tuple[Scene, RunRules]:
        """A play of `level` with `action` for the generic loop: its scene and its rules, fresh
        (rules keep a run's state). The default: `scene` and `rules`, plain rules for a `STILL`
        play. A domain whose rules are made with its scene (angrybirds: the game's objects, lives
        and birds) writes this instead of the two, and declares `simulation`."""
        return self.scene(level, action), (RunRules() if ending is Ending.STILL else self.rules(level))

    def play(
        self, level, action, scenario=None, seconds: float | None = None, ending: Ending = Ending.READ, resume=None
    ) -> Trace:
        """`level` played with `action` in the selected backend for `seconds` at most (each
        turn's), ending as `ending` says; its interactions recognised where the ending reads them,
        and judged against `scenario`'s restrictions and declared bounces when one is given.
        `resume`: a snapshot of an earlier run to go on from (physc.simulation.snapshot)."""
        restrictions = scenario.restrictions if scenario is not None else ()
        redirects = (
            {tuple(t.objects) for t in scenario.interactions if t.name == "bounce"} if scenario is not None else None
        )
        scene, rules = self.simulation(level, action, ending)
        return play_scene(
            scene,
            self.backend,
            rules,
            seconds or self.seconds,
            self.recogniser,
            restrictions,
            redirects,
            ending.recognised,
            resume,
        )

    def playout(self, level, action, seconds: float | None = None, ending: Ending = Ending.OUTCOME) -> Playout:
        """`level` played with `action` to its outcome alone (physc.simulation.scene.playout):
        solved, when, what was destroyed and where the bodies end, as `play` would say, without
        recording or recognising what no verdict reads. What acceptance, the random agent, the
        simulation cache and the agents' environments ask. With `Ending.SETTLED`, it stops once
        the outcome is settled (a verdict that reads nothing else)."""
        scene, rules = self.simulation(level, action, ending)
        return playout(scene, self.backend, rules, seconds or self.seconds, ending is not Ending.SETTLED)

    def replay(self, level, solution, scenario, rng=None) -> Trace:
        """The solution played in `level`, judged against `scenario`; with `rng`, a noisy replay
        under the domain's noise model (`actions.noisy`, the one the search's replays draw)."""
        action = self.actions.action_of(solution)
        if rng is not None:
            level, action = self.actions.noisy(level, action, rng)
        return self.play(level, action, scenario)

    def stability(self, level) -> tuple[bool, float]:
        """(stable, the largest shift) of `level` left alone for all of `seconds` (`Ending.STILL`:
        a domain's rules that may stop once all is still must not, as something that starts to tip
        slowly must not pass for standing). With `still_start` False, "stable" is PHYRE's
        acceptance of a scene: left alone, it does not solve itself (the shift is still reported)."""
        if self.still_start:
            return stable(self.play(level, None, ending=Ending.STILL), self.stable_limit)
        alone = self.play(level, None, ending=Ending.OUTCOME)
        return not alone.solved, stable(alone, self.stable_limit)[1]
