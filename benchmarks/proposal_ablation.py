"""What the proposal model changes: the same compiles with it and without it (every layout's
chance the same, so the layouts are tried in the order placed, as before the model).

    python benchmarks/proposal_ablation.py --world rolling --seconds 60 --seeds 0 1 --jobs 2 FILE.phys...

For each scenario and seed, both ways: whether a task came, in how many seconds, the placed
layouts, and the share of them that never realised the chain (the funnel's `never`). Prints a
Markdown table and the totals.
"""

from __future__ import annotations

import argparse
import multiprocessing
import time

from physc.compiler.infeasible import Infeasible
from physc.driver import ranking


def one(job: tuple[str, str | None, int, float, bool]) -> dict:
    path, world, seed, seconds, learned = job
    from physc.api.compiling import pipeline, selected
    from physc.domains import bound, load_domain
    from physc.driver.run_settings import RunSettings

    if not learned:  # every layout's chance the same: the order placed
        ranking.LinkModel.chance = lambda self, links: 0.5  # type: ignore[method-assign]
    scenario_ast, ir, _ = selected(path, None)
    domain = bound(load_domain(ir.domain), world, None)
    run = pipeline(scenario_ast, ir, domain, seed, RunSettings(time_budget=seconds, validate=False))
    started = time.perf_counter()
    try:
        with run.within_budget("task"):
            task = run.task
        made, funnel = True, task.funnel
    except Infeasible as error:
        made, funnel = False, error.funnel
    return {
        "scenario": ir.name,
        "seed": seed,
        "learned": learned,
        "made": made,
        "seconds": time.perf_counter() - started,
        "placed": funnel["placed"] if funnel else 0,
        "never": 1 - funnel["chain_realised"] / funnel["placed"] if funnel and funnel["placed"] else None,
    }


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--world", default=None)
    parser.add_argument("--seconds", type=float, default=60)
    parser.add_argument("--seeds", type=int, nargs="+", default=[0])
    parser.add_argument("--jobs", type=int, default=1)
    args = parser.parse_args()
    jobs = [
        (path, args.world, seed, args.seconds, learned)
        for path in args.files
        for seed in args.seeds
        for learned in (True, False)
    ]
    with multiprocessing.get_context("spawn").Pool(
        args.jobs, maxtasksperchild=1
    ) as pool:  # (a patched process is not reused)
        rows = pool.map(one, jobs, chunksize=1)
    print("| scenario | seed | model | task | seconds | placed layouts | never realised the chain |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        never = "–" if r["never"] is None else f"{100 * r['never']:.0f} %"
        model = "learned" if r["learned"] else "order placed"
        cells = [r["scenario"], str(r["seed"]), model, "yes" if r["made"] else "no", f"{r['seconds']:.1f}"]
        print("| " + " | ".join([*cells, str(r["placed"]), never]) + " |")
    for learned in (True, False):
        mine = [r for r in rows if r["learned"] == learned]
        placed = sum(r["placed"] for r in mine)
        never = sum(r["placed"] * (r["never"] or 0) for r in mine)
        print(
            f"\n{'learned' if learned else 'order placed'}: {sum(r['made'] for r in mine)} of {len(mine)} tasks; "
            f"{placed} placed layouts, {100 * never / max(placed, 1):.1f} % never realised the chain"
        )


if __name__ == "__main__":
    main()
