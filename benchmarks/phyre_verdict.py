"""The seconds of PHYRE's acceptance verdict on PHYRE-like tasks, and the verdicts themselves.

Reads task files (`physc compile … --task FILE`; drafts made with `--no-acceptance` do, as
the verdict is judged here, not read from the file) and judges each as the search does
(the PHYRE-like domain's `evaluation.acceptance`, physc_phyre.acceptance: PHYRE's rule on PHYRE's pool of random actions), in
this process, one after another. Prints one JSON line per task (its verdict's record and
the seconds and simulations it took) and a total line; the verdicts are what a change to
the simulation must leave the same, so two checkouts are compared by their lines (the
"seconds" aside).

    python benchmarks/phyre_verdict.py TASK.json…
    python benchmarks/phyre_verdict.py --make /tmp/verdicts   # the set docs/performance.md uses

With `--make FOLDER` it first drafts the benchmark set into FOLDER (templates `TEMPLATES`,
seed 0, `--no-acceptance`) and then judges it. Results: docs/performance.md ("PHYRE's verdict").
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "plugins" / "physc-phyre" / "examples" / "phyre"
TEMPLATES = ("00000", "00002", "00009", "00011", "00021", "00024")


class Counter:
    """The search's evaluator as the verdict uses it: runs and counts each play."""

    def __init__(self):
        self.simulations = 0

    def run(self, simulate):
        self.simulations += 1
        return simulate()


def make(folder: Path) -> list[Path]:
    """Draft the benchmark set into `folder` (tasks already there are kept)."""
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for template in TEMPLATES:
        task = folder / f"task{template}.json"
        if not task.is_file():
            command = [sys.executable, "-m", "physc", "compile", str(EXAMPLES / f"task{template}.phys"), "--seed", "0", "--no-acceptance",
                       "-o", str(folder / f"level{template}.json"), "--task", str(task), "-q"]
            subprocess.run(command, check=False)
        if task.is_file():
            out.append(task)
    return out


def judge(path: Path) -> dict:
    from physc.api import domain_of, load_task
    from physc.simulation.ending import Ending

    task = load_task(path)
    domain = domain_of(task)
    action = domain.actions.action_of(task.solution)
    counter = Counter()
    started = time.perf_counter()
    judged = domain.evaluation.acceptance(task.level, action, lambda a: counter.run(lambda: domain.playout(task.level, a, ending=Ending.SETTLED)).solved)
    seconds = time.perf_counter() - started
    return {"task": path.name, "seconds": round(seconds, 3), "plays": counter.simulations, "verdict": judged.record() if judged else None}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("tasks", nargs="*", type=Path)
    parser.add_argument("--make", type=Path, help="draft the benchmark set into this folder first, and judge it")
    args = parser.parse_args()
    tasks = list(args.tasks) + (make(args.make) if args.make else [])
    if not tasks:
        parser.error("no task files (give some, or --make FOLDER)")
    total = plays = 0.0
    for path in tasks:
        line = judge(path)
        total += line["seconds"]
        plays += line["plays"]
        print(json.dumps(line, sort_keys=True), flush=True)
    print(json.dumps({"total_seconds": round(total, 3), "plays": int(plays), "plays_per_second": round(plays / max(total, 1e-9), 1)}))


if __name__ == "__main__":
    main()
