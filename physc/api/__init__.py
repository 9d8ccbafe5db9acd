"""physc's Python API: everything the command line does, as functions (docs/api.md).

The names are exported at the top level (`physc.compile`, `physc.load_task`, …); this
package groups them by what they work on: compiling.py (scenarios to tasks), tasks.py (task
and level files), simulating.py (playing and drawing levels, verifying solutions), datasets.py
(generating, loading and evaluating datasets), errors.py (what they raise).
"""

from physc.api.compiling import check, compile, scenarios
from physc.api.datasets import Dataset, Evaluation, evaluate, generate, load_dataset
from physc.api.errors import FileError, NoTask, PhyscError, ScenarioError
from physc.api.simulating import agent_shot, read_level, render, simulate, verify
from physc.api.tasks import domain_of, level_text, load_task, save_level, save_task, scenario_of

__all__ = [
    "Dataset",
    "Evaluation",
    "FileError",
    "NoTask",
    "PhyscError",
    "ScenarioError",
    "agent_shot",
    "check",
    "compile",
    "domain_of",
    "evaluate",
    "generate",
    "level_text",
    "load_dataset",
    "load_task",
    "render",
    "read_level",
    "save_level",
    "save_task",
    "scenario_of",
    "scenarios",
    "simulate",
    "verify",
]
