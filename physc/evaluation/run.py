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

import attrs

from physc import __version__, budget
from physc.compiler.infeasible import Infeasible
from physc.domains.base import DomainError
from physc.compiler.pipeline import Pipeline
from physc.backends import DEFAULT_BACKEND, selected
from physc.compiler.task import MIN_ROBUSTNESS
from physc.domains import load_domain
from physc.dsl.frontend import analyze_files, scenario_in
from physc.evaluation import measure
from physc.execution import Executor
from physc.files import ensure_folder, read_json_lines, write_atomic
from physc.fingerprint import code_fingerprint, scenario_fingerprint
from physc.generation.verify import verify
from physc.serialize import to_data

RECORDS = "records.jsonl"


@attrs.frozen
class Job:
    path: str  # the .phys file
    scenario: str
    seed: int
    time_budget: float
    min_robustness: int = MIN_ROBUSTNESS  # see Pipeline
    fingerprint: str = ""  # of the scenario as written (scenario_fingerprint)
    code: str = ""  # of the code that generates and measures it (code_fingerprint)
    domain: str = ""  # the scenario's domain
    backend: str = DEFAULT_BACKEND  # the engine that generates and measures (--backend)
    verify_backend: str | None = None  # a second engine the solution is replayed in (--verify-backend)
    acceptance: bool = True  # the domain's acceptance rule judges each task (--no-acceptance: off)
    source: str = ""  # the scenario's text in block form: a worker reads this, never the file (it may run elsewhere)

    @property
    def key(self) -> tuple[str, str, int]:
        return (self.path, self.scenario, self.seed)

    @property
    def settings(self) -> dict:
        """What a task's record depends on besides its key: a record made with other
        settings is stale."""
        settings = {
            "time_budget": self.time_budget,
            "min_robustness": self.min_robustness,
            "scenario": self.fingerprint,
            "physc": __version__,
            "code": self.code,
        }
        # Only when not the default, so that records made before backends could be chosen stay valid.
        if self.backend != DEFAULT_BACKEND:
            settings["backend"] = self.backend
        if self.verify_backend is not None:
            settings["verify_backend"] = self.verify_backend
        if not self.acceptance:
            settings["acceptance"] = False
        return settings


def evaluate(job: Job) -> dict:
    """Generate one task (final validation skipped, as in the paper) and measure it, in the
    job's backend; with a verify backend, replay its solution there too."""
    with selected(job.backend):
        return _evaluate(job)


def _evaluate(job: Job) -> dict:
    scenario = scenario_in(job.path, job.source, job.scenario)
    domain = load_domain(scenario.domain)
    record = {
        "file": job.path,
        "scenario": job.scenario,
        "domain": scenario.domain,
        "interactions": len(scenario.interactions),
        "seed": job.seed,
        "min_robustness": job.min_robustness,
        "settings": job.settings,
    }
    started = time.perf_counter()
    try:
        task = Pipeline(
            domain, scenario, job.seed, validate=False, time_budget=job.time_budget, min_robustness=job.min_robustness,
            verify_backend=job.verify_backend, acceptance=job.acceptance,
        ).task
    except (Infeasible, DomainError) as error:  # DomainError: a scenario the domain cannot make (PHYRE: three red balls)
        record.update(generated=False, reason=error.message, generation_seconds=round(time.perf_counter() - started, 4))
        return record
    record.update(
        generated=True,
        generation_seconds=round(time.perf_counter() - started, 4),
        robustness=list(task.robustness),
        layouts_tried=task.layouts_tried,
        simulations=task.simulations,
        given_up=task.given_up,
    )
    if task.acceptance is not None:  # the domain's acceptance rule (PHYRE's flags)
        record.update(
            good_stable="GOOD_STABLE" in task.acceptance["flags"], trivial="TRIVIAL" in task.acceptance["flags"],
            solution_stable=task.acceptance["solution_stable"], stable_rate=task.acceptance["stable_rate"],
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
        **domain.accidental(task.level, scenario, task.solution, rng),
        trace=replay["trace"],
        solution=to_data(task.solution),
        level=to_data(task.level),
    )
    if job.verify_backend is not None:
        check = verify(domain, scenario, task.level, task.solution, job.verify_backend, noisy=measure.NOISY_REPLAYS)
        record.update(
            verify_backend=job.verify_backend,
            verified_solved=check.solved,
            verified_realised=check.realised,
            verified_noisy=check.noisy_passed / check.noisy_run,
            verified_trace=check.trace,
        )
    return record


def jobs_for(
    files: list[str], tasks: int, seed: int, time_budget: float, min_robustness: int = MIN_ROBUSTNESS,
    backend: str = DEFAULT_BACKEND, verify_backend: str | None = None, acceptance: bool = True,
) -> tuple[list[Job], list]:
    """Every (scenario, seed) job of the files; and the diagnostics of files with errors."""
    jobs = []
    scenarios, problems = analyze_files(files)
    for path, scenario, source in scenarios:
        engines = tuple(name for name in (backend, verify_backend) if name)
        fingerprint, code = scenario_fingerprint(scenario), code_fingerprint(scenario.domain, engines)
        jobs += [
            Job(path, scenario.name, seed + index, time_budget, min_robustness, fingerprint, code, scenario.domain, backend, verify_backend, acceptance, source)
            for index in range(tasks)
        ]
    return jobs, problems


def done_records(folder: Path) -> dict:
    """The records already written (a torn last line, from a killed run, is ignored)."""
    return {(record["file"], record["scenario"], record["seed"]): record for record in read_json_lines(folder / RECORDS)}


def run(jobs: list[Job], folder: Path, executor: Executor, progress=None) -> list[dict]:
    """Evaluate the jobs that have no record made with their settings, on `executor`; every
    job's record, in the order of `jobs`."""
    ensure_folder(folder)
    records = done_records(folder)
    # A record made with other settings is made again (the last line of a key wins).
    todo = [job for job in jobs if job.key not in records or records[job.key].get("settings") != job.settings]
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
    return [records[job.key] for job in jobs if job.key in records]
