"""One task to make: the job `physc generate` and `physc eval` hand a worker.

A job names a scenario (its text travels with it: a worker may be on another machine), a
seed, the world and engine it is made in, the run's settings (one RunSettings value,
physc.driver.run_settings) and, in a dataset, the earlier tasks it learns from (their seeds and
the examples their compiles taught: physc.dataset.waves). It depends on nothing else, so the
task it makes depends only on the job, never on the process or the number of workers.
`recorded` is what a stored result (a dataset row, an evaluation record) was made with: one
made with other settings is made again.
"""

from __future__ import annotations

from typing import Any

import attrs

from physc import __version__
from physc.backends import DEFAULT_BACKEND
from physc.domains import bound, load_domain, world_name
from physc.domains.words import INSTALLED
from physc.driver.run_settings import RunSettings
from physc.dsl.frontend import analyze_files, scenario_in
from physc.fingerprint import code_fingerprint, scenario_fingerprint
from physc.search.link_model import KindedExample


@attrs.frozen
class Job:
    path: str  # the .phys file
    scenario: str
    seed: int
    settings: RunSettings = RunSettings()  # the run's budgets and checks (eval: validate=False, as the paper)
    picture: bool = False  # also draw the task (generate --png)
    accidental: bool = False  # also measure accidental solvability (generate --accidental)
    world: str = ""  # the domain's world ("": its default)
    backend: str = DEFAULT_BACKEND  # the engine that generates and measures (--backend)
    domain: str = ""  # the scenario's domain
    fingerprint: str = ""  # of the scenario as written (scenario_fingerprint)
    code: str = ""  # of the code that makes the task (code_fingerprint)
    source: str = ""  # the scenario's text in block form: a worker reads this, never the file
    learned_from: tuple[int, ...] = ()  # seeds of the scenario's earlier tasks it learns from (physc.dataset.waves)
    earlier: tuple[KindedExample, ...] = attrs.field(default=(), eq=False, repr=False)  # their examples

    @property
    def key(self) -> tuple[str, int]:
        return (self.scenario, self.seed)

    @property
    def recorded(self) -> dict:
        """What the job's result depends on besides its key (a stored result's `settings`: one
        made with others is made again)."""
        run = self.settings
        return {
            "time_budget": run.time_budget,
            "layouts": run.layouts,
            "clause_budget": run.clause_budget,
            "min_robustness": run.min_robustness,
            "validate": run.validate,
            "acceptance": run.acceptance,
            "picture": self.picture,
            "accidental": self.accidental,
            "world": self.world,
            "backend": self.backend,
            "verify_backend": run.verify_backend,
            "scenario": self.fingerprint,
            "physc": __version__,
            "code": self.code,
            "learned_from": list(self.learned_from),
        }

    def target(self):
        """(the scenario's IR, its domain simulating in the job's world with the job's engine)."""
        scenario = scenario_in(self.path, self.source, self.scenario, INSTALLED)
        return scenario, bound(load_domain(scenario.domain), self.world or None, self.backend)


def jobs_for(files: list[str], tasks: int, seed: int, **settings) -> tuple[list[Job], list]:
    """Every (scenario, seed) job of the files, seeds `seed` to `seed + tasks - 1`, and the
    diagnostics of files with errors. `settings`: the other fields of Job (its RunSettings as
    `settings`). The world is
    named in each job (the domain's default when none is given), so a stored result says
    which world made it."""
    jobs = []
    scenarios, problems = analyze_files(files, INSTALLED)
    run = settings.get("settings") or RunSettings()
    engines = tuple(n for n in (settings.get("backend", DEFAULT_BACKEND), run.verify_backend) if n)
    for path, scenario, source in scenarios:
        world = world_name(
            bound(load_domain(scenario.domain), settings.get("world") or None)
        )  # WorldError: not this domain's
        common: dict[str, Any] = dict(  # Job's other fields, by name: the caller's, then these
            settings,
            world=world,
            domain=scenario.domain,
            fingerprint=scenario_fingerprint(scenario),
            code=code_fingerprint(scenario.domain, engines),
            source=source,
        )
        jobs += [Job(path, scenario.name, seed + index, **common) for index in range(tasks)]
    return jobs, problems
