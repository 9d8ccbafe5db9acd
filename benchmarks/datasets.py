"""Dataset generation on its executors: tasks per hour, and what Dask costs (docs/performance.md).

    python benchmarks/datasets.py [--tasks 12] [--repeat 2]

Generates the paper's 2- and 4-interaction scenarios (SF, SFTB, SFLB, R, F, S, B), `--tasks` seeds
each, into fresh folders with `physc generate`, as whole commands:
- local processes: --jobs 1 and --jobs 2;
- Dask: --dask-workers 1 and --dask-workers 2 (a LocalCluster started by the command).
Prints the median wall time of `--repeat` runs of each and the tasks per hour, the speed-up of 2
Dask workers over 1 (target >= 1.8), and Dask's overhead against local processes with the same
number of workers (target <= 5 %). Every run must make the same dataset (checked).
"""

from __future__ import annotations

import argparse
import hashlib
import json
import platform
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PAPER = Path(__file__).resolve().parents[1] / "examples" / "paper"
SCENARIOS = ["01_SF", "02_SFTB", "03_SFLB", "04_R", "05_F", "06_S", "07_B"]


def fingerprint(folder: Path) -> dict[str, str]:
    """A hash of each task file, and of each manifest row without its times, by name."""
    found = {}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and path.suffix in (".xml", ".json"):
            found[str(path.relative_to(folder))] = hashlib.sha256(path.read_bytes()).hexdigest()
    for line in (folder / "manifest.jsonl").read_text().splitlines():
        row = json.loads(line)
        row.pop("generation_seconds"), row.pop("seconds")
        found[f"row {row['scenario']} {row['seed']}"] = hashlib.sha256(json.dumps(row, sort_keys=True).encode()).hexdigest()
    return found


def timed(executor: list[str], tasks: int) -> tuple[float, dict, int]:
    work = Path(tempfile.mkdtemp(prefix="physc-bench-"))
    try:
        command = [sys.executable, "-m", "physc", "generate", *(str(PAPER / f"{s}.phys") for s in SCENARIOS),
                   "--tasks", str(tasks), "--out", str(work / "dataset"), "-q", *executor]
        started = time.perf_counter()
        subprocess.run(command, check=True)
        seconds = time.perf_counter() - started
        made = sum(1 for line in (work / "dataset" / "manifest.jsonl").read_text().splitlines())
        return seconds, fingerprint(work / "dataset"), made
    finally:
        shutil.rmtree(work, ignore_errors=True)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", type=int, default=12, help="seeds per scenario")
    parser.add_argument("--repeat", type=int, default=2)
    args = parser.parse_args()
    print(f"python {platform.python_version()}, {platform.machine()}; {len(SCENARIOS)} scenarios x {args.tasks} tasks")
    runs = {"--jobs 1": ["--jobs", "1"], "--jobs 2": ["--jobs", "2"], "--dask-workers 1": ["--dask-workers", "1"], "--dask-workers 2": ["--dask-workers", "2"]}
    medians, prints = {}, []
    for _ in range(args.repeat):  # interleaved, so that a drift of the machine's speed hits every executor
        for name, options in runs.items():
            seconds, made_print, made = timed(options, args.tasks)
            medians.setdefault(name, []).append(seconds)
            prints.append((name, made_print))
    total = len(SCENARIOS) * args.tasks
    for name, times in medians.items():
        median = statistics.median(times)
        print(f"{name:<18} median {median:7.1f} s ({', '.join(f'{t:.1f}' for t in times)})   {3600 * total / median:7.0f} tasks/hour")
    m = {name: statistics.median(times) for name, times in medians.items()}
    print(f"speed-up, 2 Dask workers over 1: {m['--dask-workers 1'] / m['--dask-workers 2']:.2f} (target >= 1.8)")
    print(f"Dask overhead against local processes: 1 worker {100 * (m['--dask-workers 1'] / m['--jobs 1'] - 1):+.1f} %, "
          f"2 workers {100 * (m['--dask-workers 2'] / m['--jobs 2'] - 1):+.1f} % (target <= 5 %)")
    first_name, first = prints[0]
    differing = {key for _, other in prints[1:] for key in first.keys() | other.keys() if first.get(key) != other.get(key)}
    print(f"the same dataset in every run: {not differing}" + (f"; differing: {', '.join(sorted(differing)[:10])}" if differing else ""))


if __name__ == "__main__":
    main()
