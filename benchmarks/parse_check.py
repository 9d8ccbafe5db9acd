"""Front-end throughput: parse and check a generated file of many scenarios, or of one huge one.

    python benchmarks/parse_check.py [--scenarios 10000] [--repeat 5] [--seed 0]
    python benchmarks/parse_check.py --long-scenario 5 [--repeat 3] [--write long.phys]

The first file cycles through the paper's 16 scenarios, alternating block and paper
form, each copy renamed; a seeded shuffle decides the order. With `--long-scenario MB`
the file is one valid scenario of about MB megabytes: a chain of every interaction
term over distinct objects (roll, hit, fall, slide, bounce, then destroy at the end) and
restrictions on most of them; it shows whether the front end stays linear in the size of
one scenario. The time covers parsing and the static checks of the whole file (reading
from memory, one process, one core). Prints the best and median rate of the repeats.
"""

from __future__ import annotations

import argparse
import platform
import random
import statistics
import time
from pathlib import Path

from physc.domains.words import INSTALLED
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


def long_scenario(megabytes: float) -> tuple[str, int]:
    """One valid scenario of about `megabytes` MB in block form, and its number of interactions."""
    links = []
    restrictions = ["cannotHit(bird, pig, any)"]
    size, i = 0, 0
    while size < megabytes * 1e6:
        link = [
            f"roll(rBlock{i}, surface{i}, right)",
            f"hit(rBlock{i}, fBlock{i}, left)",
            f"fall(fBlock{i}, sBlock{i})",
            f"hit(fBlock{i}, sBlock{i}, above)",
            f"slide(sBlock{i}, hSurface{i}, right)",
            f"hit(sBlock{i}, rBlock{i + 1}, left)",
        ]
        held = [f"cannotFall(rBlock{i})", f"cannotHit(rBlock{i}, fBlock{i}, above | below)", f"cannotFall(sBlock{i})"]
        links += link
        restrictions += held
        size += sum(len(t) + 11 for t in link + held)
        i += 1
    terms = ["hit(bird, rBlock0, left)", *links, f"bounce(rBlock{i}, iSurface, below)", f"hit(rBlock{i}, pig, above)"]
    terms.append(f"destroy(rBlock{i}, pig)")
    body = "\n        > ".join(terms)
    held = "\n        ".join(restrictions)
    text = f"scenario Long {{\n    interactions {{\n        {body}\n    }}\n\n    restrictions {{\n        {held}\n    }}\n}}\n"
    return text, len(terms)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scenarios", type=int, default=10_000)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--long-scenario", type=float, metavar="MB", help="one scenario of about MB megabytes instead")
    parser.add_argument("--write", metavar="PATH", help="also write the input there (to time `physc check` on it)")
    args = parser.parse_args()
    if args.long_scenario:
        text, interactions = long_scenario(args.long_scenario)
        expected, unit, count = 1, "interactions", interactions
    else:
        text = generate(args.scenarios, args.seed)
        expected, unit, count = args.scenarios, "scenarios", args.scenarios
    if args.write:
        Path(args.write).write_text(text, encoding="utf-8")
    warm = parse_text("scenario warm = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}")  # build the parser once
    check_file(warm.file, vocabularies=INSTALLED)  # and load the vocabulary once
    times = []
    for _ in range(args.repeat):
        start = time.perf_counter()
        parsed = parse_text(text, "bench.phys")
        checked = check_file(parsed.file, vocabularies=INSTALLED)
        times.append(time.perf_counter() - start)
        assert not parsed.diagnostics and not checked.diagnostics, (parsed.diagnostics + checked.diagnostics)[:3]
        assert len(checked.scenarios) == expected
        del parsed, checked  # each round starts from the same heap
    lines = text.count("\n")
    print(f"machine: {platform.processor() or platform.machine()}, Python {platform.python_version()}")
    what = f"one scenario of {count} interactions" if args.long_scenario else f"{count} scenarios (seed {args.seed})"
    print(f"input: {what}, {lines} lines, {len(text) / 1e6:.2f} MB")
    print(f"best:   {min(times):.3f} s = {count / min(times):,.0f} {unit}/s")
    print(f"median: {statistics.median(times):.3f} s = {count / statistics.median(times):,.0f} {unit}/s")


if __name__ == "__main__":
    main()
