"""Playing and drawing levels from Python: what `physc simulate`, `trace`, `render` and `verify` do.

`simulate` plays a task's level (or any level of a domain) with an action and returns the
trace (physc.simulation.trace.Trace): whether the goal was met (`solved`), the interactions
recognised (`interactions`, each with `text()` in .phys syntax and `time`), the objects
destroyed, and each body's path (`paths()`). `verify` replays a task's intended solution, in
any engine, as `physc verify` does.
"""

from __future__ import annotations

import os
import random

from physc.api.errors import FileError
from physc.api.tasks import domain_of, scenario_of
from physc.compiler.task import Task
from physc.domains.base import Domain
from physc.domains.simulated import SimulatedDomain
from physc.simulation.ending import Ending

__all__ = ["agent_shot", "read_level", "render", "simulate", "verify"]


def read_level(source: str | os.PathLike | bytes, domain: str = "angrybirds"):
    """The level of a level file (a path, or its bytes) of `domain` (angrybirds: a Science
    Birds XML file, as the game's own files are); FileError when it cannot be played."""
    from physc.domains import load_domain
    from physc.domains.base import LevelError

    if isinstance(source, bytes):
        data, name = source, "<level>"
    else:
        name = os.fspath(source)
        try:
            with open(name, "rb") as handle:
                data = handle.read()
        except OSError as error:
            raise FileError(f"{name}: {error.strerror or error}") from None
    try:
        return load_domain(domain).files.read_level(data)
    except LevelError as error:
        where = f":{error.line}" if error.line else ""
        raise FileError(f"{name}{where}: {error}") from None


def simulate(
    level,
    action=None,
    *,
    domain=None,
    world: str | None = None,
    backend: str | None = None,
    seconds: float | None = None,
    noise: int | random.Random | None = None,
    scenario=None,
):
    """The trace of `level` played with `action`, to rest (`physc simulate`).

    `level` is a Task (its level, played in the world and engine it was made in, judged
    against its scenario's restrictions) or a domain's level (`read_level`; `domain` names
    its domain, angrybirds by default, or is the domain itself, bound to a world and engine;
    named, it plays in the world the level names, if it names one, unless `world` says
    otherwise). `action` is the domain's action (angrybirds:
    `physc.Shot(angle=…)` or `Shot(target=(x, y), trajectory="low")`, with `tap=` seconds after
    the launch, `bird=` and `wait=` for a later bird's shot, several in `physc.Shots((…))`;
    phyre: a `BallAction`), a task's solution (`task.solution`), or None for no action.
    angrybirds also plays what Phy-Q's agents send, `[dx, dy, tap_time]` (`env.step`'s action:
    whole pixels from the slingshot's reference point, the tap in ms, 0: none), or a list of
    them, one a bird in the order shot, each later one once the level rests (`physc.agent_shot`
    makes one shot of it, with a `wait`). `noise`, a seed or a
    `random.Random`, plays it under the domain's noise model (angrybirds: objects and
    release angle jittered, as the evaluation's noisy replays are). `scenario`, a checked
    scenario (physc.check's), judges a level's play against its restrictions (a Task's is its own)."""
    if isinstance(level, Task):
        scenario = scenario_of(level)
        played = playable(domain_of(level, world, backend))
        level = level.level
    else:
        played = playable(bound_domain(domain, world, backend))
        if world is None and (domain is None or isinstance(domain, str)) and played.files.level_world(level):
            played = playable(played.at(played.files.level_world(level)))  # the world the level names
    if action is not None and isinstance(action, tuple(_solution_kinds(played))):
        action = played.actions.action_of(action)
    action = _as_sent(played, level, action, scenario)
    if noise is not None:
        rng = noise if isinstance(noise, random.Random) else random.Random(noise)
        level, action = played.actions.noisy(level, action, rng)
    return play_to_rest(played, level, action, scenario, seconds)


def _as_sent(domain: Domain, level, action, scenario):
    """A Science Birds action given as Phy-Q's agents send it (`[dx, dy, tap_time]`, or a list
    of them, one a bird) as the shots the game launches for it (physc.domains.angrybirds
    .agent_shots), its birds named as `scenario` names them (else bird, bird2, …); any other
    action as it is. ValueError for an agent action that is not one, or more than the birds."""
    if domain.name != "angrybirds" or action is None or hasattr(action, "shots") or not hasattr(action, "__len__"):
        return action
    from physc.domains.angrybirds.agent_shots import agent_shots
    from physc.domains.angrybirds.shots import birds

    several = len(action) > 0 and all(hasattr(a, "__len__") for a in action)
    names = () if scenario is None else tuple(birds(scenario, domain.vocabulary.player))
    return agent_shots(level, action if several else [action], names)


def agent_shot(level, action, *, bird: str = "bird", wait: float | None = None):
    """The Science Birds shot (`physc.Shot`) the game launches for Phy-Q's agent action `action`,
    `[dx, dy]` or `[dx, dy, tap_time]` (whole pixels from the slingshot's reference point, y up,
    and ms after the launch; each truncated as the framework does), in `level` (a level, or a
    Task's): at the angle and stretch the game reads from that release point, for `bird` (its
    name in the trace: bird, bird2, … or the task's scenario's), `wait` seconds after its bird
    came onto the slingshot (None: once the level rests). ValueError for a malformed action."""
    from physc.domains.angrybirds.agent_shots import agent_shot as shot

    return shot(level.level if isinstance(level, Task) else level, action, bird, wait)


def playable(domain: Domain) -> SimulatedDomain:
    """`domain` as one that plays levels: every domain that simulates is a SimulatedDomain
    (physc.domains.simulated), the base of angrybirds, PHYRE's and the stand-ins."""
    assert isinstance(domain, SimulatedDomain), f"the domain '{domain.name}' plays no levels"
    return domain


def play_to_rest(domain: SimulatedDomain, level, action, scenario=None, seconds: float | None = None):
    """`domain.play` of the level with the action, judged against `scenario`, until everything
    rests as the target world plays it (`Ending.WHOLE`), within `seconds` (default: the domain's)."""
    return domain.play(level, action, scenario, seconds or domain.seconds, ending=Ending.WHOLE)


def bound_domain(domain: str | Domain | None = None, world: str | None = None, backend: str | None = None) -> Domain:
    """A domain in `world` with `backend`: `domain` a name (default angrybirds) or a Domain
    (physc.domains.base.Domain) already bound, kept as it is where `world` and `backend` are None."""
    from physc.domains import bound, load_domain

    if domain is None or isinstance(domain, str):
        return bound(load_domain(domain or "angrybirds"), world, backend)
    return domain if world is None and backend is None else bound(domain, world, backend)


def _solution_kinds(domain) -> list[type]:
    from physc.domains.base import solution_classes

    return list(solution_classes(domain).values())


def verify(task: Task, *, world: str | None = None, backend: str | None = None, replays: int | None = None):
    """The task's intended solution replayed (`physc verify`): in the world and engine the
    task was made in unless `world` or `backend` names others, once as recorded and `replays`
    times under the domain's noise (None: the domain's own number, 6 in angrybirds). Returns
    physc.search.verify.Verification: `solved`, `realised`, `noisy_passed`, `trace`, `why`,
    and `passes(n)`."""
    from physc.search.verify import noisy_replays
    from physc.search.verify import verify as replay

    domain = domain_of(task, world, backend)
    count = noisy_replays(domain) if replays is None else replays
    return replay(domain, scenario_of(task), task.level, task.solution, domain.backend.name, noisy=count)


def render(
    task,
    action=None,
    *,
    fmt: str = "png",
    title: str | None = None,
    domain=None,
    world: str | None = None,
    backend: str | None = None,
) -> bytes:
    """A picture, PNG or SVG bytes (`IPython.display.Image(physc.render(task))` shows it in a
    notebook): a task drawn with the paths of its solution (`physc compile --png`), or with
    those of another `action` (any `simulate` takes: a Shot, Shots, what Phy-Q's agents send);
    a domain's level (`read_level`) drawn alone or with the paths `action` makes (`physc
    render`; `domain` a name, angrybirds by default, or a bound Domain)."""
    if isinstance(task, Task):
        played = domain_of(task, world, backend)
        if action is None and title is None:
            return played.files.picture(task, fmt)
        paths = simulate(task, action if action is not None else task.solution, world=world, backend=backend).paths()
        return played.files.draw(
            task.level, title if title is not None else f"{task.scenario} (seed {task.seed})", paths, fmt
        )
    played = bound_domain(domain, world, backend)
    paths = {} if action is None else simulate(task, action, domain=played).paths()
    return played.files.draw(task, title or "", paths, fmt)
