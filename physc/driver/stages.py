"""The stages of `physc compile`, listed once, in pipeline order.

Each stage names the IR it produces (`--emit NAME`), the pass that produces it from the
previous stage's IR, and what it asks of a domain beyond the stages before it (`needs`: the
hooks `physc.domains.base.require` checks before any work). A stage whose pass is not part of
this version of physc has `run = None`; asking for it is a usage error with a clear message.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

import attrs

from physc.suggest import did_you_mean

if TYPE_CHECKING:
    from physc.compiler.layout_graph import LayoutGraph
    from physc.compiler.qsr_dnf import QsrDnf
    from physc.compiler.task import Task
    from physc.driver.pipeline import Placed
    from physc.dsl.ast import Scenario
    from physc.dsl.scenario import ScenarioIR


@attrs.frozen
class Unit:
    """One scenario on its way through the compiler: its syntax and its checked IR."""

    ast: Scenario
    scenario: ScenarioIR


class Run(Protocol):
    """What a stage reads of the run that compiles a scenario (physc.driver.pipeline.Pipeline,
    handed down by the command)."""

    @property
    def layout_graph(self) -> LayoutGraph: ...

    @property
    def qsr(self) -> QsrDnf: ...

    @property
    def placed(self) -> Placed: ...  # the placed layout: `graphs` (the dimension graphs) and `layout`

    @property
    def task(self) -> Task: ...


@attrs.frozen
class Stage:
    name: str
    description: str
    run: Callable[[Unit, Run], object] | None = None  # (unit, the run) → IR
    formats: tuple[str, ...] = ("json",)
    needs: tuple[str, ...] = ()  # the domain's hooks it asks for, beyond the stages before it
    drawn: bool = False  # whether `--png` draws its IR (a placed layout, a task)

    @property
    def simulates(self) -> bool:
        """Whether the stage makes a task by simulation (and so may verify it in a second engine)."""
        return "satisfy" in NEEDS[self.name]


STAGES: tuple[Stage, ...] = (
    Stage("ast", "the syntax tree of the scenario (source positions included)", lambda unit, _: unit.ast),
    Stage("scenario", "the checked scenario: typed objects, narrowed directions", lambda unit, _: unit.scenario),
    Stage(
        "layout-graph",
        "objects and layout constraints with provenance (infer-layout)",
        lambda _, pipeline: pipeline.layout_graph,
        ("json", "dot"),
        ("layout_rules",),
    ),
    Stage("qsr", "the disjunction of qualitative spatial relations (to-qsr)", lambda _, pipeline: pipeline.qsr),
    Stage(
        "dimension-graphs",
        "the X and Y constraint graphs of the chosen conjunction (to-dimension-graphs)",
        lambda _, pipeline: pipeline.placed.graphs,
        ("json", "dot"),
        ("layout_parameters", "concretize"),
    ),
    Stage(
        "layout",
        "the concrete layout: objects, materials, poses (place)",
        lambda _, pipeline: pipeline.placed.layout,
        needs=("reach_targets", "reachable"),
        drawn=True,
    ),
    Stage(
        "task",
        "the generated task: level, solution, trace, how it was made (JSON)",
        lambda _, pipeline: pipeline.task,
        needs=("satisfy", "robustness_replays"),
        drawn=True,  # `--png` adds "picture" to a drawn stage
    ),
    Stage(
        "level",
        "the generated task as a level file of the domain (Science Birds XML)",
        lambda _, pipeline: pipeline.task,
        ("xml",),
        needs=("emit_level",),
        drawn=True,
    ),
)
BY_NAME = {stage.name: stage for stage in STAGES}
# What each stage of `physc compile --emit STAGE` asks of a domain, the stages before it included
# (it runs them); `picture` is asked for by `--png` of a layout, task or level.
NEEDS: dict[str, tuple[str, ...]] = {
    stage.name: tuple(dict.fromkeys(hook for before in STAGES[: k + 1] for hook in before.needs))
    for k, stage in enumerate(STAGES)
}


class StageError(Exception):
    pass


def stage(name: str) -> Stage:
    """The stage called `name`; unknown or unavailable stages raise StageError."""
    found = BY_NAME.get(name)
    if found is None:
        hint = did_you_mean(name, BY_NAME) or "stages: " + ", ".join(BY_NAME)
        raise StageError(f"unknown stage '{name}'; {hint}")
    if found.run is None:
        ready = ", ".join(s.name for s in STAGES if s.run is not None)
        raise StageError(
            f"the stage '{name}' ({found.description}) is not available in this version of physc; "
            f"available stages: {ready}"
        )
    return found
