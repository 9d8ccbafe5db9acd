"""How far a block falling on a ball at rest sets it rolling, by where it lands.

The measurement behind two choices of the angrybirds generator (docs/generation-history.md):
a block that falls on a block that then rolls is not round, and a fall onto a block
that is to move next is aimed behind that block's centre. A block is dropped from
`--height` units above a ball resting on a long flat platform, its centre off the
ball's by a share of their two half-widths (negative: to the left, so the ball should
roll right); printed per faller, ball and materials: how far the ball ends up from
where it rested, and its fastest speed to the right.

    python benchmarks/landing.py [--height 2.5]
"""

from __future__ import annotations

import argparse

from physc.backends import load_backend
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, PLATFORM_THICKNESS, by_prefab
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.worlds import PHYQ

BOX2D = load_backend("box2d")
from physc.domains.angrybirds.level import Level, LevelObject

SHARES = (0.0, -0.2, -0.4, -0.6, -0.8, -1.0)
FALLERS = ("SquareHole", "TriangleHole", "Circle", "CircleSmall")
BALLS = ("Circle", "CircleSmall")
MATERIALS = (("wood", "wood"), ("wood", "ice"), ("ice", "ice"))  # faller, ball
SECONDS = 6.0


def rolled(faller: str, ball: str, faller_material: str, ball_material: str, share: float, height: float) -> tuple[float, float]:
    """(distance the ball ends from where it rested, its fastest speed to the right)."""
    ball_radius = by_prefab(ball).width / 2
    half_width, half_height = by_prefab(faller).width / 2, by_prefab(faller).height / 2
    y = PLATFORM_THICKNESS / 2 + ball_radius + 0.005
    platform = LevelObject("Platform", "Platform", 3.0, 0.0, 0.0, scale_x=14 / PLATFORM_BASE, scale_y=PLATFORM_THICKNESS / PLATFORM_BASE, name="platform")
    resting = LevelObject("Block", ball, 0.0, y, 0.0, ball_material, name="ball")
    falling = LevelObject("Block", faller, share * (ball_radius + half_width), y + ball_radius + half_height + height, 0.0, faller_material, name="faller")
    trace = Game(Level(objects=(platform, resting, falling)), PHYQ, BOX2D).simulate(None, SECONDS)
    states = trace.states[:, trace.index("ball"), :]
    return float(states[-1, 0] - states[0, 0]), float(states[:, 3].max())


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--height", type=float, default=2.5, help="drop height above the ball's top (units)")
    args = parser.parse_args()
    print(f"Dropped from {args.height} units; per landing offset (share of the half-widths): distance / fastest speed to the right\n")
    print("| faller | ball | " + " | ".join(f"{s:+.1f}" for s in SHARES) + " |")
    print("|---|---|" + "---|" * len(SHARES))
    for faller in FALLERS:
        for ball in BALLS:
            for faller_material, ball_material in MATERIALS:
                cells = [rolled(faller, ball, faller_material, ball_material, share, args.height) for share in SHARES]
                row = " | ".join(f"{d:.2f} / {v:.2f}" for d, v in cells)
                print(f"| {faller_material} {faller} | {ball_material} {ball} | {row} |")


if __name__ == "__main__":
    main()
