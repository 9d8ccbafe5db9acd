"""Stability of real levels: the 75 Phy-Q templates standing for 10 s with no shot.

    python benchmarks/stability.py [--colliders game|phyq|round] [--backend NAME] [--seconds 10] [--limit 0.1]

A template is stable when no object moves more than `--limit` units and nothing is
destroyed. Prints each unstable template with the object that moved most.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level_xml import read_level
from physc.domains.angrybirds.worlds import catalogue_model

TEMPLATES = Path(__file__).resolve().parents[2] / "shared" / "data" / "sciencebirds" / "phyq-templates"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--colliders", choices=("game", "phyq", "round"), default="game")
    parser.add_argument("--backend", default="box2d", help="the physics engine (default box2d, the game's)")
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--limit", type=float, default=0.1)
    parser.add_argument("--templates", type=Path, default=TEMPLATES)
    args = parser.parse_args()
    paths = sorted(args.templates.glob("*.xml"))
    start = time.perf_counter()
    unstable = []
    for path in paths:
        level = read_level(path.read_bytes())
        trace = Game(level, catalogue_model(args.colliders), load_backend(args.backend)).simulate(None, args.seconds, stop_at_rest=False)
        states = trace.states
        shift = np.hypot(states[:, :, 0] - states[0, :, 0], states[:, :, 1] - states[0, :, 1]) if states.shape[1] else np.zeros((1, 1))
        worst = float(np.nanmax(shift))
        if worst > args.limit or trace.destructions:
            name = trace.names[int(np.nanargmax(np.nanmax(shift, axis=0)))]
            unstable.append((path.stem, name, worst, [d.name for d in trace.destructions]))
    stable = len(paths) - len(unstable)
    print(f"{args.backend}, colliders={args.colliders}: {stable} of {len(paths)} stable ({stable / len(paths):.1%}) in {time.perf_counter() - start:.1f} s")
    for stem, name, worst, destroyed in unstable:
        print(f"  {stem}: {name} moved {worst:.3f}" + (f"; destroyed {', '.join(destroyed)}" if destroyed else ""))


if __name__ == "__main__":
    main()
