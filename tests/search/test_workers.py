"""Every core a compile has (physc.driver.workers, physc.driver.ranking): the same task, byte for
byte, whatever the number of workers; the pool's rounds."""

from __future__ import annotations

import json
from types import SimpleNamespace

from conftest import EXAMPLES, run_physc

from physc.compiler.infeasible import Infeasible
from physc.driver.ranking import Ranking
from physc.search.link_features import LinkFeatures
from physc.search.link_model import LinkModel


def test_a_compile_gives_the_same_task_with_one_worker_or_two(tmp_path):
    made = {}
    for workers in ("1", "2"):
        level, task = tmp_path / f"r{workers}.xml", tmp_path / f"r{workers}.json"
        run = run_physc(
            "compile", EXAMPLES / "paper" / "04_R.phys", "--world", "rolling", "--workers", workers,
            "-o", level, "--task", task, "-q",
        )  # fmt: skip
        assert run.status == 0, run.stderr
        record = json.loads(task.read_text())
        record.pop("seconds")
        made[workers] = (level.read_bytes(), record)
    assert made["1"] == made["2"]
    assert made["1"][1]["proposals"]["round"] == 4 and made["1"][1]["proposals"]["learned"] > 0


class Placed:
    """A placed layout as the ranking reads it: its place, and the conjunctions tried for it."""

    def __init__(self, k):
        self.k, self.layout = k, SimpleNamespace(conjunctions_tried=k + 1)


def placements(count):
    for k in range(count):
        yield Placed(k)
    raise Infeasible("place", "no more")


def test_with_nothing_learned_the_layouts_are_tried_in_the_order_placed():
    ranking = Ranking(placements(6), LinkModel(), lambda p: [LinkFeatures("roll", 0, (float(p.k),))])
    assert [c.placed.k for c in ranking.round(4)] == [0, 1, 2, 3]
    assert [c.placed.k for c in ranking.round(4)] == [4, 5]
    assert ranking.proposed == 6
    try:
        ranking.round(4)
    except Infeasible as error:
        assert error.message == "no more"
    else:
        raise AssertionError("the pool ran dry")


def test_a_round_is_the_longest_waiting_layout_then_the_likeliest():
    model = LinkModel()
    for k in range(30):
        model.learn([LinkFeatures("roll", 0, (float(k % 10),))], 1 if k % 10 >= 7 else 0)
    ranking = Ranking(placements(20), model, lambda p: [LinkFeatures("roll", 0, (float(p.k % 10),))])
    assert [c.placed.k for c in ranking.round(4)] == [0, 1, 2, 3]  # the first round: in the order placed
    second = [c.placed.k for c in ranking.round(4)]
    assert second[0] == 4 and all(k % 10 >= 7 for k in second[1:])  # the longest waiting, then the likeliest
    third = [c.placed.k for c in ranking.round(4)]
    assert third[0] == 5 and all(k % 10 >= 7 for k in third[1:])
