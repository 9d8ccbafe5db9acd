"""Real Science Birds levels: how many load, stand and trace, per folder.

    python benchmarks/real_levels.py FOLDER... [--seconds 10] [--colliders game|round|phyq] [--limit 0.1]

Every `*.xml` under each FOLDER (recursively) is read with physc's importer, played
`--seconds` with no shot, and traced (the interactions recognised in that run). A level
*stands* when no object moves more than `--limit` units from where it is after the first
step and nothing is destroyed, as tests/domains/test_real_levels.py measures. Prints one line
per folder (loaded / stood / traced), then each level that failed a stage and why: the
diagnostic of a level that does not load, the object that moved most in one that does
not stand, the exception of one whose trace failed.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from physc.backends import load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.worlds import catalogue_model

BOX2D = load_backend("box2d")
from physc.domains.angrybirds.level_xml import LevelError, read_level


def movement(trace) -> tuple[float, str]:
    """The largest distance any object moved from its place after the first step, and which."""
    states = trace.states
    if not states.shape[1]:
        return 0.0, ""
    shift = np.hypot(states[:, :, 0] - states[0, :, 0], states[:, :, 1] - states[0, :, 1])
    worst = np.nanmax(shift, axis=0)
    index = int(np.nanargmax(worst))
    return float(worst[index]), trace.names[index]


def measure(path: Path, seconds: float, circles: str, limit: float) -> tuple[bool, bool, bool, str]:
    """Whether the level loaded, stood and traced without error, and what went wrong."""
    try:
        level = read_level(path.read_bytes())
    except LevelError as error:
        return False, False, False, f"{error.code} {error}"
    game = Game(level, catalogue_model(circles), BOX2D)
    trace = game.simulate(None, seconds, stop_at_rest=False)
    moved, name = movement(trace)
    destroyed = [d.name for d in trace.destructions]
    stood = moved <= limit and not destroyed
    why = [] if stood else [f"{name} moved {moved:.3f}" + (f"; destroyed {', '.join(destroyed)}" if destroyed else "")]
    try:
        game.read(game.world.recogniser.recognise(trace, trace.radii))  # the interactions, as a play reads them
    except Exception as error:  # noqa: BLE001 - the benchmark reports any failure of the trace
        return True, stood, False, "; ".join(why + [f"trace failed: {type(error).__name__}: {error}"])
    return True, stood, True, "; ".join(why)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", type=Path, metavar="FOLDER")
    parser.add_argument("--seconds", type=float, default=10.0, help="simulated seconds per level (default 10)")
    parser.add_argument("--colliders", choices=("game", "round", "phyq"), default="game", help="the bodies' colliders (default: the game's own)")
    parser.add_argument("--limit", type=float, default=0.1, help="how far an object may move and still stand (default 0.1)")
    args = parser.parse_args()
    failures = []
    print(f"| folder | levels | loaded | stood {args.seconds:g} s | traced | seconds |")
    print("|---|---|---|---|---|---|")
    for folder in args.folders:
        paths = sorted(folder.rglob("*.xml"))
        start = time.perf_counter()
        counts = {"loaded": 0, "stood": 0, "traced": 0}
        for path in paths:
            loaded, stood, traced, why = measure(path, args.seconds, args.colliders, args.limit)
            counts["loaded"] += loaded
            counts["stood"] += stood
            counts["traced"] += traced
            if why:
                failures.append((path, why))
        seconds = time.perf_counter() - start
        print(f"| {folder} | {len(paths)} | {counts['loaded']} | {counts['stood']} | {counts['traced']} | {seconds:.1f} |")
    for path, why in failures:
        print(f"  {path}: {why}")


if __name__ == "__main__":
    main()
