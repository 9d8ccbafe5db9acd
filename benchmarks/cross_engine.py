"""Tasks generated in one engine, replayed in another: does the solution still work?

    python benchmarks/cross_engine.py RESULTS_DIR [--backend bullet] [--replays N] [--out FILE.jsonl]

RESULTS_DIR is a `physc eval` output folder: its records.jsonl holds every generated task's
level and solution. Each is replayed in `--backend` with `physc verify`'s own function
(physc.search.verify): once as recorded and `--replays` times under the evaluation's
noise. The table says, per interaction count and per scenario, the share that the replay
solves and the share whose declared sequence it realises, and how long one exact replay
takes (median, this machine, one core).
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from collections import defaultdict
from pathlib import Path

from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze
from physc.files import write_atomic
from physc.search.verify import verify
from physc.serialize import from_data


def replayed(records: list[dict], backend: str, replays: int):
    """(record, verification, seconds of the exact replay) per generated task."""
    scenarios: dict = {}
    for record in records:
        if not record.get("generated"):
            continue
        key = (record["file"], record["scenario"])
        if key not in scenarios:
            scenarios[key] = next(s for s in analyze(record["file"], INSTALLED).scenarios if s.name == record["scenario"])
        scenario = scenarios[key]
        domain = load_domain(scenario.domain)
        level = from_data(record["level"], {cls.__name__: cls for cls in domain.files.level_classes})
        kind = domain.files.solution_class
        solution = from_data(record["solution"], {kind.__name__: kind})
        started = time.perf_counter()
        check = verify(domain, scenario, level, solution, backend)
        seconds = time.perf_counter() - started
        if replays:
            check = verify(domain, scenario, level, solution, backend, noisy=replays)
        yield record, check, seconds


def table(rows: list, key: str, backend: str, replays: int) -> list[str]:
    groups = defaultdict(list)
    for record, check, seconds in rows:
        groups[record[key]].append((check, seconds))
    header = f"| {key} | tasks | solved in {backend} | sequence realised in {backend} |"
    header += " noisy replays realising it |" if replays else ""
    header += " exact replay, median s |"
    lines = [header, "|---" * (header.count("|") - 1) + "|"]
    for name in sorted(groups, key=lambda n: (str(type(n)), n)):
        checks = groups[name]
        n = len(checks)
        cells = [str(name), str(n), f"{sum(c.solved for c, _ in checks) / n:.2f}", f"{sum(c.realised for c, _ in checks) / n:.2f}"]
        if replays:
            cells.append(f"{sum(c.noisy_passed for c, _ in checks) / (n * replays):.2f}")
        cells.append(f"{statistics.median(s for _, s in checks):.3f}")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("results", type=Path)
    parser.add_argument("--backend", default="bullet")
    parser.add_argument("--replays", type=int, default=0)
    parser.add_argument("--out", type=Path, help="also write each task's verification as JSON Lines")
    args = parser.parse_args()
    records = [json.loads(line) for line in (args.results / "records.jsonl").read_text().splitlines() if line.strip()]
    rows = list(replayed(records, args.backend, args.replays))
    total = len(rows)
    if not total:
        raise SystemExit(f"{args.results} holds no generated task")
    solved = sum(c.solved for _, c, _ in rows)
    realised = sum(c.realised for _, c, _ in rows)
    print(f"{total} tasks of {args.results} replayed in {args.backend}: solved {solved} ({solved / total:.1%}), "
          f"sequence realised {realised} ({realised / total:.1%})\n")
    print("\n".join(table(rows, "interactions", args.backend, args.replays)) + "\n")
    print("\n".join(table(rows, "scenario", args.backend, args.replays)))
    if args.out:
        lines = []
        for record, check, seconds in rows:
            line = {
                "scenario": record["scenario"], "seed": record["seed"], "solved": check.solved, "realised": check.realised,
                "noisy_passed": check.noisy_passed, "why": check.why, "trace": check.trace,
                "generated_trace": record.get("trace"), "seconds": round(seconds, 4),
            }
            lines.append(json.dumps(line) + "\n")
        write_atomic(args.out, "".join(lines))


if __name__ == "__main__":
    main()
