"""Generation: success rate and time per task for the paper's 16 scenarios (or another file's).

    python benchmarks/generation.py [--seeds 30] [--scenarios SF,R,...] [--time-budget 20] [--file F]

For every scenario and seed 0..N-1, `physc compile` end to end (validated), on one
core. Prints, per scenario and per interaction count (2, 4, 6, 8, as the paper
groups them), how many seeds gave a validated task and the median and
mean ± SD time per generated task (and the time spent on seeds that failed), the median
simulations per generated task, and
per interaction count where the time of the generated tasks went, stage by stage
(the task's own `seconds`: layout, satisfy, distract, validate).
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from pathlib import Path

from physc.compiler.infeasible import Infeasible
from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.driver.pipeline import Pipeline
from physc.driver.run_settings import RunSettings
from physc.dsl.frontend import analyze

PAPER = Path(__file__).resolve().parents[1] / "examples" / "paper" / "all.paper.phys"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=30)
    parser.add_argument("--scenarios", default="")
    parser.add_argument("--time-budget", type=float, default=20.0)
    parser.add_argument("--file", default=str(PAPER), help="the scenarios (default: the paper's 16; examples/beyond/all.beyond.phys: ours)")
    args = parser.parse_args()
    domain = load_domain("angrybirds")
    scenarios = analyze(args.file, INSTALLED).scenarios
    wanted = set(args.scenarios.split(",")) if args.scenarios else None
    by_count: dict[int, list[float]] = {}
    simulations_by_count: dict[int, list[int]] = {}
    stages_by_count: dict[int, dict[str, float]] = {}
    print(f"machine: {platform.machine()}, Python {platform.python_version()}; seeds 0-{args.seeds - 1}; time budget {args.time_budget:g} s")
    print(f"{'scenario':<8} {'n':>2} {'generated':>10} {'median s':>9} {'mean±sd s':>12} {'failed s':>9} {'sims':>6}")
    for scenario in scenarios:
        if wanted and scenario.name not in wanted:
            continue
        count = len(scenario.interactions)
        ok, failed, simulations = [], [], []
        for seed in range(args.seeds):
            start = time.perf_counter()
            try:
                task = Pipeline(domain, scenario, seed, RunSettings(time_budget=args.time_budget)).task
                ok.append(time.perf_counter() - start)
                simulations.append(task.simulations)
                stages = stages_by_count.setdefault(count, {})
                for stage, spent in task.seconds.items():
                    stages[stage] = stages.get(stage, 0.0) + spent
            except Infeasible:
                failed.append(time.perf_counter() - start)
        by_count.setdefault(count, []).extend(ok)
        simulations_by_count.setdefault(count, []).extend(simulations)
        median = f"{statistics.median(ok):.2f}" if ok else "-"
        spread = f"{statistics.mean(ok):.2f}±{statistics.pstdev(ok):.2f}" if ok else "-"
        lost = f"{statistics.median(failed):.1f}" if failed else "-"
        sims = f"{statistics.median(simulations):.0f}" if simulations else "-"
        print(f"{scenario.name:<8} {count:>2} {len(ok):>4}/{args.seeds:<5} {median:>9} {spread:>12} {lost:>9} {sims:>6}", flush=True)
    print()
    for count, times in sorted(by_count.items()):
        if times:
            print(
                f"{count} interactions: median {statistics.median(times):.2f} s, mean {statistics.mean(times):.2f}±{statistics.pstdev(times):.2f} s over {len(times)} tasks; "
                f"median {statistics.median(simulations_by_count[count]):.0f} simulations a task"
            )
            stages = stages_by_count[count]
            shares = ", ".join(f"{stage} {100 * spent / stages['total']:.1f} %" for stage, spent in stages.items() if stage != "total")
            print(f"  where the time went: {shares}")


if __name__ == "__main__":
    main()
