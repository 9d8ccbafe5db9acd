"""Where a compile's simulations go (physc.search.funnel): each placed layout's way down its
chain, summed, in the task file and in exit 3's words."""

from __future__ import annotations

import json

from conftest import EXAMPLES, run_physc

from physc.search.funnel import AFTER, Funnel, Passage, funnel_text


class Term:
    def __init__(self, text):
        self.text = text


TERMS = [Term("hit(bird, rBlock, left)"), Term("roll(rBlock, surface, right)"), Term("hit(rBlock, pig, left)")]


def test_a_passage_counts_each_simulation_at_the_stage_being_worked_on():
    passage = Passage()
    passage.enter((0, 1), 0)
    passage.realised.add((0, 1))
    passage.enter((1, 3), 40)  # 40 simulations on the first stage
    passage.enter((0, 1), 55)  # back: the second stage failed from that variant
    passage.enter((1, 3), 60)
    passage.enter(AFTER, 90)
    passage.enter(None, 100)
    assert passage.spent == {(0, 1): 45, (1, 3): 45, AFTER: 10}
    assert passage.reached == {(0, 1), (1, 3)} and passage.realised == {(0, 1)}


def test_a_funnel_sums_the_layouts_and_says_where_they_were_lost():
    funnel = Funnel()
    stuck = Passage(reached={(0, 1)}, spent={(0, 1): 30})
    realised = Passage(reached={(0, 1), (1, 3)}, realised={(0, 1), (1, 3)}, spent={(0, 1): 10, (1, 3): 20, AFTER: 5}, chain=True)
    funnel.add(stuck, 30, False, "the sequence was not realised")
    funnel.add(realised, 50, False, "the solution was too fragile")  # 20 after the chain: verify's too
    funnel.add(realised, 50, True, "")
    record = funnel.record(TERMS)
    assert record["placed"] == 3 and record["chain_realised"] == 2 and record["kept"] == 1
    assert record["lost"] == {"noise": 1}
    assert record["stages"] == [
        {"interactions": "hit(bird, rBlock, left)", "reached": 3, "realised": 2, "simulations": 50},
        {"interactions": "roll(rBlock, surface, right) > hit(rBlock, pig, left)", "reached": 2, "realised": 2, "simulations": 40},
    ]
    assert record["simulations_after_chain"] == 40  # the rest of each layout's simulations
    text = funnel_text(record)
    assert text.startswith("of 3 placed layouts, stage 1 (`hit(bird, rBlock, left)`) realised in 2 of 3 reaching it (50 simulations)")
    assert "2 realised the chain: 1 kept, 1 lost to noise (40 simulations after the chain)" in text
    funnel.proposed = 1200
    assert funnel_text(funnel.record(TERMS)).startswith("of 3 placed layouts (from 1,200 conjunctions proposed), stage 1")


def test_a_task_file_keeps_its_funnel_and_every_simulation_is_counted_once(tmp_path):
    run = run_physc("compile", EXAMPLES / "paper" / "05_F.phys", "-o", tmp_path / "f.xml", "--task", tmp_path / "f.json", "-q")
    assert run.status == 0, run.stderr
    task = json.loads((tmp_path / "f.json").read_text())
    funnel = task["funnel"]
    assert funnel["placed"] == task["layouts_tried"] and funnel["kept"] == 1 and funnel["chain_realised"] >= 1
    assert funnel["proposed"] >= task["conjunctions_tried"] and funnel["proposed"] >= funnel["placed"]  # what the layout search tried (the pool drawn ahead too)
    counted = sum(s["simulations"] for s in funnel["stages"]) + funnel["simulations_after_chain"]
    assert counted == task["simulations"]
    assert [s["interactions"] for s in funnel["stages"]][0] == "hit(bird, fBlock, left | above)"
