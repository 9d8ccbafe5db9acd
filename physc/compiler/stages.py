"""The stages of `physc compile`, listed once, in pipeline order.

Each stage names the IR it produces (`--emit NAME`) and the pass that produces
it from the previous stage's IR. A stage whose pass is not part of this version
of physc has `run = None`; asking for it is a usage error with a clear message.
"""

from __future__ import annotations

from typing import Any, Callable

import attrs

from physc.suggest import did_you_mean


@attrs.frozen
class Unit:
    """One scenario on its way through the compiler: its syntax and its checked IR."""

    ast: Any  # physc.dsl.ast.Scenario
    scenario: Any  # physc.dsl.scenario.ScenarioIR


@attrs.frozen
class Stage:
    name: str
    description: str
    run: Callable[[Unit, Any], Any] | None = None  # (unit, pipeline) → IR
    formats: tuple[str, ...] = ("json",)


STAGES: tuple[Stage, ...] = (
    Stage("ast", "the syntax tree of the scenario (source positions included)", lambda unit, _: unit.ast),
    Stage("scenario", "the checked scenario: typed objects, narrowed directions", lambda unit, _: unit.scenario),
    Stage(
        "layout-graph",
        "objects and layout constraints with provenance (infer-layout)",
        lambda _, pipeline: pipeline.layout_graph,
        ("json", "dot"),
    ),
    Stage("qsr", "the disjunction of qualitative spatial relations (to-qsr)", lambda _, pipeline: pipeline.qsr),
    Stage(
        "dimension-graphs",
        "the X and Y constraint graphs of the chosen conjunction (to-dimension-graphs)",
        lambda _, pipeline: pipeline.placed.graphs,
        ("json", "dot"),
    ),
    Stage("layout", "the concrete layout: objects, materials, poses (place)", lambda _, pipeline: pipeline.placed.layout),
    Stage("task", "the generated task: level, solution, trace, how it was made (JSON)", lambda _, pipeline: pipeline.task),
    Stage("level", "the generated task as a level file of the domain (Science Birds XML)", lambda _, pipeline: pipeline.task, ("xml",)),
)
BY_NAME = {stage.name: stage for stage in STAGES}


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
