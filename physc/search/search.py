"""The one generation search: a placed layout made a task, along its causal chain.

Every domain goes through it (angrybirds and the PHYRE-like plugin alike); a domain
supplies hooks (physc.domains.simulated.SimulatedDomain), never a search of its own. The
search is a few steps in turn, each a function of two values (problem.py): the `Problem`
it reads (the bound domain, the scenario, the layout as placed, the settings, the stages)
and the `Ledger` it writes (the simulations, how far the chain got, what noise broke):

1. **The chain** (chain.py, variants.py): depth first over the stages, with a beam; a
   stage's variants are its new objects where the simulated prefix says their actor goes,
   with the bodies the meeting favours, then local changes; the variants whose links keep a
   margin under noise are built on first.
2. **Margins raised** (strengthen.py): the first working action that keeps every link in
   every noisy replay; if none does, the weak links' coordinates (places, lengths, slopes,
   the action) moved by CMA-ES to raise the least margin, then fresh replays to confirm.
3. **Guards** (guards.py): obstacles against forbidden direct hits (`cannotHit` of the
   player) and against shortcuts, kept only if the solution still holds up; after the
   distractors, against the plays of the evaluation's agent that solve the task by accident
   (accidents.py).
4. **Stability** of the level, **distraction**, **contrasts** (contrasts.py: the action aimed at
   a contrast does not solve the task), **properties** (properties.py: what the scenario says
   must fail fails, against every action the player could send), **precision** (precision.py: every action the domain's
   agents may send beside the solution's solves it too, in every reading), **validation**
   (unless told not to), and the domain's **acceptance** rule (its evaluation's `acceptance`:
   PHYRE's, in the plugin).

Every simulation goes through the ledger's Evaluator, which counts it: the figure
generation's cost is measured in. Noise is drawn from generators named after the action's
label, so a seed gives the same task in any process.
"""

from __future__ import annotations

import random
import time

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.base import require
from physc.domains.simulated import SimulatedDomain, search_needs
from physc.dsl.scenario import ScenarioIR
from physc.search import guards, settings
from physc.search.accidents import guard as guard_accidents
from physc.search.chain import Node, chain
from physc.search.contrasts import contrasts
from physc.search.funnel import AFTER
from physc.search.outcome import Outcome, Parts
from physc.search.precision import precise
from physc.search.problem import ALL_CHECKS, Checks, Ledger, Problem, replayed
from physc.search.properties import properties
from physc.search.strengthen import Strong, least_passed, lost_links, strengthen
from physc.simulation.ending import Ending
from physc.simulation.stopped import why_stopped
from physc.simulation.trace import Trace


def satisfy(
    domain: SimulatedDomain,
    scenario: ScenarioIR,
    layout: ConcreteLayout,
    rng: random.Random,
    checks: Checks = ALL_CHECKS,
    accept: int | None = None,
) -> Outcome:
    """One placed layout made a task by the search with `domain`'s hooks (a SimulatedDomain),
    or why not, under the run's `checks` (whether the task is validated and judged by the
    domain's acceptance rule); `accept`: the noisy replays a solution must pass (default:
    all of them)."""
    require(domain, search_needs(domain), "generating a task")
    replays_run = domain.robustness_replays or 0
    problem = Problem.of(domain, scenario, layout, replays_run if accept is None else accept, checks)
    return search(problem, Ledger(), rng)


def search(problem: Problem, ledger: Ledger, rng: random.Random) -> Outcome:
    """The steps of the module docstring, in turn, for one placed layout."""
    domain = problem.domain
    if not domain.actions.candidates(problem.level_of(problem.placed), problem.scenario):
        return given_up(problem, ledger, settings.NO_ACTION)
    found = chain(problem, ledger, Node(problem.placed, (), -1), 0)
    ledger.turn(AFTER)
    if found is None:
        return given_up(problem, ledger, settings.NOT_REALISED)
    ledger.passage.chain = True
    strong = strengthen(problem, ledger, found)
    if strong is None:
        return given_up(problem, ledger, settings.FRAGILE if ledger.tried else settings.NOT_REALISED)
    layout, attempt, passed = strong.layout, strong.attempt, strong.passed
    obstructed = guards.obstruct(problem, ledger, layout, attempt)
    if obstructed is None:
        return given_up(problem, ledger, settings.NOT_OBSTRUCTED)
    layout, obstacles = obstructed
    if obstacles:  # the guards changed the level: the solution replayed in it
        passed = min(passed, again := least_passed(problem, ledger, attempt, layout))
        if again < problem.accept:
            return given_up(problem, ledger, settings.OBSTRUCTED_FRAGILE, nearest=again)
    layout, shortcuts = guards.guard(problem, ledger, layout, attempt, len(obstacles))
    if not ledger.evaluator.run(lambda: domain.stability(problem.level_of(layout)))[0]:
        return given_up(problem, ledger, settings.UNSTABLE)
    distracting = time.perf_counter()
    layout, distractors = guards.distract(problem, ledger, rng, layout, attempt)
    accidents = guard_accidents(problem, ledger, layout, attempt, len(obstacles) + len(shortcuts))
    layout, shortcuts = accidents.layout, shortcuts + list(accidents.obstacles)
    why, contrasted = contrasts(problem, ledger, layout, attempt)
    if why is not None:
        return given_up(problem, ledger, why)
    checked = properties(problem, ledger, layout, attempt)
    if checked.why is not None:
        return attrs.evolve(given_up(problem, ledger, checked.why), broken="; ".join(checked.notes))
    layout, contrasted = checked.layout, contrasted + checked.notes
    if checked.obstacles and not ledger.evaluator.run(lambda: domain.stability(problem.level_of(layout)))[0]:
        return given_up(problem, ledger, settings.UNSTABLE)
    why, precision, attempt = precise(problem, ledger, layout, attempt)
    if why is not None:
        return given_up(problem, ledger, why)
    validating = time.perf_counter()
    validated, trace = None, attempt.trace
    if problem.checks.validate:
        final = replayed(problem, ledger, problem.level_of(layout), attempt.action)
        if not final.fidelity.valid:
            return given_up(problem, ledger, settings.NOT_VALIDATED)
        validated, trace = True, final.trace
    level = problem.level_of(layout)
    if not domain.actions.valid(level, attempt.action):  # the finished level (obstacles, distractors) may block it
        return given_up(problem, ledger, settings.INVALID_ACTION)
    accepting = time.perf_counter()
    judged = accepted(problem, ledger, level, attempt) if problem.checks.acceptance else None
    if judged is not None and not judged.accepted:
        return given_up(problem, ledger, judged.reason or settings.NOT_ACCEPTED)  # the benchmark's own words
    solution = domain.actions.played_as(level, domain.actions.solution(attempt.label, attempt.action))
    steps = found.steps + ((f"margins raised: {strong.raised}",) if strong.raised else ()) + contrasted + precision
    parts = Parts(
        level=domain.files.with_solution(level, solution),
        solution=solution,
        trace=trace.sequence(),
        validated=validated,
        robustness=(passed, domain.robustness_replays or 0),
        repairs=steps,
        obstacles=tuple(obstacles + shortcuts) + checked.obstacles,
        distractors=tuple(distractors),
        acceptance=None if judged is None else judged.record(),
        margins=margins_record(problem, ledger, trace, strong, steps),
        accidental=accidents.record,
    )
    seconds = {"distract": validating - distracting, "validate": accepting - validating} | (
        {} if judged is None else {"accept": time.perf_counter() - accepting}
    )
    return made(problem, ledger, parts, seconds)


def made(problem: Problem, ledger: Ledger, parts: Parts, seconds: dict[str, float]) -> Outcome:
    """The layout made a task: its parts, with what the ledger counted."""
    ledger.turn(None)
    return Outcome(
        True,
        ledger.simulations,
        parts,
        seconds=seconds,
        best=ledger.best,
        stopped=stopped(problem, ledger),
        passage=ledger.passage,
    )


def margins_record(problem: Problem, ledger: Ledger, trace: Trace, strong: Strong, steps: tuple[str, ...]) -> dict:
    """What the task file says of its margins: every link's as the solution plays, the weakest
    over the noisy replays it passed, what raising them moved (the search's `steps` that did)
    and the candidates it judged."""
    played = problem.domain.margins(problem.scenario, trace)
    weakest = strong.weakest or played.weakest
    raised = [step for step in steps if "margins raised: " in step]
    return {
        "weakest": None if weakest is None else weakest.record(),
        "links": played.record(),
        "raised": raised or None,
        "candidates": ledger.raised,
    }


def stopped(problem: Problem, ledger: Ledger) -> str:
    """What the play that came furthest shows about where it stopped."""
    furthest = ledger.furthest
    return "" if furthest is None else why_stopped(problem.scenario, furthest.trace, furthest.fidelity)


def given_up(problem: Problem, ledger: Ledger, why: str, nearest: int = 0) -> Outcome:
    """The layout given up for `why`, with what the ledger noted of how far it got; `nearest`: the
    noisy replays a solution given up as fragile passed, if more than the ledger's."""
    ledger.nearest = max(ledger.nearest, nearest)
    furthest, layout = ledger.furthest, ledger.furthest_layout  # (noted together)
    ledger.turn(None)
    return Outcome(
        False,
        ledger.simulations,
        nearest=ledger.nearest,
        given_up=why,
        best=ledger.best,
        stopped=stopped(problem, ledger),
        lost=lost_links(ledger),
        weakest=ledger.weakest,
        furthest=None
        if furthest is None or layout is None
        else (furthest.fidelity.score, problem.level_of(layout), furthest.action, problem.placed),
        passage=ledger.passage,
    )


def accepted(problem: Problem, ledger: Ledger, level: object, attempt):
    """The domain's acceptance rule's verdict on `attempt` in the finished `level` (PHYRE's)."""
    domain = problem.domain
    return domain.evaluation.acceptance(
        level, attempt.action, lambda candidate: solves(domain, level, candidate, ledger)
    )


def solves(domain: SimulatedDomain, level: object, action: object, ledger: Ledger) -> bool:
    """Whether `action` solves `level`: one play of the benchmark's acceptance, counted by the
    search's evaluator within its budget."""
    return ledger.evaluator.run(lambda: domain.playout(level, action, ending=Ending.SETTLED)).solved
