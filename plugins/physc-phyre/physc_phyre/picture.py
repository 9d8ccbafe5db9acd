"""Pictures in PHYRE's look: a white square scene, bodies filled in PHYRE's colours
(vis.py's palette), the red ball of the action, and the paths the solution makes."""

from __future__ import annotations

import math

import matplotlib
import matplotlib.pyplot as plt
from matplotlib import patches

from physc.backends import Circle, parts
from physc.picture import save
from physc_phyre.level import BallAction, PhyreLevel, SceneBody, TwoBallAction
from physc_phyre.world import PIXELS_PER_METRE, SCENE, outline

matplotlib.use("Agg")  # drawn off-screen; pyplot resolves its backend lazily, so Agg it is

PALETTE = {
    "red": "#f34f46",
    "green": "#6bcebb",
    "blue": "#1877f2",
    "purple": "#4b4aa4",
    "gray": "#b9cad2",
    "black": "#000000",
}


def _draw(axes, shape, x: float, y: float, angle: float, color: str) -> None:
    c, s = math.cos(angle), math.sin(angle)
    for part in parts(shape):
        if isinstance(part, Circle):
            axes.add_patch(patches.Circle((x, y), part.radius, color=color, zorder=2))
        else:
            points = [(x + px * c - py * s, y + px * s + py * c) for px, py in part.points]
            axes.add_patch(patches.Polygon(points, closed=True, color=color, zorder=2))


def draw(level: PhyreLevel, title: str = "", action: BallAction | TwoBallAction | None = None, paths=None):
    figure, axes = plt.subplots(figsize=(5.4, 5.8), dpi=100)
    axes.set_xlim(0, SCENE)
    axes.set_ylim(0, SCENE)
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.set_facecolor("white")
    body: SceneBody
    for body in level.bodies:
        _draw(axes, outline(body.shape, body.size), body.x, body.y, body.angle, PALETTE[body.color])
    for ball in action.balls if action is not None else ():
        axes.add_patch(patches.Circle((ball.x, ball.y), ball.radius, color=PALETTE["red"], zorder=3))
    for points in (paths or {}).values():
        xs = [p[0] * PIXELS_PER_METRE for p in points]
        ys = [p[1] * PIXELS_PER_METRE for p in points]
        axes.plot(xs, ys, linestyle="--", linewidth=1.0, color="#555555", zorder=4)
    if title:
        axes.set_title(title, fontsize=8)
    figure.tight_layout()
    return figure


def picture(level: PhyreLevel, title: str, action: BallAction | TwoBallAction | None, paths, fmt: str) -> bytes:
    return save(draw(level, title, action, paths), fmt)
