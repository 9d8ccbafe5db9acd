"""One task of a dataset: the function that makes it in a worker (its job: physc.driver.job).

The worker returns the task's manifest row and its files' contents; the process that runs the
dataset writes them (physc.dataset.build), so a worker may be on another machine. Everything a
task's files and row hold depends only on its scenario, seed and settings, except the times.
"""

from __future__ import annotations

import json
import random
import time

from physc.compiler.infeasible import Infeasible
from physc.dataset import waves
from physc.dataset.manifest import terms
from physc.domains.base import DomainError
from physc.driver.job import Job
from physc.driver.pipeline import Pipeline
from physc.serialize import to_data

OK, FALLBACK, NO_TASK = "ok", "fallback", "no task"  # a row's outcome


def scenario_file(scenario: str) -> str:
    """Where a dataset keeps a scenario as written, relative to the dataset: rows name this, not
    the path it was read from, so the dataset stands alone."""
    return f"{scenario}/scenario.phys"


def file_names(job: Job, level_suffix: str) -> dict[str, str]:
    """The task's files, relative to the dataset folder: level, task and picture."""
    level = f"{job.seed}.level.json" if level_suffix == "json" else f"{job.seed}.{level_suffix}"
    return {
        "level": f"{job.scenario}/{level}",
        "task": f"{job.scenario}/{job.seed}.json",
        "picture": f"{job.scenario}/{job.seed}.png",
    }


def make(job: Job) -> dict:
    """Make one task (in a worker): {"row": its manifest row, "files": {relative path: contents}}."""
    scenario, domain = job.target()
    row = {
        "file": scenario_file(job.scenario),
        "scenario": job.scenario,
        "seed": job.seed,
        "domain": scenario.domain,
        "world": domain.world.name,
        "backend": domain.backend.name,
        "title": scenario.title,
        "interactions": len(scenario.interactions),
        "sequence": " > ".join(t.text for t in scenario.interactions),
        "sequence_terms": [t.text for t in scenario.interactions],
        "settings": job.recorded,
    }
    started = time.perf_counter()
    run = Pipeline(domain, scenario, job.seed, job.settings, job.source, earlier=job.earlier)
    examples = waves.examples_file(job.scenario, job.seed)  # what its compile taught, for later waves
    row.update(learned_from=list(job.learned_from), examples=examples)
    try:
        with run.within_budget():  # the picture is part of the task's work, within its one budget
            task = run.task
            picture = domain.files.picture(task, "png") if job.picture else None
    except (
        Infeasible,
        DomainError,
    ) as error:  # DomainError: a scenario the domain cannot make (PHYRE: three red balls)
        row.update(outcome=NO_TASK, reason=error.message, generation_seconds=round(time.perf_counter() - started, 4))
        return {"row": row, "files": {examples: waves.dumped(run.taught)}}
    seconds = round(time.perf_counter() - started, 4)
    names = file_names(job, domain.files.level_suffix)
    data = to_data(task)
    assert isinstance(data, dict), "an attrs value dumps to an object"
    data.pop("seconds", None)  # times are the manifest's: the task file's bytes depend on its seed only
    files: dict[str, str | bytes] = {
        names["level"]: domain.files.emit_level(task.level),
        names["task"]: json.dumps(data, indent=2, ensure_ascii=False) + "\n",
        examples: waves.dumped(run.taught),
    }
    if picture is not None:
        files[names["picture"]] = picture
    passed, run = task.robustness
    row.update(
        outcome=OK if passed >= run else FALLBACK,
        reason=None,
        level=names["level"],
        task=names["task"],
        picture=names["picture"] if picture is not None else None,
        solution=to_data(task.solution),
        trace=task.trace,
        trace_terms=terms(task.trace),
        robustness_passed=passed,
        robustness_run=run,
        validated=task.validated,
        layouts_tried=task.layouts_tried,
        simulations=task.simulations,
    )
    if job.accidental:
        rng = random.Random(f"physc-generate/{job.scenario}/{job.seed}")
        row.update(domain.evaluation.accidental(task.level, scenario, task.solution, rng))
    row.update(generation_seconds=seconds, seconds=task.seconds)
    return {"row": row, "files": files}
