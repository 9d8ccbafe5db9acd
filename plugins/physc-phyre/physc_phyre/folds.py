"""PHYRE's evaluation folds: train, dev and test task ids, within and across templates.

PHYRE's `get_fold(eval_setup, seed)` (src/python/phyre/metrics.py; docs/phyre-sources.md,
section 4), reimplemented over any set of task ids `TTTTT:VVV`, so that a physc benchmark is
split the way PHYRE's own is: orders come from `stable_shuffle` (sorting by the md5 of id
and salt), shares from TRAIN_SHARE = 0.8.

* **Cross-template**: the templates ordered with the salt `ball_cross_template_half_{seed}`;
  the last round(20 %) are test; the rest reordered with `dev_ball_cross_template_half_{seed}`,
  the first int(80 %) train and the others dev.
* **Within-template**: each template's ids ordered with `ball_online_ind_tasks{seed}`, the
  first round(80 %) kept for training and the rest test; the kept ids of every template
  pooled, ordered with `make_dev{seed}`, the first int(80 %) train and the rest dev.

Each action tier is split on its own (PHYRE's setups are per tier: ball_cross_template,
two_balls_cross_template, …) and the parts pooled. The salts say "ball" in every tier, as
PHYRE's do. Every list is sorted, as PHYRE returns it.
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable

TRAIN_SHARE = 0.8
SETUPS = ("cross_template", "within_template")
SEEDS = 10  # PHYRE reports the mean over folds 0-9


def stable_shuffle(strings: Iterable[str], salt: str = "") -> list[str]:
    """PHYRE's util.stable_shuffle: sorted by md5(string + salt)."""
    return sorted(strings, key=lambda s: hashlib.md5((str(s) + salt).encode("utf8")).hexdigest())


def _templates(ids: Iterable[str]) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for task in sorted(ids):
        out.setdefault(task.split(":")[0], []).append(task)
    return out


def cross_template(ids: Iterable[str], seed: int) -> tuple[list[str], list[str], list[str]]:
    """(train, dev, test) with whole templates in each."""
    per = _templates(ids)
    order = stable_shuffle(per, f"ball_cross_template_half_{seed}")
    kept = int(round(len(order) * TRAIN_SHARE))
    test = order[kept:]
    order = stable_shuffle(order[:kept], f"dev_ball_cross_template_half_{seed}")
    trained = int(len(order) * TRAIN_SHARE)
    return tuple(sorted(t for tpl in group for t in per[tpl]) for group in (order[:trained], order[trained:], test))


def within_template(ids: Iterable[str], seed: int) -> tuple[list[str], list[str], list[str]]:
    """(train, dev, test) with every template in each (dev drawn from the pool, not per template)."""
    kept, test = [], []
    for _, group in sorted(_templates(ids).items()):
        group = stable_shuffle(group, f"ball_online_ind_tasks{seed}")
        n = int(round(len(group) * TRAIN_SHARE))
        if not n:
            continue
        kept += group[:n]
        test += group[n:]
    kept = stable_shuffle(kept, f"make_dev{seed}")
    trained = int(len(kept) * TRAIN_SHARE)
    return tuple(sorted(part) for part in (kept[:trained], kept[trained:], test))


def fold(setup: str, ids: Iterable[str], seed: int) -> tuple[list[str], list[str], list[str]]:
    """PHYRE's fold `seed` of `setup` ("cross_template" or "within_template") over `ids`."""
    if setup not in SETUPS:
        raise ValueError(f"no evaluation setup '{setup}' (PHYRE's: {', '.join(SETUPS)})")
    return (cross_template if setup == "cross_template" else within_template)(list(ids), seed)


def folds(ids: Iterable[str], seeds: int = SEEDS, tiers: dict[str, str] | None = None) -> dict:
    """Every setup's folds 0 .. seeds - 1: {setup: {seed: {"train": […], "dev": […], "test": […]}}}.
    With `tiers` (a task id's action tier), each tier is split on its own, as PHYRE splits
    its ball and two-ball tiers, and the parts pooled."""
    ids = list(ids)
    groups: dict[str, list[str]] = {}
    for task in ids:
        groups.setdefault((tiers or {}).get(task, ""), []).append(task)

    def split(setup: str, seed: int) -> dict:
        parts = [fold(setup, group, seed) for _, group in sorted(groups.items())]
        return {name: sorted(t for part in parts for t in part[k]) for k, name in enumerate(("train", "dev", "test"))}

    return {setup: {str(seed): split(setup, seed) for seed in range(seeds)} for setup in SETUPS}
