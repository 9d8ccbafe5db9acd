# The names physc exports, for type checkers and editors: physc/__init__.py imports them when
# first used (its _EXPORTS), so that `import physc` stays cheap.
from physc.api import Dataset as Dataset
from physc.api import Evaluation as Evaluation
from physc.api import FileError as FileError
from physc.api import NoTask as NoTask
from physc.api import PhyscError as PhyscError
from physc.api import ScenarioError as ScenarioError
from physc.api import agent_shot as agent_shot
from physc.api import check as check
from physc.api import compile as compile
from physc.api import domain_of as domain_of
from physc.api import evaluate as evaluate
from physc.api import generate as generate
from physc.api import level_text as level_text
from physc.api import load_dataset as load_dataset
from physc.api import load_task as load_task
from physc.api import read_level as read_level
from physc.api import render as render
from physc.api import save_level as save_level
from physc.api import save_task as save_task
from physc.api import scenario_of as scenario_of
from physc.api import scenarios as scenarios
from physc.api import simulate as simulate
from physc.api import verify as verify
from physc.compiler.task import Task as Task
from physc.diagnostics import Diagnostic as Diagnostic
from physc.domains.angrybirds.launch import Shot as Shot
from physc.domains.angrybirds.launch import Shots as Shots
from physc.domains.angrybirds.shots import Solution as Solution
from physc.envs.simulator import ActionSimulator as ActionSimulator
from physc.envs.simulator import Simulation as Simulation
from physc.envs.simulator import SimulationStatus as SimulationStatus
from physc.simulation.trace import Trace as Trace

__version__: str
__all__: list[str]
