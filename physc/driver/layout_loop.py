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
import copy
import time
from collections.abc import Callable, Iterator, Sequence
from typing import Protocol

import attrs

from physc import budget
from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.infeasible import Exhausted, Infeasible
from physc.compiler.task import given_up_summary
from physc.domains.simulated import SimulatedDomain
from physc.driver import link_prior
from physc.driver.link_prior import Prior
from physc.driver.ranking import POOL, ROUND, Ranking
from physc.driver.run_settings import RunSettings
from physc.driver.workers import Run, Workers, satisfy_layout
from physc.dsl.scenario import ScenarioIR
from physc.search import elsewhere, placing
from physc.search.funnel import Funnel, funnel_text
from physc.search.link_features import LinkFeatures, features
from physc.search.link_model import KindedExample, LinkModel, by_kind
from physc.search.outcome import Outcome
from physc.simulation.margins import Margin
from physc.worlds import differing_kinds

FALLBACKS = 6  # fragile layouts tried again, most robust first, when no layout gave a robust solution


class Placement(Protocol):
    """What the loop reads of a placed layout (the pipeline's Placed)."""

    @property
    def layout(self) -> ConcreteLayout: ...

    @property
    def structure(self) -> str: ...  # the layout rules' structure it was placed in


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

    outcome: Outcome  # the search's Outcome (search.satisfy), satisfied
    placed: Placement  # what it came from (the pipeline's Placed: its `layout`, and its `structure`)
    layouts: int
    simulations: int
    given_up: dict[str, dict[str, int]]  # why → {"layouts": n, "simulations": n}
    seconds: dict[str, float]  # "layout" (placement), "satisfy", and the stages after satisfaction
    funnel: dict | None = None  # where the placed layouts went down the chain (physc.search.funnel)
    proposals: dict | None = None  # how the layouts were proposed (LayoutLoop.proposals)


@attrs.define
class Tally:
    """What the layout loop has counted and kept over the layouts it tried, as the search's
    Ledger is for one layout: the costs, why layouts were given up, and what a failure's
    explanation reports."""

    layouts: int = 0
    simulations: int = 0
    seconds: dict[str, float] = attrs.field(factory=lambda: {"layout": 0.0, "satisfy": 0.0})
    fragile: list[tuple[int, int, Placement]] = attrs.field(factory=list)  # (-replays passed, order, placed)
    nearest: int = 0  # most noisy replays passed by a solution given up as too fragile
    best: int = 0  # most interactions of the sequence realised, in order, in any simulation
    stopped: str = ""  # what the first simulation that got that far shows about the next interaction
    lost: dict[str, tuple[int, str]] = attrs.field(factory=dict)  # the noisy replays' losses: term → (count, why)
    weakest: Margin | None = None  # of the chains realised but not robust, the strongest weakest link
    # The plays that came furthest, one a layout: (score, level, action, placed), replayed
    # elsewhere on failure.
    furthest: list[tuple] = attrs.field(factory=list)
    given_up: dict[str, dict[str, int]] = attrs.field(factory=dict)  # why → {"layouts": n, "simulations": n}
    broken: str = ""  # the first declared property that gave a layout up, and what broke it
    funnel: Funnel = attrs.field(factory=Funnel)  # where the placed layouts went down the chain (physc.search.funnel)

    def note(self, result: Outcome) -> None:
        """What one layout's search showed of how far the sequence gets and how robustly."""
        self.simulations += result.simulations
        if result.passage is not None:
            self.funnel.add(result.passage, result.simulations, result.satisfied, result.given_up)
        if result.best > self.best or (result.best == self.best and not self.stopped):
            self.best, self.stopped = result.best, result.stopped
        for term, count, why in result.lost:
            before, first_why = self.lost.get(term, (0, why))
            self.lost[term] = (before + count, first_why)
        weakest = result.weakest
        if isinstance(weakest, Margin) and (
            self.weakest is None or (weakest.held, weakest.share) > (self.weakest.held, self.weakest.share)
        ):
            self.weakest = weakest
        if result.furthest is not None:
            plays = sorted([*self.furthest, result.furthest], key=lambda play: play[0], reverse=True)
            self.furthest = plays[: elsewhere.PLAYS]

    def give_up(self, result: Outcome, placed: Placement, min_robustness: int) -> None:
        """A layout given up: why, and as a fallback if its solution was robust enough."""
        self.nearest = max(self.nearest, result.nearest)
        why = self.given_up.setdefault(result.given_up or "not said", {"layouts": 0, "simulations": 0})
        why["layouts"] += 1
        why["simulations"] += result.simulations
        self.broken = self.broken or result.broken
        if result.nearest >= min_robustness:
            self.fragile.append((-result.nearest, self.layouts - 1, placed))  # (its place in the run)


Found = tuple[Outcome, Placement]  # the satisfied outcome, and the layout it came from


@attrs.define
class LayoutLoop:
    domain: SimulatedDomain
    scenario: ScenarioIR
    seed: int | None  # the run's seed: each layout's search draws from a generator named after it and its place
    settings: RunSettings  # the run's budgets and checks (physc.driver.run_settings)
    progress: Callable[[Progress], None] | None = None
    earlier: Sequence[KindedExample] = ()  # a dataset's earlier tasks' examples (physc.dataset.waves)
    model: LinkModel = attrs.field(factory=LinkModel)  # the proposal model (physc.search.link_model)
    workers: Workers = attrs.field(init=False)  # who satisfies a round (physc.driver.workers)
    prior: Prior | None = attrs.field(init=False)  # the world's prior, as shipped (physc.driver.link_prior)

    def __attrs_post_init__(self) -> None:
        self.workers = Workers(self.run_of, self.settings.workers)
        self.prior = link_prior.load(self.domain)
        if self.prior is not None and self.prior.fingerprint == link_prior.recognition(self.domain):
            self.model.prior = self.prior.examples
        self.model.earlier = by_kind(self.earlier)

    @property
    def proposals(self) -> dict:
        """What the task file says of how its layouts were proposed: the prior the model started
        from (None: the domain ships none for the world) and the examples the compile taught it."""
        prior = self.prior
        used = prior is not None and bool(self.model.prior)
        return {
            "prior": None if prior is None else prior.record(used),
            "learned": self.model.learned,
            "earlier": len(self.earlier),
            "pool": POOL,
            "round": ROUND,
        }

    @property
    def min_robustness(self) -> int:
        """Noisy replays a solution must pass at least: fragile layouts that passed this many
        are fallbacks."""
        return self.settings.robustness(self.domain)

    @property
    def run_of(self) -> Run:
        return Run(self.domain, self.scenario, self.settings, self.seed)

    def satisfy(self, layout: ConcreteLayout, accept: int | None = None, index: int = 0) -> Outcome:
        """One layout satisfied in this process (physc.driver.workers.satisfy), as the `index`th of the run."""
        return satisfy_layout(self.run_of, index, layout, accept)

    def links_of(self, placed: Placement) -> list[LinkFeatures]:
        """The features of each link of the scenario in a placed layout (the proposal model's)."""
        layout = placed.layout
        parameters = self.domain.layout_parameters
        assert parameters is not None, "a layout is placed only with the domain's layout parameters"
        support_of = placing.Supports.of(layout, parameters).support_of
        return features(layout, self.scenario.interactions, support_of, self.domain)

    def run(self, placements: Iterator[Placement]) -> Generated:
        """Satisfy the placed layouts in turn (`placements` yields objects with a
        `layout`); Infeasible when none gives a task within the budgets."""
        started = time.perf_counter()
        tally = Tally()
        others = concerned(self.domain, self.scenario)  # the worlds exit 3 may try and name
        kept = elsewhere.reserve(others, self.settings.time_budget)
        left = budget.remaining()
        inner = budget.deadline(left - kept) if kept and left is not None and left > kept else contextlib.nullcontext()
        with inner:  # the search stops early enough to leave the reserve
            try:
                found = self._search(placements, tally, started)
                if isinstance(found, Infeasible):
                    found = self._fall_back(found, tally)
            finally:
                self.workers.close()
        if isinstance(found, Infeasible):
            other = elsewhere.elsewhere(
                others, self.scenario, tally.furthest, tally.best, tally.weakest, self.min_robustness
            )
            raise self.explained(found, tally, other)
        result, used = found
        # The stages after satisfaction (distract, validate, accept), counted apart from it.
        for stage, spent in result.seconds.items():
            tally.seconds["satisfy"] -= spent
            tally.seconds[stage] = spent
        tally.seconds["total"] = time.perf_counter() - started
        funnel = tally.funnel.record(self.scenario.interactions)
        placed = {o.name: [o.x, o.y] for o in used.layout.objects if o.role != "support"}
        proposals = self.proposals | {"placed": placed}  # where its objects were proposed: a dataset's diversity
        return Generated(
            result, used, tally.layouts, tally.simulations, tally.given_up, tally.seconds, funnel, proposals
        )

    def _search(self, placements: Iterator[Placement], tally: Tally, started: float) -> Found | Infeasible:
        """The placed layouts satisfied in rounds, the likeliest first (physc.driver.ranking),
        until one gives a task, or why none did within the budgets of layouts and time."""
        ranking = Ranking(placements, self.model, self.links_of)
        clock = time.perf_counter()
        while True:
            try:
                chosen = ranking.round(min(ROUND, self.settings.layouts - tally.layouts))
            except Infeasible as error:
                if not tally.layouts:
                    raise
                return Infeasible(
                    "satisfy",
                    f"{tally.layouts} layouts were placed, but in none did the simulated solution realise the sequence",
                    tried=error.tried,
                    budget=error.budget or Exhausted.ALLOWED,
                )
            except budget.OutOfTime:
                return self._out_of_time(tally.layouts)
            tally.seconds["layout"] += time.perf_counter() - clock
            tally.funnel.proposed = ranking.proposed
            clock = time.perf_counter()
            jobs = [(tally.layouts + k, c.placed.layout, None) for k, c in enumerate(chosen)]
            try:
                answers = self.workers.satisfy(jobs)
            except budget.OutOfTime:
                return self._out_of_time(tally.layouts + 1)
            finally:
                tally.seconds["satisfy"] += time.perf_counter() - clock
            for candidate, result in zip(chosen, answers, strict=False):  # (answers stop at the first task)
                tally.layouts += 1
                if result is None:
                    return self._out_of_time(tally.layouts)
                tally.note(result)
                self.model.learn(candidate.links, result.best)
                if result.satisfied:
                    return result, candidate.placed
                tally.give_up(result, candidate.placed, self.min_robustness)
                if self.progress is not None:
                    elapsed = time.perf_counter() - started
                    interactions = len(self.scenario.interactions)
                    self.progress(Progress(tally.layouts, tally.simulations, elapsed, tally.best, interactions))
            if tally.layouts >= self.settings.layouts:
                return Infeasible(
                    "satisfy",
                    f"no layout realised the sequence in simulation within the budget ({tally.layouts} layouts)",
                    tried=chosen[-1].placed.layout.conjunctions_tried,
                    budget=Exhausted.LAYOUTS,
                )
            clock = time.perf_counter()

    def _fall_back(self, failure: Infeasible, tally: Tally) -> Found | Infeasible:
        """After `failure`, the first fragile layout that a second try accepts (unless the time
        is spent); else the failure."""
        clock = time.perf_counter()
        try:
            fallback = None if failure.budget is Exhausted.TIME else self.fallback(tally.fragile)
        except budget.OutOfTime:
            failure, fallback = self._out_of_time(tally.layouts), None
        tally.seconds["satisfy"] += time.perf_counter() - clock
        if fallback is None:
            return failure
        simulated, result, used = fallback
        tally.simulations += simulated
        return result, used

    def fallback(self, fragile: list[tuple[int, int, Placement]]) -> tuple[int, Outcome, Placement] | None:
        """No solution survived every noisy replay: the layouts given up as fragile, most
        robust first, satisfied again accepting min_robustness replays. (simulations, the
        outcome, what it was placed from) of the first that succeeds, or None."""
        tried = sorted(fragile, key=lambda item: item[:2])[:FALLBACKS]
        if not tried:
            return None
        answers = self.workers.satisfy([(order, placed.layout, self.min_robustness) for _, order, placed in tried])
        last = answers[-1]
        if last is None:  # the time ran out during it
            raise budget.OutOfTime(self.settings.time_budget)
        if last.satisfied:
            simulations = sum(result.simulations for result in answers if result is not None)
            return simulations, last, tried[len(answers) - 1][2]
        return None

    def _out_of_time(self, layouts: int) -> Infeasible:
        return Infeasible(
            "satisfy",
            f"the time budget of {self.settings.time_budget:g} s ran out after {layouts} "
            f"{'layout' if layouts == 1 else 'layouts'}",
            budget=Exhausted.TIME,
        )

    def explained(self, failure: Infeasible, tally: Tally, other: elsewhere.Elsewhere | None = None) -> Infeasible:
        """The failure, with how far the best simulation got, why the layouts were given up,
        which link noise broke and its best margin, the most robust fragile solution found
        and what would accept it."""
        message = failure.message
        interactions = self.scenario.interactions
        best, stopped, lost, weakest, nearest = tally.best, tally.stopped, tally.lost, tally.weakest, tally.nearest
        if best:
            message += f"; the best simulation realised {best} of the {len(interactions)} interactions in order"
            if best < len(interactions):
                message += f" (never `{interactions[best].text}` after them" + (f": {stopped})" if stopped else ")")
        if tally.given_up:
            message += f"; given up: {given_up_summary(tally.given_up)}"
        if tally.broken:
            message += f"; the first layout given up for a declared property: {tally.broken}"
        if lost and best >= len(interactions):  # every link was made, but not robustly: say which one noise breaks
            term, (count, why) = max(lost.items(), key=lambda item: item[1][0])
            total = sum(n for n, _ in lost.values())
            message += f"; of the {total} noisy replays that failed, {count} lost `{term}` first" + (
                f" ({why})" if why else ""
            )
        if weakest is not None and best >= len(interactions):  # of the chains that did not hold, the strongest
            message += f"; {weakest.named_weakest('at best')}"
        if nearest:
            if nearest < self.min_robustness:
                hint = f"--min-robustness {nearest} accepts such a one"
            elif failure.budget is Exhausted.TIME:
                hint = "no time was left to try it again as a fallback"
            else:
                hint = "tried again as a fallback, it failed"
            message += (
                f"; the most robust solution found passed {nearest} of {self.domain.robustness_replays} "
                f"noisy replays ({hint})"
            )
        funnel = tally.funnel.record(interactions) if tally.funnel.placed else None
        if funnel is not None:
            message += f"; where the simulations went: {funnel_text(funnel)}"
        if other is not None:
            message += f"; {elsewhere_text(other)}"
        return Infeasible(failure.stage, message, tried=failure.tried, budget=failure.budget, funnel=funnel)


def elsewhere_text(other: elsewhere.Elsewhere) -> str:
    """The world a replay elsewhere names (physc.search.elsewhere), its weakest link in words
    that read right whatever its margin (Margin.named_weakest)."""
    how = (
        "built again there by the search's stages from one of the best layouts"
        if other.built
        else "the best layout, replayed"
    )
    link = "" if other.weakest is None else f"; {other.weakest.named_weakest()}"
    return (
        f"in the world '{other.world}', {how}, realises {other.matched} of the {other.total}"
        f" interactions{link}: --world {other.world} may carry this scenario (physc worlds describes it)"
    )


def concerned(domain: SimulatedDomain, scenario: ScenarioIR) -> SimulatedDomain:
    """`domain` with, of its other worlds, only those that differ from its own in a kind of
    interaction the scenario has (physc.worlds.differing_kinds: what each variant declares it
    `concerns`; one that declares nothing may differ in any): exit 3 tries and names no other
    world (physc.search.elsewhere), and keeps no time for one, where none is left."""
    own, kinds = domain.world, {term.name for term in scenario.interactions}

    def differs(world) -> bool:
        differing = differing_kinds(own, world, domain.worlds)
        return differing is None or bool(differing & kinds)

    kept = tuple(w for w in domain.worlds if w.name == own.name or differs(w))
    if len(kept) == len(domain.worlds):
        return domain
    narrowed = copy.copy(domain)
    narrowed.worlds = kept
    return narrowed
