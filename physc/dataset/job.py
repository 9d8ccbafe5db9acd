"""One task of a dataset: its job, and the function that makes it in a worker.

The worker returns the task's manifest row and its files' contents; the process that runs the
dataset writes them (physc.dataset.build), so a worker may be on another machine. Everything a
task's files and row hold depends only on its scenario, seed and settings, except the times.
"""

from __future__ import annotations

import json
import random
import time

import attrs

from physc import __version__, budget
from physc.backends import DEFAULT_BACKEND, selected
from physc.compiler.infeasible import Infeasible
from physc.domains.base import DomainError
from physc.compiler.pipeline import Pipeline
from physc.compiler.task import MIN_ROBUSTNESS
from physc.domains import load_domain
from physc.dsl.frontend import analyze_files, scenario_in
from physc.dataset.manifest import terms
from physc.fingerprint import code_fingerprint, scenario_fingerprint
from physc.serialize import to_data

OK, FALLBACK, NO_TASK = "ok", "fallback", "no task"  # a row's outcome


@attrs.frozen
class TaskJob:
    path: str  # the .phys file
    scenario: str
    seed: int
    time_budget: float
    min_robustness: int = MIN_ROBUSTNESS
    validate: bool = True  # the final validation of a generated task (physc compile's)
    acceptance: bool = True  # the domain's acceptance rule judges each task (physc compile's --no-acceptance)
    picture: bool = False  # also draw the task (<seed>.png)
    accidental: bool = False  # also measure accidental solvability (the domain's agent)
    backend: str = DEFAULT_BACKEND
    verify_backend: str | None = None
    domain: str = ""
    fingerprint: str = ""  # of the scenario as written
    code: str = ""  # of the code that makes the task
    source: str = ""  # the scenario's text in block form: a worker reads this, never the file (it may run elsewhere)

    @property
    def key(self) -> tuple[str, int]:
        return (self.scenario, self.seed)

    @property
    def settings(self) -> dict:
        """What the task's files and row depend on besides its key: a row made with other
        settings is made again."""
        return {
            "time_budget": self.time_budget, "min_robustness": self.min_robustness, "validate": self.validate,
            "acceptance": self.acceptance, "picture": self.picture, "accidental": self.accidental, "backend": self.backend,
            "verify_backend": self.verify_backend, "scenario": self.fingerprint, "physc": __version__, "code": self.code,
        }


def jobs_for(files: list[str], tasks: int, seed: int, **settings) -> tuple[list[TaskJob], list]:
    """Every (scenario, seed) job of the files, seeds `seed` to `seed + tasks - 1`; and the
    diagnostics of files with errors. `settings`: the other fields of TaskJob."""
    jobs = []
    scenarios, problems = analyze_files(files)
    engines = tuple(n for n in (settings.get("backend", DEFAULT_BACKEND), settings.get("verify_backend")) if n)
    for path, scenario, source in scenarios:
        common = dict(
            settings, domain=scenario.domain, fingerprint=scenario_fingerprint(scenario), code=code_fingerprint(scenario.domain, engines), source=source,
        )
        jobs += [TaskJob(path, scenario.name, seed + index, **common) for index in range(tasks)]
    return jobs, problems


def scenario_file(scenario: str) -> str:
    """Where a dataset keeps a scenario as written, relative to the dataset: rows name this, not
    the path it was read from, so the dataset stands alone."""
    return f"{scenario}/scenario.phys"


def file_names(job: TaskJob, level_suffix: str) -> dict[str, str]:
    """The task's files, relative to the dataset folder: level, task and picture."""
    level = f"{job.seed}.level.json" if level_suffix == "json" else f"{job.seed}.{level_suffix}"
    return {"level": f"{job.scenario}/{level}", "task": f"{job.scenario}/{job.seed}.json", "picture": f"{job.scenario}/{job.seed}.png"}


def make(job: TaskJob) -> dict:
    """Make one task (in a worker): {"row": its manifest row, "files": {relative path: contents}}."""
    with selected(job.backend):
        return _make(job)


def _make(job: TaskJob) -> dict:
    scenario = scenario_in(job.path, job.source, job.scenario)
    domain = load_domain(scenario.domain)
    row = {
        "file": scenario_file(job.scenario), "scenario": job.scenario, "seed": job.seed, "domain": scenario.domain, "title": scenario.title,
        "interactions": len(scenario.interactions), "sequence": " > ".join(t.text for t in scenario.interactions),
        "sequence_terms": [t.text for t in scenario.interactions], "settings": job.settings,
    }
    started = time.perf_counter()
    try:
        with budget.deadline(job.time_budget):
            task = Pipeline(
                domain, scenario, job.seed, validate=job.validate, acceptance=job.acceptance, time_budget=job.time_budget,
                source=job.source, min_robustness=job.min_robustness, verify_backend=job.verify_backend,
            ).task
            picture = domain.picture(task, "png") if job.picture else None
    except (Infeasible, DomainError) as error:  # DomainError: a scenario the domain cannot make (PHYRE: three red balls)
        row.update(outcome=NO_TASK, reason=error.message, generation_seconds=round(time.perf_counter() - started, 4))
        return {"row": row, "files": {}}
    except budget.OutOfTime:
        row.update(outcome=NO_TASK, reason=f"the time budget of {job.time_budget:g} s ran out", generation_seconds=round(time.perf_counter() - started, 4))
        return {"row": row, "files": {}}
    seconds = round(time.perf_counter() - started, 4)
    names = file_names(job, domain.level_suffix)
    data = to_data(task)
    data.pop("seconds", None)  # times are the manifest's: the task file's bytes depend on its seed only
    files = {names["level"]: domain.emit_level(task.level), names["task"]: json.dumps(data, indent=2, ensure_ascii=False) + "\n"}
    if picture is not None:
        files[names["picture"]] = picture
    passed, run = task.robustness
    row.update(
        outcome=OK if passed >= run else FALLBACK, reason=None,
        level=names["level"], task=names["task"], picture=names["picture"] if picture is not None else None,
        solution=to_data(task.solution), trace=task.trace, trace_terms=terms(task.trace), robustness_passed=passed, robustness_run=run,
        validated=task.validated, layouts_tried=task.layouts_tried, simulations=task.simulations,
    )
    if job.accidental:
        rng = random.Random(f"physc-generate/{job.scenario}/{job.seed}")
        row.update(domain.accidental(task.level, scenario, task.solution, rng))
    row.update(generation_seconds=seconds, seconds=task.seconds)
    return {"row": row, "files": files}
