"""Candidate actions: the paper's discretised solution space.

The player's one action is the shot. Following the paper, it is aimed at points
of interest on the object that starts the sequence (its five points and the
middle of each side), at full stretch, on the low and the high trajectory: at
most 18 shots, of which the unreachable ones are dropped.
"""

from __future__ import annotations

from physc.compiler.qsr_evaluate import five_points
from physc.domains.angrybirds.catalogue import extent
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import LevelObject

POINTS = ("ll", "ul", "ur", "lr", "c")


def points_of_interest(obj: LevelObject) -> dict[str, tuple[float, float]]:
    width, height = extent(obj)
    points = {k: (v.real, v.imag) for k, v in five_points(obj.x, obj.y, width, height, obj.rotation or 0.0).items()}
    for name, (a, b) in {"left": ("ll", "ul"), "top": ("ul", "ur"), "right": ("ur", "lr")}.items():
        points[name] = ((points[a][0] + points[b][0]) / 2, (points[a][1] + points[b][1]) / 2)
    return points


def candidate_shots(target: LevelObject, world) -> list[tuple[str, Shot]]:
    """(label, shot) for every point of interest in reach in `world`, and trajectory."""
    out = []
    for label, (x, y) in points_of_interest(target).items():
        if not world.reachable(x, y):
            continue
        for trajectory in ("low", "high"):
            out.append(
                (f"{target.name}.{label}, {trajectory}", Shot(target=(round(x, 5), round(y, 5)), trajectory=trajectory))
            )
    return out


def agent_targets(level, excluded: str | None):
    """What the paper's heuristic agent shoots at: every block, pig and TNT of the level
    except `excluded` (the solution's target)."""
    return [obj for obj in level.objects if obj.element in ("Block", "Pig", "TNT") and obj.name != excluded]
