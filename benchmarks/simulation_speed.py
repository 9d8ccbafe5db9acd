"""Simulation speed: physics steps per second for a level of 20 bodies, one core.

    python benchmarks/simulation_speed.py [--seconds 10] [--repeat 5] [--backend NAME]

The level: a row of 3 towers of wood, stone and ice blocks (4 high) on the
ground, with 4 pigs and 4 circles on platforms: 20 dynamic bodies and 4
platforms, at rest. Two measurements: the level standing for the given time (no
shot: the resting cost), and a shot into the towers (collisions, damage,
destruction). Each counts every step of the full game loop: physics, contact
callbacks, rules, trace recording. A third runs the same shot on the backend's
world alone (its step, the contact callbacks, the contacts drained; no rules, no
trace): the part of a game step that is the engine's.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ

MATERIALS = ("wood", "stone", "ice")


def level() -> Level:
    objects = []
    for tower, x in enumerate((0.0, 2.5, 5.0)):
        for floor in range(4):
            y = -3.5 + 0.3918 + floor * 0.7936
            objects.append(LevelObject("Block", "SquareHole", x, y, 0.0, MATERIALS[(tower + floor) % 3], name=f"block{tower}{floor}"))
    for k, x in enumerate((-4.0, -1.5, 8.0, 10.5)):
        objects.append(LevelObject("Platform", "Platform", x, -1.0, 0.0, scale_x=3.0, scale_y=0.5, name=f"platform{k}"))
        objects.append(LevelObject("Pig", "BasicSmall", x - 0.4, -1.0 + 0.16 + 0.236, 0.0, name=f"pig{k}"))
        objects.append(LevelObject("Block", "Circle", x + 0.45, -1.0 + 0.16 + 0.385, 0.0, "wood", name=f"circle{k}"))
    return Level(objects=tuple(objects))


def measure(shot, seconds: float, repeat: int, backend) -> list[float]:
    rates = []
    game = Game(level(), PHYQ, backend)
    for _ in range(repeat):
        start = time.perf_counter()
        trace = game.simulate(shot, seconds, stop_at_rest=False)
        rates.append(trace.steps / (time.perf_counter() - start))
    return rates


def measure_engine(shot, seconds: float, repeat: int, backend) -> list[float]:
    """The shot's steps on the world alone, as the game builds it."""
    rates = []
    game = Game(level(), PHYQ, backend)
    rules = game.rules
    steps = int(round(seconds / rules.dt))
    for _ in range(repeat):
        start = time.perf_counter()
        world = game.build()
        game.launch(world, shot)
        for _ in range(steps):
            world.step(rules.dt)
            world.begun()
            world.ended()
        rates.append(steps / (time.perf_counter() - start))
    return rates


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--backend", default="box2d", help="the physics engine (default box2d)")
    args = parser.parse_args()
    backend = load_backend(args.backend)
    bodies = sum(1 for o in level().objects if o.element != "Platform")
    print(f"machine: {platform.machine()}, Python {platform.python_version()}; {args.backend}; {bodies} dynamic bodies, {args.seconds:g} s per run")
    for label, shot in (("standing, no shot", None), ("shot into the towers", Shot(target=(0.0, -2.5)))):
        rates = measure(shot, args.seconds, args.repeat, backend)
        print(f"{label:<22} median {statistics.median(rates):,.0f} steps/s  (best {max(rates):,.0f})")
    rates = measure_engine(Shot(target=(0.0, -2.5)), args.seconds, args.repeat, backend)
    print(f"{'the shot, engine only':<22} median {statistics.median(rates):,.0f} steps/s  (best {max(rates):,.0f})")


if __name__ == "__main__":
    main()
