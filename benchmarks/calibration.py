"""What Phy-Q's labelled levels read as: the calibration of the motion words on the benchmark's own levels.

    python benchmarks/calibration.py FOLDER... [--worlds phyq rolling] [--step 1] [--readings] [--show] [--json FILE]

Each `*.xml` under each FOLDER is a level of Phy-Q's, labelled with its scenario by its file name
(a template `2_3_2_1.xml` or a generated level `2_03_02_00001.xml`: scenario 2_3, sliding). Every
full-stretch shot on a sweep of `--step` degrees (0° to 85°) is played in each world, to rest,
and the levels are reported:

* which levels a single shot solves, and for each solving shot the sequence physc recognises
  (`--show`);
* the words the body that destroyed a pig (the bird included) did before it destroyed it: roll,
  slide, fall, bounce, or nothing; a label × word table by shots (the share of solving shots in
  which the destroyer did the word) and by levels (levels with a solving shot in which it did);
* how many levels have a solving shot read as their label (`read`), apart from those where every
  body of the level that destroyed the pig in a solving shot travelled less than the world's
  `travel` floor before it met the pig (`apart`: a block standing against the pig cannot slide
  *before* it strikes it);
* the words' edges: single-force solving shots whose destroyer rolled or slid, and falling ones
  whose faller rolled or slid and did not fall;
* with `--readings`, every single-bird level of the folders (labelled or not) and, for each
  reading of what the game's files leave open, the levels some shot solves and those that every
  other reading solves but it does not.

The labels and words: single force 1_1 (none), rolling 2_1 (roll), falling 2_2 (fall), sliding
2_3 (slide), bouncing 2_4 (bounce), as Phy-Q's README defines its scenarios.
docs/angrybirds.md ("What the motion words mean") records the figures.
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np

import physc
from physc.api.simulating import bound_domain
from physc.simulation.ending import Ending
from physc.worlds import under_readings

LABELS = {"1_1": ("single force", None), "2_1": ("rolling", "roll"), "2_2": ("falling", "fall"), "2_3": ("sliding", "slide"), "2_4": ("bouncing", "bounce")}
WORDS = ("roll", "slide", "fall", "bounce", "nothing")
NAME = re.compile(r"^(\d+)_0*(\d+)_")


def label_of(path: Path) -> str | None:
    """The Phy-Q scenario a level's file name says it is ("2_3"), if one of LABELS."""
    match = NAME.match(path.name)
    scenario = f"{match.group(1)}_{match.group(2)}" if match else None
    return scenario if scenario in LABELS else None


def destroyers(trace) -> list[dict]:
    """For each pig destroyed by damage: who destroyed it, when, the motion words the destroyer
    did before, and how far the destroyer travelled from where it started moving to where it
    first touched the pig (its travel before it met it)."""
    out = []
    for d in trace.destructions:
        if trace.kinds.get(d.name) != "pig" or d.cause != "damage" or d.by is None:
            continue
        by = blow = trace.parts.get(d.by, d.by)
        if by not in trace.names:  # a platform or the ground dealt the blow: the pig was thrown
            by = next((i.objects[0] for i in reversed(trace.interactions) if i.name == "hit" and i.objects[1] == d.name and i.time <= d.time + 1e-9), by)
            blow = by
            by = trace.parts.get(by, by)
        words = [i.name for i in trace.interactions if i.name in WORDS and i.objects[0] == by and i.time <= d.time + 1e-9]
        out.append({"pig": d.name, "by": by, "time": round(d.time, 2), "words": sorted(set(words)) or ["nothing"], "travel": travel(trace, blow, d.name)})
    return out


def travel(trace, mover: str, target: str) -> float | None:
    """How far `mover` went from its place at the start to where it first touched `target`
    (None: a body that was not in the level at the start, as the bird is not)."""
    if mover not in trace.names or trace.kinds.get(mover) == "bird":
        return None
    met = next((c.time for c in trace.contacts if {c.a, c.b} == {mover, target}), None)
    if met is None:
        return None
    column = trace.states[: max(int(round(met / trace.dt)), 1), trace.index(mover), :2]
    column = column[~np.isnan(column[:, 0])]
    return round(float(np.hypot(*(column[-1] - column[0]))), 3) if len(column) else 0.0


def sweep(path: Path, world: str, step: float, readings: bool) -> dict:
    """Every shot of the sweep on one level in one world: the solving ones with what they read,
    and (readings) in how many shots each reading of the open points solves it. Each shot plays
    only the readings that can change it (physc.worlds.under_readings); every other reading
    plays the same run as an explored one that agrees with it on that run's decisive points."""
    domain = bound_domain("angrybirds", world, None)
    level = physc.read_level(path)
    shots, solved_in = [], defaultdict(int)
    own = domain.world
    every = own.readings() if readings else (own,)
    points = own.open_points()
    angles = np.round(np.arange(0.0, 85.0 + 1e-9, step), 3)
    for angle in angles:
        shot = physc.Shot(angle=float(angle))

        def run(reading, shot=shot):
            return domain.at(reading).play(level, shot, None, domain.seconds, ending=Ending.WHOLE)

        runs = under_readings(own, run) if readings else [(own, run(own))]
        explored = [(r.open_values(), t) for r, t in runs]
        trace = runs[0][1]
        if trace.solved:
            shots.append({"angle": float(angle), "sequence": trace.sequence(), "destroyers": destroyers(trace)})
        for reading in every:
            values = reading.open_values()
            played = next(t for v, t in explored if all(values[i] == v[i] for i, p in enumerate(points) if p.setting in t.decisive))
            solved_in[reading.name] += played.solved
    return {"level": path.name, "label": label_of(path), "birds": len(level.birds), "world": world, "shots": shots,
            "readings": {w.name: solved_in[w.name] for w in every}}


def reads(shot: dict, word: str | None) -> bool:
    """Whether a solving shot reads as the word: some pig's destroyer did it before (no word:
    single force, whose destroyer, it says, neither rolled nor slid)."""
    if word is None:
        return all(not {"roll", "slide"} & set(d["words"]) for d in shot["destroyers"])
    return any(word in d["words"] for d in shot["destroyers"])


def below_floor(shots: list[dict], floor: float) -> bool:
    """Whether the label's motion lies below the travel floor in a level: in every solving shot
    whose pig a body of the level destroyed (not the bird, whose shot is no such motion), that
    body travelled less than `floor` before it met the pig; and there is such a shot."""
    moved = [d for s in shots for d in s["destroyers"] if d["travel"] is not None]
    return bool(moved) and all(d["travel"] < floor for d in moved)


def report(results: list[dict], floors: dict[str, float]) -> str:
    """The tables, in Markdown."""
    lines = []
    for world in sorted({r["world"] for r in results}):
        mine = [r for r in results if r["world"] == world]
        floor = floors[world]
        lines += [f"### {world}", "", f"| label | levels | solvable | read as label | apart (travel < {floor:g}) | % of the rest |", "|---|---|---|---|---|---|"]
        for label, (title, word) in LABELS.items():
            rows = [r for r in mine if r["label"] == label]
            if not rows:
                continue
            solvable = [r for r in rows if r["shots"]]
            read = [r for r in solvable if any(reads(s, word) for s in r["shots"])]
            apart = [r for r in solvable if r not in read and word is not None and below_floor(r["shots"], floor)]
            rest = len(solvable) - len(apart)
            share = f"{100 * len(read) / rest:.0f} %" if rest else "-"
            lines.append(f"| {title} ({label}) | {len(rows)} | {len(solvable)} | {len(read)} | {len(apart)} | {share} |")
        lines += ["", "By shots (share of solving shots whose pig's destroyer did the word before destroying it) and levels:", ""]
        lines += ["| label | solving shots | " + " | ".join(WORDS) + " |", "|---|---|" + "---|" * len(WORDS)]
        for label, (title, _) in LABELS.items():
            rows = [r for r in mine if r["label"] == label]
            shots = [s for r in rows for s in r["shots"]]
            if not shots:
                continue
            cells = []
            for word in WORDS:
                by_shot = sum(any(word in d["words"] for d in s["destroyers"]) for s in shots)
                by_level = sum(any(any(word in d["words"] for d in s["destroyers"]) for s in r["shots"]) for r in rows)
                cells.append(f"{100 * by_shot / len(shots):.0f} % ({by_level})")
            lines.append(f"| {title} | {len(shots)} | " + " | ".join(cells) + " |")
        lines += ["", "Edges: " + "; ".join(_edges(mine)), ""]
        single = [r for r in mine if r["birds"] == 1]
        if any(len(r["readings"]) > 1 for r in single):
            lines += [f"Single-bird levels some shot solves, per reading ({len(single)} levels):", ""] + _readings(single)
    return "\n".join(lines)


def _edges(rows: list[dict]) -> list[str]:
    """The words' edges: single-force solving shots whose destroyer rolled or slid; falling
    solving shots whose faller rolled or slid and did not fall."""
    out = []
    for label, test in (("1_1", lambda d: {"roll", "slide"} & set(d["words"])), ("2_2", lambda d: {"roll", "slide"} & set(d["words"]) and "fall" not in d["words"])):
        shots = [s for r in rows if r["label"] == label for s in r["shots"]]
        if shots:
            hits = sum(any(test(d) for d in s["destroyers"]) for s in shots)
            out.append(f"{LABELS[label][0]} shots whose destroyer {'rolled or slid' if label == '1_1' else 'rolled or slid and did not fall'}: {hits} of {len(shots)} ({100 * hits / len(shots):.0f} %)")
    return out


def _readings(rows: list[dict]) -> list[str]:
    names = list(rows[0]["readings"])
    solvable = {n: {r["level"] for r in rows if r["readings"][n]} for n in names}
    lines = ["| reading | levels a shot solves | solved by every other reading, not by this one |", "|---|---|---|"]
    for n in names:
        others = set.intersection(*(solvable[m] for m in names if m != n)) if len(names) > 1 else set()
        missing = sorted(others - solvable[n])
        lines.append(f"| {n} | {len(solvable[n])} of {len(rows)} | {', '.join(missing) or '-'} |")
    return lines + [""]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folders", nargs="+", type=Path, metavar="FOLDER")
    parser.add_argument("--worlds", nargs="+", default=["phyq", "rolling"])
    parser.add_argument("--step", type=float, default=1.0, help="degrees between shots (default 1)")
    parser.add_argument("--readings", action="store_true", help="play every reading of the open points too")
    parser.add_argument("--show", action="store_true", help="print each solving shot's sequence")
    parser.add_argument("--json", type=Path, help="write every result here")
    args = parser.parse_args()
    # The words need labels; the readings are weighed on every single-bird level.
    paths = sorted(p for folder in args.folders for p in folder.rglob("*.xml") if label_of(p) or args.readings)
    results = []
    for world in args.worlds:
        for path in paths:
            result = sweep(path, world, args.step, args.readings)
            results.append(result)
            if args.show:
                print(f"{world} {path.name}: {len(result['shots'])} solving shots", file=sys.stderr)
                for shot in result["shots"]:
                    print(f"  {shot['angle']:5.1f}  {shot['destroyers']}  {shot['sequence']}", file=sys.stderr)
    floors = {w: bound_domain("angrybirds", w, None).world.recogniser.travel for w in args.worlds}
    print(report(results, floors))
    if args.json:
        args.json.write_text(json.dumps(results, indent=1))


if __name__ == "__main__":
    main()
