# The names physc exports, for type checkers and editors: physc/__init__.py imports them when
# first used (its _EXPORTS), so that `import physc` stays cheap.
from physc.api import (
    Dataset as Dataset,
    Evaluation as Evaluation,
    FileError as FileError,
    NoTask as NoTask,
    PhyscError as PhyscError,
    ScenarioError as ScenarioError,
    check as check,
    compile as compile,
    domain_of as domain_of,
    evaluate as evaluate,
    generate as generate,
    level_text as level_text,
    load_dataset as load_dataset,
    load_task as load_task,
    read_level as read_level,
    render as render,
    save_level as save_level,
    save_task as save_task,
    scenario_of as scenario_of,
    scenarios as scenarios,
    simulate as simulate,
    verify as verify,
)
from physc.compiler.task import Solution as Solution, Task as Task
from physc.diagnostics import Diagnostic as Diagnostic
from physc.domains.angrybirds.launch import Shot as Shot
from physc.envs.simulator import ActionSimulator as ActionSimulator, Simulation as Simulation, SimulationStatus as SimulationStatus
from physc.simulation.trace import Trace as Trace

__version__: str
__all__: list[str]
