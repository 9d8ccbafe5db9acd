"""The Task IR: a generated task, its solution (the domain's own record of its action), and how
it was made."""

from __future__ import annotations

import attrs


@attrs.frozen
class Task:
    scenario: str
    domain: str
    seed: int
    source: str  # the scenario as written, in block form
    level: object  # the domain's level (angrybirds: a Science Birds Level)
    solution: object  # the domain's record of the intended action (its files' solution_class)
    trace: str  # the interactions the solution realises, in .phys syntax
    validated: bool | None  # None when validation was skipped
    robustness: tuple[int, int]  # perturbed replays passed, run (fewer than run: a fallback)
    repairs: tuple[str, ...]  # what simulation-based satisfaction changed
    obstacles: tuple[str, ...]
    distractors: tuple[str, ...]
    layouts_tried: int
    conjunctions_tried: int
    simulations: int
    # Why the layouts tried before the one used were given up (the domain's words) →
    # {"layouts": how many, "simulations": what they cost}; the fallbacks' second tries are not counted.
    given_up: dict
    seconds: dict  # stage → time spent
    acceptance: dict | None = None  # what random actions showed, for a domain with an acceptance rule (PHYRE's flags)
    # The world the task was made in and the engine that simulated it (physc.worlds): what
    # `verify`, `eval`, `simulate`, `trace` and `render` replay it in unless told otherwise.
    # A task file written before worlds were named reads as the domain's default world.
    world: str = ""
    backend: str = ""
    # Whether the solution passed fewer than all of the generator's noisy replays: a fallback,
    # made only on request (--min-robustness K).
    fallback: bool = False
    # The layout rules' structure the task was laid out in (physc.compiler.layout_rules,
    # "Structures"): "flat", the paper's reading, or "ramp".
    structure: str = "flat"
    # How far each link was from failing (physc.simulation.margins): the weakest link over
    # the noisy replays the solution passed, every link as the solution plays, what raising
    # them moved and the candidates it simulated. None in task files written before margins.
    margins: dict | None = None
    # Where the compile's placed layouts went down the chain, and the simulations each stage
    # cost (physc.search.funnel). None in task files written before it.
    funnel: dict | None = None
    # How the compile proposed its layouts (physc.driver.ranking): the world's prior the
    # proposal model started from, with its provenance, and the examples it learned. None in
    # task files written before it.
    proposals: dict | None = None
    # The evaluation's agent's plays that solve the task by accident (physc.search.accidents):
    # `plays`, the share `solved_before` the search's bars against them and after (`solved`),
    # and the bars added. None where the domain's agent plays no fixed list, or before it.
    accidental: dict | None = None


def given_up_summary(given_up: dict) -> str:
    """`Task.given_up` in words, most frequent reason first: "66 × the sequence was not
    realised, 9 × the solution was too fragile"."""
    ranked = sorted(given_up.items(), key=lambda item: (-item[1]["layouts"], item[0]))
    return ", ".join(f"{counts['layouts']} × {why}" for why, counts in ranked)
