"""How agents play PHYRE-like tasks (physc/PhyreLike-v0, physc.envs): PHYRE's action, a ball
(or two) in [0, 1]³ (or [0, 1]⁶) as PHYRE's action mapper reads it; PHYRE's featurized objects
and its 256 × 256 picture of colour indices; reward 1 for a solved task. An action PHYRE
calls invalid (outside the scene, over a body, two balls too close) is not played."""

from __future__ import annotations

import json

import numpy as np

from physc.domains.playing import Playing, seen_features
from physc_phyre import observation
from physc_phyre.actions import from_unit
from physc_phyre.task_file import task_json
from physc_phyre.world import PIXELS_PER_METRE, SCENE

ACTION_MODES = {"BALL": "ball", "TWO_BALLS": "two_balls"}  # a level's tier → its action mode
SIZES = {"ball": 3, "two_balls": 6}

DROP_RADIUS = 0.5  # of [0, 1]: the middle of PHYRE's radii
DROP_STEP = 0.05  # of the scene's height: how much higher each next attempt drops the ball


def drop_on_green(env, observation, attempt: int):
    """The heuristic agent: a middle-sized ball dropped on the green object, from just above
    it and, when that is invalid (over a body), from higher up at each next attempt; in the
    two-ball tier the second ball beside the first, further up."""
    rows = seen_features(env, observation)
    names = {name: index for index, name in enumerate(PhyrePlaying.feature_names)}
    green = [r for r in rows if r[names["color_green"]] > 0.5]
    if not green:
        return env.action_space.sample()
    x, y, diameter = (float(green[0][names[n]]) for n in ("x", "y", "diameter"))
    height = min(1.0, y + diameter / 2 + DROP_STEP * (attempt + 1))
    ball = [x, height, DROP_RADIUS]
    if env.simulator.mode == "two_balls":
        ball += [min(1.0, x + 0.1), min(1.0, height + 0.1), DROP_RADIUS]
    return np.array(ball, np.float64)


class PhyrePlaying(Playing):
    env_id = "physc/PhyreLike-v0"
    modes = ("ball", "two_balls")
    noise = False  # PHYRE's simulator is deterministic
    # PHYRE's featurized objects (phyre/simulator.py's OBJECT_FEATURE_NAMES order; observation.py)
    feature_names = (
        "x",
        "y",
        "angle",
        "diameter",
        "shape_ball",
        "shape_bar",
        "shape_jar",
        "shape_standingsticks",
        "color_red",
        "color_green",
        "color_blue",
        "color_purple",
        "color_gray",
        "color_black",
    )
    picture_shape = (SCENE, SCENE)  # PHYRE's observation: colour indices, row 0 at the bottom
    heuristic = staticmethod(drop_on_green)

    def mode_of(self, tasks, asked: str | None) -> str:
        """The tasks' own tier: PHYRE evaluates its ball and two-ball tiers apart."""
        tiers = sorted({ACTION_MODES[t.level.tier] for t in tasks})
        if len(tiers) > 1:
            raise ValueError("these tasks are of both of PHYRE's tiers: play the ball and the two-ball tasks apart")
        if asked is not None and asked != tiers[0]:
            raise ValueError(
                f"these are tasks of the {tiers[0]} tier, played with the action mode {tiers[0]!r}, not {asked!r}"
            )
        return tiers[0]

    def action_space(self, mode: str, world):
        from gymnasium import spaces

        return spaces.Box(0.0, 1.0, (SIZES[mode],), np.float64)

    def action(self, domain, level, mode: str, action):
        vector = np.asarray(action, dtype=np.float64).reshape(-1)
        if len(vector) != SIZES[mode]:
            raise ValueError(f"an action of the {mode} tier has {SIZES[mode]} numbers, not {len(vector)}")
        played = from_unit(vector)
        return played if played is not None and domain.actions.valid(level, played) else None

    def features(self, domain, level) -> np.ndarray:
        return observation.features(json.loads(task_json(level))).astype(np.float32)

    def picture(self, domain, level) -> np.ndarray:
        return observation.raster(json.loads(task_json(level)))

    @staticmethod
    def _frame(level, action, trace, step: int) -> tuple[dict, list[tuple[float, float, float, float]]]:
        """(the task in PHYRE's structure with its bodies where the trace has them after `step`,
        the agent's balls there: x, y, radius in pixels, angle)."""
        import attrs

        from physc.domains.playing import states_at

        states = states_at(trace, step)
        moved = tuple(
            attrs.evolve(b, x=s[0] * PIXELS_PER_METRE, y=s[1] * PIXELS_PER_METRE, angle=s[2])
            if (s := states.get(b.name))
            else b
            for b in level.bodies
        )
        radii = {name: ball.radius for name, ball in zip(level.players, action.balls, strict=False)}
        balls = [
            (s[0] * PIXELS_PER_METRE, s[1] * PIXELS_PER_METRE, radii[name], s[2])
            for name in level.players
            if (s := states.get(name))
        ]
        return json.loads(task_json(attrs.evolve(level, bodies=moved))), balls

    def frame_features(self, domain, level, action, trace, step: int) -> np.ndarray:
        task, balls = self._frame(level, action, trace, step)
        return observation.features(task, *balls).astype(np.float32)

    def frame_picture(self, domain, level, action, trace, step: int) -> np.ndarray:
        task, balls = self._frame(level, action, trace, step)
        return observation.raster(task, *[(x, y, radius) for x, y, radius, _ in balls])

    def reward(self, trace) -> tuple[float, dict]:
        return float(trace.solved), {}


PLAYING = PhyrePlaying()
