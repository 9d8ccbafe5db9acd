"""The domain interface: what a domain plugin says, what it can do, and what physc
assumes where it says nothing (docs/plugins.md, "The domain interface").

A domain subclasses `Domain`, as a dialect subclasses sqlglot's `Dialect`: class
attributes and methods for what differs, inherited defaults for the rest. Two levels
of promise:

* **The front end** (`physc check`, `fmt`, `domains`, `compile --emit ast|scenario`)
  needs `name`, `description` and `vocabulary`. Every domain must say them; they are
  abstract, so a subclass that forgets one cannot be instantiated; `load_domain` refuses a
  plugin object that is not a `Domain` (E0702).
* **Generation** needs capabilities, which a domain declares (`capabilities`): `layout_rules`,
  `layout_parameters`, `concretize`, `satisfy` (physc's one search makes its tasks: a
  SimulatedDomain), `replay` (verification), `stability` (the evaluation), and among its files
  (`files`, physc.domains.level_files) `emit_level`, `picture`, and for playing level files
  `read_level` and `draw`. No default could be right for another domain, so the base class has
  none; a domain that lacks them still loads and checks, and a command that needs one refuses
  before any work with E0703, naming the domain and what it lacks (`missing`, `require`).
  `reach_targets`, `reachable`, `robustness_replays` and the evaluation (`evaluation`,
  physc.domains.evaluation: acceptance, the accidental agent, scored agents) have working
  defaults.
* **Worlds**: a domain names the worlds it simulates (`worlds`, physc.worlds.World) and its
  default; `at(world, backend)` binds a copy to one world and one physics engine, which then
  pass down with the domain to every simulation (`world`, `backend`).

A domain whose task is one action in a simulated scene subclasses
physc.domains.simulated.SimulatedDomain instead, which has `satisfy`, `replay`,
`stability` and `accidental` from a few hooks of its own.
"""

from __future__ import annotations

import abc
import copy
from typing import TYPE_CHECKING, Any

from physc.domains.errors import DomainError, LevelError, MissingCapability
from physc.domains.evaluation import Evaluation
from physc.domains.level_files import LevelFiles
from physc.domains.part import part
from physc.domains.vocabulary import Vocabulary

if TYPE_CHECKING:
    from physc.backends import Backend
    from physc.compiler.concrete_layout import Body
    from physc.compiler.dimension_graphs import LayoutParameters
    from physc.compiler.layout_graph import LayoutGraph
    from physc.compiler.layout_rules import LayoutRules
    from physc.domains.playing import Playing
    from physc.dsl.scenario import ScenarioIR
    from physc.simulation.trace import Trace
    from physc.worlds import World

__all__ = [
    "CAPABILITIES",
    "DEFAULTS",
    "REQUIRED",
    "Domain",
    "DomainError",
    "LevelError",
    "MissingCapability",
    "missing",
    "provides",
    "require",
    "solution_classes",
    "FILES",
]

REQUIRED = ("name", "description", "vocabulary")  # what every domain must say
CAPABILITIES = (
    "layout_rules",
    "layout_parameters",
    "concretize",
    "satisfy",
    "emit_level",
    "picture",
    "replay",
    "stability",
    "read_level",
    "draw",
)  # no default
DEFAULTS = (
    "reach_targets",
    "reachable",
    "robustness_replays",
    "worlds",
    "default_world",
    "at",
    "world",
    "backend",
    "playing",
    "files",
    "evaluation",
)  # working defaults
FILES = ("emit_level", "picture", "read_level", "draw")  # the capabilities that are members of `files`


def provides(domain: Domain, hook: str) -> bool:
    """Whether `domain` has `hook`: what every domain says (REQUIRED) and the working defaults
    (DEFAULTS) it always has; any other hook (CAPABILITIES, and a SimulatedDomain's own) when
    it declares it in `capabilities`."""
    return hook in REQUIRED or hook in DEFAULTS or hook in domain.capabilities


def missing(domain: Domain, hooks: tuple[str, ...]) -> tuple[str, ...]:
    """The hooks of `hooks` that `domain` lacks, in order."""
    return tuple(hook for hook in hooks if not provides(domain, hook))


def solution_classes(domain: Domain) -> dict[str, type]:
    """The classes a task file's solution may be in `domain`, by name (its files' `solution_class`)."""
    kinds = domain.files.solution_class or ()
    return {cls.__name__: cls for cls in (kinds if isinstance(kinds, tuple) else (kinds,))}


def require(domain: Domain, hooks: tuple[str, ...], asked: str) -> None:
    """MissingCapability (E0703) unless `domain` has every hook of `hooks`."""
    lacking = missing(domain, hooks)
    if lacking:
        raise MissingCapability(domain.name, lacking, asked)


class _Required:
    """What every domain must say (REQUIRED) and a subclass has not said yet: abstract to `abc`,
    so that a Domain subclass that leaves one out cannot be instantiated (E0702 names it)."""

    __isabstractmethod__ = True

    def __init__(self, doc: str) -> None:
        self.__doc__ = doc


def _required(doc: str) -> Any:
    """An attribute every domain must set (`_Required`), typed as the value a subclass sets."""
    return _Required(doc)


class Domain(abc.ABC):  # noqa: B024 - abstract through its `_required` attributes, which abc counts
    """A domain of physics tasks. Subclass it and set at least `name`, `description`
    and `vocabulary`; set or override the generation hooks the domain has."""

    # --- the front end: every domain says these --------------------------------

    name: str = _required("What a scenario selects the domain by (`domain phyre`): its entry point's name.")
    description: str = _required("One line for `physc domains`.")
    vocabulary: Vocabulary = _required(
        "The object and interaction terms of `.phys` in this domain: all the static checks need "
        "(physc.domains.vocabulary)."
    )

    capabilities: frozenset[str] = frozenset()
    """The capabilities (CAPABILITIES) the domain has: each names the hook it writes, and
    "satisfy" that physc's search makes its tasks (SimulatedDomain declares it). A command
    asks for what it needs before any work (`require`) and refuses with E0703 naming what
    is not declared here."""

    # --- the world it simulates, and the engine -----------------------------------

    worlds: tuple[World, ...] = ()
    """The worlds the domain simulates (physc.worlds.World): each a value with every setting
    of its physics, a variant derived from another. Empty: the domain does not simulate."""

    default_world: str = ""
    """The name of the world a command uses unless `--world` names another ("": the first of
    `worlds`)."""

    _world: World | None = None
    _backend: Backend | None = None

    def at(self, world: str | World | None = None, backend: str | Backend | None = None) -> Domain:
        """This domain simulating in `world` (a name of `worlds`, or a World) with the physics
        backend `backend` (a name, or a Backend): a copy, so that the world and the engine pass
        down with the domain, on one path, to every simulation a command runs. None keeps
        this copy's (at first: the default world, the default backend). WorldError or
        BackendError for a name that is not there."""
        from physc.backends import Backend as BackendValue
        from physc.backends import load_backend
        from physc.worlds import by_name

        bound = copy.copy(self)
        if world is not None:
            bound._world = world if not isinstance(world, str) else by_name(self.worlds, world, self.name)
        if backend is not None:
            bound._backend = backend if isinstance(backend, BackendValue) else load_backend(backend)
        return bound

    @property
    def world(self) -> World:
        """The world this domain simulates in (`at`; the default world unless told otherwise)."""
        if self._world is None:
            from physc.worlds import WorldError, by_name

            if not self.worlds:
                raise WorldError(f"the domain '{self.name}' names no world to simulate in")
            return by_name(self.worlds, self.default_world or self.worlds[0].name, self.name)
        return self._world

    @property
    def backend(self) -> Backend:
        """The physics engine this domain simulates with (`at`; physc's default, box2d, unless told otherwise)."""
        if self._backend is None:
            from physc.backends import load_backend

            return load_backend()
        return self._backend

    # --- generation: capabilities without a default ----------------------------

    @property
    def layout_rules(self) -> LayoutRules | None:
        """The layout inference (stage layout-graph, physc.compiler.layout_rules): its `infer(scenario,
        structure)` gives the `LayoutGraph` of the scenario's objects and QSRs, each with its
        provenance. None: the domain does not lay out."""
        return None

    @property
    def layout_parameters(self) -> LayoutParameters | None:
        """The distances of the QSRs (clearance, far) and the area objects are placed in
        (stages dimension-graphs and layout). None: the domain does not place."""
        return None

    def concretize(self, graph: LayoutGraph, scenario: ScenarioIR, rng) -> dict[str, Body]:
        """The concrete game object, material and shape of every node of the layout graph,
        by name (stage dimension-graphs); draws from `rng` only, so a seed gives the same
        shapes."""
        raise MissingCapability(self.name, ("concretize",), "placing objects")

    def replay(self, level, solution, scenario: ScenarioIR, rng=None) -> Trace:
        """The solution played in `level`, in the domain's world and backend (`at`): a
        physc.simulation.trace.Trace with its interactions
        recognised and its restrictions checked. With `rng`, a noisy replay: the domain's
        noise model (the one its robustness replays use) drawn from `rng`. What `physc
        verify`, `--verify-backend` and the evaluation's replays run."""
        raise MissingCapability(self.name, ("replay",), "replaying a solution")

    def stability(self, level) -> tuple[bool, float]:
        """(stable, the largest shift) of `level` left alone: the evaluation's physical
        stability (angrybirds: 10 s, nothing moves more than 0.05 units, nothing destroyed)."""
        raise MissingCapability(self.name, ("stability",), "measuring stability")

    files = part(LevelFiles)
    """The domain's files (physc.domains.level_files): its level files read and written, its
    pictures, its task files' values; `emit_level`, `picture`, `read_level` and `draw` are
    capabilities among them, declared in `capabilities`."""

    evaluation = part(Evaluation)
    """The domain's evaluation (physc.domains.evaluation): the benchmark's rule for keeping a
    task, the agent that measures accidental solvability, agents scored on a dataset
    (`score_agent`, a capability), and what its measurements mean."""

    # --- generation: working defaults ------------------------------------------

    robustness_replays: int | None = None
    """The noisy replays `satisfy` puts a solution through; `--min-robustness K` may ask
    at most this many. None (the default): the domain makes no noisy replays, so
    --min-robustness has nothing to count and is not checked."""

    @property
    def playing(self) -> Playing | None:
        """How agents play the domain's tasks (a physc.domains.playing.Playing): what gives it a
        Gymnasium environment and an ActionSimulator (physc.envs). None: agents cannot play it."""
        return None

    def reach_targets(self, scenario: ScenarioIR) -> list[str]:
        """The objects the player's action must reach directly (angrybirds: the first hit's
        target); placement gives up a layout that puts none of such an object's points in
        reach. Default: none, since only the domain knows how its player acts."""
        return []

    def reachable(self, x: float, y: float) -> bool:
        """Whether the player's action reaches the point (x, y) (angrybirds: the bird's
        trajectories). Default: everywhere, a player without a limited reach; placement
        asks it only about `reach_targets`."""
        return True
