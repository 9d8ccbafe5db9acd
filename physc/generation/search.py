"""The action search: a placed layout made a task by simulating candidate actions.

The generic satisfier of a one-action domain (physc.domains.simulated): the paper's
step 4 without a domain's own repairs. For one placed layout it

1. gives the layout up unless it stands (left alone, nothing moves more than the
   domain's limit);
2. simulates every candidate action the domain offers (the first target's points of
   interest), judging each trace against the scenario (sequence fidelity, restrictions,
   goal);
3. a working action that fails some noisy replays is first centred: moved to the middle of
   the run of working actions around it, along the line the domain's `nudged` draws (PHYRE:
   the ball a pixel at a time sideways), and replayed again;
4. if none realises the sequence, makes liesOnPath true in simulation: the play that came
   furthest stops at a hit or fall, and that target (with its structure) is moved onto
   the actor's simulated path (on_path.py), one interaction at a time;
5. keeps the first working action that passes `accept` of the domain's noisy replays,
   and as many fresh ones (a confirmation: it was chosen for passing the first);
6. validates it once more (unless told not to).

Every simulation goes through an Evaluator, which counts it: the figure generation's
cost is measured in. Noise is drawn from generators named after the action's label, so a
seed gives the same task in any process.
"""

from __future__ import annotations

import random

import attrs

from physc.generation import on_path
from physc.generation.evaluator import Evaluator
from physc.generation.outcome import Outcome, Parts
from physc.simulation.fidelity import Fidelity, fidelity
from physc.simulation.stopped import why_stopped
from physc.simulation.trace import Trace

NOISE_STREAMS = ("robustness", "confirmation")  # the replays an action is chosen for, and the fresh ones that confirm it
CANDIDATES = 3  # working actions put through the noisy replays at most, per layout
MOVES = 6  # liesOnPath proposals simulated per interaction brought about
CENTRING_STEPS = 6  # nudges tried each way around a fragile action
# Why a layout is given up (`Outcome.given_up`), in the order of the steps.
UNSTABLE = "the level did not stand"
NO_ACTION = "no candidate action"
NOT_REALISED = "the sequence was not realised"
FRAGILE = "the solution was too fragile"
NOT_VALIDATED = "validation failed"


@attrs.frozen
class Attempt:
    """One candidate action played: its label, the action, the judged trace and its fidelity."""

    label: str
    action: object
    trace: Trace
    fidelity: Fidelity


class ActionSearch:
    """The search for one layout (module docstring)."""

    def __init__(self, domain, scenario, layout, accept: int, validate: bool = True):
        self.domain = domain
        self.scenario = scenario
        self.layout = layout
        self.level = domain.level_from_layout(layout, scenario)
        self.repairs: list[str] = []
        self.accept = accept
        self.validate = validate
        self.evaluator = Evaluator(0)
        self.best = 0  # most interactions realised in order by one play
        self.furthest: Attempt | None = None
        self.nearest = 0  # most noisy replays passed by a working action given up as fragile
        self.tried = 0  # working actions put through the noisy replays

    def simulate(self, label: str, action, level=None) -> Attempt:
        """`action` played in `level` (default: the layout's), judged against the scenario."""
        trace = self.evaluator.run(lambda: self.domain.play(level or self.level, action, self.scenario))
        attempt = Attempt(label, action, trace, fidelity(self.scenario, trace))
        if level is None:
            self.best = max(self.best, attempt.fidelity.matched)
            if self.furthest is None or attempt.fidelity.score > self.furthest.fidelity.score:
                self.furthest = attempt
        return attempt

    def robustness(self, attempt: Attempt, stream: str) -> int:
        """How many of the domain's noisy replays of the attempt realise the sequence."""
        noise = random.Random(f"{stream}/{attempt.label}")
        passed = 0
        for _ in range(self.domain.robustness_replays):
            level, action = self.domain.noisy(self.level, attempt.action, noise)
            passed += self.simulate(attempt.label, action, level).fidelity.valid
        return passed

    def run(self) -> Outcome:
        if not self.evaluator.run(lambda: self.domain.stability(self.level))[0]:
            return self.give_up(UNSTABLE)
        candidates = self.domain.actions(self.level, self.scenario)
        if not candidates:
            return self.give_up(NO_ACTION)
        chosen = self.robust(self.simulate(label, action) for label, action in candidates)
        if chosen is None and self.tried == 0:
            chosen = self.robust(self.moved_onto_paths())
        if chosen is None:
            return self.give_up(FRAGILE if self.tried else NOT_REALISED)
        attempt, passed = chosen
        validated, trace = None, attempt.trace
        if self.validate:
            final = self.simulate(attempt.label, attempt.action)
            if not final.fidelity.valid:
                return self.give_up(NOT_VALIDATED)
            validated, trace = True, final.trace
        solution = self.domain.solution(attempt.label, attempt.action)
        parts = Parts(
            level=self.domain.with_solution(self.level, solution),
            solution=solution,
            trace=trace.sequence(),
            validated=validated,
            robustness=(passed, self.domain.robustness_replays),
            repairs=tuple(self.repairs),
            obstacles=(),
            distractors=(),
        )
        return Outcome(True, self.evaluator.simulations, parts, best=self.best, stopped=self.stopped)

    def robust(self, attempts) -> tuple[Attempt, int] | None:
        """The first of `attempts` (simulated lazily, in order) that realises the sequence and
        passes `accept` noisy replays and as many fresh ones, with the replays it passed; at
        most CANDIDATES working ones are put through the replays."""
        for attempt in attempts:
            if not attempt.fidelity.valid:
                continue
            self.tried += 1
            passed = self.robustness(attempt, NOISE_STREAMS[0])
            if passed < self.domain.robustness_replays:
                centred = self.centred(attempt)
                if centred is not None:
                    again = self.robustness(centred, NOISE_STREAMS[0])
                    if again > passed:
                        attempt, passed = centred, again
            if passed >= self.accept:
                passed = min(passed, self.robustness(attempt, NOISE_STREAMS[1]))
            if passed >= self.accept:
                return attempt, passed
            self.nearest = max(self.nearest, passed)
            if self.tried == CANDIDATES:
                return None
        return None

    def centred(self, attempt: Attempt) -> Attempt | None:
        """The action in the middle of the run of working actions around `attempt` along the
        domain's `nudged` line (at most CENTRING_STEPS each way), if that is another action
        and works; None otherwise (or when the domain draws no such line)."""
        def nudge(step: int) -> Attempt | None:
            action = self.domain.nudged(attempt.action, step)
            if action is None or not self.domain.valid(self.level, action):
                return None
            return self.simulate(f"{attempt.label}, nudged {step:+d}", action)

        low = high = 0
        while low > -CENTRING_STEPS and (found := nudge(low - 1)) is not None and found.fidelity.valid:
            low -= 1
        while high < CENTRING_STEPS and (found := nudge(high + 1)) is not None and found.fidelity.valid:
            high += 1
        middle = (low + high) // 2
        if middle == 0:
            return None
        centre = nudge(middle)
        return centre if centre is not None and centre.fidelity.valid else None

    def moved_onto_paths(self) -> list[Attempt]:
        """Step 3: while the furthest play stops at a hit or a fall, the layout with that
        target moved onto the actor's path (the first of MOVES proposals that gets further
        and still stands) is adopted; the play, once it realises the whole sequence."""
        domain = self.domain
        for _ in range(len(self.scenario.interactions)):
            furthest = self.furthest
            proposed = on_path.proposals(
                self.layout, self.scenario, furthest.trace, furthest.fidelity, domain.layout_parameters, domain.trace_scale
            )
            for description, layout in proposed[:MOVES]:
                level = domain.level_from_layout(layout, self.scenario)
                if not domain.valid(level, furthest.action):
                    continue
                trial = self.simulate(furthest.label, furthest.action, level)
                if trial.fidelity.matched > furthest.fidelity.matched and self.evaluator.run(lambda: domain.stability(level))[0]:
                    break
            else:
                return []
            self.layout, self.level, self.furthest = layout, level, trial
            self.best = max(self.best, trial.fidelity.matched)
            self.repairs.append(description)
            if trial.fidelity.valid:
                return [trial]
        return []

    @property
    def stopped(self) -> str:
        """What the play that came furthest shows about where it stopped."""
        return "" if self.furthest is None else why_stopped(self.scenario, self.furthest.trace, self.furthest.fidelity)

    def give_up(self, why: str) -> Outcome:
        return Outcome(False, self.evaluator.simulations, nearest=self.nearest, given_up=why, best=self.best, stopped=self.stopped)
