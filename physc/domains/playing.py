"""How an agent plays a domain's tasks: the base class a domain writes to be played through
physc's Gymnasium environments and its ActionSimulator (physc.envs).

A domain that can be played sets `Domain.playing` to an instance of a subclass of `Playing`,
which says only what differs between domains: its environment's id, its action modes and
their spaces, how an agent's action becomes the domain's action (or is invalid), what an agent
sees of a level (features, a picture) and what a play is worth. The loop (reset, step, the
noise, the task sources) is physc's own (physc/envs: env.py, simulator.py).
"""

from __future__ import annotations

import abc
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    from gymnasium import spaces


def states_at(trace, step: int) -> dict[str, tuple[float, float, float] | None]:
    """Each simulated body's (x, y, angle in radians) after step `step` of `trace` (a Trace,
    or a Playout for its last step), in the engine's units; None for a body gone by then
    (destroyed, or out of the level)."""
    from physc.simulation.trace import Playout

    if isinstance(trace, Playout):
        if step < trace.steps - 1:
            raise ValueError(
                f"an outcome playout keeps the states of its last step ({trace.steps - 1}) alone, not of step {step}"
            )
        row = trace.final
    else:
        row = trace.states[min(step, trace.steps - 1)]
    return {
        name: (None if np.isnan(row[i, 0]) else (float(row[i, 0]), float(row[i, 1]), float(row[i, 2])))
        for i, name in enumerate(trace.names)
    }


def seen_features(env, observation) -> np.ndarray:
    """The objects' features an agent was shown (a heuristic's input): the observation itself,
    its "features" when it holds both, or, for a picture alone, the task's features from the
    environment's simulator."""
    rows = observation["features"] if isinstance(observation, dict) else observation
    if not isinstance(rows, np.ndarray) or rows.ndim != 2:
        rows = env.simulator.features(env.task_index)
    return rows


class Playing(abc.ABC):
    """A domain's rules of play for agents."""

    env_id: str = ""
    """The Gymnasium id its environment is registered under ("physc/AngryBirds-v0")."""

    modes: tuple[str, ...] = ()
    """The action modes, the default first (angrybirds: "angle", "point")."""

    noise: bool = False
    """Whether an environment plays under the domain's noise model unless told otherwise (the
    world's own randomness: angrybirds yes, PHYRE's deterministic simulator no)."""

    feature_names: tuple[str, ...] = ()
    """What each column of `features` holds."""

    max_objects: int = 64
    """Rows of the feature observation (padded with zeros; a level with more objects is refused)."""

    picture_shape: tuple[int, ...] = ()
    """The shape of `picture`'s array."""

    max_attempts: int = 100
    """Steps an episode may take (invalid actions are not played and do not end it: PHYRE's rule)."""

    heuristic = None
    """The domain's heuristic agent, `heuristic(env, observation, attempt) -> action`
    (physc.envs.agents.heuristic_agent), or None."""

    def mode_of(self, tasks, asked: str | None) -> str:
        """The action mode for `tasks`: `asked`, or the default one."""
        mode = asked or self.modes[0]
        if mode not in self.modes:
            raise ValueError(f"the action mode is one of {', '.join(self.modes)}, not {mode!r}")
        return mode

    @abc.abstractmethod
    def action_space(self, mode: str, world) -> spaces.Space:
        """The Gymnasium space of an action in `mode`, in `world`."""

    @abc.abstractmethod
    def action(self, domain, level, mode: str, action) -> object | None:
        """The domain's action (what `Domain.play` takes) for the agent's `action`, or None when
        the action is invalid in `level` (not played, as PHYRE does not play an occluding ball)."""

    @abc.abstractmethod
    def features(self, domain, level) -> np.ndarray:
        """The level's objects as rows of `feature_names` (float32)."""

    @abc.abstractmethod
    def picture(self, domain, level) -> np.ndarray:
        """The level as an array of `picture_shape` (uint8)."""

    @abc.abstractmethod
    def frame_features(self, domain, level, action, trace, step: int) -> np.ndarray:
        """The features of the level as `trace` (a play of the domain's `action`) has it after
        step `step` (0: the first): its bodies where the simulation put them, the action
        included where the domain shows it (PHYRE's balls), rows kept in the initial order."""

    @abc.abstractmethod
    def frame_picture(self, domain, level, action, trace, step: int) -> np.ndarray:
        """The picture of the level as `trace` has it after step `step`."""

    @abc.abstractmethod
    def reward(self, trace) -> tuple[float, dict]:
        """(the reward of a play, what `info` tells of it) from its trace."""
