"""How agents play Science Birds levels (physc/AngryBirds-v0, physc.envs): one shot, at a
release angle (the default, as physc's solutions are recorded) or at a target point on the low
or high trajectory; the objects as features; the reward the share of pigs destroyed, so 1.0 is
a solved level (the game's goal: every pig destroyed)."""

from __future__ import annotations

import numpy as np

from physc.domains.angrybirds.catalogue import BY_PREFAB, extent
from physc.domains.playing import Playing, seen_features

KINDS = ("pig", "block", "platform", "tnt")
MATERIALS = ("wood", "ice", "stone")
# Release angles an agent may choose: every direction of a shot forward, from straight down
# to straight up (the game's slingshot is dragged back and released forward).
ANGLES = (-90.0, 90.0)
TRAJECTORIES = ("low", "high")
FARTHEST = 45.0  # degrees: the release angle of the longest flight over level ground, without drag
PICTURE = (520, 1200, 3)  # the picture's rows, columns, channels: picture.py's 12 × 5.2 in at 100 dpi


def aim_at_pigs(env, observation, attempt: int):
    """The heuristic agent: a shot at a pig's centre, the pigs nearest the slingshot first, each
    on the low trajectory and then the high one (an unreachable point is not played, so the next
    attempt tries the next). In the angle mode, the release angle of that shot."""
    playing = env.playing
    rows = seen_features(env, observation)
    column = {name: index for index, name in enumerate(playing.feature_names)}
    pigs = sorted((float(r[column["x"]]), float(r[column["y"]])) for r in rows if r[column["is_pig"]] > 0.5)
    if not pigs:
        return env.action_space.sample()
    x, y = pigs[(attempt // 2) % len(pigs)]
    trajectory = attempt % 2
    if env.simulator.mode == "point":
        return {"target": np.array([x, y], np.float32), "trajectory": trajectory}
    world = env.simulator.domain.world
    angle = world.launch.aim(x, y, TRAJECTORIES[trajectory], world.gravity)
    if angle is None:  # out of reach on this trajectory: the other one, or the shot that flies farthest
        angle = world.launch.aim(x, y, TRAJECTORIES[1 - trajectory], world.gravity) or FARTHEST
    return np.array([angle], np.float32)


class AngryBirdsPlaying(Playing):
    env_id = "physc/AngryBirds-v0"
    modes = ("angle", "point")
    noise = True  # the evaluation's noise model (noise.py): objects and release angle jittered
    feature_names = (
        "x",
        "y",
        "rotation",
        "width",
        "height",
        *(f"is_{k}" for k in KINDS),
        *(f"is_{m}" for m in MATERIALS),
        "is_round",
    )
    picture_shape = PICTURE
    heuristic = staticmethod(aim_at_pigs)

    def action_space(self, mode: str, world):
        from gymnasium import spaces

        if mode == "angle":
            return spaces.Box(np.float32(ANGLES[0]), np.float32(ANGLES[1]), (1,), np.float32)
        frame = world.frame
        low = np.array([frame.left, frame.ground_top], np.float32)
        high = np.array([frame.right, frame.placement.top], np.float32)
        return spaces.Dict(
            target=spaces.Box(low, high, (2,), np.float32), trajectory=spaces.Discrete(len(TRAJECTORIES))
        )

    def action(self, domain, level, mode: str, action):
        """A Shot; None for a point the bird cannot reach on the trajectory asked."""
        from physc.domains.angrybirds.launch import Shot

        if mode == "angle":
            angle = float(np.asarray(action, dtype=np.float64).reshape(-1)[0])
            return Shot(angle=min(max(angle, ANGLES[0]), ANGLES[1]))
        x, y = (float(v) for v in np.asarray(action["target"], dtype=np.float64).reshape(2))
        trajectory = TRAJECTORIES[int(action["trajectory"])]
        shot = Shot(target=(x, y), trajectory=trajectory)
        return shot if domain.world.launch.aim(x, y, trajectory, domain.world.gravity) is not None else None

    def features(self, domain, level) -> np.ndarray:
        rows = []
        for obj in level.objects:
            shape = BY_PREFAB.get(obj.type)
            kind = shape.kind if shape is not None else obj.element.lower()
            width, height = extent(obj) if shape is not None else (0.0, 0.0)
            rows.append(
                [
                    obj.x,
                    obj.y,
                    obj.rotation or 0.0,
                    width,
                    height,
                    *(kind == k for k in KINDS),
                    *((obj.material or "") == m for m in MATERIALS),
                    bool(shape is not None and shape.round),
                ]
            )
        return np.array(rows, np.float32).reshape(len(rows), len(self.feature_names))

    def picture(self, domain, level) -> np.ndarray:
        return self._rendered(domain, level, True)

    @staticmethod
    def _rendered(domain, level, bird, top: float | None = None) -> np.ndarray:
        """picture.py's drawing of the level as an RGB array of PICTURE's shape."""
        import matplotlib.pyplot as plt
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        from physc.domains.angrybirds.picture import draw_level

        figure = draw_level(level, domain.world, bird=bird, top=top)
        try:
            canvas = figure.canvas
            assert isinstance(canvas, FigureCanvasAgg), canvas  # picture.py draws with Agg
            canvas.draw()
            image = np.asarray(canvas.buffer_rgba())[..., :3].copy()
        finally:
            plt.close(figure)
        return image

    @staticmethod
    def _moved(level, trace, step: int):
        """(the level's objects where the trace has them after `step`, the names gone by then,
        the bird's point or False once it is gone)."""
        import math

        import attrs

        from physc.domains.playing import states_at

        states = states_at(trace, step)
        moved, gone = [], set()
        for obj in level.objects:
            state = states.get(obj.name, ())
            if state is None:
                gone.add(obj.name)
            moved.append(
                obj if not state else attrs.evolve(obj, x=state[0], y=state[1], rotation=math.degrees(state[2]))
            )
        bird = states.get("bird")
        return attrs.evolve(level, objects=tuple(moved)), gone, (bird[0], bird[1]) if bird else False

    def frame_features(self, domain, level, action, trace, step: int) -> np.ndarray:
        """Every object's row, in the level's order; an object gone by then is a row of zeros."""
        moved, gone, _ = self._moved(level, trace, step)
        rows = self.features(domain, moved)
        for index, obj in enumerate(moved.objects):
            if obj.name in gone:
                rows[index] = 0.0
        return rows

    def frame_picture(self, domain, level, action, trace, step: int) -> np.ndarray:
        """The objects still there where they are, the bird where it flies, at the scale of the
        level's own picture."""
        import attrs

        from physc.domains.angrybirds.picture import picture_top

        moved, gone, bird = self._moved(level, trace, step)
        shown = attrs.evolve(moved, objects=tuple(o for o in moved.objects if o.name not in gone))
        return self._rendered(domain, shown, bird, top=picture_top(level))

    def reward(self, trace) -> tuple[float, dict]:
        pigs = list(trace.goal)
        destroyed = [d.name for d in trace.destructions if d.name in pigs]
        return (len(destroyed) / len(pigs) if pigs else float(trace.solved)), {
            "pigs": len(pigs),
            "pigs_destroyed": len(destroyed),
        }


PLAYING = AngryBirdsPlaying()
