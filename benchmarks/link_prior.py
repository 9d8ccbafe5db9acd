"""Make a world's prior for the proposal model (physc.driver.link_prior), by simulation.

    python benchmarks/link_prior.py --world rolling --seconds 30 --seed 1000 \
        --out physc/domains/angrybirds/priors/rolling.json examples/paper/*.phys examples/phyq/*.phys

For each scenario, a compile's search is run on its placed layouts in the order they are
placed (no ranking: the examples are not chosen by a model) for `--seconds`, and each layout
teaches its links' examples (physc.search.link_model.examples). The prior keeps them with its
provenance: the world, its recognition fingerprint, the scenarios, seed, seconds, physc's version,
the date and this command. Make it again whenever the world's recognition changes (the test
suite says when: tests/search/test_link_model.py). The held-out sets (examples/heldout,
examples/shots, examples/long, examples/phyre-heldout) are kept out of it.
"""

from __future__ import annotations

import argparse
import datetime
import multiprocessing
import sys
from pathlib import Path

from physc import __version__, budget
from physc.api.compiling import pipeline, scenarios, selected
from physc.domains import bound, load_domain
from physc.driver import link_prior
from physc.driver.layout_loop import LayoutLoop
from physc.driver.run_settings import RunSettings
from physc.search.link_model import examples


def collect(job: tuple[str, str, str | None, float, int]) -> list[tuple[str, tuple[float, ...], bool]]:
    """The examples of one scenario's placed layouts, searched for `seconds`."""
    path, name, world, seconds, seed = job
    scenario_ast, ir, _ = selected(path, name)
    domain = bound(load_domain(ir.domain), world, None)
    run = pipeline(scenario_ast, ir, domain, seed, RunSettings(time_budget=seconds))
    loop = LayoutLoop(domain, ir, seed, run.settings)
    rows: list[tuple[str, tuple[float, ...], bool]] = []
    try:
        with budget.deadline(budget.Deadline(seconds)):
            for index, placed in enumerate(run.placements()):
                links = loop.links_of(placed)
                result = loop.satisfy(placed.layout, index=index)
                rows += examples(links, result.best)
    except (budget.OutOfTime, Exception) as error:  # a scenario that cannot be placed teaches nothing more
        if not isinstance(error, budget.OutOfTime):
            print(f"{name}: {type(error).__name__}: {error}"[:200], file=sys.stderr)
    print(f"{name}: {len(rows)} examples", file=sys.stderr)
    return rows


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--world", required=True)
    parser.add_argument("--seconds", type=float, default=30)
    parser.add_argument("--seed", type=int, default=1000)
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--out", type=Path, required=True)
    args = parser.parse_args()
    jobs = [(path, name, args.world, args.seconds, args.seed) for path in args.files for name in scenarios(path)]
    with multiprocessing.get_context("forkserver").Pool(args.jobs) as pool:
        found = pool.map(collect, jobs, chunksize=1)
    rows = [row for rows in found for row in rows]
    domain = bound(load_domain(selected(jobs[0][0], jobs[0][1])[1].domain), args.world, None)
    provenance = {
        "scenarios": [f"{path}:{name}" for path, name, *_ in jobs],
        "seed": args.seed,
        "seconds": args.seconds,
        "physc": __version__,
        "made": datetime.date.today().isoformat(),
        "command": "python benchmarks/link_prior.py " + " ".join(sys.argv[1:]),
    }
    prior = link_prior.write(args.out, domain, rows, provenance)
    print(f"{args.out}: {prior.count} examples of {len(prior.examples)} kinds, fingerprint {prior.fingerprint}")


if __name__ == "__main__":
    main()
