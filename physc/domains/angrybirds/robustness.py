"""Whether a solution survives noise, and what is done for one that does not.

The solution kept is the first candidate that survives every noisy replay, on the
level as finally written. A candidate that fails some is first centred in its window
of working release angles (`centred`), then firmed up (`firmed`: the targets of rolling
and sliding blocks brought nearer). Whichever way it came to pass them, it must pass as
many fresh replays too (a confirmation, the second of NOISE_STREAMS: it was chosen for
passing the first), and every obstacle, platform against a shortcut and distractor added
after it must leave it passing both (`holds_up`). A layout given up as fragile reports the
most replays a solution passed (`Satisfier.nearest`), and the pipeline's fallbacks satisfy
it again accepting fewer (`Satisfier.accept`), confirmed likewise. Also here: the shots
that solve a level (`solving_shots`), which the shortcut guard and the distractors check.
A mixin of `Satisfier` (satisfy.py), whose `run` applies these in that order.
"""

from __future__ import annotations

import random
from collections.abc import Collection

import attrs

from physc.domains.angrybirds.actions import candidate_shots
from physc.domains.angrybirds.attempt import Attempt, _along
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.noise import ANGLE_SIGMA, ROBUSTNESS_REPLAYS, jitter

CENTRING_STEP = 0.05  # degrees: the release angles around a fragile solution are tried this far apart
CENTRING_STEPS = 8  # each way (0.4°, four times the noise's σ)
FIRMING = (0.15, 0.3, 0.5)  # how much nearer a fragile solution's rolling or sliding blocks' targets are tried
NOISE_STREAMS = ("robustness", "confirmation")  # the replays a solution is chosen for, and the fresh ones that confirm it


class Robustness:
    """The satisfier's noisy replays and what makes a fragile solution firmer (mixed into
    `Satisfier`)."""

    def robustness(self, attempt: Attempt, level: Level | None = None, stream: str = NOISE_STREAMS[0]) -> tuple[int, int]:
        """How many replays under noise (the evaluation's model) realise the sequence
        (`stream` names the noise drawn: another name, other replays)."""
        noise = random.Random(f"{stream}/{attempt.label}/{attempt.shot.release_angle():.6f}")
        angle = attempt.shot.release_angle()
        passed = 0
        level = level or self.level
        for _ in range(ROBUSTNESS_REPLAYS):
            noisy = jitter(level, noise)  # each replay from the level itself: noise does not add up
            if self.simulate(Shot(angle=angle + noise.gauss(0.0, ANGLE_SIGMA)), noisy).fidelity.valid:
                passed += 1
        return passed, ROBUSTNESS_REPLAYS

    def holds_up(self, attempt: Attempt, level: Level) -> bool:
        """Whether the solution in `level` still passes as many noisy replays as it must, in
        both noise streams (the replays it was chosen for and the confirmation's). A change
        made after the confirmation (an obstacle, a platform against a shortcut, a
        distractor) is itself chosen for passing the replays it is checked with: with the
        same 6 each time, every change kept could break the solution a little more in noise
        those 6 never draw."""
        return all(self.robustness(attempt, level, stream)[0] >= self.accept for stream in NOISE_STREAMS)

    def centred(self, attempt: Attempt) -> Attempt | None:
        """A solution that noise breaks too often, moved to the middle of the interval of
        release angles around it that realise the sequence (a chain's window of working
        angles can be narrow, and the shot found may lie at its edge): None if the middle
        is the shot itself or does not realise the sequence."""
        angle = attempt.shot.release_angle()

        def works(step: int) -> bool:
            return self.simulate(attempt.shot.at_angle(angle + step * CENTRING_STEP)).fidelity.valid

        low = 0
        while low > -CENTRING_STEPS and works(low - 1):
            low -= 1
        high = 0
        while high < CENTRING_STEPS and works(high + 1):
            high += 1
        if low + high == 0:
            return None
        centre = self.simulate(attempt.shot.at_angle(angle + (low + high) / 2 * CENTRING_STEP))
        return attrs.evolve(centre, label=attempt.label) if centre.fidelity.valid else None

    def firmed(self, chosen: Attempt, passed: int) -> tuple[Attempt, int]:
        """A working solution that noise breaks too often: a block that rolls or slides into
        its next target may arrive too slowly, or only just, so that target and the world
        beyond it come a little nearer (the last such link first). A change is kept when
        the solution still realises the sequence and survives more noisy replays. Returns
        the solution in the level as it is now and how many replays it passes."""
        for index in reversed(range(len(self.scenario.interactions))):
            term = self.scenario.interactions[index]
            mover, goal = term.objects[0], term.objects[-1]
            heading = self.heading_of(mover, index) if term.name == "hit" else None
            if heading is None or goal not in self.objects:
                continue
            sign = 1.0 if heading == "right" else -1.0
            start = _along(self.objects[goal], sign)[0]
            for distance in FIRMING:
                candidate = self.world_beyond(start - 1e-3, distance, sign)
                if candidate is None:
                    continue
                trial = self.simulate(chosen.shot, candidate)
                if not trial.fidelity.valid:
                    continue
                trial = attrs.evolve(trial, label=chosen.label)
                score = self.robustness(trial, candidate)[0]
                if score > passed:
                    self.repairs.append(f"firmer: {goal} and the world beyond {distance:.2f} nearer to {mover}")
                    self.adopt(candidate)
                    chosen, passed = trial, score
                    if passed >= ROBUSTNESS_REPLAYS:  # a fallback, too, is firmed as far as it goes
                        return chosen, passed
                    break
        return chosen, passed

    def solving_shot(self, obj: LevelObject, level: Level, skip: Collection[str] = ()) -> Attempt | None:
        """A shot at one of obj's points of interest that solves the level, if any (other
        than those labelled in `skip`)."""
        return next(self.solving_shots(obj, level, skip), None)

    def solving_shots(self, obj: LevelObject, level: Level, skip: Collection[str] = ()):
        """The shots at obj's points of interest that solve the level (other than those
        labelled in `skip`), lazily."""
        for label, shot in candidate_shots(obj):
            if label in skip:
                continue
            trace = self.flight(level, shot)
            if trace.solved:
                yield Attempt(label, shot, trace, None)
