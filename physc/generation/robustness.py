"""Whether a solution survives noise, and centring one that does not.

A working action is replayed under the domain's noise model (`noisy`, the evaluation's)
`robustness_replays` times. One that fails some is first centred: moved to the middle of
the run of working actions around it along the domain's `nudged` line (angrybirds: the
release angle 0.05° a step; PHYRE: the ball a pixel a step). Whichever way it came to
pass them, it must pass as many fresh replays too (the second of NOISE_STREAMS: it was
chosen for passing the first), and every obstacle and distractor added after it must
leave it passing both (`holds_up`).
"""

from __future__ import annotations

import random

import attrs

from physc.generation.attempt import Attempt
from physc.generation.settings import NOISE_STREAMS
from physc.simulation.stopped import why_stopped


class Robustness:
    """The noisy replays of a search (mixed into physc.generation.search.Search, whose
    `simulate`, `domain`, `settings` and `accept` they use)."""

    def robustness(self, attempt: Attempt, layout, stream: str = NOISE_STREAMS[0]) -> int:
        """How many of the domain's noisy replays of the attempt in `layout` realise the
        sequence (`stream` names the noise drawn: another name, other replays)."""
        noise = random.Random(f"{stream}/{attempt.label}")
        level = self.level_of(layout)
        passed = 0
        for _ in range(self.domain.robustness_replays or 0):
            noisy_level, action = self.domain.noisy(level, attempt.action, noise)
            played = self.play(noisy_level, action)
            passed += played.fidelity.valid
            if not played.fidelity.valid:
                self.lose(played)
        return passed

    def lose(self, played: Attempt) -> None:
        """Count a failed noisy replay against the declared interaction it lost first (a
        restriction it broke, when it realised them all), with what the first such replay shows."""
        interactions = self.scenario.interactions
        k = played.fidelity.matched
        term = interactions[k].text if k < len(interactions) else "the restrictions"
        count, why = self.lost.get(term, (0, None))
        if why is None:
            why = why_stopped(self.scenario, played.trace, played.fidelity) if k < len(interactions) else ", ".join(played.fidelity.violations)
        self.lost[term] = (count + 1, why)

    def lost_links(self) -> tuple[tuple[str, int, str], ...]:
        """The noisy replays' losses (Outcome.lost), most often lost first."""
        return tuple(sorted(((term, n, why) for term, (n, why) in self.lost.items()), key=lambda item: -item[1]))

    def holds_up(self, attempt: Attempt, layout) -> bool:
        """Whether the solution in `layout` still passes as many noisy replays as it must,
        in both noise streams (a change made after the confirmation is itself chosen for
        passing the replays it is checked with)."""
        return all(self.robustness(attempt, layout, stream) >= self.accept for stream in NOISE_STREAMS)

    def centred(self, attempt: Attempt, layout) -> Attempt | None:
        """The action in the middle of the run of working actions around `attempt` along the
        domain's `nudged` line (at most `centring_steps` each way), if that is another action
        and works; None otherwise (or when the domain draws no such line)."""
        level = self.level_of(layout)

        def nudge(step: int) -> Attempt | None:
            action = self.domain.nudged(attempt.action, step)
            if action is None or not self.domain.valid(level, action):
                return None
            return attrs.evolve(self.simulate(layout, action), label=f"{attempt.label}, nudged {step:+d}")

        steps = self.settings.centring_steps
        low = high = 0
        while low > -steps and (found := nudge(low - 1)) is not None and found.fidelity.valid:
            low -= 1
        while high < steps and (found := nudge(high + 1)) is not None and found.fidelity.valid:
            high += 1
        middle = (low + high) // 2
        if middle == 0:
            return None
        centre = nudge(middle)
        return centre if centre is not None and centre.fidelity.valid else None

    def robust(self, attempts, layout) -> tuple[Attempt, int] | None:
        """The first of `attempts` (in `layout`) that realises the sequence and passes `accept` noisy
        replays (centred first if it fails some) and as many fresh ones, with the replays it
        passed; at most `candidates` working ones are put through the replays."""
        replays = self.domain.robustness_replays or 0
        for attempt in attempts:
            if not attempt.fidelity.valid:
                continue
            self.tried += 1
            passed = self.robustness(attempt, layout)
            if passed < replays:
                centred = self.centred(attempt, layout)
                if centred is not None:
                    again = self.robustness(centred, layout)
                    if again > passed:
                        attempt, passed = centred, again
            if passed >= self.accept:
                passed = min(passed, self.robustness(attempt, layout, NOISE_STREAMS[1]))
            if passed >= self.accept:
                return attempt, passed
            self.nearest = max(self.nearest, passed)
            if self.tried == self.settings.candidates:
                return None
        return None
