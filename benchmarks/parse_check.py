"""Front-end throughput: parse and check a generated file of many scenarios.

    python benchmarks/parse_check.py [--scenarios 10000] [--repeat 5] [--seed 0]

The file cycles through the paper's 16 scenarios, alternating block and paper
form, each copy renamed; a seeded shuffle decides the order. The time covers
parsing and the static checks of the whole file (reading from memory, one
process, one core). Prints the best and median rate of the repeats.
"""

from __future__ import annotations

import argparse
import platform
import random
import statistics
import time
from pathlib import Path

from physc.dsl.check import check_file
from physc.dsl.fmt import format_file
from physc.dsl.parser import parse_text

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "paper"


def generate(count: int, seed: int) -> str:
    paper_lines = [
        line for line in (EXAMPLES / "all.paper.phys").read_text(encoding="utf-8").splitlines()
        if line.startswith("scenario ")
    ]
    blocks = [format_file(parse_text(line).file) for line in paper_lines]
    rng = random.Random(seed)
    order = [rng.randrange(len(paper_lines)) for _ in range(count)]
    parts = []
    for index, which in enumerate(order):
        name = paper_lines[which].split()[1]
        text = paper_lines[which] if index % 2 else blocks[which]
        parts.append(text.replace(f"scenario {name} ", f"scenario {name}_{index} ", 1))
    return "\n".join(parts) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seed", type=int, default=0)
    args = parser.parse_args()
    text = generate(args.scenarios, args.seed)
    parse_text("scenario warm = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}")  # build the parser once
    times = []
    for _ in range(args.repeat):
        start = time.perf_counter()
        parsed = parse_text(text, "bench.phys")
        checked = check_file(parsed.file)
        times.append(time.perf_counter() - start)
        assert not parsed.diagnostics and not checked.diagnostics
        assert len(checked.scenarios) == args.scenarios
        del parsed, checked  # each round starts from the same heap
    lines = text.count("\n")
    print(f"machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}")
    print(f"input: {args.scenarios} scenarios, {lines} lines, {len(text) / 1e6:.2f} MB (seed {args.seed})")
    print(f"best:   {min(times):.3f} s = {args.scenarios / min(times):,.0f} scenarios/s")
    print(f"median: {statistics.median(times):.3f} s = {args.scenarios / statistics.median(times):,.0f} scenarios/s")


if __name__ == "__main__":
    main()
