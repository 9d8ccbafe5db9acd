"""The compiler pipeline: the passes in order, for one scenario and one seed.

Every stage's result is computed once and cached, so `--emit qsr` and `--emit
layout` of the same scenario and seed run the same passes on the same random
stream. The one random generator (`random.Random(seed)`) is handed to the passes
explicitly, in pipeline order; nothing else draws random numbers.
"""

from __future__ import annotations

import functools
import random
import time

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.dimension_graphs import DimensionGraphs
from physc import budget
from physc.compiler.infeasible import LAYOUT_BUDGET as LAYOUTS_RAN_OUT
from physc.compiler.infeasible import PLACEMENT_BUDGET as PLACEMENTS_RAN_OUT
from physc.compiler.infeasible import TIME_BUDGET as TIME_RAN_OUT
from physc.compiler.infeasible import Infeasible
from physc.compiler.infer_layout import InferLayout
from physc.compiler.layout_graph import LayoutGraph
from physc.compiler.place import Place
from physc.compiler.qsr_dnf import QsrDnf
from physc.compiler.task import LAYOUT_BUDGET, MIN_ROBUSTNESS, TIME_BUDGET, Task, given_up_summary
from physc.compiler.to_dimension_graphs import DEFAULT_NODE_BUDGET, ToDimensionGraphs
from physc.compiler.to_qsr import ToQsr
from physc.dsl.scenario import ScenarioIR

PLACEMENT_BUDGET = 200  # consistent conjunctions that placement may try
FALLBACKS = 6  # fragile layouts tried again, most robust first, when no layout gave a robust solution


@attrs.frozen
class Progress:
    """How a generation is doing, after each layout given up."""

    layouts: int
    simulations: int
    seconds: float
    best: int  # most interactions of the sequence realised, in order, in one simulation
    interactions: int


@attrs.frozen
class Placed:
    graphs: DimensionGraphs
    layout: ConcreteLayout


class Pipeline:
    def __init__(
        self,
        domain,
        scenario: ScenarioIR,
        seed: int = 0,
        budget: int = DEFAULT_NODE_BUDGET,
        validate: bool = True,
        layout_budget: int = LAYOUT_BUDGET,
        time_budget: float = TIME_BUDGET,
        source: str = "",
        min_robustness: int = MIN_ROBUSTNESS,
        progress=None,
    ):
        self.domain = domain
        self.scenario = scenario
        self.seed = seed
        self.budget = budget  # clause choices the search may try per shape draw
        self.validate = validate
        self.layout_budget = layout_budget  # layouts that simulation may try
        self.time_budget = time_budget  # seconds for the whole generation
        self.source = source
        # Noisy replays (of the domain's robustness_replays) that a solution must pass at
        # least: when no layout within the budget gives one that passes them all, the most
        # robust of the fragile ones that pass this many is used (a fallback). All of
        # them: no fallbacks.
        self.min_robustness = min_robustness
        self.rng = random.Random(seed)
        # Called after each layout given up, with a Progress: long generations say how
        # they are doing instead of one line for minutes.
        self.progress = progress

    @functools.cached_property
    def layout_graph(self) -> LayoutGraph:
        return InferLayout(self.domain).run(self.scenario)

    @functools.cached_property
    def qsr(self) -> QsrDnf:
        return ToQsr().run(self.layout_graph, self.rng, self.seed)

    @functools.cached_property
    def placed(self) -> Placed:
        return next(self.placements())

    def placements(self):
        """Placed layouts, one after the other, from the next consistent conjunctions."""
        dnf = self.qsr
        search = ToDimensionGraphs(self.domain, self.budget).run(dnf, self.layout_graph, self.scenario, self.rng)
        place = Place(self.domain)
        consistent = 0
        try:
            for graphs in search:
                consistent += 1
                layout = place.run(graphs, self.scenario, dnf.deferred, self.rng)
                if layout is not None:
                    yield Placed(graphs, layout)
                if consistent >= PLACEMENT_BUDGET:
                    raise Infeasible(
                        Place.name,
                        f"{consistent} consistent conjunctions were found, but no placement kept the objects "
                        "apart and the bird's targets in reach",
                        tried=graphs.conjunctions_tried,
                        budget=PLACEMENTS_RAN_OUT,
                    )
        except Infeasible as error:
            if consistent and not error.budget:
                raise Infeasible(
                    Place.name,
                    f"{consistent} conjunctions were consistent, but none could be placed "
                    "(objects overlap, or the bird cannot reach its target)",
                    tried=error.tried,
                ) from None
            raise
        raise AssertionError("the search ends by raising Infeasible")

    def fallback(self, fragile: list):
        """No solution survived every noisy replay: the layouts given up as fragile, most
        robust first, satisfied again accepting min_robustness replays. (simulations, the
        outcome, its layout) of the first that succeeds, or None."""
        simulations = 0
        for _, _, layout in sorted(fragile, key=lambda item: item[:2])[:FALLBACKS]:
            result = self.domain.satisfy(self.scenario, layout, self.rng, self.validate, accept=self.min_robustness)
            simulations += result.simulations
            if result.satisfied:
                return simulations, result, layout
        return None

    def _out_of_time(self, layouts: int, started: float) -> Infeasible:
        return Infeasible(
            "satisfy",
            f"the time budget of {self.time_budget:g} s ran out after {layouts} "
            f"{'layout' if layouts == 1 else 'layouts'} ({time.perf_counter() - started:.1f} s)",
            budget=TIME_RAN_OUT,
        )

    def explained(self, failure: Infeasible, nearest: int, given_up: dict, best: int = 0) -> Infeasible:
        """The failure, with why the layouts were given up, how far the best simulation got,
        the most robust fragile solution found and what would accept it."""
        message = failure.message
        if best:
            message += f"; the best simulation realised {best} of the {len(self.scenario.interactions)} interactions in order"
        if given_up:
            message += f"; given up: {given_up_summary(given_up)}"
        if nearest:
            if nearest < self.min_robustness:
                hint = f"--min-robustness {nearest} accepts such a one"
            elif failure.budget == TIME_RAN_OUT:
                hint = "no time was left to try it again as a fallback"
            else:
                hint = "tried again as a fallback, it failed"
            message += f"; the most robust solution found passed {nearest} of {self.domain.robustness_replays} noisy replays ({hint})"
        return Infeasible(failure.stage, message, tried=failure.tried, budget=failure.budget)

    @functools.cached_property
    def task(self) -> Task:
        """Generate the task: layouts one after another until simulation-based
        satisfaction succeeds, within the budgets of layouts and time. The time budget
        covers everything, the fallbacks included: the work stops at its next stopping
        point (a simulated step, a clause choice) once the time is spent."""
        with budget.deadline(self.time_budget):
            return self._generate()

    def _generate(self) -> Task:
        started = time.perf_counter()
        seconds = {"layout": 0.0, "satisfy": 0.0}
        layouts = simulations = 0
        fragile: list[tuple[int, int, ConcreteLayout]] = []  # (-replays passed, order, layout)
        nearest = 0  # most noisy replays passed by a solution given up as too fragile
        best = 0  # most interactions of the sequence realised, in order, in any simulation
        given_up: dict[str, dict[str, int]] = {}  # why → layouts, simulations (Task.given_up)
        clock = time.perf_counter()
        placements = self.placements()
        while True:
            try:
                placed = next(placements)
            except Infeasible as error:
                if not layouts:
                    raise
                failure = Infeasible(
                    "satisfy",
                    f"{layouts} layouts were placed, but in none did the simulated solution realise the sequence",
                    tried=error.tried,
                    budget=error.budget,
                )
                break
            except budget.OutOfTime:
                failure = self._out_of_time(layouts, started)
                break
            layouts += 1
            seconds["layout"] += time.perf_counter() - clock
            clock = time.perf_counter()
            try:
                result = self.domain.satisfy(self.scenario, placed.layout, self.rng, self.validate)
            except budget.OutOfTime:
                failure = self._out_of_time(layouts, started)
                break
            finally:
                seconds["satisfy"] += time.perf_counter() - clock
            simulations += result.simulations
            best = max(best, getattr(result, "best", 0))
            if result.satisfied:
                failure, used = None, placed.layout
                break
            nearest = max(nearest, result.nearest)
            why = given_up.setdefault(getattr(result, "given_up", "") or "not said", {"layouts": 0, "simulations": 0})
            why["layouts"] += 1
            why["simulations"] += result.simulations
            if result.nearest >= self.min_robustness:
                fragile.append((-result.nearest, layouts, placed.layout))
            if self.progress is not None:
                self.progress(Progress(layouts, simulations, time.perf_counter() - started, best, len(self.scenario.interactions)))
            if layouts >= self.layout_budget:
                failure = Infeasible(
                    "satisfy",
                    f"no layout realised the sequence in simulation within the budget "
                    f"({layouts} layouts, {time.perf_counter() - started:.1f} s)",
                    tried=placed.layout.conjunctions_tried,
                    budget=LAYOUTS_RAN_OUT,
                )
                break
            clock = time.perf_counter()
        if failure is not None:
            clock = time.perf_counter()
            try:
                fallback = None if failure.budget == TIME_RAN_OUT else self.fallback(fragile)
            except budget.OutOfTime:
                failure, fallback = self._out_of_time(layouts, started), None
            seconds["satisfy"] += time.perf_counter() - clock
            if fallback is None:
                raise self.explained(failure, nearest, given_up, best)
            simulated, result, used = fallback
            simulations += simulated
        # The domain's own stages after satisfaction (angrybirds: distract, validate), if it
        # times them, counted apart from it.
        for stage, spent in getattr(result, "seconds", {}).items():
            seconds["satisfy"] -= spent
            seconds[stage] = spent
        seconds["total"] = time.perf_counter() - started
        parts = result.parts
        return Task(
            scenario=self.scenario.name,
            domain=self.domain.name,
            seed=self.seed,
            source=self.source,
            level=parts.level,
            solution=parts.solution,
            trace=parts.trace,
            validated=parts.validated,
            robustness=parts.robustness,
            repairs=parts.repairs,
            obstacles=parts.obstacles,
            distractors=parts.distractors,
            layouts_tried=layouts,
            conjunctions_tried=used.conjunctions_tried,
            simulations=simulations,
            given_up=given_up,
            seconds={k: round(v, 4) for k, v in seconds.items()},
        )
