"""What the search answers for one placed layout: a task's parts, or why not.

The search (search.satisfy) returns an `Outcome`; the layout loop reads it to count simulations,
note why a layout was given up and how far it got, keep fragile layouts for the
fallbacks, and, when it is satisfied, make the task from its `Parts`.
"""

from __future__ import annotations

import attrs

from physc.search.funnel import Passage
from physc.simulation.margin import Margin


@attrs.frozen
class Parts:
    """The parts of a task that a satisfied layout gives: each field is the Task's field of the
    same name (physc.compiler.task.Task), which the pipeline passes on whole. Why a record of its
    own: the search makes it for one layout, before the layout loop knows which layout the task
    comes from and what the run cost; `Outcome` carries it with why a layout was given up, and
    the layout loop's `Generated` with the costs."""

    level: object  # the domain's level
    solution: object  # the domain's record of the action (its actions' `solution`)
    trace: str  # the interactions the solution realises, in .phys syntax
    validated: bool | None  # None when validation was skipped
    robustness: tuple[int, int]  # noisy replays passed, run
    repairs: tuple[str, ...]
    obstacles: tuple[str, ...]
    distractors: tuple[str, ...]
    acceptance: dict | None = (
        None  # what random actions showed (the domain's evaluation's `acceptance`), if the domain has a rule
    )
    margins: dict | None = (
        None  # the links' margins: the weakest over the noisy replays, each as played (search.margins_record)
    )
    accidental: dict | None = (
        None  # the agent's plays that solve it by accident, before and after the guard (accidents.py)
    )


@attrs.frozen
class Outcome:
    satisfied: bool
    simulations: int  # simulations run for this layout
    parts: Parts | None = None  # when satisfied
    nearest: int = 0  # most noisy replays passed by a solution given up as too fragile
    given_up: str = ""  # why the layout was given up, when it was
    best: int = 0  # most interactions of the sequence realised, in order, in one simulation
    stopped: str = ""  # what that simulation shows about the next interaction (physc.simulation.stopped)
    seconds: dict = attrs.field(factory=dict)  # stage → time spent, for the stages after satisfaction
    # The noisy replays that failed, by the declared interaction they lost first: (term, count,
    # what the first such replay shows about it, physc.simulation.stopped), most often lost first.
    lost: tuple[tuple[str, int, str], ...] = ()
    # Of the chains realised but not robust, the strongest weakest link (physc.simulation.margins).
    weakest: Margin | None = None
    # The play that came furthest: (its fidelity score, its level, its action, the layout as
    # placed), replayed in the domain's other worlds when no task is found (physc.search.elsewhere).
    furthest: tuple | None = None
    # Where a declared property (physc.search.properties) gave the layout up: which, and what broke
    # it (the action and what it took), for exit 3 to say.
    broken: str = ""
    # The layout's way down the chain: the stages reached and realised, the simulations each cost
    # (physc.search.funnel); None where no search ran.
    passage: Passage | None = None
