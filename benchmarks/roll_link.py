"""Whether any surface structure lets a struck circle roll into a small pig and destroy it, in a world.

The measurement behind "Roll into a pig: the structures tried" (docs/results.md, issue 53). The
link is the paper's R without the bird's restriction, so that only the roll link is judged:
`hit(bird, rBlock, left) > roll(rBlock, surface, right) > hit(rBlock, pig, left) >
destroy(rBlock, pig)` with `cannotFall(rBlock)`. A Circle rests near the right end of a
1-unit ledge; a flat run-up of `runup` units follows, then the rolling surface `surface`,
declining to the right at `angle` degrees for `length` units, then a flat floor with a small
pig `gap` units past the foot. Each of the Circle's candidate shots is played under every
reading of the world (World.readings); a shot that realises the link in all of them is
replayed with the domain's noise (6 draws, as generation's robustness replays) and counted
robust when every noisy replay realises it in every reading.

    python benchmarks/roll_link.py                       # the default sweep, world phyq
    python benchmarks/roll_link.py --world rolling
    python benchmarks/roll_link.py --angles 12.7,26.8 --runups 0 --lengths 5.4,7.1
    python benchmarks/roll_link.py --runups 3 --angles 35 --lengths 3 --gaps 0.3 --replays 12 --why
"""

from __future__ import annotations

import argparse
import itertools
import math
import random

import numpy as np

from physc.domains import load_domain
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze_text
from physc.simulation.fidelity import fidelity
from physc.simulation.stopped import why_stopped

LINK = """scenario RollLink {
    interactions {
        hit(bird, rBlock, left) > roll(rBlock, surface, right) > hit(rBlock, pig, left) > destroy(rBlock, pig)
    }
    restrictions { cannotFall(rBlock) }
}
"""
TOP = 3.0  # the ledge's top: high enough that the steepest, longest ramp ends above the ground (-3.5)
LEDGE = 1.0
REPLAYS = 6
THICKNESS = 0.32  # a Platform's height at scale_y 0.5


def _platform(x0: float, y0: float, angle: float, length: float, name: str) -> LevelObject:
    """A platform whose top edge starts at (x0, y0) and declines to the right at `angle`°."""
    a = math.radians(angle)
    half = THICKNESS / 2
    cx = x0 + length / 2 * math.cos(a) + half * math.sin(a)
    cy = y0 - length / 2 * math.sin(a) - half * math.cos(a)
    return LevelObject("Platform", "Platform", cx, cy, -angle, scale_x=length / 0.64, scale_y=0.5, name=name)


def level(runup: float, angle: float, length: float, gap: float) -> Level:
    x, y = -5.0, TOP
    objects = [_platform(x, y, 0.0, LEDGE, "ledge"), LevelObject("Block", "Circle", x + LEDGE - 0.45, y + 0.38, 0.0, "wood", name="rBlock")]
    x += LEDGE
    if runup > 0:
        objects.append(_platform(x, y, 0.0, runup, "runup"))
        x += runup
    objects.append(_platform(x, y, angle, length, "surface"))
    x, y = x + length * math.cos(math.radians(angle)), y - length * math.sin(math.radians(angle))
    objects.append(_platform(x, y, 0.0, 8.0, "floor"))
    objects.append(LevelObject("Pig", "BasicSmall", x + gap + 0.23, y + 0.235, 0.0, name="pig"))
    return Level(objects=tuple(objects))


def measure(domain, scenario, lv: Level, replays: int = REPLAYS, why: bool = False) -> tuple[int, int, float]:
    """(shots realising the link in every reading, of them those robust to `replays` noisy
    replays, the fastest the circle struck the pig in any play); with `why`, each failed noisy
    replay's reason printed (physc.simulation.stopped)."""
    readings = [domain.at(world) for world in domain.world.readings()]

    def plays(lv, shot):
        return [reading.play(lv, shot, scenario) for reading in readings]

    realised = robust = 0
    fastest = 0.0
    for label, shot in domain.actions.candidates(lv, scenario):
        traces = plays(lv, shot)
        for trace in traces:
            fastest = max(fastest, _strike(trace))
        if not all(fidelity(scenario, t).valid for t in traces):
            continue
        realised += 1
        passed = True
        for k in range(replays):
            noisy_level, noisy_shot = domain.actions.noisy(lv, shot, random.Random(k))
            for reading, trace in zip(readings, plays(noisy_level, noisy_shot)):
                judged = fidelity(scenario, trace)
                passed = passed and judged.valid
                if why and not judged.valid:
                    print(f"    {label}, noisy replay {k}, reading {reading.world.name!r}: {why_stopped(scenario, trace, judged) or judged.violations}")
        robust += passed
    return realised, robust, fastest


def _strike(trace) -> float:
    """The circle's fastest speed in the 0.2 s before it first touched the pig (0: it never did)."""
    touch = next((c.time for c in trace.contacts if {c.a, c.b} == {"rBlock", "pig"}), None)
    if touch is None:
        return 0.0
    rows = trace.states[max(int((touch - 0.2) / trace.dt), 0) : int(touch / trace.dt) + 1, trace.index("rBlock"), 3:5]
    return float(np.nanmax(np.hypot(rows[:, 0], rows[:, 1]))) if len(rows) else 0.0


def _floats(text: str) -> list[float]:
    return [float(v) for v in text.split(",")]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--world", default=None)
    parser.add_argument("--runups", type=_floats, default=[0.0, 1.5, 3.0])
    parser.add_argument("--angles", type=_floats, default=[12.7, 26.8, 35.0, 45.0, 55.0])
    parser.add_argument("--lengths", type=_floats, default=[1.5, 3.0, 6.0])
    parser.add_argument("--gaps", type=_floats, default=[0.3, 1.0])
    parser.add_argument("--replays", type=int, default=REPLAYS, help="noisy replays of a realised shot")
    parser.add_argument("--why", action="store_true", help="print why each failed noisy replay failed")
    args = parser.parse_args()
    deepest = max(math.sin(math.radians(a)) * n for a in args.angles for n in args.lengths)
    if TOP - deepest < -3.2:
        parser.error(f"a ramp {deepest:.1f} units deep would end below the ground: shorter --lengths or gentler --angles")
    domain = load_domain("angrybirds").at(args.world)
    analysis = analyze_text("roll_link.phys", LINK, INSTALLED)
    (scenario,) = analysis.scenarios
    print(f"world {domain.world.name}; readings: {'; '.join(w.name for w in domain.world.readings())}")
    print("runup  angle  length  gap   realised  robust  fastest strike (units/s)")
    totals = [0, 0, 0]
    for runup, angle, length, gap in itertools.product(args.runups, args.angles, args.lengths, args.gaps):
        realised, robust, fastest = measure(domain, scenario, level(runup, angle, length, gap), args.replays, args.why)
        totals = [totals[0] + 1, totals[1] + (realised > 0), totals[2] + (robust > 0)]
        print(f"{runup:5.1f}  {angle:5.1f}  {length:6.1f}  {gap:3.1f}   {realised:8d}  {robust:6d}  {fastest:6.2f}", flush=True)
    print(f"structures: {totals[0]}; realised in every reading: {totals[1]}; robust: {totals[2]}")


if __name__ == "__main__":
    main()
