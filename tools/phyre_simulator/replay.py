"""Replay every task of a physc PHYRE dataset in PHYRE's own simulator.

    python tools/phyre_simulator/replay.py DATASET_DIR [--phyre BUILD] [--out DIR]

DATASET_DIR is what `physc generate` wrote (its `phyre/` folder: tasks50.bin.lzma and
tasks.parquet). The tasks are read by PHYRE's own loader (`phyre.loader.load_compiled_task_dict`,
with PHYRE's task folder, `phyre.settings.TASK_DIR`, pointed at DATASET_DIR/phyre), so the check
covers physc's Thrift files as much as its physics. Each task's intended action (tasks.parquet's
`action`, which the Thrift tasks do not carry) is simulated by PHYRE's `ActionSimulator` in the
task's tier (BALL: `ball`, TWO_BALLS: `two_balls`), once plainly (SOLVED / NOT_SOLVED /
INVALID_INPUT) and once with `stable=True` (STABLY_SOLVED / UNSTABLY_SOLVED: PHYRE's 8 neighbours
of the action, half a pixel away, all solve it or are invalid). A task that the intended action
does not solve also gets PHYRE's step-by-step record (the first step the goal holds, its longest
run; PHYRE needs 180 steps in a row) to say what happened.

If DATASET_DIR/phyre/cache/ holds PHYRE simulation caches (`simulation_cache.gz`, in the folder
or in one folder per tier), each is loaded with PHYRE's `SimulationCache` and its statuses for the
first --cache-actions actions are compared with PHYRE's simulator.

PHYRE must be importable: `--phyre BUILD` puts BUILD/python (or BUILD, if it holds `phyre/`) on
the path first (PHYRE's wheels stop at Python 3.9, so on newer Pythons it is built from PHYRE's
sources; see README.md here).

Writes OUT/replay.csv (one row per task), OUT/replay.json (the same, with the summary) and
OUT/replay.md (the summary); OUT defaults to DATASET_DIR/phyre-replay. Prints the summary.
Exit status: 0 done (whatever the agreement), 2 bad input (no dataset, no PHYRE).
"""

from __future__ import annotations

import argparse
import csv
import datetime
import json
import pathlib
import sys

TIERS = {"BALL": "ball", "TWO_BALLS": "two_balls"}  # physc's task tier -> PHYRE's action tier
CACHE_FILE = "simulation_cache.gz"  # phyre.simulation_cache.CACHE_FILE_NAME
SOLUTION_STEPS = 180  # PHYRE's kStepsForSolution (task_utils.h): 3 s at 60 steps a second


class BadInput(Exception):
    """A problem with what the user gave: reported in one line, exit status 2."""


def import_phyre(build: str | None):
    """PHYRE's package, from `build` when given (BUILD/python or BUILD itself)."""
    if build is not None:
        root = pathlib.Path(build).expanduser()
        candidates = [root / "python", root]
        found = [c for c in candidates if (c / "phyre" / "__init__.py").is_file()]
        if not found:
            raise BadInput(f"--phyre {build}: no phyre package in {root}/python or {root}")
        sys.path.insert(0, str(found[0]))
    try:
        import phyre
        import phyre.loader  # noqa: F401
        import phyre.settings  # noqa: F401
        import phyre.simulator  # noqa: F401
    except ImportError as error:
        raise BadInput(
            f"PHYRE cannot be imported ({error}); build it from PHYRE's sources and pass --phyre BUILD (see tools/phyre_simulator/README.md)"
        ) from None
    return phyre


def read_rows(folder: pathlib.Path) -> list[dict]:
    """tasks.parquet's rows: task_id, tier, action, scenario, seed, task (physc's task file)."""
    path = folder / "tasks.parquet"
    if not path.is_file():
        raise BadInput(f"{path}: no such file (is {folder.parent} a dataset written by `physc generate` for PHYRE?)")
    import pyarrow.parquet as pq

    table = pq.read_table(path)
    missing = {"task_id", "tier", "action"} - set(table.column_names)
    if missing:
        raise BadInput(f"{path}: no column {', '.join(sorted(missing))}")
    keep = [c for c in ("task_id", "tier", "action", "scenario", "seed", "task") if c in table.column_names]
    return table.select(keep).to_pylist()


def load_tasks(phyre, folder: pathlib.Path, task_ids: list[str]) -> dict:
    """The tasks, read by PHYRE's own loader from `folder` (phyre.settings.TASK_DIR)."""
    if not any(folder.glob("tasks*.bin.lzma")):
        raise BadInput(f"{folder}: no tasks*.bin.lzma (PHYRE's task files)")
    phyre.settings.TASK_DIR = folder
    try:
        return phyre.loader.load_compiled_task_dict(task_ids)
    except (RuntimeError, OSError, EOFError) as error:
        raise BadInput(f"{folder}: PHYRE's loader could not read the tasks: {error}") from None


def goal_steps(phyre, task, tier: str, action) -> dict:
    """PHYRE's step-by-step record of one action: the first step at which the goal holds, its
    longest run of steps, the steps simulated (stride 1; PHYRE's debugging path)."""
    import phyre.action_mappers

    mapper = phyre.action_mappers.get_action_mapper(tier)
    user_input, valid = mapper.action_to_user_input(action)
    if not valid:
        return {}
    simulation = phyre.simulator.simulate_task_with_input(
        task, user_input, stride=1, keep_space_around_bodies=mapper.KEEP_SPACE_AROUND_BODIES
    )
    states = list(simulation.solvedStateList or ())
    first = next((i for i, s in enumerate(states) if s), None)
    longest = run = 0
    for state in states:
        run = run + 1 if state else 0
        longest = max(longest, run)
    return {"phyre_goal_first_step": first, "phyre_goal_longest_run": longest, "phyre_steps": simulation.stepsSimulated}


def replay(phyre, tasks: dict, rows: list[dict]) -> list[dict]:
    """One result per row: PHYRE's status for the intended action, plain and stable."""
    import numpy as np

    results = []
    for tier in sorted({row["tier"] for row in rows}):
        mine = [row for row in rows if row["tier"] == tier]
        if tier not in TIERS:
            results += [dict(_base(row), status="UNKNOWN_TIER", stable_status="UNKNOWN_TIER") for row in mine]
            continue
        simulator = phyre.ActionSimulator([tasks[row["task_id"]] for row in mine], TIERS[tier])
        for index, row in enumerate(mine):
            result = _base(row)
            thrift_tier = tasks[row["task_id"]].tier
            if thrift_tier != tier:
                result["note"] = f"tasks.parquet says {tier}, the Thrift task {thrift_tier}"
            action = row["action"]
            if action is None:
                results.append(dict(result, status="NO_ACTION", stable_status="NO_ACTION"))
                continue
            action = np.array(action, dtype=float)
            plain = simulator.simulate_action(index, action, need_images=False).status
            stable = simulator.simulate_action(index, action, need_images=False, stable=True).status
            result.update(status=plain.name, stable_status=stable.name)
            if not plain.is_solved():
                result.update(goal_steps(phyre, tasks[row["task_id"]], TIERS[tier], action))
            results.append(result)
    return sorted(results, key=lambda r: r["task_id"])


def _base(row: dict) -> dict:
    return {
        "task_id": row["task_id"],
        "tier": row["tier"],
        "scenario": row.get("scenario"),
        "seed": row.get("seed"),
        "task_file": row.get("task"),
        "action": None if row["action"] is None else [round(float(v), 6) for v in row["action"]],
    }


def check_caches(phyre, folder: pathlib.Path, tasks: dict, rows: list[dict], n_actions: int) -> list[dict]:
    """Each PHYRE simulation cache under folder/cache, read by PHYRE's SimulationCache: do its
    statuses for the first n_actions actions agree with PHYRE's simulator (plain, not stable)?"""
    from phyre.simulation_cache import SimulationCache

    root = folder / "cache"
    if not root.is_dir():
        return []
    reports = []
    for path in sorted(root.rglob(CACHE_FILE)):
        report = {"cache": str(path.parent)}
        try:
            cache = SimulationCache(path.parent)
        except Exception as error:  # a broken cache is a finding, not a crash
            reports.append(dict(report, error=f"{type(error).__name__}: {error}"))
            continue
        actions = cache.action_array[:n_actions]
        tier = {3: "ball", 6: "two_balls"}.get(actions.shape[1] if actions.ndim == 2 else -1)
        if tier is None:
            reports.append(dict(report, error=f"actions of shape {actions.shape}: neither ball (3) nor two_balls (6)"))
            continue
        physc_tier = {v: k for k, v in TIERS.items()}[tier]
        ids = sorted(t for t in cache.task_ids if t in tasks and any(r["task_id"] == t and r["tier"] == physc_tier for r in rows))
        report.update(tier=tier, actions=int(len(actions)), cache_tasks=len(cache.task_ids), tasks_checked=len(ids),
                      unknown_tasks=sorted(t for t in cache.task_ids if t not in tasks)[:10])
        simulator = phyre.ActionSimulator([tasks[t] for t in ids], tier)
        compared = differing = 0
        examples = []
        for index, task_id in enumerate(ids):
            stored = cache.load_simulation_states(task_id)[: len(actions)]
            for k, action in enumerate(actions):
                status = int(simulator.simulate_action(index, action, need_images=False).status)
                compared += 1
                if status != int(stored[k]):
                    differing += 1
                    if len(examples) < 10:
                        examples.append({"task_id": task_id, "action_index": k, "cache": int(stored[k]), "phyre": status})
        reports.append(dict(report, compared=compared, differing=differing, examples=examples))
    return reports


def summarize(results: list[dict]) -> dict:
    """Counts and shares: solved (plain), stably solved, per tier and in all."""
    def counts(rs):
        n = len(rs)
        solved = sum(r["status"] == "SOLVED" for r in rs)
        stable = sum(r["stable_status"] == "STABLY_SOLVED" for r in rs)
        return {"tasks": n, "solved": solved, "stably_solved": stable,
                "solved_share": solved / n if n else None, "stably_solved_share": stable / n if n else None,
                "statuses": _tally(r["status"] for r in rs), "stable_statuses": _tally(r["stable_status"] for r in rs)}

    out = {"all": counts(results)}
    for tier in sorted({r["tier"] for r in results}):
        out[tier] = counts([r for r in results if r["tier"] == tier])
    return out


def _tally(values) -> dict:
    out: dict = {}
    for v in values:
        out[v] = out.get(v, 0) + 1
    return dict(sorted(out.items()))


def markdown(dataset: pathlib.Path, phyre, summary: dict, results: list[dict], caches: list[dict]) -> str:
    """The summary as a markdown section."""
    def pct(x):
        return "–" if x is None else f"{100 * x:.1f} %"

    lines = [f"# PHYRE's own simulator on {dataset}", "",
             f"{datetime.date.today().isoformat()}; PHYRE from {pathlib.Path(phyre.__file__).parent}", "",
             "| tier | tasks | solved (plain) | stably solved | statuses (stable=True) |", "| --- | ---: | ---: | ---: | --- |"]
    for tier, c in summary.items():
        statuses = ", ".join(f"{k} {v}" for k, v in c["stable_statuses"].items())
        lines.append(f"| {tier} | {c['tasks']} | {c['solved']} ({pct(c['solved_share'])}) | {c['stably_solved']} ({pct(c['stably_solved_share'])}) | {statuses} |")
    misses = [r for r in results if r["status"] != "SOLVED" or r["stable_status"] != "STABLY_SOLVED" or r.get("note")]
    if misses:
        lines += ["", "Not solved stably by the intended action:", "",
                  "| task | scenario, seed | plain | stable | PHYRE: goal first holds at step, longest run | note |", "| --- | --- | --- | --- | --- | --- |"]
        for r in misses:
            steps = "" if "phyre_goal_longest_run" not in r else f"{r['phyre_goal_first_step']}, {r['phyre_goal_longest_run']} of {SOLUTION_STEPS} needed ({r['phyre_steps']} steps run)"
            lines.append(f"| {r['task_id']} | {r['scenario']} {r['seed']} | {r['status']} | {r['stable_status']} | {steps} | {r.get('note', '')} |")
    for c in caches:
        lines += ["", f"Simulation cache {c['cache']}: " + (c["error"] if "error" in c else
                  f"{c['tier']}, {c['tasks_checked']} of its {c['cache_tasks']} tasks checked on its first {c['actions']} actions: "
                  f"{c['compared'] - c['differing']} of {c['compared']} statuses agree with PHYRE's simulator")]
    return "\n".join(lines) + "\n"


def write(out: pathlib.Path, results: list[dict], summary: dict, caches: list[dict], text: str) -> None:
    out.mkdir(parents=True, exist_ok=True)
    fields = ["task_id", "tier", "scenario", "seed", "task_file", "action", "status", "stable_status",
              "phyre_goal_first_step", "phyre_goal_longest_run", "phyre_steps", "note"]
    with open(out / "replay.csv", "w", newline="") as stream:
        writer = csv.DictWriter(stream, fields, extrasaction="ignore")
        writer.writeheader()
        for r in results:
            writer.writerow(dict(r, action=" ".join(map(str, r["action"] or []))))
    (out / "replay.json").write_text(json.dumps({"summary": summary, "tasks": results, "caches": caches}, indent=1) + "\n")
    (out / "replay.md").write_text(text)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dataset", metavar="DATASET_DIR", help="a dataset written by `physc generate` (with phyre/)")
    parser.add_argument("--phyre", metavar="BUILD", help="PHYRE's build folder (BUILD/python holds the phyre package)")
    parser.add_argument("--out", metavar="DIR", help="where the results go (default DATASET_DIR/phyre-replay)")
    parser.add_argument("--cache-actions", type=int, default=200, metavar="N", help="actions of each simulation cache to check (default 200)")
    args = parser.parse_args(argv)
    try:
        dataset = pathlib.Path(args.dataset)
        if not dataset.is_dir():
            raise BadInput(f"{dataset}: no such folder")
        folder = dataset / "phyre"
        if not folder.is_dir():
            raise BadInput(f"{folder}: no such folder (is {dataset} a dataset written by `physc generate` for PHYRE?)")
        rows = read_rows(folder)
        if not rows:
            raise BadInput(f"{folder / 'tasks.parquet'}: no tasks")
        phyre = import_phyre(args.phyre)
        tasks = load_tasks(phyre, folder, [row["task_id"] for row in rows])
    except BadInput as error:
        print(f"replay: {error}", file=sys.stderr)
        return 2
    results = replay(phyre, tasks, rows)
    caches = check_caches(phyre, folder, tasks, rows, args.cache_actions)
    summary = summarize(results)
    text = markdown(dataset, phyre, summary, results, caches)
    out = pathlib.Path(args.out) if args.out else dataset / "phyre-replay"
    write(out, results, summary, caches, text)
    print(text, end="")
    print(f"replay: wrote {out / 'replay.csv'}, replay.json, replay.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
