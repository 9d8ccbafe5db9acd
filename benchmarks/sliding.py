"""Which blocks slide when the bird strikes them, and which tip over or break.

The measurement behind the satisfier's slide repairs (docs/generation-history.md, "Which blocks
slide"). A block rests on a long flat platform, `--distance`s from the slingshot; the
bird is shot at a point of interest of the block on the low trajectory, at full stretch.
Printed per block, material and place: how far the block travelled, how far it turned
at most (degrees), and whether a slide was recognised; "broken" when the bird's blow
destroyed it.

Wood and stone grip a platform at friction 1.26 (the geometric mean of 4.0 and the
platform's 0.4), more than a square's width over its height, so a sliding square tips
over its leading edge; ice grips at 0.53.

    python benchmarks/sliding.py
"""

from __future__ import annotations

import argparse
import math

import numpy as np

from physc.backends import load_backend
from physc.domains.angrybirds.actions import points_of_interest
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, PLATFORM_THICKNESS, by_prefab
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.worlds import PHYQ

BOX2D = load_backend("box2d")
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject

BLOCKS = ("SquareHole", "TriangleHole")
MATERIALS = ("wood", "ice", "stone")
POINTS = ("ll", "left", "lr", "c")
PLATFORM_Y = -2.0
PLATFORM_LENGTH = 10.0
SECONDS = 6.0


def struck(prefab: str, material: str, x: float, point: str) -> tuple[float, float, bool] | None:
    """(distance travelled, largest turn in degrees, slide recognised), or None if broken."""
    platform = LevelObject(
        "Platform", "Platform", x + PLATFORM_LENGTH / 2 - 2.0, PLATFORM_Y, 0.0,
        scale_x=PLATFORM_LENGTH / PLATFORM_BASE, scale_y=PLATFORM_THICKNESS / PLATFORM_BASE, name="platform",
    )
    height = by_prefab(prefab).height
    block = LevelObject("Block", prefab, x, PLATFORM_Y + PLATFORM_THICKNESS / 2 + height / 2 + 0.002, 0.0, material, name="block")
    target = points_of_interest(block)[point]
    trace = Game(Level(objects=(platform, block)), PHYQ, BOX2D).play(Shot(target=target, trajectory="low"), SECONDS)
    states = trace.states[:, trace.index("block")]
    if np.isnan(states[-1, 0]):
        return None
    slid = any(found.name == "slide" and found.objects[0] == "block" for found in trace.interactions)
    return float(states[-1, 0] - states[0, 0]), math.degrees(float(np.abs(states[:, 2]).max())), slid


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--distance", type=float, nargs="+", default=[-4.0, 0.0, 4.0], help="the block's x (the slingshot is at -12.15)")
    args = parser.parse_args()
    print("Per point struck: distance travelled / largest turn (degrees) / slide recognised\n")
    print("| block | x | " + " | ".join(POINTS) + " |")
    print("|---|---|" + "---|" * len(POINTS))
    for prefab in BLOCKS:
        for material in MATERIALS:
            for x in args.distance:
                cells = []
                for point in POINTS:
                    result = struck(prefab, material, x, point)
                    cells.append("broken" if result is None else f"{result[0]:.2f} / {result[1]:.0f}° / {'slides' if result[2] else '–'}")
                print(f"| {material} {prefab} | {x:g} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
