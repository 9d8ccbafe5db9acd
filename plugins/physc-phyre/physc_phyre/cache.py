"""`python -m physc_phyre.cache DATASET`: PHYRE's simulation cache of a generated dataset's tasks.

Writes `DATASET/phyre/cache/offline_simulation/<N>/<tier>/simulation_cache.gz` for each action
tier the dataset has (`ball`, `two_balls`), in PHYRE's format (simulation_cache.py), so that
PHYRE with `PHYRE_CACHE_DIR=DATASET/phyre/cache` finds it where its own cache would be.

physc has no way for a plugin to add a command, or for `physc generate` to pass a domain an
option, so this is a module of the plugin. The simulations run where physc's own jobs run
(`--jobs N` local processes, `--scheduler`/`--dask-workers` a Dask cluster: physc.execution),
in chunks of CHUNK actions of one task; only this process writes, each file whole
(physc.files.write_atomic), and the bytes do not depend on where or in what order the chunks ran.
Exit status: 0 written, 2 usage (a bad option, a dataset without PHYRE's files, an unreadable
task file, an output that cannot be written), 130 interrupted, 70 a bug.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from physc_phyre import simulation_cache

DEFAULT_ACTIONS = 1_000  # enough for PHYRE's random agent (100 valid attempts a task); README
MAX_ACTIONS = 100_000  # PHYRE's own cache (DEFAULT_NUM_ACTIONS); any smaller one is its prefix
CHUNK = 250  # actions of one task per job: about a second of simulation
PROG = "python -m physc_phyre.cache"


def _actions(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if not 1 <= value <= MAX_ACTIONS:
        raise argparse.ArgumentTypeError(
            f"expected a whole number from 1 to {MAX_ACTIONS} (PHYRE's cache holds {MAX_ACTIONS}), got {text!r}"
        )
    return value


def parser() -> argparse.ArgumentParser:
    from physc.commands.common import Parser
    from physc.commands.running import add_executor

    made = Parser(
        prog=PROG,
        description="PHYRE's simulation cache (simulation_cache.gz) of the tasks of a dataset physc generate wrote",
    )
    made.add_argument("dataset", metavar="DATASET", help="a dataset of PHYRE-like tasks (physc generate --out)")
    made.add_argument(
        "--actions",
        type=_actions,
        default=DEFAULT_ACTIONS,
        metavar="N",
        help=f"actions per task: the first N of PHYRE's pool of seed 42 (default {DEFAULT_ACTIONS}; PHYRE's own "
        f"cache: {MAX_ACTIONS})",
    )
    add_executor(made)
    made.add_argument("-q", "--quiet", action="store_true", help="no progress lines")
    return made


def tasks_of(dataset: Path) -> dict[str, list[tuple[str, str]]]:
    """(task id, task file) of each task of the dataset, by PHYRE's action tier, in id order;
    every task file is read here, so that a bad one stops the run before any work."""
    import pyarrow.parquet as pq

    from physc.commands.common import UsageError

    table = dataset / "phyre" / "tasks.parquet"
    if not table.is_file():
        raise UsageError(
            f"{dataset} has no phyre/tasks.parquet: is it a dataset physc generate wrote from PHYRE-like scenarios?"
        )
    try:
        rows = pq.read_table(table, columns=["task_id", "task", "tier"]).to_pylist()
    except Exception as error:  # pyarrow's errors for a damaged or foreign file have no common base
        raise UsageError(f"cannot read {table}: {error}") from None
    if not rows:
        raise UsageError(f"{table} lists no tasks")
    tiers: dict[str, list[tuple[str, str]]] = {}
    for row in sorted(rows, key=lambda r: r["task_id"]):
        if row["tier"] not in simulation_cache.TIERS:
            raise UsageError(
                f"{table}: task {row['task_id']} is of the tier {row['tier']!r}, which PHYRE's cache does not hold"
            )
        path = str(dataset / row["task"])
        try:
            simulation_cache.task_level(path)
        except ValueError as error:
            raise UsageError(str(error)) from None
        tiers.setdefault(simulation_cache.TIERS[row["tier"]], []).append((row["task_id"], path))
    return tiers


def chunks(tasks: list[tuple[str, str]], actions: np.ndarray) -> list[simulation_cache.Chunk]:
    return [
        simulation_cache.Chunk(task_id, path, start, actions[start : start + CHUNK])
        for task_id, path in tasks
        for start in range(0, len(actions), CHUNK)
    ]


def build(dataset: Path, tiers: dict[str, list[tuple[str, str]]], count: int, executor, say) -> list[Path]:
    """Simulate `count` actions on the tasks of each tier (tasks_of) and write each tier's
    cache; the files written."""
    from physc.budget import interruptible
    from physc.commands.common import plural
    from physc.files import ensure_folder, write_atomic

    pools = {tier: simulation_cache.pool(tier, count) for tier in tiers}
    jobs = [chunk for tier, tasks in tiers.items() for chunk in chunks(tasks, pools[tier])]
    statuses = {task_id: np.zeros(count, np.int8) for tasks in tiers.values() for task_id, _ in tasks}
    waiting = {task_id: -(-count // CHUNK) for task_id in statuses}
    total, done, started = len(statuses), 0, time.monotonic()
    say(f"{plural(total, 'task')} × {plural(count, 'action')} on {executor.describe()}")

    def keep(result) -> None:
        nonlocal done
        task_id, start, data = result
        statuses[task_id][start : start + len(data)] = np.frombuffer(data, np.int8)
        waiting[task_id] -= 1
        if not waiting[task_id]:
            done += 1
            say(f"{done}/{total} tasks, {time.monotonic() - started:.0f} s: {task_id}")

    with interruptible():  # Ctrl-C stops the run between simulations, not inside one
        executor.map(simulation_cache.simulate, jobs, keep)
    written = []
    for tier, tasks in tiers.items():
        folder = ensure_folder(simulation_cache.cache_folder(dataset / "phyre" / "cache", count, tier))
        write_atomic(
            folder / simulation_cache.FILE_NAME,
            simulation_cache.cache_bytes(pools[tier], {t: statuses[t] for t, _ in tasks}),
        )
        written.append(folder / simulation_cache.FILE_NAME)
    return written


def main(argv: list[str] | None = None) -> int:
    from physc.budget import stopped
    from physc.commands.common import EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_OK, EXIT_USAGE, UsageError
    from physc.commands.running import executor_from
    from physc.diagnostics import safe
    from physc.execution import ExecutorError
    from physc.files import OutputError

    args = parser().parse_args(argv)

    def say(line: str) -> None:
        if not args.quiet:
            print(f"cache: {line}", file=sys.stderr, flush=True)

    try:
        dataset = Path(args.dataset)
        if not dataset.is_dir():
            raise UsageError(f"no dataset folder {args.dataset}")
        tiers = tasks_of(dataset)
        with executor_from(args) as executor:
            written = build(dataset, tiers, args.actions, executor, say)
    except (UsageError, OutputError, ExecutorError) as error:
        print(f"{PROG}: error: {safe(str(error))}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        stopped()
        print(f"{PROG}: interrupted", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Exception as error:  # a bug: said in one line, never a bare traceback
        print(f"{PROG}: internal error: {type(error).__name__}: {safe(str(error))}", file=sys.stderr)
        return EXIT_INTERNAL
    for path in written:
        say(f"wrote {path}")
    say(
        f"PHYRE reads it with PHYRE_CACHE_DIR={dataset / 'phyre' / 'cache'}: "
        f"phyre.SimulationCache(phyre.simulation_cache.get_cache_folder({args.actions}) / tier)"
    )
    return EXIT_OK


if __name__ == "__main__":
    sys.exit(main())
