"""The state of one search, as two values: what it reads (`Problem`) and what it writes (`Ledger`).

The search of one placed layout (physc.search.search) is a few steps in turn: the chain
built stage by stage (chain.py), its margins raised (strengthen.py), guards, distractors,
validation and acceptance. Each step is a function of the `Problem`, a frozen value of
everything fixed for the layout (the bound domain, the scenario, the layout as placed, the
search's settings, which objects enter at which stage), and of the `Ledger`, the one record
every step writes to as it goes (the simulations run and kept, how far the chain got, what
noise broke and how near a fragile solution came). No step keeps state of its own.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import cast

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.layout_rules import LayoutRules
from physc.compiler.sequence import pushes
from physc.domains.simulated import SimulatedDomain
from physc.dsl.scenario import ScenarioIR, TermIR
from physc.search import placing
from physc.search.attempt import Attempt
from physc.search.chain_stages import ChainStage, introduced, stages
from physc.search.evaluator import Evaluator
from physc.search.funnel import Passage
from physc.search.settings import SETTINGS, SearchSettings
from physc.simulation.ending import Ending
from physc.simulation.fidelity import fidelity
from physc.simulation.margins import Margin
from physc.simulation.snapshot import Snapshot
from physc.simulation.trace import Trace

KEPT_SIMULATIONS = 256  # the search's last simulations, kept: backtracking meets the same scene again


def search_seconds(domain: SimulatedDomain) -> float:
    """A play's simulated time at most while `domain` is searched (each turn's): its search's
    `seconds`, else the domain's."""
    return domain.search.seconds or domain.seconds


def _parameters(domain: SimulatedDomain) -> LayoutParameters:
    """The domain's layout parameters: a layout is searched only after the layout stages, which need them."""
    parameters = domain.layout_parameters
    assert parameters is not None, "a layout is searched only after the layout stages, which need its parameters"
    return parameters


@attrs.frozen
class Checks:
    """What the search checks of a realised, robust chain besides its physics: the run's choices
    (RunSettings.checks), the only part of the run's settings the search reads."""

    validate: bool = True  # the task is validated (replayed whole, `--no-validate`: not)
    acceptance: bool = True  # the domain's acceptance rule judges it (`--no-acceptance`: not)


ALL_CHECKS = Checks()  # the default: the task validated and judged by the acceptance rule


@attrs.frozen
class Problem:
    """What one search reads and never changes."""

    domain: SimulatedDomain  # bound to its world and engine (Domain.at)
    scenario: ScenarioIR  # the checked scenario
    placed: ConcreteLayout  # the layout as placed; the steps make new ones
    settings: SearchSettings
    supports: placing.Supports  # what rests on what, what never moves onto a path
    entry: dict[str, int]  # object → the interaction at which it enters the scene
    plan: tuple[ChainStage, ...]
    players: frozenset[str]  # the player's objects (the bird)
    accept: int  # noisy replays a solution must pass (fewer: a fallback's)
    checks: Checks = ALL_CHECKS  # the run's checks: validation, the acceptance rule
    action_starts: tuple[int, ...] = ()  # the interactions at which a later action of the player starts

    @classmethod
    def of(
        cls,
        domain: SimulatedDomain,
        scenario: ScenarioIR,
        layout: ConcreteLayout,
        accept: int,
        checks: Checks = ALL_CHECKS,
    ) -> Problem:
        vocabulary = domain.vocabulary
        carried = [
            (t.objects[0], t.objects[1])
            for t in scenario.restrictions
            if (term := vocabulary.term(t.name)) is not None and term.carries
        ]
        starts = tuple(domain.actions.starts(scenario))
        entry = introduced(layout, scenario.interactions, carried)
        if starts:  # several actions of the player: each later one's stage keeps a goal to act for
            entry = goals_kept(entry, scenario, starts, vocabulary.goal)
        return cls(
            domain,
            scenario,
            layout,
            domain.search.settings or SETTINGS,
            placing.Supports.of(layout, _parameters(domain)),
            entry,
            tuple(stages(scenario.interactions, entry, starts)),
            frozenset(o.name for o in scenario.objects if o.term == domain.vocabulary.player),
            accept,
            checks,
            starts,
        )

    @property
    def interactions(self) -> tuple[TermIR, ...]:
        return self.scenario.interactions

    @property
    def seconds(self) -> float:
        """A play's simulated time at most while searching (each turn's)."""
        return search_seconds(self.domain)

    @property
    def parameters(self) -> LayoutParameters:
        """The layout's QSR distances and placement area (the domain's)."""
        return _parameters(self.domain)

    @property
    def rules(self) -> LayoutRules:
        """The domain's layout rules (what placed the layout searched)."""
        rules = self.domain.layout_rules
        assert rules is not None, "a layout is searched only after the layout stages, which need the domain's rules"
        return rules

    @property
    def scale(self) -> float:
        """Layout lengths per length of the simulation."""
        return self.domain.search.trace_scale

    def level_of(self, layout: ConcreteLayout) -> object:
        return self.domain.level_from_layout(layout, self.scenario)

    def pushed_by(self, k: int) -> str | None:
        """The way ("left" or "right") the hit `interactions[k]` pushes its target, if known
        (physc.compiler.sequence.pushes, with the domain's heading of the player's object)."""
        pushed = pushes(self.interactions, k, self.players, self.rules.player_heading)
        return pushed if pushed in ("left", "right") else None

    def heading_after(self, name: str, index: int) -> str | None:
        """The way `name` next rolls or slides, from interaction `index` on."""
        term = next(
            (t for t in self.interactions[index:] if t.name in ("roll", "slide") and t.objects[0] == name), None
        )
        return None if term is None else term.directions[0]


def goals_kept(entry: dict[str, int], scenario: ScenarioIR, starts: tuple[int, ...], goal: str) -> dict[str, int]:
    """`entry` with, at each later action's start, a goal object left in the scene: a domain's
    world may end once every goal in it is met (Science Birds: every pig destroyed), and a
    stage's scene holds only what has entered, so a later shot whose own goal enters after it
    starts would never be taken. The first goal object the sequence meets from that start on
    enters there instead, unless one that enters by then is still to be met."""
    entry = dict(entry)
    goals = [o.name for o in scenario.objects if o.term == goal]
    met = {}
    for k, term in enumerate(scenario.interactions):
        for name in term.objects:
            if name in goals:
                met[name] = k  # the last interaction that names it
    for start in starts:
        later = [g for g in goals if met.get(g, -1) >= start and g in entry]
        if later and not any(entry[g] <= start for g in later):
            first = min(later, key=lambda g: entry[g])
            entry[first] = start
    return entry


@attrs.define
class Ledger:
    """What one search writes as it goes."""

    evaluator: Evaluator = attrs.field(factory=lambda: Evaluator(KEPT_SIMULATIONS))
    best: int = 0  # most interactions realised in order by one play
    furthest: Attempt | None = None  # the play that came furthest
    furthest_layout: ConcreteLayout | None = None  # the layout it was played in
    nearest: int = 0  # most noisy replays passed by a working action given up as fragile
    tried: int = 0  # working actions put through the noisy replays
    # declared term → (failed noisy replays that lost it first, what the first shows)
    lost: dict[str, tuple[int, str]] = attrs.field(factory=dict)
    variants_tried: int = 0
    screened: list[str] = attrs.field(factory=list)  # labels of the first stage's actions that came nearest
    failed: dict[int, Attempt] = attrs.field(factory=dict)  # stage → the best attempt of a variant that failed there
    failed_layout: dict[int, ConcreteLayout] = attrs.field(factory=dict)  # stage → the layout it failed in
    weakest: Margin | None = None  # the strongest weakest link of a chain realised but not robust (exit 3 names it)
    raised: int = 0  # candidates the raising of margins judged (raising.py)
    stages_raised: int = 0  # stages whose margins were raised (physc.search.chain)
    passage: Passage = attrs.field(factory=Passage)  # the layout's way down the chain (physc.search.funnel)

    @property
    def simulations(self) -> int:
        return self.evaluator.simulations

    def turn(self, stage: tuple[int, int] | None) -> None:
        """The search turns to `stage` of the chain (funnel.AFTER: past it; None: done)."""
        self.passage.enter(stage, self.simulations)


def simulate(
    problem: Problem,
    ledger: Ledger,
    layout: ConcreteLayout,
    action: object,
    seconds: float | None = None,
    resume: Snapshot | None = None,
) -> Attempt:
    """`action` played in `layout`'s level for `seconds` (default: the search's, `Problem.seconds`), from the
    snapshot `resume` if given, judged against the scenario; run once while among the last
    KEPT_SIMULATIONS asked for. The ledger notes how far it got."""
    key = (seconds, layout.objects, action, resume is not None and resume.step)

    def play() -> Trace:  # `resume` passed only when given: a domain's own `play` may not take it
        level, time = problem.level_of(layout), seconds or problem.seconds
        if resume is None:
            return problem.domain.play(level, action, problem.scenario, time)
        return problem.domain.play(level, action, problem.scenario, time, resume=resume)

    trace = ledger.evaluator.kept(key, play)
    attempt = Attempt("", action, trace, fidelity(problem.scenario, trace))
    ledger.best = max(ledger.best, attempt.fidelity.matched)
    if ledger.furthest is None or attempt.fidelity.score > ledger.furthest.fidelity.score:
        ledger.furthest, ledger.furthest_layout = attempt, layout
    return attempt


def replayed(problem: Problem, ledger: Ledger, level: object, action: object, label: str = "") -> Attempt:
    """`action` played in `level` once more, judged against the scenario (uncached: a noisy
    replay, a guard's try, the final play)."""
    trace = ledger.evaluator.run(lambda: problem.domain.play(level, action, problem.scenario, problem.seconds))
    return Attempt(label, action, trace, fidelity(problem.scenario, trace))


def play_in(
    problem: Problem, ledger: Ledger, level: object, action: object, scenario=None, ending: Ending = Ending.READ
) -> Callable[[object], Trace]:
    """One play of `action` in `level` in a given reading of the world (the domain itself in its
    own; Domain.at in another), judged against `scenario` if given, ending as `ending` says,
    counted by the ledger's evaluator: the `run` physc.worlds.under_readings takes."""
    domain = problem.domain

    def run(reading) -> Trace:
        there = domain if reading is domain.world else cast(SimulatedDomain, domain.at(reading))  # Domain.at: its class
        return ledger.evaluator.run(lambda: there.play(level, action, scenario, problem.seconds, ending))

    return run
