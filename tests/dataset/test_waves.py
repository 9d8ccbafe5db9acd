"""A dataset's later tasks learn from its earlier ones (issue 74): waves of seeds, the examples
each task's search taught kept beside it, named in the manifest, the same bytes however made."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

from conftest import EXAMPLES, run_physc

from physc.dataset import waves
from physc.driver.job import Job
from physc.search.link_model import LinkModel

SF = EXAMPLES / "paper" / "01_SF.phys"


def files(folder: Path) -> dict[str, str]:
    """The tasks' files by path, hashed (manifest and README left out: they hold times and the folder)."""
    return {
        str(p.relative_to(folder)): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.rglob("*"))
        if p.is_file() and p.parent != folder
    }


def rows(folder: Path) -> list[dict]:
    return [json.loads(line) for line in (folder / "manifest.jsonl").read_text().splitlines()]


def test_a_task_learns_from_the_waves_before_its_own_counted_in_seed_order():
    assert list(waves.learned_from(0, 4)) == [] and list(waves.learned_from(3, 4)) == []
    assert list(waves.learned_from(4, 4)) == [0, 1, 2, 3] and list(waves.learned_from(9, 4)) == list(range(8))
    assert list(waves.learned_from(41, 4)) == list(range(40 - waves.HORIZON, 40))  # the latest, at most HORIZON
    assert list(waves.learned_from(9, 0)) == []  # a wave of 0: each task on its own
    jobs = [Job("a.phys", name, seed) for name in ("A", "B") for seed in (12, 10, 11)]
    assigned = {(j.scenario, j.seed): j.learned_from for j in waves.assigned(jobs, 2)}
    assert assigned == {("A", 10): (), ("A", 11): (), ("A", 12): (10, 11), ("B", 10): (), ("B", 11): (), ("B", 12): (10, 11)}


def test_a_large_dataset_names_a_bounded_list_of_earlier_tasks():
    assigned = waves.assigned([Job("a.phys", "A", seed) for seed in range(100_000)], 4)
    assert assigned[-1].learned_from == tuple(range(99_980, 99_996)) and max(len(j.learned_from) for j in assigned) == waves.HORIZON


def test_the_examples_carried_are_capped_evenly_per_kind():
    many = [[("hit", (float(i),), i % 2 == 0) for i in range(waves.CAP * 3)], [("roll", (1.0,), True)]]
    carried = waves.carried(many)
    hits = [values[0] for kind, values, _ in carried if kind == "hit"]
    assert len(hits) == waves.CAP and hits[:3] == [0.0, 3.0, 6.0]  # every third: spread over all of them
    assert [kind for kind, _, _ in carried].count("roll") == 1


def test_earlier_examples_move_the_model_as_the_compiles_own_do():
    assert LinkModel().chance([_link("roll")]) == 0.5  # nothing known
    model = LinkModel()
    model.earlier = {"roll": [((1.0,), True)] * 8}
    assert model.chance([_link("roll")]) > 0.8 and model.learned == 0  # not the compile's own


def _link(kind: str):
    from physc.search.link_features import LinkFeatures

    return LinkFeatures(kind, 0, (1.0,))


def test_a_dataset_in_waves_names_what_each_task_learned_from_and_resumes_to_the_same_bytes(tmp_path):
    one, two = tmp_path / "one", tmp_path / "two"
    assert run_physc("generate", SF, "--tasks", "3", "--wave", "2", "--out", one, "-q").status == 0
    made = rows(one)
    assert [r["learned_from"] for r in made] == [[], [], [0, 1]]
    assert [r["settings"]["learned_from"] for r in made] == [[], [], [0, 1]]
    taught = [waves.read(one / r["examples"]) for r in made]
    assert all(taught), "every task's search taught something"
    task = json.loads((one / made[2]["task"]).read_text())
    assert task["proposals"]["earlier"] == len(waves.carried(taught[:2]))
    # Two processes, the same bytes; a lost side file is made again, and so is nothing else.
    assert run_physc("generate", SF, "--tasks", "3", "--wave", "2", "--out", two, "--jobs", "2", "-q").status == 0
    assert files(two) == files(one)
    (two / made[0]["examples"]).unlink()
    run = run_physc("generate", SF, "--tasks", "3", "--wave", "2", "--out", two)
    assert run.status == 0 and "resuming: 2 of 3 tasks already done" in run.stderr, run.stderr
    assert files(two) == files(one)


def test_the_first_wave_is_what_each_task_is_on_its_own(tmp_path):
    assert run_physc("generate", SF, "--tasks", "3", "--wave", "0", "--out", tmp_path / "alone", "-q").status == 0
    assert run_physc("generate", SF, "--tasks", "3", "--wave", "2", "--out", tmp_path / "waves", "-q").status == 0
    alone, learning = files(tmp_path / "alone"), files(tmp_path / "waves")
    first = [p for p in alone if p.split("/")[1].split(".")[0] in ("0", "1")]
    assert first and all(alone[p] == learning[p] for p in first)
    assert all(r["learned_from"] == [] for r in rows(tmp_path / "alone"))
