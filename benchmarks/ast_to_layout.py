"""Middle-end speed: time from the syntax tree to a concrete layout, per paper scenario.

    python benchmarks/ast_to_layout.py [--seeds 50]

For each of the paper's 16 scenarios and each seed 0..N-1, the clock runs from the
parsed scenario (AST) through the static checks, infer-layout, to-qsr,
to-dimension-graphs and place. Prints the median and 90th percentile per scenario
and the median per interaction count, in milliseconds.
"""

from __future__ import annotations

import argparse
import platform
import statistics
import time
from pathlib import Path

from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.driver.pipeline import Pipeline
from physc.dsl import ast
from physc.dsl.check import check_file
from physc.dsl.parser import parse_text

PAPER = Path(__file__).resolve().parents[1] / "examples" / "paper" / "all.paper.phys"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seeds", type=int, default=50)
    args = parser.parse_args()
    parsed = parse_text(PAPER.read_text(encoding="utf-8"))
    domain = load_domain("angrybirds")
    Pipeline(domain, check_file(parsed.file, vocabularies=INSTALLED).scenarios[0], 0).placed  # warm up imports and caches
    by_count: dict[int, list[float]] = {}
    print(f"machine: {platform.machine()}, Python {platform.python_version()}; {args.seeds} seeds per scenario")
    print(f"{'scenario':<8} {'interactions':>12} {'median ms':>10} {'p90 ms':>8}")
    for scenario in parsed.file.scenarios:
        times = []
        for seed in range(args.seeds):
            start = time.perf_counter()
            (checked,) = check_file(ast.File((scenario,)), vocabularies=INSTALLED).scenarios
            Pipeline(domain, checked, seed).placed
            times.append((time.perf_counter() - start) * 1000)
        count = len(scenario.interactions)
        by_count.setdefault(count, []).extend(times)
        p90 = statistics.quantiles(times, n=10)[-1]
        print(f"{scenario.name.text:<8} {count:>12} {statistics.median(times):>10.2f} {p90:>8.2f}")
    print()
    for count, times in sorted(by_count.items()):
        print(f"{count} interactions: median {statistics.median(times):.2f} ms, max {max(times):.2f} ms")


if __name__ == "__main__":
    main()
