"""Verification: a task's intended solution replayed, in every reading of its world and in any backend.

A task counts where it is played: its solution must solve the level and realise the declared
sequence as recorded and under the domain's noise, under every reading of what the world's
files leave open (physc.worlds.OpenPoint; Science Birds: the sign of relativeVelocity, the
kinematic platform's mass, near ties of the attacker), and, when asked, in an engine with
another contact solver. `verify` replays the solution once as recorded (and once as the
target world's players send it, where the domain says how: `actions.sent_action`), each
action those players may send beside it once (`actions.agent_variants`: the deterministic check
of physc.search.precision), and `noisy` times under the domain's noise, each replay in every
reading that can change it (physc.worlds.under_readings: the readings its own run shows to
decide something), and says which readings and which of the players' actions failed.
`physc verify`, `physc compile --verify-backend`, the generation's check
(physc.driver.layout_loop) and `physc eval` all use it. Nothing here depends on a domain.
"""

from __future__ import annotations

import random

import attrs
import numpy as np

from physc.simulation.fidelity import fidelity
from physc.worlds import under_readings


@attrs.frozen
class Verification:
    backend: str
    solved: bool  # the recorded solution solves the level (the domain's goal is met) in every reading
    realised: bool  # and its simulation realises the declared sequence, breaking no restriction, in every reading
    noisy_passed: int  # noisy replays that realised the sequence in every reading
    noisy_run: int
    trace: str  # the interactions the recorded solution realises (the world's own reading), in .phys syntax
    why: str  # what the replay got wrong, in words ("" when it passed)
    readings: int = 1  # readings of the world played (the most any replay needed)
    failed: tuple[str, ...] = ()  # the readings (world names) in which a replay failed, in the order met
    simulations: int = 0  # simulations run in all
    variants: int = 0  # actions the players may send beside the recorded one, played (actions.agent_variants)
    imprecise: tuple[str, ...] = ()  # those that failed: their labels (and the reading, where not the world's own)

    def passes(self, noisy_needed: int = 0) -> bool:
        """The recorded solution solves the level and realises the sequence, so does every
        action the players may send beside it, and at least `noisy_needed` noisy replays realise
        it too, in every reading."""
        return self.solved and self.realised and not self.imprecise and self.noisy_passed >= noisy_needed

    def summary(self) -> str:
        parts = [
            "solved" if self.solved else "not solved",
            "sequence realised" if self.realised else "sequence not realised",
        ]
        if self.noisy_run:
            parts.append(f"{self.noisy_passed} of {self.noisy_run} noisy replays realise it")
        if self.readings > 1:
            parts.append(
                f"in each of the {self.readings} readings of the world that change a replay"
                if not self.failed
                else f"{len(self.failed)} of the readings fail"
            )
        if self.variants:
            failing = len(self.imprecise)
            parts.append(
                f"{failing} of the {self.variants} actions agents may send beside it fail"
                if failing
                else f"the {self.variants} actions agents may send beside it solve it"
            )
        return f"in {self.backend}: " + ", ".join(parts)


def noisy_replays(domain) -> int:
    """The noisy replays a solution is put through by default: the domain's own (none for a
    domain without a noise model)."""
    return domain.robustness_replays or 0


FALLING = 0.5  # trace units/s: a body coming down faster is still falling (a fall's landing may yet change the verdict)


def settled(scenario, trace) -> float:
    """When the verdict on `trace` is settled: the declared sequence complete, the goal met
    and nothing coming down (a fall that began before may still be recognised, and break a
    restriction, where it lands); the end of the run when any of them is not."""
    check = fidelity(scenario, trace)
    if not check.valid or not check.times:
        return float("inf")
    done = max(check.times[-1], max((d.time for d in trace.destructions if d.name in trace.goal), default=0.0))
    row = min(int(round(done / trace.dt)), trace.steps - 1)
    falling = trace.states[row, :, 4]
    return float("inf") if (falling[~np.isnan(falling)] < -FALLING).any() else done


def _why(scenario, trace, check) -> str:
    if not trace.solved:
        return "the solution does not solve the level"
    if check.violations:
        return "it breaks " + ", ".join(check.violations)
    if not check.valid:
        missing = scenario.interactions[check.matched].text
        return f"it realises {check.matched} of {check.total} interactions in order (never `{missing}`)"
    return ""


def failing_reading(world, scenario, run) -> str | None:
    """The first reading of `world` (its name) in which `run` (one play, in a given reading)
    does not solve the level and realise `scenario`'s sequence, among the readings that can
    change the play; None: it holds in every one."""
    for reading, trace in under_readings(world, run, lambda trace: settled(scenario, trace)):
        if not (trace.solved and fidelity(scenario, trace).valid):
            return reading.name
    return None


def agents_actions(there, scenario, level, solution) -> tuple[int, list[str], int]:
    """(how many actions the players may send beside `solution`'s, the labels of those that
    fail in some reading, the simulations run): physc.search.precision's check."""
    variants = there.actions.agent_variants(level, solution)
    failed, plays = [], []

    def run(reading, action):
        plays.append(reading)
        return there.at(reading).play(level, action, scenario)

    for label, action in variants:
        wrong = failing_reading(there.world, scenario, lambda reading, a=action: run(reading, a))
        if wrong is not None:
            failed.append(label + ("" if wrong == there.world.name else f" (in the reading '{wrong}')"))
    return len(variants), failed, len(plays)


def verify(domain, scenario, level, solution, backend: str, noisy: int = 0) -> Verification:
    """Replay `solution` in `level` with `backend`: once as recorded, then `noisy` times
    under the domain's noise (drawn from a generator seeded by the backend and the solution,
    so a verification is the same whenever and wherever it runs), each in every reading of
    the world that can change it. The world is the domain's (`Domain.at`)."""
    there = domain.at(backend=backend)
    world = there.world
    failed: list[str] = []
    simulations = 0
    most = 1

    after = []  # the noise generator's state after a replay's draws (the same in every reading)

    def played(rng_state=None, sent=None) -> list:
        """(reading, trace, fidelity) of one replay in every reading that can change it, each
        reading drawing the same noise (from `rng_state`); `sent`: the solution played as the
        target world's players send it instead (exact)."""
        nonlocal simulations, most

        def run(reading):
            rng = None
            if rng_state is not None:
                rng = random.Random()
                rng.setstate(rng_state)
            if sent is not None:
                return there.at(reading).play(level, sent, scenario)
            trace = there.at(reading).replay(level, solution, scenario, rng)
            if rng is not None:
                after.append(rng.getstate())
            return trace

        runs = under_readings(world, run, lambda trace: settled(scenario, trace))
        simulations += len(runs)
        most = max(most, len(runs))
        out = [(reading, trace, fidelity(scenario, trace)) for reading, trace in runs]
        for reading, _, check in out:
            if not check.valid and reading.name not in failed:
                failed.append(reading.name)
        return out

    exact = played()
    sent = there.actions.sent_action(solution)
    if sent is not None:  # the action as players send it (Phy-Q's agents: whole pixels) must hold too
        exact += played(sent=sent)
    _, trace, check = exact[0]
    solved = all(t.solved for _, t, _ in exact)
    realised = all(c.valid for _, _, c in exact)
    why = next((_why(scenario, t, c) for _, t, c in exact if not c.valid), "")
    if why and exact[0][2].valid:
        why = f"in the reading '{next(r.name for r, _, c in exact if not c.valid)}': {why}"
    variants, imprecise, spent = agents_actions(there, scenario, level, solution)
    why = why or (f"as an agent may send it, it fails: {'; '.join(imprecise)}" if imprecise else "")
    rng = random.Random(f"physc-verify/{backend}/{scenario.name}/{solution!r}")
    passed = 0
    for _ in range(noisy):
        after.clear()
        replays = played(rng.getstate())
        passed += all(c.valid for _, _, c in replays)
        rng.setstate(after[0])
    if not why and passed < noisy:
        why = f"{passed} of {noisy} noisy replays realise the sequence" + (
            f" in every reading (failing in: {'; '.join(failed)})" if failed else ""
        )
    result = Verification(backend, solved, realised, passed, noisy, trace.sequence(), why, most, tuple(failed))
    return attrs.evolve(result, simulations=simulations + spent, variants=variants, imprecise=tuple(imprecise))
