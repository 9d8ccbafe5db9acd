"""The layout loop: placed layouts, one after another, until one gives a task.

Generation is a search over layouts. For each layout the placement passes offer, physc's
one search (search.py, with the hooks of a SimulatedDomain) says whether it gives a task,
and if not, why it was given up and how robust its best solution was. The
loop keeps the budgets (`--layouts`, and `--time-budget` through `physc.budget`),
counts what each layout cost and why it was given up, reports progress, and when the
budget ends without a robust task, tries the most robust fragile layouts again as
fallbacks (`--min-robustness`). Nothing here depends on a domain.
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator

import attrs

from physc import budget
from physc.compiler.infeasible import Exhausted, Infeasible
from physc.compiler.task import given_up_summary
from physc.driver.run_settings import RunSettings
from physc.search import elsewhere, search
from physc.search.verify import noisy_replays, verify

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
class Generated:
    """The outcome of the layout loop: the search's satisfied outcome, the layout it
    came from, and what the search cost."""

    outcome: object  # the search's Outcome (search.satisfy), satisfied
    placed: object  # what it came from (the pipeline's Placed: its `layout`, and its `structure`)
    layouts: int
    simulations: int
    given_up: dict  # why → {"layouts": n, "simulations": n}
    seconds: dict  # "layout" (placement), "satisfy", and the stages after satisfaction


@attrs.define
class LayoutLoop:
    domain: object
    scenario: object
    rng: object
    settings: RunSettings  # the run's budgets and checks (physc.driver.run_settings)
    progress: Callable[[Progress], None] | None = None

    @property
    def min_robustness(self) -> int:
        """Noisy replays a solution must pass at least: fragile layouts that passed this many
        are fallbacks."""
        return self.settings.robustness(self.domain)

    def satisfy(self, layout, accept: int | None = None):
        """The search's satisfaction of one layout with the domain's hooks (accepting `accept`
        noisy replays, for a fallback), then the checks that it holds where it is played."""
        result = search.satisfy(self.domain, self.scenario, layout, self.rng, self.settings.checks, accept)
        return self.checked(result, accept) if result.satisfied else result

    def checked(self, result, accept: int | None):
        """`result`, if its solution passes what `physc verify` runs (the recorded solution
        and the domain's noisy replays, drawn as verify draws them) under every reading of
        what the world's files leave open that can change a replay (physc.worlds.under_readings),
        and in the second backend if one is asked for; else the layout given up for that
        reason (the search goes on to the next layout). `accept`: a fallback needs K of the
        noisy replays."""
        parts = result.parts
        replays = noisy_replays(self.domain)
        needed = accept if accept is not None else replays
        places = [(self.domain, None)]
        if self.settings.verify_backend is not None:
            places.append((self.domain, self.settings.verify_backend))
        spent = 0
        for domain, other in places:
            check = verify(
                domain, self.scenario, parts.level, parts.solution, other or domain.backend.name, noisy=replays
            )
            spent += check.simulations
            if not check.passes(needed):
                if other is not None:
                    why = f"the solution fails in {other}"
                else:
                    where = check.failed[0] if check.failed else domain.world.name
                    why = f"the solution fails physc verify in the world '{where}'"
                return attrs.evolve(
                    result, satisfied=False, parts=None, simulations=result.simulations + spent, given_up=why, nearest=0
                )
        return attrs.evolve(result, simulations=result.simulations + spent)

    def run(self, placements: Iterator) -> Generated:
        """Satisfy the placed layouts in turn (`placements` yields objects with a
        `layout`); Infeasible when none gives a task within the budgets."""
        started = time.perf_counter()
        seconds = {"layout": 0.0, "satisfy": 0.0}
        layouts = simulations = 0
        fragile: list[tuple[int, int, object]] = []  # (-replays passed, order, placed)
        nearest = 0  # most noisy replays passed by a solution given up as too fragile
        best = 0  # most interactions of the sequence realised, in order, in any simulation
        stopped = ""  # what the first simulation that got that far shows about the next interaction
        lost: dict[str, list] = {}  # the noisy replays' losses over the layouts: term → [count, why]
        weakest = None  # of the chains realised but not robust, the strongest weakest link
        furthest: list = []  # the plays that came furthest, one a layout: (score, level, action, placed), replayed elsewhere on failure
        given_up: dict[str, dict[str, int]] = {}
        clock = time.perf_counter()
        kept = elsewhere.reserve(self.domain, self.settings.time_budget)
        left = budget.remaining()
        inner = budget.deadline(left - kept) if kept and left is not None and left > kept else contextlib.nullcontext()
        fallback = None
        with inner:  # the search stops early enough to leave the reserve
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
                        budget=error.budget or Exhausted.ALLOWED,
                    )
                    break
                except budget.OutOfTime:
                    failure = self._out_of_time(layouts)
                    break
                layouts += 1
                seconds["layout"] += time.perf_counter() - clock
                clock = time.perf_counter()
                try:
                    result = self.satisfy(placed.layout)
                except budget.OutOfTime:
                    failure = self._out_of_time(layouts)
                    break
                finally:
                    seconds["satisfy"] += time.perf_counter() - clock
                simulations += result.simulations
                if result.best > best or (result.best == best and not stopped):
                    best, stopped = result.best, result.stopped
                for term, count, why in result.lost:
                    lost.setdefault(term, [0, why])[0] += count
                if result.weakest is not None and (
                    weakest is None or (result.weakest.held, result.weakest.share) > (weakest.held, weakest.share)
                ):
                    weakest = result.weakest
                if result.furthest is not None:
                    furthest = sorted(furthest + [result.furthest], key=lambda play: play[0], reverse=True)[
                        : elsewhere.PLAYS
                    ]
                if result.satisfied:
                    failure, used = None, placed
                    break
                nearest = max(nearest, result.nearest)
                why = given_up.setdefault(result.given_up or "not said", {"layouts": 0, "simulations": 0})
                why["layouts"] += 1
                why["simulations"] += result.simulations
                if result.nearest >= self.min_robustness:
                    fragile.append((-result.nearest, layouts, placed))
                if self.progress is not None:
                    self.progress(
                        Progress(
                            layouts, simulations, time.perf_counter() - started, best, len(self.scenario.interactions)
                        )
                    )
                if layouts >= self.settings.layouts:
                    failure = Infeasible(
                        "satisfy",
                        f"no layout realised the sequence in simulation within the budget ({layouts} layouts)",
                        tried=placed.layout.conjunctions_tried,
                        budget=Exhausted.LAYOUTS,
                    )
                    break
                clock = time.perf_counter()
            if failure is not None:
                clock = time.perf_counter()
                try:
                    fallback = None if failure.budget is Exhausted.TIME else self.fallback(fragile)
                except budget.OutOfTime:
                    failure, fallback = self._out_of_time(layouts), None
                seconds["satisfy"] += time.perf_counter() - clock
        if failure is not None and fallback is None:
            other = elsewhere.elsewhere(self.domain, self.scenario, furthest, best, weakest, self.min_robustness)
            raise self.explained(failure, nearest, given_up, best, stopped, lost, weakest, other)
        if failure is not None:
            simulated, result, used = fallback
            simulations += simulated
        # The stages after satisfaction (distract, validate, accept), counted apart from it.
        for stage, spent in result.seconds.items():
            seconds["satisfy"] -= spent
            seconds[stage] = spent
        seconds["total"] = time.perf_counter() - started
        return Generated(result, used, layouts, simulations, given_up, seconds)

    def fallback(self, fragile: list):
        """No solution survived every noisy replay: the layouts given up as fragile, most
        robust first, satisfied again accepting min_robustness replays. (simulations, the
        outcome, what it was placed from) of the first that succeeds, or None."""
        simulations = 0
        for _, _, placed in sorted(fragile, key=lambda item: item[:2])[:FALLBACKS]:
            result = self.satisfy(placed.layout, accept=self.min_robustness)
            simulations += result.simulations
            if result.satisfied:
                return simulations, result, placed
        return None

    def _out_of_time(self, layouts: int) -> Infeasible:
        return Infeasible(
            "satisfy",
            f"the time budget of {self.settings.time_budget:g} s ran out after {layouts} {'layout' if layouts == 1 else 'layouts'}",
            budget=Exhausted.TIME,
        )

    def explained(
        self,
        failure: Infeasible,
        nearest: int,
        given_up: dict,
        best: int = 0,
        stopped: str = "",
        lost: dict | None = None,
        weakest=None,
        other=None,
    ) -> Infeasible:
        """The failure, with how far the best simulation got, why the layouts were given up,
        which link noise broke and its best margin, the most robust fragile solution found
        and what would accept it."""
        message = failure.message
        interactions = self.scenario.interactions
        if best:
            message += f"; the best simulation realised {best} of the {len(interactions)} interactions in order"
            if best < len(interactions):
                message += f" (never `{interactions[best].text}` after them" + (f": {stopped})" if stopped else ")")
        if given_up:
            message += f"; given up: {given_up_summary(given_up)}"
        if lost and best >= len(interactions):  # every link was made, but not robustly: say which one noise breaks
            term, (count, why) = max(lost.items(), key=lambda item: item[1][0])
            total = sum(n for n, _ in lost.values())
            message += f"; of the {total} noisy replays that failed, {count} lost `{term}` first" + (
                f" ({why})" if why else ""
            )
        if weakest is not None and best >= len(interactions):
            message += f"; the weakest link was `{weakest.term}`: best margin {weakest.value:+.3g} {weakest.unit} ({weakest.what})"
        if nearest:
            if nearest < self.min_robustness:
                hint = f"--min-robustness {nearest} accepts such a one"
            elif failure.budget is Exhausted.TIME:
                hint = "no time was left to try it again as a fallback"
            else:
                hint = "tried again as a fallback, it failed"
            message += f"; the most robust solution found passed {nearest} of {self.domain.robustness_replays} noisy replays ({hint})"
        if other is not None:
            message += f"; {other.text()}"
        return Infeasible(failure.stage, message, tried=failure.tried, budget=failure.budget)
