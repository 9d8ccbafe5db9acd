"""The sequential strategy: a task built along its causal chain, with the simulation in the loop.

Instead of placing every object first and repairing the whole layout afterwards, the
chain is built in its own order. The scenario's interactions are cut into *stages*: a
stage begins at an interaction that brings objects into the scene (the next target of
a hit, what a fall lands on) and runs to the next such interaction. A stage's scene
holds only the objects brought in so far, so what the chain has not reached yet can
neither help nor get in the way, and each simulation says exactly how far the prefix
gets.

The search is depth first over stages. For each stage the domain offers *variants*
(the new objects where the simulated prefix says the actor goes, then the layout as
placed, then local changes) and simulates each with the actions that realised the
prefix so far. The first variant that realises every interaction of the stage becomes
the parent of the next stage; when no variant of a stage does, the search goes back one
stage and tries that stage's next variant. A budget of variants bounds each layout.

What a domain supplies is a `ChainBuilder`: the stages (which interaction brings in which
objects), the variants of a stage, and the check that simulates one. Nothing here
depends on a domain.
"""

from __future__ import annotations

import abc
from collections.abc import Iterator, Mapping, Sequence

import attrs

from physc import budget

VARIANTS = 12  # variants tried per stage and parent at most
BUDGET = 60  # variants simulated per layout at most


@attrs.frozen
class Stage:
    """Interactions `start` .. `end` - 1 of the sequence, realised by the scene that has
    the objects brought in at `start` (`new`) and before."""

    index: int
    start: int
    end: int
    new: tuple[str, ...]


def stages(interactions: Sequence, introduced: Mapping[str, int]) -> list[Stage]:
    """The stages of a sequence of `interactions` whose objects enter the scene at the
    interaction `introduced` says (objects brought in by no interaction: at
    len(interactions), a last stage that realises nothing new but must keep the rest)."""
    total = len(interactions)
    starts = sorted({0, *(k for k in introduced.values() if 0 < k < total)})
    if any(k >= total for k in introduced.values()):
        starts.append(total)
    out = []
    for i, start in enumerate(starts):
        end = starts[i + 1] if i + 1 < len(starts) and starts[i + 1] < total else total
        new = tuple(sorted(n for n, k in introduced.items() if k == start))
        out.append(Stage(i, start, max(end, start), new))
    return out


@attrs.frozen
class State:
    """A scene that realises the sequence up to `stage` (its end), with the attempts (the
    domain's simulated actions) that realise it, best first, and the steps that built it."""

    scene: object
    attempts: tuple
    stage: int
    steps: tuple[str, ...] = ()


class ChainBuilder(abc.ABC):
    """What a domain says to build a chain: its stages, their variants, and whether one
    realises its stage."""

    @abc.abstractmethod
    def stages(self) -> list[Stage]:
        """The stages of the scenario, in order."""

    @abc.abstractmethod
    def root(self) -> State:
        """The state before the first stage: the scene as placed, no attempts yet."""

    @abc.abstractmethod
    def variants(self, parent: State, stage: Stage) -> Iterator[tuple[str, object, int]]:
        """(description, scene, lead) for the stage's objects brought in to the parent's
        scene, most promising first (where the parent's simulated attempts say they will be
        met); `lead`: the parent's attempt the variant was made for."""

    @abc.abstractmethod
    def realised(self, scene, parent: State, stage: Stage, lead: int = 0) -> tuple | None:
        """The attempts, best first, that realise every interaction up to the stage's end in
        `scene` (the actions of the parent's attempts, the lead's first, or every candidate
        action at the first stage); None when none does."""


@attrs.define
class Sequential:
    """The depth-first search over stages (module docstring)."""

    builder: ChainBuilder
    variants_per_stage: int = VARIANTS
    budget: int = BUDGET
    tried: int = 0  # variants simulated
    furthest: int = 0  # interactions realised in order by the furthest state reached
    failed_at: dict = attrs.field(factory=dict)  # stage index → variants that failed there

    def run(self) -> State | None:
        """The state that realises the whole sequence, or None."""
        plan = self.builder.stages()
        return self._search(self.builder.root(), plan, 0)

    def _search(self, parent: State, plan: list[Stage], i: int) -> State | None:
        if i == len(plan):
            return parent
        stage = plan[i]
        offered = 0
        for description, scene, lead in self.builder.variants(parent, stage):
            if self.tried >= self.budget or offered >= self.variants_per_stage:
                break
            budget.check()
            offered += 1
            self.tried += 1
            attempts = self.builder.realised(scene, parent, stage, lead)
            if not attempts:
                self.failed_at[stage.index] = self.failed_at.get(stage.index, 0) + 1
                continue
            self.furthest = max(self.furthest, stage.end)
            child = State(scene, tuple(attempts), stage.index, parent.steps + ((description,) if description else ()))
            found = self._search(child, plan, i + 1)
            if found is not None:
                return found
        return None
