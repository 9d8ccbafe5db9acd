"""Learning across the tasks of a dataset: a scenario's tasks made in waves, each wave learning
from the waves before it.

Within one compile, the proposal model (physc.search.link_model) learns which placed layouts
realise which links of the chain. `physc generate` hands that on: a scenario's tasks are made in
*waves* of `wave` seeds (`--wave`, default WAVE; seeds S … S+wave−1 first, then the next wave), the
tasks of a wave side by side, and a task of a later wave starts with the examples that the
compiles of the same scenario in the waves before taught (made or not: where a link failed
teaches as much as where it held), the latest HORIZON of them. So the 100th task's layouts are
ranked by what the 16 before its wave simulated, while its own seed still draws its own layouts
(no earlier layout is repeated; `physc eval`'s diversity measures how far apart they are). The
horizon keeps what a wave reads, and each row's list of seeds, bounded in a dataset of any size.

The contract stays explicit: a task depends on its scenario, seed, settings, world, the prior's
fingerprint and the earlier tasks its manifest row names (`learned_from`: their seeds); their
examples are in the dataset, one side file a task (`<scenario>/<seed>.examples.json`), so a
resumed run gives a later wave the same examples, and the same command gives the same bytes
whatever the number of processes (the waves are fixed by the seeds, never by `--jobs`). A wave of
0 makes every task on its own, as `physc compile` and `physc eval` do (a task of the first wave is
the one `physc compile --seed` makes).

An earlier wave's examples count as the compile's own; at most CAP of each kind are carried,
evenly spaced over them in the order of the tasks, so that a long dataset's later tasks fit
their models as quickly as its first.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import attrs

if TYPE_CHECKING:  # the command line reads WAVE without loading the search
    from physc.driver.job import Job
    from physc.search.link_model import KindedExample

WAVE = 4  # a scenario's tasks made side by side before the next ones learn from them
CAP = 600  # earlier examples carried of each kind at most
HORIZON = 16  # earlier tasks a task learns from at most (the latest): what a later wave reads stays bounded


def learned_from(index: int, wave: int) -> range:
    """The places (0, 1, …, in seed order) of the scenario's tasks that the task at `index`
    learns from: the last HORIZON of those in the waves before its own (none, with a wave of 0)."""
    start = (index // wave) * wave if wave > 0 else 0
    return range(max(start - HORIZON, 0), start)


def assigned(jobs: Sequence[Job], wave: int) -> list[Job]:
    """`jobs`, each naming the seeds it learns from (`learned_from`): those of its scenario's
    jobs in the waves before its own, its place among them counted in seed order."""
    seeds: dict[str, list[int]] = {}
    for job in jobs:
        seeds.setdefault(job.scenario, []).append(job.seed)
    order = {name: sorted(found) for name, found in seeds.items()}
    place = {(name, seed): i for name, found in order.items() for i, seed in enumerate(found)}
    return [
        attrs.evolve(job, learned_from=tuple(order[job.scenario][i] for i in learned_from(place[job.key], wave)))
        for job in jobs
    ]


def in_waves(todo: Sequence[Job], folder: Path, rows: dict) -> Iterator[list[Job]]:
    """The jobs to make, wave by wave, each carrying what its earlier tasks taught: read from
    their rows' side files in `folder` when its wave comes (`rows`, the manifest's rows by key,
    holds the waves before by then), once for a wave's tasks of one scenario, and not kept
    between waves (a long dataset's side files would fill the memory)."""

    def after(job: Job) -> int:  # the last seed before its wave: a scenario's waves come in its order
        return max(job.learned_from, default=-1)

    for last in sorted({after(job) for job in todo}):
        group = [job for job in todo if after(job) == last]
        earlier: dict[str, tuple[KindedExample, ...]] = {}
        for job in group:
            if job.scenario not in earlier:
                earlier[job.scenario] = gathered(folder, [rows.get((job.scenario, s)) for s in job.learned_from])
        yield [attrs.evolve(job, earlier=earlier[job.scenario]) for job in group]


def gathered(folder: Path, rows: Sequence[dict | None]) -> tuple[KindedExample, ...]:
    """The examples of the earlier tasks' `rows` (their side files in `folder`), `carried`."""
    paths = [folder / row["examples"] if row is not None and row.get("examples") else None for row in rows]
    return carried([read(path) if path is not None and path.is_file() else [] for path in paths])


def examples_file(scenario: str, seed: int) -> str:
    """Where a dataset keeps the examples a task's compile taught, relative to the dataset."""
    return f"{scenario}/{seed}.examples.json"


def dumped(examples: Sequence[KindedExample]) -> str:
    """A side file's contents: [kind, features, realised] rows, features to four places."""
    rows = [[kind, [round(v, 4) for v in values], bool(realised)] for kind, values, realised in examples]
    return json.dumps(rows, separators=(",", ":")) + "\n"


def read(path: Path) -> list[KindedExample]:
    """The examples of a side file `dumped` wrote."""
    return [
        (str(kind), tuple(float(v) for v in values), bool(realised))
        for kind, values, realised in json.loads(path.read_text(encoding="utf-8"))
    ]


def carried(taught: Sequence[Sequence[KindedExample]]) -> tuple[KindedExample, ...]:
    """The examples a later task starts with, from each earlier task's (in seed order): at most
    CAP of each kind, evenly spaced over them."""
    kinds: dict[str, list[KindedExample]] = {}
    for examples in taught:
        for example in examples:
            kinds.setdefault(example[0], []).append(example)
    kept: list[KindedExample] = []
    for kind in sorted(kinds):
        rows = kinds[kind]
        if len(rows) > CAP:
            rows = [rows[i * len(rows) // CAP] for i in range(CAP)]
        kept += rows
    return tuple(kept)
