"""The settings of one run that makes a task, as one value: from `physc compile`'s options and
`physc.compile`'s keywords down to the layout loop, the search and the workers of `physc
generate` and `physc eval`, under one name each (the option `--time-budget` is the field
`time_budget` everywhere). A job (physc.driver.job.Job) carries one; a stored result says
which it was made with (the job's `recorded`)."""

from __future__ import annotations

import attrs

from physc.compiler.to_dimension_graphs import CLAUSE_BUDGET
from physc.search.problem import Checks

# A task whose solution failed some noisy replays of the generator (the domain's
# robustness_replays; 6 in angrybirds) is a fallback, made only on request (--min-robustness K):
# by default (None) a solution must pass all of them.
MIN_ROBUSTNESS = None
LAYOUT_BUDGET = 160  # placed layouts that simulation-based satisfaction may try
TIME_BUDGET = 120.0  # seconds for generating one task


@attrs.frozen
class RunSettings:
    """How one run makes a task (each field is the option of the same name; docs/cli.md)."""

    time_budget: float = TIME_BUDGET
    """Seconds for the whole run, fallbacks and picture included (`--time-budget`)."""
    layouts: int = LAYOUT_BUDGET
    """Placed layouts that simulation may try (`--layouts`)."""
    clause_budget: int = CLAUSE_BUDGET
    """Clause choices the layout search may try per shape draw (`--clause-budget`)."""
    min_robustness: int | None = MIN_ROBUSTNESS
    """Noisy replays a fallback must pass at least (`--min-robustness`); None: no fallbacks, a
    task passes every noisy replay of the domain's `robustness_replays`."""
    validate: bool = True
    """Whether a generated task is validated at the end (`--no-validate`: not; the evaluation,
    as the paper, skips it)."""
    acceptance: bool = True
    """Whether the domain's acceptance rule judges each task (`--no-acceptance`: not)."""
    verify_backend: str | None = None
    """A second physics backend the task's solution must also pass in (`--verify-backend`)."""
    workers: int = 1
    """Processes that satisfy a round's placed layouts side by side (`--workers`;
    physc.driver.workers): the task is the same whatever their number, so a stored result does
    not record it."""

    @property
    def checks(self) -> Checks:
        """What of these settings the search reads: whether it validates and judges a task."""
        return Checks(self.validate, self.acceptance)

    def robustness(self, domain) -> int:
        """The noisy replays a solution must pass at least in `domain`: `min_robustness`, or all
        of the domain's (at least one)."""
        return self.min_robustness if self.min_robustness is not None else (domain.robustness_replays or 1)


def overridden(settings: RunSettings | None, caller: str, **overrides) -> RunSettings:
    """`settings` (None: the defaults) with fields replaced by keyword, as the API's functions
    take them (`physc.compile(path, time_budget=60)`); a name that is no field is a TypeError,
    worded as Python words one for a keyword `caller` does not take."""
    unknown = sorted(set(overrides) - set(attrs.fields_dict(RunSettings)))
    if unknown:
        raise TypeError(f"{caller}() got an unexpected keyword argument {unknown[0]!r}")
    return attrs.evolve(settings if settings is not None else RunSettings(), **overrides)
