"""Layout outcomes: how many layouts a task costs, and why the others were given up.

    python benchmarks/layout_outcomes.py [--seeds 10] [--scenarios SRF,SFR,RRF] [--time-budget 120]

For every scenario and seed 0..N-1, `physc compile` end to end (validated), on one core,
as `benchmarks/generation.py` runs it. Prints, per scenario, the layouts tried per generated
task (median, mean), the simulations per task, and, summed over the generated tasks, the
share of the layouts and of the simulations that went to layouts given up for each reason
(the task's `given_up`) and to the layout used. Failed seeds are counted apart (their
reasons are in their E0802 message, not in a task). Last, over every seed (failed ones
included), where the layouts given up because the sequence was not realised stopped: how
many of them got k interactions of the chain, in order, in their best simulation (the
interaction after those k is where the chain broke).
"""

from __future__ import annotations

import argparse
import platform
import statistics
from pathlib import Path

from physc.compiler.infeasible import Infeasible
from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.driver.pipeline import Pipeline
from physc.driver.run_settings import RunSettings
from physc.dsl.frontend import analyze
from physc.search import search
from physc.search.settings import NOT_REALISED

PAPER = Path(__file__).resolve().parents[1] / "examples" / "paper" / "all.paper.phys"
USED = "(the layout used, fallbacks' second tries included)"


class Watched:
    """Every layout's outcome, noted while the search runs: (why it was given up, how many
    interactions its best simulation realised in order). The layout loop calls
    `search.satisfy`; while watching, that is this recorder around it."""

    def __init__(self):
        self.outcomes: list[tuple[str, int]] = []
        self.satisfy = search.satisfy

    def __enter__(self):
        def recorded(*args, **kwargs):
            result = self.satisfy(*args, **kwargs)
            self.outcomes.append(("" if result.satisfied else result.given_up, result.best))
            return result

        search.satisfy = recorded
        return self

    def __exit__(self, *exc):
        search.satisfy = self.satisfy


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=10)
    parser.add_argument("--scenarios", default="SRF,SFR,RRF")
    parser.add_argument("--time-budget", type=float, default=120.0)
    args = parser.parse_args()
    domain = load_domain("angrybirds")
    wanted = args.scenarios.split(",")
    scenarios = {s.name: s for s in analyze(str(PAPER), INSTALLED).scenarios}
    print(f"machine: {platform.machine()}, Python {platform.python_version()}; seeds 0-{args.seeds - 1}; time budget {args.time_budget:g} s")
    for name in wanted:
        scenario = scenarios[name]
        layouts, simulations, failed = [], [], 0
        by_reason: dict[str, list[int]] = {}  # reason → [layouts, simulations]
        with Watched() as watched:
            tasks = [_task(domain, scenario, seed, args.time_budget) for seed in range(args.seeds)]
        for task in tasks:
            if task is None:
                failed += 1
                continue
            layouts.append(task.layouts_tried)
            simulations.append(task.simulations)
            spent = 0
            for why, counts in task.given_up.items():
                entry = by_reason.setdefault(why, [0, 0])
                entry[0] += counts["layouts"]
                entry[1] += counts["simulations"]
                spent += counts["simulations"]
            used = by_reason.setdefault(USED, [0, 0])
            used[0] += 1
            used[1] += task.simulations - spent
        stopped = [best for why, best in watched.outcomes if why == NOT_REALISED]
        if not layouts:
            print(f"\n{name}: no task in {args.seeds} seeds")
            _chain_breaks(scenario, stopped)
            continue
        print(
            f"\n{name} ({len(scenario.interactions)} interactions): {len(layouts)} of {args.seeds} seeds generated"
            f"{f', {failed} failed' if failed else ''}; layouts per task median {statistics.median(layouts):g}, "
            f"mean {statistics.mean(layouts):.1f}; simulations per task median {statistics.median(simulations):g}, "
            f"mean {statistics.mean(simulations):.0f}"
        )
        total_layouts = sum(entry[0] for entry in by_reason.values())
        total_simulations = sum(entry[1] for entry in by_reason.values())
        for why, (n, sims) in sorted(by_reason.items(), key=lambda item: -item[1][1]):
            print(f"  {100 * n / total_layouts:5.1f} % of layouts, {100 * sims / total_simulations:5.1f} % of simulations: {why}", flush=True)
        _chain_breaks(scenario, stopped)


def _task(domain, scenario, seed: int, time_budget: float):
    """The task of one seed, or None where it gives none."""
    try:
        return Pipeline(domain, scenario, seed, RunSettings(time_budget=time_budget)).task
    except Infeasible:
        return None


def _chain_breaks(scenario, stopped: list[int]) -> None:
    """Where the layouts whose sequence was never realised broke the chain."""
    if not stopped:
        return
    print(f"  {len(stopped)} layouts given up as not realised, by the interactions their best simulation realised:")
    for k in range(len(scenario.interactions)):
        n = stopped.count(k)
        if n:
            print(f"    {k} then not `{scenario.interactions[k].text}`: {n} ({100 * n / len(stopped):.0f} %)", flush=True)


if __name__ == "__main__":
    main()
