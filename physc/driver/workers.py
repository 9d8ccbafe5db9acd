"""Every core a compile has: the placed layouts of a round satisfied side by side.

The layout loop tries placed layouts in rounds of a fixed size (physc.driver.ranking.ROUND).
`Workers` satisfies a round's layouts, in order, and answers with their outcomes up to and
including the first that gives a task: with one worker, one after another in this process
(stopping at that first); with more, each in a process of a pool at once (the rest are let
go). Each layout's search draws from a generator named after the run's seed and the layout's
place in the run (`satisfy_layout`), never from a generator another layout moved, and the loop reads
the outcomes in the round's order, so a compile gives the same task, byte for byte, whatever
the number of workers: they change only how soon.

A worker process is started from a fork server that has physc's search imported; it is handed
the bound domain, the scenario and the run's settings once (they pickle in a few kilobytes),
then one placed layout at a time, with the moment the run's time budget ends (a monotonic
clock, which is the machine's, not the process's). It ignores Ctrl-C: the loop stops the pool.

With `physc generate --jobs J` (tasks spread over J processes), each task's compile uses
`--workers W` processes of its own: J × W in all, so W is 1 there unless the machine has cores
to spare.
"""

from __future__ import annotations

import multiprocessing
import random
import signal
from collections.abc import Sequence

import attrs

from physc import budget
from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.simulated import SimulatedDomain
from physc.driver.run_settings import RunSettings
from physc.dsl.scenario import ScenarioIR
from physc.search import search
from physc.search.outcome import Outcome
from physc.search.verify import noisy_replays, verify

Job = tuple[int, ConcreteLayout, int | None]  # (the layout's place in the run, the layout, accept)


@attrs.frozen
class Run:
    """What every layout's satisfaction reads: the bound domain, the scenario, the run's settings
    and seed."""

    domain: SimulatedDomain
    scenario: ScenarioIR
    settings: RunSettings
    seed: int | None


def satisfy_layout(run: Run, index: int, layout: ConcreteLayout, accept: int | None = None) -> Outcome:
    """The search's satisfaction of one layout with the domain's hooks (accepting `accept`
    noisy replays, for a fallback), then the checks that it holds where it is played. Its
    generator is named after the run's seed and the layout's place `index` in the run."""
    rng = random.Random(f"{run.seed}/layout/{index}/{accept}")
    result = search.satisfy(run.domain, run.scenario, layout, rng, run.settings.checks, accept)
    return checked(run, result, accept) if result.satisfied else result


def checked(run: Run, result: Outcome, accept: int | None) -> Outcome:
    """`result`, if its solution passes what `physc verify` runs (the recorded solution and the
    domain's noisy replays, drawn as verify draws them) under every reading of what the world's
    files leave open that can change a replay (physc.worlds.under_readings), and in the second
    backend if one is asked for; else the layout given up for that reason (the search goes on
    to the next layout). `accept`: a fallback needs K of the noisy replays."""
    parts = result.parts
    assert parts is not None, "a satisfied outcome has its parts"
    replays = noisy_replays(run.domain)
    needed = accept if accept is not None else replays
    places: list[str | None] = [None]
    if run.settings.verify_backend is not None:
        places.append(run.settings.verify_backend)
    spent = 0
    for other in places:
        check = verify(
            run.domain, run.scenario, parts.level, parts.solution, other or run.domain.backend.name, noisy=replays
        )
        spent += check.simulations
        if not check.passes(needed):
            if other is not None:
                why = f"the solution fails in {other}"
            else:
                where = check.failed[0] if check.failed else run.domain.world.name
                why = f"the solution fails physc verify in the world '{where}'"
            return attrs.evolve(
                result, satisfied=False, parts=None, simulations=result.simulations + spent, given_up=why, nearest=0
            )
    return attrs.evolve(result, simulations=result.simulations + spent)


_RUN: Run | None = None  # a worker process's run, handed over once (`_start`)


def _start(run: Run) -> None:
    global _RUN
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # the loop stops the pool on Ctrl-C
    _RUN = run


def _satisfy_until(job: Job, end: float | None, seconds: float) -> Outcome | None:
    """A worker's satisfaction of one job, within the run's time budget (ending at the
    monotonic `end`; None: none)."""
    assert _RUN is not None, "a worker is started with its run"
    index, layout, accept = job
    try:
        if end is None:
            return satisfy_layout(_RUN, index, layout, accept)
        with budget.deadline(budget.Deadline.until(end, seconds)):
            return satisfy_layout(_RUN, index, layout, accept)
    except budget.OutOfTime:
        return None  # the time budget ran out during its search


@attrs.define
class Workers:
    """A round's layouts satisfied with `count` workers (module docstring)."""

    run: Run
    count: int = 1
    pool: object | None = None  # a multiprocessing pool, started with the first round that needs it

    def satisfy(self, jobs: Sequence[Job]) -> list[Outcome | None]:
        """The outcomes of `jobs`, in order, up to and including the first that gives a task or
        ran out of time (None)."""
        if self.count <= 1 or len(jobs) <= 1:
            return self._here(jobs)
        end, seconds = budget.current()
        pool = self._pool()
        waiting = [pool.apply_async(_satisfy_until, (job, end, seconds)) for job in jobs]  # type: ignore[attr-defined]
        answers: list[Outcome | None] = []
        for pending in waiting:
            while not pending.ready():  # waiting in short steps: Ctrl-C and the deadline are heard
                pending.wait(0.05)
                if end is not None:
                    budget.check()
            answer = pending.get()
            answers.append(answer)
            if answer is None or answer.satisfied:
                break
        return answers

    def _here(self, jobs: Sequence[Job]) -> list[Outcome | None]:
        answers: list[Outcome | None] = []
        for index, layout, accept in jobs:
            try:
                answer = satisfy_layout(self.run, index, layout, accept)
            except budget.OutOfTime:
                answers.append(None)
                break
            answers.append(answer)
            if answer.satisfied:
                break
        return answers

    def _pool(self):
        if self.pool is None:
            context = multiprocessing.get_context("forkserver")
            context.set_forkserver_preload(["physc.driver.workers"])
            self.pool = context.Pool(self.count, initializer=_start, initargs=(self.run,))
        return self.pool

    def close(self) -> None:
        """The worker processes stopped (what they were doing is not needed)."""
        if self.pool is not None:
            self.pool.terminate()  # type: ignore[attr-defined]
            self.pool.join()  # type: ignore[attr-defined]
            self.pool = None
