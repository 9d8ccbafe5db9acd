"""PHYRE's fixed pools of random actions, drawn exactly as PHYRE draws them.

`ActionSimulator.build_discrete_action_space(n, seed)` (src/python/phyre/action_simulator.py)
is `rng = numpy.random.RandomState(seed)` and `n` calls of the tier's
`ActionMapper.sample(rng=rng)`, each repeating `rng.uniform(size=3)` (six numbers in the
two-ball tier) until the mapper places the action inside the scene (action_mappers.py).
Two pools are built this way:

* the acceptance pool (eval_task_complexity.py): action i is action `i % 10000` of the pool
  of seed `1000 + i // 10000` (`ACCEPTANCE_POOL_SIZE`, `ACCEPTANCE_SEED`);
* the simulation cache's (simulation_cache.py): the first `n` actions of seed 42
  (`CACHE_SEED`; PHYRE ships n = 100,000).

Whether an action occludes a body is not the pool's concern: such an action is in the pool
and counts as an invalid attempt.
"""

from __future__ import annotations

import functools

import numpy as np

from physc_phyre.actions import from_unit

ACCEPTANCE_POOL_SIZE = 10_000  # eval_task_complexity.ACTION_POOL_SIZE
ACCEPTANCE_SEED = 1000  # the pool of chunk k has seed 1000 + k
CACHE_SEED = 42  # simulation_cache.ACTION_SEED
CACHE_ACTIONS = 100_000  # simulation_cache.DEFAULT_NUM_ACTIONS


def discrete_actions(balls: int, count: int, seed: int) -> tuple[np.ndarray, list]:
    """PHYRE's `build_discrete_action_space(count, seed)` for a tier of `balls` red balls:
    the actions in [0, 1]^(3·balls) as a (count, 3·balls) float64 array, and each placed as
    PHYRE places it (a BallAction or TwoBallAction, physc_phyre.actions.from_unit)."""
    if balls not in (1, 2):
        raise ValueError(f"PHYRE's tiers place one or two balls, not {balls}")
    rng = np.random.RandomState(seed=seed)
    units = np.empty((count, 3 * balls))
    placed = []
    for i in range(count):
        while True:
            action = rng.uniform(size=3 * balls)
            ball = from_unit(action)
            if ball is not None:
                break
        units[i] = action
        placed.append(ball)
    return units, placed


@functools.lru_cache(maxsize=8)
def acceptance_chunk(balls: int, chunk: int, size: int = ACCEPTANCE_POOL_SIZE) -> tuple[np.ndarray, list]:
    """Chunk `chunk` (0, 1, …) of the acceptance's actions: actions 10,000·chunk on (the
    first `size` of them)."""
    return discrete_actions(balls, size, ACCEPTANCE_SEED + chunk)
