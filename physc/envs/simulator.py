"""PHYRE's way of playing tasks without a game loop, for physc's tasks of any domain that can
be played (`Domain.playing`): an ActionSimulator over a list of tasks plays one action on one
task and says what happened.

    sim = physc.ActionSimulator("out/dataset")        # a dataset, a task file, Tasks
    action = sim.sample()                              # from sim.action_space
    result = sim.simulate_action(0, action)            # task 0 of sim.task_ids
    result.status.is_solved(), result.reward, result.info["interactions"]
    sim.simulate_action(0, action, need_interactions=False)   # the outcome alone, sooner

As in PHYRE, an invalid action (angrybirds: a point out of the bird's reach; PHYRE: a ball
outside the scene or over a body) is not played: its status is INVALID_INPUT.
"""

from __future__ import annotations

import enum
import random
from typing import TYPE_CHECKING

import attrs
import numpy as np

from physc.compiler.task import Task
from physc.envs import sources
from physc.simulation.ending import Ending
from physc.simulation.trace import Playout, Trace

if TYPE_CHECKING:
    from physc.domains.playing import Playing
    from physc.domains.simulated import SimulatedDomain


class SimulationStatus(enum.IntEnum):
    """A play's outcome, with PHYRE's values (phyre.SimulationStatus)."""

    NOT_SOLVED = -1
    INVALID_INPUT = 0
    SOLVED = 1

    def __str__(self) -> str:
        return self.name

    def is_solved(self) -> bool:
        return self is SimulationStatus.SOLVED

    def is_not_solved(self) -> bool:
        return self is SimulationStatus.NOT_SOLVED

    def is_invalid(self) -> bool:
        return self is SimulationStatus.INVALID_INPUT


@attrs.frozen
class Simulation:
    """One play: its status, its reward (the domain's: angrybirds the share of pigs destroyed),
    what the domain tells of it (`info`: the interactions recognised, whether the task's
    sequence was realised, …) and the trace itself (None for an invalid action; a Playout,
    physc.simulation.trace, when the play was an outcome playout). With
    `need_images` and `need_featurized_objects`, PHYRE's frames: `images` (frames, *picture)
    and `featurized_objects` (frames, objects, features), every `stride` steps from the first
    and the last."""

    status: SimulationStatus
    reward: float
    info: dict = attrs.field(eq=False)
    trace: Trace | Playout | None = attrs.field(default=None, eq=False, repr=False)
    images: np.ndarray | None = attrs.field(default=None, eq=False, repr=False)
    featurized_objects: np.ndarray | None = attrs.field(default=None, eq=False, repr=False)
    # (the domain, the level and the action as played: noisy ones under noise)
    played: tuple = attrs.field(default=(), eq=False, repr=False)


class ActionSimulator:
    """Plays actions on a fixed list of tasks of one domain (`tasks`: a Task, a task file, a
    dataset folder, or a list of them), in the world and engine each task was made in unless
    `world` or `backend` names others. `mode` is the domain's action mode (angrybirds:
    "angle", the default, or "point"; PHYRE-like: "ball" or "two_balls", the tasks' own)."""

    def __init__(
        self,
        tasks,
        *,
        domain: str | None = None,
        mode: str | None = None,
        world: str | None = None,
        backend: str | None = None,
    ):
        from physc.api.simulating import playable
        from physc.api.tasks import domain_of, scenario_of

        gathered = sources.gather(tasks)
        name = domain or gathered[0].domain
        self.tasks: list[Task] = sources.of_domain(gathered, name)
        self.task_ids: list[str] = sources.task_ids(self.tasks)
        self._domains: list[SimulatedDomain] = [playable(domain_of(t, world, backend)) for t in self.tasks]
        self.domain = self._domains[0]
        playing = self.domain.playing
        if playing is None:
            raise ValueError(f"the domain '{name}' cannot be played by agents (it has no `playing`)")
        self.playing: Playing = playing
        self.mode = self.playing.mode_of(self.tasks, mode)
        self.action_space = self.playing.action_space(self.mode, self.domain.world)
        self._scenarios = [scenario_of(t) for t in self.tasks]
        self._features: dict[int, np.ndarray] = {}

    def __len__(self) -> int:
        return len(self.tasks)

    def _index(self, task: int | str) -> int:
        if isinstance(task, str):
            if task not in self.task_ids:
                raise KeyError(
                    f"no task '{task}' (task ids: {', '.join(self.task_ids[:5])}{', …' if len(self) > 5 else ''})"
                )
            return self.task_ids.index(task)
        if not 0 <= task < len(self):
            raise IndexError(f"task index {task} is not in 0 .. {len(self) - 1}")
        return task

    def features(self, task: int | str) -> np.ndarray:
        """The task's objects as rows of `playing.feature_names` (PHYRE's featurized objects)."""
        index = self._index(task)
        if index not in self._features:
            self._features[index] = self.playing.features(self._domains[index], self.tasks[index].level)
        return self._features[index].copy()

    @property
    def initial_featurized_objects(self) -> list[np.ndarray]:
        """Every task's features, in task order (PHYRE's name)."""
        return [self.features(i) for i in range(len(self))]

    def picture(self, task: int | str) -> np.ndarray:
        """The task's level as an image array (`playing.picture_shape`)."""
        index = self._index(task)
        return self.playing.picture(self._domains[index], self.tasks[index].level)

    def sample(self, seed: int | None = None):
        """A uniform action of `action_space` (seeded when `seed` is given)."""
        if seed is not None:
            self.action_space.seed(seed)
        return self.action_space.sample()

    def simulate_action(
        self,
        task: int | str,
        action,
        *,
        noise: int | random.Random | None = None,
        need_images: bool = False,
        need_featurized_objects: bool = False,
        stride: int | None = None,
        need_interactions: bool = True,
    ) -> Simulation:
        """`action` played on the task (an index or an id), to rest; with `noise` (a seed or a
        random.Random), under the domain's noise model. `need_images`, `need_featurized_objects`:
        the frames of the play, every `stride` steps (default: a second of simulated time, as
        PHYRE's 60 steps). `need_interactions` False: played as an outcome playout (the same
        status, reward and last frame, sooner), and `info` leaves out the recognised
        `interactions` and whether the sequence was `realised`."""
        from physc.api.simulating import play_to_rest
        from physc.simulation.fidelity import fidelity

        index = self._index(task)
        domain, level = self._domains[index], self.tasks[index].level
        played = self.playing.action(domain, level, self.mode, action)
        if played is None:
            return Simulation(SimulationStatus.INVALID_INPUT, 0.0, {"valid": False})
        if noise is not None:
            rng = noise if isinstance(noise, random.Random) else random.Random(noise)
            level, played = domain.actions.noisy(level, played, rng)
        scenario = self._scenarios[index]
        trace: Trace | Playout
        if need_interactions or need_images or need_featurized_objects:
            trace = play_to_rest(domain, level, played, scenario)
        else:
            trace = domain.playout(level, played, ending=Ending.WHOLE)
        reward, told = self.playing.reward(trace)
        info = {"valid": True, "solved": bool(trace.solved), **told}
        if need_interactions:
            assert isinstance(trace, Trace), "played to rest: a whole trace"
            info.update(interactions=[i.text() for i in trace.interactions], realised=fidelity(scenario, trace).valid)
        images = featurized = None
        if need_images or need_featurized_objects:
            every = stride or max(int(round(1.0 / trace.dt)), 1)
            steps = sorted({*range(0, trace.steps, every), trace.steps - 1})
            if need_images:
                images = np.stack([self.playing.frame_picture(domain, level, played, trace, s) for s in steps])
            if need_featurized_objects:
                featurized = np.stack([self.playing.frame_features(domain, level, played, trace, s) for s in steps])
        status = SimulationStatus.SOLVED if trace.solved else SimulationStatus.NOT_SOLVED
        return Simulation(status, reward, info, trace, images, featurized, (domain, level, played))

    def frame(self, result: Simulation, step: int = -1, picture: bool = False) -> np.ndarray:
        """The features (or, with `picture`, the picture) of a valid play's level after step
        `step` (-1: the last, when everything rests)."""
        from physc.api.simulating import play_to_rest

        domain, level, played = result.played
        trace = result.trace
        assert trace is not None, "a valid play has its trace (an invalid one has no frames)"
        if isinstance(trace, Playout) and 0 <= step < trace.steps - 1:  # an outcome playout: the whole play, again
            trace = play_to_rest(domain, level, played)
        make = self.playing.frame_picture if picture else self.playing.frame_features
        return make(domain, level, played, trace, trace.steps - 1 if step < 0 else step)
