"""Running an evaluation: generate and measure tasks, resumably, in parallel.

Each task is one (scenario, seed) pair, seed = base seed + index, evaluated on an executor
(physc.execution: local processes or a Dask cluster). Its record is
appended to DIR/records.jsonl as soon as it is done (one JSON object a line,
flushed), so a killed run resumes where it stopped: tasks with a record are not
done again, unless the record was made with other settings (the generation settings,
the scenario as written, the source code of physc and of the scenario's domain plugin):
those are made again. A task's record
depends only on its scenario and seed, never on the process that made it, so the
results do not depend on the executor or the number of workers.
"""

from __future__ import annotations

import json
import random
import time
from pathlib import Path

from physc import budget
from physc.compiler.infeasible import Infeasible
from physc.domains.base import DomainError
from physc.driver.job import Job
from physc.driver.pipeline import Pipeline
from physc.evaluation import measure
from physc.execution import Executor
from physc.files import ensure_folder, read_json_lines, write_atomic
from physc.search.verify import verify
from physc.serialize import to_data

RECORDS = "records.jsonl"


def evaluate(job: Job) -> dict:
    """Generate one task (final validation skipped, as in the paper: the job says so) and
    measure it, in the job's world and engine; with a verify backend, replay its solution there too."""
    scenario, domain = job.target()
    record = {
        "file": job.path,
        "scenario": job.scenario,
        "domain": scenario.domain,
        "world": domain.world.name,
        "backend": domain.backend.name,
        "interactions": len(scenario.interactions),
        "seed": job.seed,
        "min_robustness": job.settings.min_robustness,
        "settings": job.recorded,
    }
    started = time.perf_counter()
    try:
        task = Pipeline(domain, scenario, job.seed, job.settings).task
    except (
        Infeasible,
        DomainError,
    ) as error:  # DomainError: a scenario the domain cannot make (PHYRE: three red balls)
        record.update(generated=False, reason=error.message, generation_seconds=round(time.perf_counter() - started, 4))
        if isinstance(error, Infeasible) and error.funnel is not None:  # where the layouts went (search.funnel)
            record.update(funnel=error.funnel)
        return record
    record.update(
        generated=True,
        generation_seconds=round(time.perf_counter() - started, 4),
        robustness=list(task.robustness),
        layouts_tried=task.layouts_tried,
        simulations=task.simulations,
        given_up=task.given_up,
        structure=task.structure,
    )
    proposals = dict(task.proposals or {})  # how its layouts were proposed, and where its objects were placed
    record.update(funnel=task.funnel, placed=proposals.pop("placed", None), proposals=proposals or None)
    weakest = (task.margins or {}).get("weakest")
    if weakest is not None:  # the weakest link over the noisy replays the solution passed (physc.simulation.margins)
        record.update(
            weakest_link=weakest["term"],
            weakest_share=weakest["share"],
            weakest_margin=f"{weakest['value']:+.3g} {weakest['unit']}",
        )
    if task.margins is not None:
        record.update(raised=bool(task.margins.get("raised")), raise_candidates=task.margins.get("candidates", 0))
    if task.acceptance is not None:  # the domain's acceptance rule (PHYRE's flags)
        record.update(
            good_stable="GOOD_STABLE" in task.acceptance["flags"],
            trivial="TRIVIAL" in task.acceptance["flags"],
            solution_stable=task.acceptance["solution_stable"],
            solve_rate=task.acceptance.get("solve_rate"),
        )
    rng = random.Random(f"physc-eval/{job.scenario}/{job.seed}")
    stable, shift = domain.stability(task.level)
    replay = measure.intended(domain, task.level, task.solution, scenario, rng)
    record.update(
        stable=stable,
        largest_shift=round(shift, 5),
        intended_exact=replay["exact_solved"],
        intended_noisy=replay["noisy_solved"],
        fidelity_exact=replay["exact_faithful"],
        fidelity_noisy=replay["noisy_faithful"],
        **domain.evaluation.accidental(task.level, scenario, task.solution, rng),
        trace=replay["trace"],
        solution=to_data(task.solution),
        level=to_data(task.level),
    )
    if job.settings.verify_backend is not None:
        check = verify(
            domain, scenario, task.level, task.solution, job.settings.verify_backend, noisy=measure.NOISY_REPLAYS
        )
        record.update(
            verify_backend=job.settings.verify_backend,
            verified_solved=check.solved,
            verified_realised=check.realised,
            verified_noisy=check.noisy_passed / check.noisy_run,
            verified_trace=check.trace,
        )
    return record


def key(job: Job) -> tuple[str, str, int]:
    """A record's key: scenarios of two files may share a name."""
    return (job.path, job.scenario, job.seed)


def done_records(folder: Path) -> dict:
    """The records already written (a torn last line, from a killed run, is ignored)."""
    return {
        (record["file"], record["scenario"], record["seed"]): record for record in read_json_lines(folder / RECORDS)
    }


def run(jobs: list[Job], folder: Path, executor: Executor, progress=None) -> list[dict]:
    """Evaluate the jobs that have no record made with their settings, on `executor`; every
    job's record, in the order of `jobs`."""
    ensure_folder(folder)
    records = done_records(folder)
    # A record made with other settings is made again (the last line of a key wins).
    todo = [job for job in jobs if key(job) not in records or records[key(job)].get("settings") != job.recorded]
    path = folder / RECORDS
    # Rewrite the file whole first, so that a torn last line cannot stay in the middle.
    if records:
        write_atomic(path, "".join(json.dumps(records[k], sort_keys=True) + "\n" for k in sorted(records)))
    if progress:
        progress.start(len(jobs), len(jobs) - len(todo), executor.describe())
    with path.open("a", encoding="utf-8") as out:

        def keep(record):
            records[(record["file"], record["scenario"], record["seed"])] = record
            out.write(json.dumps(record, sort_keys=True) + "\n")
            out.flush()
            if progress:
                progress.advance(record)

        try:
            with budget.interruptible():  # Ctrl-C stops the work at its next stopping point
                executor.map(evaluate, todo, keep)
        finally:  # the bar's display ends whatever stopped the work
            if progress:
                progress.stop()
    return [records[key(job)] for job in jobs if key(job) in records]
