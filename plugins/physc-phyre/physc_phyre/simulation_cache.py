"""PHYRE's simulation cache for physc's tasks: the status of each action of a fixed pool on
each task, in the file PHYRE's `phyre.SimulationCache` reads (docs/phyre-sources.md, section 9).

PHYRE builds its cache with scripts/offline_simulation/ and reads it with
src/python/phyre/simulation_cache.py; this module writes the same:

* the actions: the first N of seed 42 (`ACTION_SEED`), drawn one after another by the tier's
  mapper (`save_action_space.py`, as pool.discrete_actions draws them) and stored as float32:
  N × 3 in the `ball` tier, N × 6 in `two_balls`;
* a task's statuses: int8, one per action, of the float32 action as stored
  (`save_partial_simulation.py` simulates the actions it loads back): SOLVED 1, NOT_SOLVED -1,
  INVALID_INPUT 0 (the mapper refuses it, or the ball occludes a body);
* one file per action tier, `<root>/offline_simulation/<N>/<tier>/simulation_cache.gz`:
  `{"statuses_per_task": {task id: statuses, in id order}, "actions": actions}` written by
  `joblib.dump` to that `.gz` name, which makes it gzip at joblib's default level, 3
  (`compress_partial_simuations.py`).

A status here is the plugin's simulation under PHYRE's rules: the float32 action read as PHYRE
reads it (actions.from_unit: the same pixel and radius as PHYRE's mapper for all 100,000 actions
of both tiers), INVALID when the mapper refuses it or a ball occludes a body (`status`), else
whether the task's own world and engine (Box2D at PHYRE's settings by default) solve it. Each
status depends on its task and action alone, so the file is the same bytes on any executor.
"""

from __future__ import annotations

import functools
import io
import json
from pathlib import Path

import attrs
import numpy as np

from physc.simulation.ending import Ending
from physc_phyre.actions import from_unit, placeable
from physc_phyre.pool import CACHE_SEED, discrete_actions

FILE_NAME = "simulation_cache.gz"  # simulation_cache.CACHE_FILE_NAME
FOLDER = "offline_simulation"  # simulation_cache.get_cache_folder: <root>/offline_simulation/<N>
SOLVED, INVALID, NOT_SOLVED = 1, 0, -1  # SimulationStatus's values (action_simulator.py)
# PHYRE's action tiers, the folders of its cache, by the task tier each holds and the balls of
# its actions. (PHYRE's `ball` cache also holds its VIRTUAL_TOOLS tasks; physc makes none.)
TIERS = {"BALL": "ball", "TWO_BALLS": "two_balls"}
BALLS = {"ball": 1, "two_balls": 2}
COMPRESSION = ("gzip", 3)  # what joblib.dump picks for a name ending .gz


def cache_folder(root: Path, actions: int, tier: str) -> Path:
    """The folder of the cache of `actions` actions of `tier` under `root`: PHYRE's
    `get_cache_folder(actions) / tier` when `root` is its PHYRE_CACHE_DIR."""
    return Path(root) / FOLDER / str(actions) / tier


def pool(tier: str, count: int) -> np.ndarray:
    """The cache's actions of `tier`: the first `count` of PHYRE's pool of seed 42, float32."""
    units, _ = discrete_actions(BALLS[tier], count, CACHE_SEED)
    return units.astype(np.float32)


def status(domain, level, action: np.ndarray) -> int:
    """PHYRE's status of one action (a row of the pool) on `level`: INVALID when PHYRE's mapper
    refuses it (from_unit: outside the scene, two balls closer than r1 + r2 + 1 px before they
    are rounded to pixels) or a placed ball occludes a body of the scene (`placeable`), as
    PHYRE's simulator checks each ball against the scene's bodies only
    (image_to_box2d.cpp, mergeUserInputIntoScene). Not the domain's `valid`, which also
    refuses two balls that rounding left closer than r1 + r2 + 1 px."""
    placed = from_unit(action)
    if placed is None or not all(placeable(level, ball) for ball in placed.balls):
        return INVALID
    return SOLVED if domain.playout(level, placed, ending=Ending.SETTLED).solved else NOT_SOLVED


@functools.lru_cache(maxsize=8)
def task_level(path: str):
    """(the domain in the task's own world and engine, the level) of a physc task file of the
    PHYRE-like domain; ValueError, saying why, for a file that is not one."""
    from physc.backends import BackendError
    from physc.domains import bound
    from physc.serialize import from_data
    from physc.worlds import WorldError
    from physc_phyre import DOMAIN

    try:
        task = json.loads(Path(path).read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as error:
        raise ValueError(f"cannot read the task file {path}: {getattr(error, 'strerror', None) or error}") from None
    if not isinstance(task, dict) or task.get("domain") != DOMAIN.name:
        raise ValueError(f"{path} is not a task of the domain '{DOMAIN.name}'")
    try:
        domain = bound(DOMAIN, task.get("world") or None, task.get("backend") or None)
        level = from_data(task["level"], {cls.__name__: cls for cls in DOMAIN.files.level_classes})
    except (WorldError, BackendError) as error:
        raise ValueError(f"{path}: {error}") from None
    except (TypeError, ValueError, AttributeError, KeyError, RecursionError) as error:
        raise ValueError(f"{path}: its level cannot be read: {error or type(error).__name__}") from None
    if not isinstance(level, DOMAIN.files.level_classes[0]):
        raise ValueError(f"{path}: its level is not a {DOMAIN.files.level_classes[0].__name__}")
    return domain, level


@attrs.frozen
class Chunk:
    """A job: the statuses of the actions `actions` (rows `start`… of the pool) on the task of
    the task file `task` (PHYRE's id `task_id`)."""

    task_id: str
    task: str
    start: int
    actions: np.ndarray = attrs.field(eq=False, repr=False)


def simulate(chunk: Chunk) -> tuple[str, int, bytes]:
    """(task id, first row, int8 statuses as bytes) of a chunk; what a worker runs."""
    domain, level = task_level(chunk.task)
    statuses = np.array([status(domain, level, action) for action in chunk.actions], np.int8)
    return chunk.task_id, chunk.start, statuses.tobytes()


def cache_bytes(actions: np.ndarray, statuses_per_task: dict[str, np.ndarray]) -> bytes:
    """The cache file: what PHYRE's `joblib.dump(dict(statuses_per_task=…, actions=…),
    path.gz)` writes, its tasks in id order (float32 actions, int8 statuses)."""
    import joblib

    cache = {
        "statuses_per_task": {t: np.asarray(statuses_per_task[t], np.int8) for t in sorted(statuses_per_task)},
        "actions": np.asarray(actions, np.float32),
    }
    buffer = io.BytesIO()
    joblib.dump(cache, buffer, compress=COMPRESSION)  # pyright: ignore[reportArgumentType]  # joblib takes (method, level); its stub reads int from the default 0
    return buffer.getvalue()
