"""The run loop against the engine alone: steps a second on the same scenes, per domain.

For each task file (Angry Birds: the golden tasks; PHYRE-like: the plugin's test tasks; or
the files given), plays a set of actions three ways on one core and counts steps a second:

* **full**: the run as the search records it (physc.simulation.run.run: every state, contact
  and separation kept), recognition left out;
* **playout**: the outcome playout (physc.simulation.run.run_to_outcome), played to the end;
* **engine alone**: the same worlds, built the same way, stepped as many steps with the
  contact callbacks drained and nothing read: the physical limit here.

Angry Birds' actions are the task's shot and `--actions` − 1 noisy replays of it; PHYRE's, the
first `--actions` valid actions of PHYRE's acceptance pool. Checks on the way that each
playout says what its full run says (solved, steps).

    python benchmarks/run_loop.py [--actions 40] [TASK.json…]

Results: docs/performance.md ("The run loop against the engine alone").
"""

from __future__ import annotations

import argparse
import platform
import random
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = sorted((ROOT / "tests" / "golden" / "task").glob("*.json")) + sorted((ROOT / "plugins" / "physc-phyre" / "tests" / "data").glob("*.json"))


def actions(domain, task, count: int) -> list:
    if task.domain == "angrybirds":
        rng = random.Random(0)
        shot = domain.actions.action_of(task.solution)
        return [shot] + [domain.actions.noisy(task.level, shot, rng)[1] for _ in range(count - 1)]
    from physc_phyre.pool import acceptance_chunk

    _, placed = acceptance_chunk(len(task.level.players), 0)
    return [a for a in placed if domain.actions.valid(task.level, a)][:count]


def worlds(domain, level, action):
    """(a world as a play of `action` builds it, its step): the engine alone."""
    if hasattr(domain, "game"):
        game = domain.game(level)
        world = game.build()
        if action is not None:
            game.launch(world, action)
        return world, domain.world.engine.dt
    from physc.simulation.scene import built

    scene = domain.scene(level, action)
    return built(scene, domain.backend), scene.dt


def measure(path: Path, count: int) -> dict:
    from physc.api import domain_of, load_task
    from physc.simulation.ending import Ending

    task = load_task(path)
    domain = domain_of(task)
    played = actions(domain, task, count)
    started = time.perf_counter()
    full = [domain.play(task.level, a, ending=Ending.OUTCOME) for a in played]
    full_s = time.perf_counter() - started
    started = time.perf_counter()
    outs = [domain.playout(task.level, a) for a in played]
    playout_s = time.perf_counter() - started
    if any((f.solved, f.steps) != (o.solved, o.steps) for f, o in zip(full, outs)):
        raise SystemExit(f"{path.name}: a playout differs from its full run")
    steps = sum(f.steps for f in full)
    started = time.perf_counter()
    for action, trace in zip(played, full):
        world, dt = worlds(domain, task.level, action)
        for _ in range(trace.steps):
            world.step(dt)
            world.begun()
            world.ended()
    alone_s = time.perf_counter() - started
    return {"task": path.name, "domain": task.domain, "steps": steps, "full": steps / full_s, "playout": steps / playout_s, "alone": steps / alone_s}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("tasks", nargs="*", type=Path, default=DEFAULT)
    parser.add_argument("--actions", type=int, default=40, help="actions played per task (default 40)")
    args = parser.parse_args()
    print(f"machine: {platform.machine()}, Python {platform.python_version()}")
    rows = [measure(path, args.actions) for path in args.tasks]
    print(f"{'task':<22} {'steps':>8} {'full':>10} {'playout':>10} {'alone':>10}  playout/alone")
    for row in rows:
        print(f"{row['task']:<22} {row['steps']:>8} {row['full']:>10,.0f} {row['playout']:>10,.0f} {row['alone']:>10,.0f}  {row['playout'] / row['alone']:.0%}")
    for domain in sorted({r["domain"] for r in rows}):
        mine = [r for r in rows if r["domain"] == domain]
        steps = sum(r["steps"] for r in mine)
        seconds = {k: sum(r["steps"] / r[k] for r in mine) for k in ("full", "playout", "alone")}
        rates = {k: steps / s for k, s in seconds.items()}
        print(f"{domain:<22} {steps:>8} {rates['full']:>10,.0f} {rates['playout']:>10,.0f} {rates['alone']:>10,.0f}  "
              f"{rates['playout'] / rates['alone']:.0%} (full run: {rates['full'] / rates['alone']:.0%})")


if __name__ == "__main__":
    main()
