"""A Gymnasium environment over physc's tasks of one domain (physc/AngryBirds-v0,
physc/PhyreLike-v0): an episode is one task; the agent acts until a valid action has been
played to rest (PHYRE's rule: an invalid action is not played, and the episode goes on), and
the last observation is the level as it then lies.

    import gymnasium, physc.envs
    env = gymnasium.make("physc/AngryBirds-v0", tasks="out/f.json")
    observation, info = env.reset(seed=0)
    observation, reward, terminated, truncated, info = env.step(env.action_space.sample())

The domain (`Domain.playing`) says what an action is, what the agent sees and what a play is
worth; this class is the loop, the same for every domain.
"""

from __future__ import annotations

import random

import gymnasium
import numpy as np
from gymnasium import spaces

from physc.envs.simulator import ActionSimulator

OBSERVATIONS = ("features", "picture", "both")


class TaskEnv(gymnasium.Env):
    """Episodes over `tasks` (a Task, a task file, a dataset folder, or a list of them) of
    `domain`. `action`: the domain's action mode (its first by default). `observation`:
    "features" (the objects as a padded array, `Playing.feature_names`), "picture", or "both"
    (a dict). `noise`: play under the domain's noise model (default: the domain's
    `Playing.noise`), drawn from the environment's seeded generator. `interactions`: whether a
    step's `info` says which interactions the play realised and whether the task's sequence
    was (`realised`); False plays each action as an outcome playout, sooner, with the same
    reward and observation. `reset(options={"task": i or id})` picks a task; otherwise each
    reset draws one uniformly."""

    metadata = {"render_modes": ["rgb_array"]}

    def __init__(
        self,
        domain: str,
        tasks,
        *,
        action: str | None = None,
        observation: str = "features",
        noise: bool | None = None,
        world: str | None = None,
        backend: str | None = None,
        render_mode: str | None = None,
        interactions: bool = True,
    ):
        if observation not in OBSERVATIONS:
            raise ValueError(f"observation is one of {', '.join(OBSERVATIONS)}, not {observation!r}")
        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(
                f"render_mode is one of {', '.join(self.metadata['render_modes'])} or None, not {render_mode!r}"
            )
        self.simulator = ActionSimulator(tasks, domain=domain, mode=action, world=world, backend=backend)
        playing = self.simulator.playing
        self.playing = playing
        self.noise = playing.noise if noise is None else noise
        self.observation_kind = observation
        self.render_mode = render_mode
        self.interactions = interactions
        self.action_space = self.simulator.action_space
        # Unbounded: even PHYRE's normalised features pass 1 (a bar longer than the scene).
        features = spaces.Box(-np.inf, np.inf, (playing.max_objects, len(playing.feature_names)), np.float32)
        self._features_space = features  # its shape is every features observation's, in "both" too
        picture = spaces.Box(0, 255, playing.picture_shape, np.uint8)
        self.observation_space = {
            "features": features,
            "picture": picture,
            "both": spaces.Dict(features=features, picture=picture),
        }[observation]
        for index in range(len(self.simulator)):
            rows = len(self.simulator.features(index))
            if rows > playing.max_objects:
                raise ValueError(
                    f"the task {self.simulator.task_ids[index]} has {rows} objects, more than the"
                    f" {playing.max_objects} an observation holds"
                )
        self.task_index = 0
        self._last = None  # the last valid play of the episode

    @property
    def task_ids(self) -> list[str]:
        return self.simulator.task_ids

    def _observation(self, result=None):
        """The task's level as the episode begins, or, after the valid play `result`, as it lies
        when everything rests."""
        features = picture = None
        if self.observation_kind != "picture":
            rows = self.simulator.features(self.task_index) if result is None else self.simulator.frame(result)
            features = np.zeros(self._features_space.shape, np.float32)
            features[: len(rows)] = rows
        if self.observation_kind != "features":
            picture = (
                self.simulator.picture(self.task_index)
                if result is None
                else self.simulator.frame(result, picture=True)
            )
        if self.observation_kind == "both":
            return {"features": features, "picture": picture}
        return features if picture is None else picture

    def _info(self) -> dict:
        task = self.simulator.tasks[self.task_index]
        return {"task_id": self.task_ids[self.task_index], "scenario": task.scenario, "seed": task.seed}

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        super().reset(seed=seed)
        chosen = (options or {}).get("task")
        if chosen is None:
            self.task_index = int(self.np_random.integers(len(self.simulator)))
        else:
            self.task_index = self.simulator._index(chosen)
        self._last = None
        return self._observation(), self._info()

    def step(self, action):
        rng = random.Random(int(self.np_random.integers(2**63))) if self.noise else None
        result = self.simulator.simulate_action(self.task_index, action, noise=rng, need_interactions=self.interactions)
        info = {**self._info(), **result.info}
        valid = not result.status.is_invalid()
        if valid:
            self._last = result
        return self._observation(result if valid else None), float(result.reward), valid, False, info

    def render(self):
        """The picture of the level as the last step left it (as the episode began, before one)."""
        if self.render_mode != "rgb_array":
            return None
        if self._last is not None:
            return self.simulator.frame(self._last, picture=True)
        return self.simulator.picture(self.task_index)
