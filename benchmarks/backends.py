"""The physics backends side by side: the same Science Birds situations in each engine.

    python benchmarks/backends.py [--backends box2d,pymunk,bullet] [--templates DIR]

Each row is one situation, built by the game (its shapes, materials and rules) and run in
every backend; the table says what each engine makes of it. What the rows measure:

* free fall: a SquareSmall dropped 3 units onto the ground, the time until it touches;
* flight at full stretch: the bird alone, released at five angles, where it first lands;
* a circle rolling: a wood Circle on the ground, set moving at 3 units/s (as a hit does),
  how far it goes before it rests;
* a square sliding: a wood SquareSmall on the ground pushed at 3 units/s, how far it slides;
* a square tipping off a ledge: a wood SquareSmall overhanging a platform's edge by 0.15, pushed
  at 0.6 units/s, where it lands on the ground and where and at what angle it rests;
* a Triangle whose centroid (not its points' origin) is on a ledge: it must stay;
* a TNT crate (its own gravity scale) thrown: it must not turn;
* a square at rest for 5 s, then pushed: a body set moving after it came to rest;
* a five-block stack: five wood SquareSmalls stacked on the ground, the largest shift in 10 s;
* the real Phy-Q templates (75 in ../shared/data/sciencebirds): how many stand 10 s
  (shift ≤ 0.1 units, nothing destroyed), with each Circle model;
* speed: game steps per second of the 20-body level of benchmarks/simulation_speed.py, standing
  and with a shot into its towers, through the whole game loop.
"""

from __future__ import annotations

import argparse
import math
import pathlib
import statistics
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).parent))

from simulation_speed import level as speed_level  # noqa: E402

from physc.backends import load_backend  # noqa: E402
from physc.domains.angrybirds.catalogue import extent  # noqa: E402
from physc.domains.angrybirds.game import BIRD, GROUND, Game  # noqa: E402
from physc.domains.angrybirds.launch import Shot  # noqa: E402
from physc.domains.angrybirds.level import Level, LevelObject  # noqa: E402
from physc.domains.angrybirds.level_xml import read_level  # noqa: E402
from physc.domains.angrybirds.worlds import PHYQ, catalogue_model  # noqa: E402
from physc.simulation.stability import largest_shift  # noqa: E402

GROUND_TOP = PHYQ.frame.ground_top
TEMPLATES = pathlib.Path(__file__).resolve().parents[2] / "shared/data/sciencebirds/phyq-templates"
SQUARE = 0.3772  # SquareSmall's side
CIRCLE = 0.75
ANGLES = (15, 30, 45, 60, 75)


def block(kind: str, x: float, y: float, name: str, rotation: float = 0.0) -> LevelObject:
    return LevelObject("Block", kind, x, y, rotation, "wood", name=name)


def steps(game: Game, world, seconds: float):
    """Step `world` (built by `game`) for `seconds`, yielding (time, world) after each step."""
    dt = game.rules.dt
    for step in range(int(round(seconds / dt))):
        world.step(dt)
        yield (step + 1) * dt, world


def first_touch(game, world, name: str, other: str, seconds: float) -> tuple[float, tuple] | None:
    """(time, state) when `name` first begins touching `other`."""
    for t, w in steps(game, world, seconds):
        for event in w.begun():
            if {event.a, event.b} == {name, other}:
                return t, w.state(name)
        w.ended()
    return None


def at_rest(game, world, name: str, seconds: float) -> tuple:
    """`name`'s state once it has been still for 0.2 s (or after `seconds`)."""
    still = 0.0
    state = world.state(name)
    for _, w in steps(game, world, seconds):
        w.begun(), w.ended()
        state = w.state(name)
        still = still + game.rules.dt if abs(state[3]) + abs(state[4]) + abs(state[5]) < 0.02 else 0.0
        if still >= 0.2:
            break
    return state


def free_fall(backend) -> str:
    game = Game(Level(objects=(block("SquareSmall", 0.0, GROUND_TOP + SQUARE / 2 + 3.0, "square"),)), PHYQ, backend)
    found = first_touch(game, game.build(), "square", GROUND, 5.0)
    expected = math.sqrt(2 * 3.0 / game.rules.gravity)
    return f"{found[0]:.2f} s (exact {expected:.2f} s)" if found else "never lands"


def flight(backend, angle: float) -> str:
    game = Game(Level(objects=()), PHYQ, backend)
    world = game.build()
    game.launch(world, Shot(angle=angle))
    found = first_touch(game, world, BIRD, GROUND, 10.0)
    return f"x {found[1][0]:.2f}" if found else "out of the level"


def moving(backend, kind: str, speed: float) -> str:
    height = CIRCLE if kind == "Circle" else SQUARE
    game = Game(Level(objects=(block(kind, 0.0, GROUND_TOP + height / 2, "body"),)), PHYQ, backend)
    world = game.build()
    world.step(game.rules.dt)  # settle onto the ground first
    world.begun(), world.ended()
    x0 = world.state("body")[0]
    world.set_velocity("body", speed, 0.0, -speed / (height / 2) if kind == "Circle" else 0.0)
    state = at_rest(game, world, "body", 30.0)
    return f"{state[0] - x0:.2f} units"


def tipping(backend) -> str:
    platform = LevelObject("Platform", "Platform", 0.0, -1.0, 0.0, scale_x=3.0, scale_y=0.5, name="ledge")
    width, height = extent(platform)
    square = block("SquareSmall", width / 2 - SQUARE / 2 + 0.15, -1.0 + height / 2 + SQUARE / 2 + 0.015, "square")
    game = Game(Level(objects=(platform, square)), PHYQ, backend)
    world = game.build()
    world.set_velocity("square", 0.6, 0.0)
    landed = first_touch(game, world, "square", GROUND, 5.0)
    if landed is None:
        return "stays on the ledge"
    rest = at_rest(game, world, "square", 10.0)
    turned = math.degrees(rest[2]) % 90.0
    return f"lands at x {landed[1][0]:.2f}, t {landed[0]:.2f} s; rests at x {rest[0]:.2f}, turned {min(turned, 90 - turned):.0f}°"


def triangle_on_ledge(backend) -> str:
    """A wood Triangle (its centroid is off its points' origin) with its right corner over a
    ledge's edge but its centroid on the ledge: it should stay."""
    platform = LevelObject("Platform", "Platform", 0.0, -1.0, 0.0, scale_x=3.0, scale_y=0.5, name="ledge")
    width, height = extent(platform)
    triangle = block("Triangle", width / 2 - 0.3, -1.0 + height / 2 + 0.375 + 0.015, "triangle")
    trace = Game(Level(objects=(platform, triangle)), PHYQ, backend).simulate(None, 5.0, stop_at_rest=False)
    return f"largest shift {largest_shift(trace):.3f}"


def tnt_flight(backend) -> str:
    """A TNT crate (gravity scale 1/0.48) thrown at 10 units/s: it must not start turning."""
    game = Game(Level(objects=(LevelObject("TNT", "TNT", 0.0, 2.0, 0.0, name="tnt"),)), PHYQ, backend)
    world = game.build()
    world.set_velocity("tnt", 10.0, 0.0)
    for _ in steps(game, world, 1.0):
        world.begun(), world.ended()
    return f"turned {abs(world.state('tnt')[2]):.3f} rad in 1 s"


def pushed_after_rest(backend) -> str:
    """A SquareSmall at rest on the ground for 5 s, then pushed at 3 units/s."""
    game = Game(Level(objects=(block("SquareSmall", 0.0, GROUND_TOP + SQUARE / 2, "body"),)), PHYQ, backend)
    world = game.build()
    for _ in steps(game, world, 5.0):
        world.begun(), world.ended()
    x0 = world.state("body")[0]
    world.set_velocity("body", 3.0, 0.0, 0.0)
    return f"{at_rest(game, world, 'body', 10.0)[0] - x0:.2f} units"


def stack(backend) -> str:
    objects = tuple(block("SquareSmall", 0.0, GROUND_TOP + SQUARE / 2 + 0.015 + k * (SQUARE + 0.015), f"b{k}") for k in range(5))
    trace = Game(Level(objects=objects), PHYQ, backend).simulate(None, 10.0, stop_at_rest=False)
    return f"largest shift {largest_shift(trace):.3f}"


def templates(backend, circles: str, folder: pathlib.Path) -> str:
    paths = sorted(folder.glob("*.xml"))
    if not paths:
        return "no templates found"
    standing = 0
    for path in paths:
        trace = Game(read_level(path.read_bytes()), catalogue_model(circles), backend).simulate(None, 10.0, stop_at_rest=False)
        standing += largest_shift(trace) <= 0.1 and not trace.destructions
    return f"{standing} of {len(paths)} ({standing / len(paths):.0%})"


def speed(backend, shot) -> str:
    game = Game(speed_level(), PHYQ, backend)
    rates = []
    for _ in range(3):
        start = time.perf_counter()
        trace = game.simulate(shot, 10.0, stop_at_rest=False)
        rates.append(trace.steps / (time.perf_counter() - start))
    return f"{statistics.median(rates):,.0f} steps/s"


def rows(backend, folder):
    yield "free fall, 3 units", free_fall(backend)
    for angle in ANGLES:
        yield f"bird at full stretch, {angle}°: first landing", flight(backend, angle)
    yield "Circle rolling from 3 units/s: distance", moving(backend, "Circle", 3.0)
    yield "SquareSmall sliding from 3 units/s: distance", moving(backend, "SquareSmall", 3.0)
    yield "SquareSmall tipping off a ledge", tipping(backend)
    yield "Triangle with its centroid on a ledge, 5 s", triangle_on_ledge(backend)
    yield "TNT thrown at 10 units/s: spin", tnt_flight(backend)
    yield "SquareSmall at rest 5 s, then pushed at 3 units/s: distance", pushed_after_rest(backend)
    yield "five SquareSmalls stacked, 10 s", stack(backend)
    for colliders in ("game", "phyq", "round"):
        yield f"Phy-Q templates standing 10 s (colliders {colliders})", templates(backend, colliders, folder)
    yield "20 bodies standing: game steps/s", speed(backend, None)
    yield "20 bodies, a shot into the towers: game steps/s", speed(backend, Shot(target=(0.0, -2.5)))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--backends", default="box2d,pymunk,bullet")
    parser.add_argument("--templates", type=pathlib.Path, default=TEMPLATES)
    args = parser.parse_args()
    names = args.backends.split(",")
    columns = [dict(rows(load_backend(name), args.templates)) for name in names]
    print("| situation | " + " | ".join(names) + " |")
    print("|---|" + "---|" * len(names))
    for label in columns[0]:
        print(f"| {label} | " + " | ".join(column[label] for column in columns) + " |")


if __name__ == "__main__":
    main()
