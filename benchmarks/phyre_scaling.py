"""How PHYRE-like generation with PHYRE's exact filtering scales over workers.

Runs `physc eval` twice on PHYRE's templates: once on `--baseline` tasks with one worker,
once on every task with a local Dask cluster of `--workers` workers, and reads the
per-task generation seconds from both runs' records. A task's work is fixed by its seed, so
the tasks both runs share say how much slower a task runs when all workers are busy; the
speed-up is the one-worker time of all tasks (each task's seconds in the parallel run,
scaled by that slowdown) over the parallel run's wall time.

    python benchmarks/phyre_scaling.py --workers 16 --seeds 4 --out /tmp/scaling
    python benchmarks/phyre_scaling.py --templates 00009,00024 --seeds 2 --workers 2 --baseline 1

Results of a run are in docs/results.md ("PHYRE's filtering at scale").
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

EXAMPLES = Path(__file__).resolve().parents[1] / "plugins" / "physc-phyre" / "examples" / "phyre"
TEMPLATES = "00002,00006,00009,00011,00021,00022,00024,00003"


def run(files: list[Path], seeds: int, out: Path, where: list[str], budget: float) -> tuple[float, dict]:
    """Wall seconds of one `physc eval`, and its records by (scenario, seed)."""
    command = [sys.executable, "-m", "physc", "eval", *map(str, files), "--seed", "0", "--tasks", str(seeds),
               "--time-budget", str(budget), "--out", str(out), "-q", *where]
    started = time.perf_counter()
    done = subprocess.run(command, capture_output=True, text=True)
    wall = time.perf_counter() - started
    if done.returncode not in (0, 1):
        sys.exit(f"physc eval failed ({done.returncode}): {done.stderr[-2000:]}")
    records = [json.loads(line) for line in (out / "records.jsonl").read_text().splitlines()]
    return wall, {(r["scenario"], r["seed"]): r for r in records}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--templates", default=TEMPLATES, help=f"PHYRE template ids (default {TEMPLATES})")
    parser.add_argument("--seeds", type=int, default=4, help="seeds per template in the parallel run")
    parser.add_argument("--workers", type=int, default=16)
    parser.add_argument("--baseline", type=int, default=2, help="tasks of the first template run with one worker")
    parser.add_argument("--time-budget", type=float, default=300.0)
    parser.add_argument("--out", type=Path, default=Path("/tmp/phyre-scaling"))
    args = parser.parse_args()
    files = [EXAMPLES / f"task{t}.phys" for t in args.templates.split(",")]
    missing = [str(f) for f in files if not f.is_file()]
    if missing:
        sys.exit(f"no such template: {', '.join(missing)}")
    wall_1, one = run(files[:1], args.baseline, args.out / "one", ["--jobs", "1"], args.time_budget)
    wall_n, many = run(files, args.seeds, args.out / "many", ["--dask-workers", str(args.workers)], args.time_budget)
    shared = [k for k in one if k in many and one[k].get("generation_seconds") and many[k].get("generation_seconds")]
    slowdown = statistics.mean(many[k]["generation_seconds"] / one[k]["generation_seconds"] for k in shared) if shared else 1.0
    busy = sum(r.get("generation_seconds") or 0.0 for r in many.values())
    made = sum(bool(r.get("generated")) for r in many.values())
    speedup = busy / slowdown / wall_n
    summary = {
        "workers": args.workers, "tasks": len(many), "made": made, "wall_one_worker": round(wall_1, 1), "baseline_tasks": len(one),
        "wall_parallel": round(wall_n, 1), "task_seconds_parallel": round(busy, 1), "slowdown_under_load": round(slowdown, 3),
        "speedup": round(speedup, 2), "efficiency": round(speedup / args.workers, 3),
        "median_task_seconds": round(statistics.median(r["generation_seconds"] for r in many.values() if r.get("generation_seconds")), 1),
        "made_per_hour": round(made / wall_n * 3600, 1),
    }
    print(json.dumps(summary, indent=1))
    (args.out / "summary.json").write_text(json.dumps(summary, indent=1) + "\n")


if __name__ == "__main__":
    main()
