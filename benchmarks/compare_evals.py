"""Two `physc eval` runs side by side, scenario by scenario, over the seeds both ran.

    python benchmarks/compare_evals.py BEFORE/results.csv AFTER/results.csv [--seeds N]

For each scenario in both: tasks generated (of the seeds compared), fallbacks among them, the
mean noisy intended solvability and sequence fidelity of the tasks, and the median simulations
and generation seconds of a generated task. Prints a Markdown table.
"""

from __future__ import annotations

import argparse
import csv
import statistics
from collections import defaultdict


def load(path: str, seeds: int | None) -> dict:
    out = defaultdict(dict)
    with open(path, newline="") as handle:
        for row in csv.DictReader(handle):
            seed = int(row["seed"])
            if seeds is None or seed < seeds:
                out[row["scenario"]][seed] = row
    return out


def summary(rows: list[dict]) -> str:
    made = [r for r in rows if r["generated"] == "True"]
    if not made:
        return f"0/{len(rows)}", "–", "–", "–"
    fallbacks = sum(1 for r in made if r.get("robustness", "6/6").split("/")[0] != r.get("robustness", "6/6").split("/")[1])
    noisy = statistics.mean(float(r["intended_noisy"]) for r in made if r["intended_noisy"])
    fidelity = statistics.mean(float(r["fidelity_noisy"]) for r in made if r["fidelity_noisy"])
    cost = f"{statistics.median(int(r['simulations']) for r in made):,.0f} / {statistics.median(float(r['generation_seconds']) for r in made):.1f} s"
    generated = f"{len(made)}/{len(rows)}" + (f" ({fallbacks} fb)" if fallbacks else "")
    return generated, f"{noisy:.2f} / {fidelity:.2f}", cost, ""


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--seeds", type=int, default=None, help="compare seeds 0..N-1 only")
    args = parser.parse_args()
    before, after = load(args.before, args.seeds), load(args.after, args.seeds)
    print("| scenario | generated before | after | noisy solvability / fidelity before | after | median simulations / seconds before | after |")
    print("|---|---|---|---|---|---|---|")
    for name in after:
        if name not in before:
            continue
        seeds = sorted(set(before[name]) & set(after[name]))
        b = summary([before[name][s] for s in seeds])
        a = summary([after[name][s] for s in seeds])
        print(f"| {name} | {b[0]} | {a[0]} | {b[1]} | {a[1]} | {b[2]} | {a[2]} |")


if __name__ == "__main__":
    main()
