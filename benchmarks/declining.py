"""Whether gravity could give a chain's last ball the speed to destroy a small pig.

The measurement behind "Why RRR rarely generates" (docs/generation-history.md). Two tables:

1. A ball starts at rest 0.5 units down a surface declining at `theta` degrees, of a
   given length, and rolls onto a flat platform where a small pig stands 0.8 units
   past the joint: the ball's fastest speed, and whether the pig is destroyed (damage
   counts from the start, as after the level's first 2 s).
2. A small pig stands on such a surface (turned to match it) with nothing else: how far
   it moves in 10 s (the evaluation's stability test allows 0.05 units).

    python benchmarks/declining.py
"""

from __future__ import annotations

import math

import numpy as np

from physc.backends import load_backend
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, PLATFORM_THICKNESS, by_prefab
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.worlds import PHYQ

BOX2D = load_backend("box2d")
from physc.domains.angrybirds.level import Level, LevelObject

ANGLES = (10, 15, 20, 25)
LENGTHS = (1.0, 1.5, 2.0)
BALLS = (("Circle", "ice"), ("Circle", "wood"), ("CircleSmall", "ice"), ("CircleSmall", "wood"))
PIG = "BasicSmall"
PIG_GAP = 0.8  # from the foot of the decline to the pig's centre
START = 0.5  # how far down the decline the ball starts
FLAT = 3.0


def _decline(theta: float, length: float) -> tuple[LevelObject, tuple[float, float], tuple[float, float]]:
    """A platform declining to the right from (0, 0) (its top edge's upper end): the
    platform, the unit vector down its top edge and the unit normal out of it."""
    angle = math.radians(-theta)
    down, normal = (math.cos(angle), math.sin(angle)), (-math.sin(angle), math.cos(angle))
    x = down[0] * length / 2 - normal[0] * PLATFORM_THICKNESS / 2
    y = down[1] * length / 2 - normal[1] * PLATFORM_THICKNESS / 2
    scale = dict(scale_x=length / PLATFORM_BASE, scale_y=PLATFORM_THICKNESS / PLATFORM_BASE)
    return LevelObject("Platform", "Platform", x, y, -theta, name="decline", **scale), down, normal


def rolled_down(theta: float, length: float, ball: str, material: str) -> tuple[float, bool]:
    """(the ball's fastest speed, whether the pig was destroyed)."""
    decline, down, normal = _decline(theta, length)
    foot = (down[0] * length, down[1] * length)
    flat = LevelObject(
        "Platform", "Platform", foot[0] + FLAT / 2, foot[1] - PLATFORM_THICKNESS / 2, 0.0,
        scale_x=FLAT / PLATFORM_BASE, scale_y=PLATFORM_THICKNESS / PLATFORM_BASE, name="flat",
    )
    radius = by_prefab(ball).width / 2 + 0.01
    rolling = LevelObject(
        "Block", ball, down[0] * START + normal[0] * radius, down[1] * START + normal[1] * radius, 0.0, material, name="ball"
    )
    pig = LevelObject("Pig", PIG, foot[0] + PIG_GAP, foot[1] + by_prefab(PIG).height / 2 + 0.005, name="pig")
    trace = Game(Level(objects=(decline, flat, rolling, pig)), PHYQ, BOX2D).simulate(None, 6.0, invulnerable=0.0)
    states = trace.states[:, trace.index("ball"), :]
    return float(np.nanmax(np.hypot(states[:, 3], states[:, 4]))), any(d.name == "pig" for d in trace.destructions)


def pig_moved(theta: float) -> float:
    """How far a small pig standing on a decline moves in 10 s."""
    decline, down, normal = _decline(theta, 3.0)
    lift = by_prefab(PIG).height / 2 + 0.005
    pig = LevelObject("Pig", PIG, down[0] * 1.5 + normal[0] * lift, down[1] * 1.5 + normal[1] * lift, -theta, name="pig")
    trace = Game(Level(objects=(decline, pig)), PHYQ, BOX2D).simulate(None, 10.0, stop_at_rest=False)
    points = trace.states[:, trace.index("pig"), :2]
    return float(np.nanmax(np.hypot(*(points - points[0]).T)))


def main() -> None:
    print("A ball rolling down a decline onto a small pig: fastest speed (units/s), * = pig destroyed\n")
    print("| ball | decline | " + " | ".join(f"{length} units" for length in LENGTHS) + " |")
    print("|---|---|" + "---|" * len(LENGTHS))
    for ball, material in BALLS:
        for theta in ANGLES:
            cells = [rolled_down(theta, length, ball, material) for length in LENGTHS]
            row = " | ".join(f"{speed:.2f}{' *' if destroyed else ''}" for speed, destroyed in cells)
            print(f"| {material} {ball} | {theta}° | {row} |")
    print("\nA small pig standing on a decline: how far it moves in 10 s (units)\n")
    print("| decline | " + " | ".join(f"{theta}°" for theta in (8, 10, 12, 15, 20, 25)) + " |")
    print("|---|" + "---|" * 6)
    print("| moved | " + " | ".join(f"{pig_moved(theta):.2f}" for theta in (8, 10, 12, 15, 20, 25)) + " |")


if __name__ == "__main__":
    main()
