"""The angrybirds steps after placement: satisfy, distract, validate (the paper's 4–6)."""

from __future__ import annotations

import random
import time

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.task import Solution
from physc.domains.angrybirds.distract import distract
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.satisfy import Satisfier
from physc.domains.angrybirds.stability import stability
from physc.dsl.scenario import ScenarioIR
from physc.generation.outcome import Outcome, Parts

UNSTABLE = "the level did not stand"
NOT_VALIDATED = "validation failed"


def satisfy(
    domain,
    scenario: ScenarioIR,
    layout: ConcreteLayout,
    rng: random.Random,
    validate: bool,
    accept: int | None = None,
) -> Outcome:
    """`accept`: the noisy replays a solution must pass (default: all of them)."""
    satisfier = Satisfier(domain, scenario, layout, ROBUSTNESS_REPLAYS if accept is None else accept)
    found = satisfier.run()
    if found is None:
        return Outcome(False, satisfier.simulations, nearest=satisfier.nearest, given_up=satisfier.given_up, best=satisfier.best, stopped=satisfier.stopped)
    if not stability(satisfier.level)[0]:
        return Outcome(False, satisfier.simulations, given_up=UNSTABLE, best=satisfier.best, stopped=satisfier.stopped)
    attempt = found.attempt
    # Re-verifying each distractor belongs to the distraction step itself; --no-validate
    # skips only the final validation below (the paper's evaluation setting).
    distracting = time.perf_counter()
    distractors = distract(satisfier, attempt, rng)
    validating = time.perf_counter()
    validated = None
    trace = attempt.trace
    if validate:
        final = satisfier.simulate(attempt.shot)
        if not final.fidelity.valid:
            return Outcome(False, satisfier.simulations, given_up=NOT_VALIDATED, best=satisfier.best, stopped=satisfier.stopped)
        validated, trace = True, final.trace
    seconds = {"distract": validating - distracting, "validate": time.perf_counter() - validating}
    shot = attempt.shot
    solution = Solution(attempt.label, shot.target, shot.trajectory, round(shot.release_angle(), 5))
    parts = Parts(
        level=satisfier.level,
        solution=solution,
        trace=trace.sequence(),
        validated=validated,
        robustness=found.robustness,
        repairs=found.repairs,
        obstacles=found.obstacles,
        distractors=tuple(distractors),
    )
    return Outcome(True, satisfier.simulations, parts, seconds=seconds, best=satisfier.best, stopped=satisfier.stopped)
