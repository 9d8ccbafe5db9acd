"""The angrybirds steps after placement: satisfy, distract, validate (the paper's 4–6)."""

from __future__ import annotations

import random
import time

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.task import Solution
from physc.domains.angrybirds.distract import distract
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.satisfy import Satisfier
from physc.domains.angrybirds.stability import stability

UNSTABLE = "the level did not stand"
NOT_VALIDATED = "validation failed"
from physc.dsl.scenario import ScenarioIR


@attrs.frozen
class Parts:
    level: object
    solution: Solution
    trace: str
    validated: bool | None
    robustness: tuple[int, int]
    repairs: tuple[str, ...]
    obstacles: tuple[str, ...]
    distractors: tuple[str, ...]


@attrs.frozen
class Outcome:
    satisfied: bool
    simulations: int
    parts: Parts | None = None
    nearest: int = 0  # most noisy replays passed by a solution given up as too fragile
    given_up: str = ""  # why the layout was given up, when it was
    best: int = 0  # most interactions of the sequence realised, in order, in one simulation
    seconds: dict = attrs.field(factory=dict)  # stage → time spent, for the stages after satisfy


def satisfy(
    domain, scenario: ScenarioIR, layout: ConcreteLayout, rng: random.Random, validate: bool, accept: int | None = None
) -> Outcome:
    """`accept`: the noisy replays a solution must pass (default: all of them)."""
    satisfier = Satisfier(domain, scenario, layout, ROBUSTNESS_REPLAYS if accept is None else accept)
    found = satisfier.run()
    if found is None:
        return Outcome(False, satisfier.simulations, nearest=satisfier.nearest, given_up=satisfier.given_up, best=satisfier.best)
    if not stability(satisfier.level)[0]:
        return Outcome(False, satisfier.simulations, given_up=UNSTABLE, best=satisfier.best)
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
            return Outcome(False, satisfier.simulations, given_up=NOT_VALIDATED, best=satisfier.best)
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
    return Outcome(True, satisfier.simulations, parts, seconds=seconds, best=satisfier.best)
