"""The driver of one run: the compiler's passes in order, then the layout loop, for one
scenario and one seed, within one time budget.

Every stage's result is computed once and cached, so `--emit qsr` and `--emit
layout` of the same scenario and seed run the same passes on the same random
stream. The one random generator (`random.Random(seed)`) is handed to the passes
explicitly, in pipeline order; nothing else draws random numbers.

The run owns its deadline (`within_budget`): started once, when its work starts, it
covers the generation and whatever the caller does with the result within the same
block (a picture of the task), and an overrun comes out as one Infeasible.
"""

from __future__ import annotations

import contextlib
import functools
import random
from collections.abc import Callable, Iterator, Sequence
from typing import cast

import attrs

from physc import budget
from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.dimension_graphs import DimensionGraphs
from physc.compiler.infeasible import Exhausted, Infeasible
from physc.compiler.infer_layout import InferLayout
from physc.compiler.layout_graph import LayoutGraph
from physc.compiler.passes import PassContext, rules_of
from physc.compiler.place import Place
from physc.compiler.qsr_dnf import QsrDnf
from physc.compiler.task import Task
from physc.compiler.to_dimension_graphs import ToDimensionGraphs
from physc.compiler.to_qsr import ToQsr
from physc.domains import world_name
from physc.domains.base import Domain
from physc.domains.simulated import SimulatedDomain
from physc.driver.layout_loop import LayoutLoop, Progress
from physc.driver.run_settings import RunSettings
from physc.dsl.scenario import ScenarioIR
from physc.search.link_model import KindedExample

PLACEMENT_BUDGET = 200  # consistent conjunctions that placement may try
DEFAULT_SETTINGS = RunSettings()  # a run's budgets and checks when none are given


@attrs.frozen
class Placed:
    graphs: DimensionGraphs
    layout: ConcreteLayout
    structure: str = "flat"  # the layout rules' structure it was placed in


class Pipeline:
    def __init__(
        self,
        domain: Domain,
        scenario: ScenarioIR,
        seed: int = 0,
        settings: RunSettings = DEFAULT_SETTINGS,
        source: str = "",
        progress: Callable[[Progress], None] | None = None,
        earlier: Sequence[KindedExample] = (),
    ):
        self.domain = domain
        self.scenario = scenario
        self.seed = seed
        self.settings = settings  # the run's budgets and checks, as one value (physc.driver.run_settings)
        self.source = source
        self.rng = random.Random(seed)
        # Called after each layout given up, with a Progress: long generations say how
        # they are doing instead of one line for minutes.
        self.progress = progress
        # A dataset's task learns from its scenario's earlier tasks (physc.dataset.waves): the
        # examples their compiles taught; `taught`, once the task is made (or not), is this one's.
        self.earlier = earlier
        self.taught: list[KindedExample] = []

    @functools.cached_property
    def deadline(self) -> budget.Deadline:
        """The run's time budget, started when it is first asked for: when the run's work
        starts (`within_budget`), not when the pipeline is made."""
        return budget.Deadline(self.settings.time_budget)

    @contextlib.contextmanager
    def within_budget(self, stage: str = "task"):
        """The rest of this run, within its one time budget: the stages computed inside the
        block, and what the caller does with them there (a picture of the task), stop at
        their next stopping point once `time_budget` seconds have passed since the first
        such block began. An overrun that the layout loop has not already explained is
        Infeasible(`stage`, budget=Exhausted.TIME)."""
        try:
            with budget.deadline(self.deadline):
                yield
        except budget.OutOfTime:
            raise Infeasible(
                stage, f"the time budget of {self.settings.time_budget:g} s ran out", budget=Exhausted.TIME
            ) from None

    @functools.cached_property
    def context(self) -> PassContext:
        """What every pass reads besides its input: the scenario, the one generator, the seed."""
        return PassContext(self.scenario, self.rng, self.seed)

    @functools.cached_property
    def layout_graph(self) -> LayoutGraph:
        return InferLayout(self.domain).run(self.scenario, self.context)

    @functools.cached_property
    def qsr(self) -> QsrDnf:
        return ToQsr().run(self.layout_graph, self.context)

    @functools.cached_property
    def structures(self) -> tuple[str, ...]:
        """The structures the scenario can be laid out in (physc.compiler.layout_rules,
        "Structures"): the paper's reading first."""
        return rules_of(self.domain).structures(self.scenario)

    @functools.cached_property
    def placed(self) -> Placed:
        return next(self.placements())

    def placements(self) -> Iterator[Placed]:
        """Placed layouts, one after the other: with one structure, from its next consistent
        conjunctions; with several, a layout of each in turn, so that simulation decides which
        structure carries the chain (a structure whose placements run out drops out; the
        paper's reading's failure is reported when all have)."""
        self.check_players()
        if len(self.structures) == 1:
            yield from self._placements("flat", self.layout_graph, self.qsr)
            return
        streams = [
            self._placements(s, InferLayout(self.domain, s).run(self.scenario, self.context), None)
            for s in self.structures
        ]
        failures: list[Infeasible] = []
        while streams:
            for stream in list(streams):
                try:
                    yield next(stream)
                except Infeasible as error:
                    failures.append(error)
                    streams.remove(stream)
        raise failures[0]

    def check_players(self) -> None:
        """Infeasible (E0804) for more of the player's objects than the domain places (its
        vocabulary's `players`; physc check warns of it, W0302)."""
        vocabulary = self.domain.vocabulary
        most = getattr(vocabulary, "players", None)
        players = [o.name for o in self.scenario.objects if o.term == vocabulary.player]
        if most is not None and len(players) > most:
            raise Infeasible(
                "place",
                f"it has {len(players)} {vocabulary.player}s ({', '.join(players)}); "
                f"the domain's actions place at most {most}",
                budget=Exhausted.VERSION,
            )

    def _placements(self, structure: str, graph: LayoutGraph, dnf: QsrDnf | None) -> Iterator[Placed]:
        """The placed layouts of one structure's layout graph."""
        dnf = dnf or ToQsr().run(graph, self.context)
        context = attrs.evolve(self.context, layout_graph=graph, deferred=dnf.deferred)
        search = ToDimensionGraphs(self.domain, self.settings.clause_budget).run(dnf, context)
        place = Place(self.domain)
        consistent = 0
        try:
            for graphs in search:
                consistent += 1
                layout = place.run(graphs, context)
                if layout is not None:
                    yield Placed(graphs, layout, structure)
                if consistent >= PLACEMENT_BUDGET:
                    raise Infeasible(
                        Place.name,
                        f"{consistent} consistent conjunctions were found, but no placement kept the objects "
                        "apart and the player's first targets in reach",
                        tried=graphs.conjunctions_tried,
                        budget=Exhausted.PLACEMENTS,
                    )
        except Infeasible as error:
            if consistent and not error.budget:
                raise Infeasible(
                    Place.name,
                    f"{consistent} conjunctions were consistent, but none could be placed "
                    "(objects overlap, or the player cannot reach its first target)",
                    tried=error.tried,
                ) from None
            raise
        raise AssertionError("the search ends by raising Infeasible")

    @functools.cached_property
    def task(self) -> Task:
        """Generate the task: the layout loop over the placed layouts, within the budgets of
        layouts and time. The time budget covers everything, the fallbacks included: the
        work stops at its next stopping point (a simulated step, a clause choice) once the
        time is spent."""
        # The task stage needs `satisfy`, which `require` checked before any work: the capability
        # SimulatedDomain declares (physc.domains.base), so the domain is one.
        loop = LayoutLoop(
            cast(SimulatedDomain, self.domain), self.scenario, self.seed, self.settings, self.progress, self.earlier
        )
        try:
            with self.within_budget():
                generated = loop.run(self.placements())
        finally:
            self.taught = loop.model.taught()
        parts = generated.outcome.parts
        assert parts is not None, "the layout loop's outcome is satisfied"
        # The search's Parts are the Task's own fields, passed whole; the rest is what only the
        # run knows (the scenario, seed, world and engine) and what the layout loop counted.
        return Task(
            **attrs.asdict(parts, recurse=False),
            scenario=self.scenario.name,
            domain=self.domain.name,
            seed=self.seed,
            world=world_name(self.domain),
            backend=self.domain.backend.name,
            source=self.source,
            fallback=parts.robustness[0] < parts.robustness[1],
            structure=generated.placed.structure,
            layouts_tried=generated.layouts,
            conjunctions_tried=generated.placed.layout.conjunctions_tried,
            simulations=generated.simulations,
            given_up=generated.given_up,
            seconds={k: round(v, 4) for k, v in generated.seconds.items()},
            funnel=generated.funnel,
            proposals=generated.proposals,
        )
