"""physc: a compiler for physics tasks.

A `.phys` scenario (a causal sequence of physical interactions plus restrictions)
is compiled into a task whose intended solution realises that sequence.

As a library (docs/api.md):

    import physc
    task = physc.compile("examples/paper/05_F.phys", seed=1)   # a Task: level, solution, trace, seconds
    physc.save_level(task, "f.xml")
    trace = physc.simulate(task, physc.Shot(angle=40))           # what one shot does
    physc.verify(task).passes()

Agents play the tasks through Gymnasium (`import physc.envs`; `physc/AngryBirds-v0`,
`physc/PhyreLike-v0`) or PHYRE's way (`physc.ActionSimulator`). The names are imported when
first used, so `import physc` stays cheap for the command line; `__init__.pyi` states them for
type checkers and editors.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

# Each exported name → the module that defines it.
_EXPORTS = {
    **dict.fromkeys(
        (
            "check",
            "compile",
            "scenarios",
            "load_task",
            "save_task",
            "save_level",
            "level_text",
            "render",
            "domain_of",
            "scenario_of",
            "read_level",
            "simulate",
            "agent_shot",
            "verify",
            "generate",
            "load_dataset",
            "evaluate",
            "Dataset",
            "Evaluation",
            "PhyscError",
            "ScenarioError",
            "NoTask",
            "FileError",
        ),
        "physc.api",
    ),
    "Task": "physc.compiler.task",
    "Solution": "physc.domains.angrybirds.shots",
    "Trace": "physc.simulation.trace",
    "Diagnostic": "physc.diagnostics",
    "Shot": "physc.domains.angrybirds.launch",
    "Shots": "physc.domains.angrybirds.launch",
    "ActionSimulator": "physc.envs.simulator",
    "Simulation": "physc.envs.simulator",
    "SimulationStatus": "physc.envs.simulator",
}

__all__ = ["__version__", *sorted(_EXPORTS)]


def __getattr__(name: str):
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'physc' has no attribute {name!r}")
    value = getattr(importlib.import_module(module), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_EXPORTS))
