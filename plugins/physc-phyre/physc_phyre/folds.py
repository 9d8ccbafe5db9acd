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

Each action tier is split on its own, under PHYRE's own setup names (`setup`):
`ball_cross_template`, `ball_within_template`, `two_balls_cross_template`,
`two_balls_within_template`. The salts say "ball" in every tier, as PHYRE's do. Every list is
sorted, as PHYRE returns it.
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterable

TRAIN_SHARE = 0.8
KINDS = ("cross_template", "within_template")  # the two ways PHYRE splits a tier's tasks
TIERS = {"BALL": "ball", "TWO_BALLS": "two_balls"}  # an action tier → its setups' prefix
SETUPS = tuple(f"{prefix}_{kind}" for prefix in TIERS.values() for kind in KINDS)  # PHYRE's eval setups
SEEDS = 10  # PHYRE reports the mean over folds 0-9


def setup(tier: str, kind: str) -> str:
    """PHYRE's name of the evaluation setup that splits `tier`'s tasks by `kind`."""
    return f"{TIERS[tier]}_{kind}"


_KIND_OF = {kind: kind for kind in KINDS} | {
    setup(tier, kind): kind for tier in TIERS for kind in KINDS
}  # a setup → how it splits


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
    train, dev, tested = (
        sorted(t for tpl in group for t in per[tpl]) for group in (order[:trained], order[trained:], test)
    )
    return train, dev, tested


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
    return sorted(kept[:trained]), sorted(kept[trained:]), sorted(test)


def fold(name: str, ids: Iterable[str], seed: int) -> tuple[list[str], list[str], list[str]]:
    """PHYRE's fold `seed` of the setup `name` (one of SETUPS, or a kind of split:
    "cross_template", "within_template") over `ids`."""
    kind = _KIND_OF.get(name)
    if kind is None:
        raise ValueError(f"no evaluation setup '{name}' (PHYRE's: {', '.join(SETUPS)})")
    return (cross_template if kind == "cross_template" else within_template)(list(ids), seed)


def folds(ids: Iterable[str], seeds: int = SEEDS, tiers: dict[str, str] | None = None) -> dict:
    """The folds 0 .. seeds - 1 of PHYRE's setups for the tiers among `ids` (`tiers`: a task
    id's action tier; BALL when not given): {setup: {seed: {"train": […], "dev": […],
    "test": […]}}}, each tier split on its own, as PHYRE's are."""
    groups: dict[str, list[str]] = {}
    for task in ids:
        groups.setdefault((tiers or {}).get(task, "BALL"), []).append(task)

    def split(kind: str, group: list[str], seed: int) -> dict:
        return dict(zip(("train", "dev", "test"), fold(kind, group, seed), strict=False))

    return {
        setup(tier, kind): {str(seed): split(kind, group, seed) for seed in range(seeds)}
        for tier, group in sorted(groups.items(), key=lambda item: list(TIERS).index(item[0]))
        for kind in KINDS
    }
