"""How closely a local build of PHYRE's simulator reproduces PHYRE's own published simulations.

    python tools/phyre_simulator/selfcheck.py [--phyre BUILD] [--templates 00000,00001,...]
        [--tiers ball,two_balls] [--tasks 20]

PHYRE ships, with its tasks, the evaluation its official build made of each template
(`phyre/data/evaluations/TTTTT.lzma`: per task and tier, up to 5 actions that solved it stably and
5 that solved it but not stably). This plays each recorded action on its task with
`simulate_action(..., stable=True)` and counts how often the status is the recorded one
(STABLY_SOLVED, UNSTABLY_SOLVED). It is the yardstick for replay.py: a build that differs from
PHYRE's on k % of these near-boundary actions can be expected to differ from physc on as many.
Exit status 0 when it ran, 2 when PHYRE is not importable or a template has no evaluation.
"""

from __future__ import annotations

import argparse
import collections
import sys

from replay import BadInput, import_phyre

EXPECTED = {"solutions": "STABLY_SOLVED", "unstable_solutions": "UNSTABLY_SOLVED"}


def check(phyre, templates: list[str], tiers: list[str], per_template: int):
    """(counts by (tier, recorded kind, status), the actions whose status differs)."""
    import joblib
    import numpy as np
    import phyre.loader
    import phyre.settings

    tasks = phyre.loader.load_compiled_task_dict()
    counts: collections.Counter = collections.Counter()
    differing = []
    for template in templates:
        path = phyre.settings.TASK_EVAL_DIR / f"{template}.lzma"
        if not path.is_file():
            raise BadInput(f"{path}: PHYRE has no evaluation of template {template}")
        stats = joblib.load(path)["eval_stats"]
        ids = sorted(set(stats) & set(tasks))[:per_template]
        for tier in tiers:
            simulator = phyre.ActionSimulator([tasks[i] for i in ids], tier)
            for index, task_id in enumerate(ids):
                for kind, expected in EXPECTED.items():
                    for action in stats[task_id][tier][kind]:
                        status = simulator.simulate_action(index, np.array(action), need_images=False, stable=True).status.name
                        counts[(tier, kind, status)] += 1
                        if status != expected:
                            differing.append((task_id, tier, kind, status))
    return counts, differing


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--phyre", metavar="BUILD", help="PHYRE's build folder (BUILD/python holds the phyre package)")
    parser.add_argument("--templates", default=",".join(f"{t:05d}" for t in range(25)), help="PHYRE templates (default its 25 ball-tier ones)")
    parser.add_argument("--tiers", default="ball,two_balls")
    parser.add_argument("--tasks", type=int, default=20, help="tasks per template (default 20)")
    args = parser.parse_args(argv)
    try:
        phyre = import_phyre(args.phyre)
        counts, differing = check(phyre, args.templates.split(","), args.tiers.split(","), args.tasks)
    except BadInput as error:
        print(f"selfcheck: {error}", file=sys.stderr)
        return 2
    for task_id, tier, kind, status in differing:
        print(f"differs: {task_id} {tier}: recorded {EXPECTED[kind]}, here {status}")
    for (tier, kind, status), n in sorted(counts.items()):
        print(f"{tier} {kind} (recorded {EXPECTED[kind]}): {status} {n}")
    total = sum(counts.values())
    unsolved = sum(n for (_, _, status), n in counts.items() if status in ("NOT_SOLVED", "INVALID_INPUT"))
    print(f"selfcheck: {total - len(differing)} of {total} recorded statuses reproduced "
          f"({100 * (total - len(differing)) / max(total, 1):.2f} %); {unsolved} recorded solutions not solved here")
    return 0


if __name__ == "__main__":
    sys.exit(main())
