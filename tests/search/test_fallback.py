"""--min-robustness: when no layout gives a solution that survives every noisy replay,
the most robust fragile one is used (and only one that passes at least K)."""

from __future__ import annotations

import json
from unittest import mock

import pytest
from conftest import EXAMPLES, run_physc
from middle_end import DOMAIN, paper_scenarios

from physc.compiler.infeasible import Infeasible
from physc.driver.run_settings import MIN_ROBUSTNESS
from physc.driver.layout_loop import FALLBACKS, LayoutLoop
from physc.driver import workers
from physc.driver.pipeline import Pipeline
from physc.driver.run_settings import RunSettings
from physc.search import search
from physc.search.outcome import Outcome, Parts


class Scripted:
    """The search, following a script (the angrybirds domain places the layouts): layout i
    (in order of placement) is given up with `nearest[i]` replays passed, and a second try
    of layout i succeeds, passing works[i] replays, when `accept` is at most that."""

    def __init__(self, nearest, works=None):
        self.nearest = nearest
        self.works = works or {}
        self.order = {}
        self.calls = []

    def satisfy(self, domain, scenario, layout, rng, validate=True, accept=None, acceptance=True):
        index = self.order.setdefault(id(layout), len(self.order))
        self.calls.append((index, accept))
        if accept is None:
            return Outcome(False, 1, nearest=self.nearest[index] if index < len(self.nearest) else 0)
        if accept <= self.works.get(index, -1):
            parts = Parts(None, None, "", None, (self.works[index], 6), (), (), ())
            return Outcome(True, 1, parts)
        return Outcome(False, 1)


def generate(script, min_robustness, layouts=5):
    # The scripted outcomes have no level to replay: the checks in the game are left out here
    # (tests/search/test_checked.py has them).
    with mock.patch.object(search, "satisfy", script.satisfy), mock.patch.object(workers, "checked", lambda run, result, accept: result):
        return Pipeline(DOMAIN, paper_scenarios()["R"], 0, RunSettings(layouts=layouts, min_robustness=min_robustness, validate=False)).task


def test_the_most_robust_fragile_layout_is_tried_first():
    script = Scripted([3, 5, 0, 5, 4], works={1: 5, 3: 5})
    task = generate(script, 4)
    assert task.robustness == (5, 6)
    assert script.calls[5:] == [(1, 4)]  # the first of the two that passed 5, accepting 4


def test_fallbacks_go_on_when_a_second_try_fails():
    script = Scripted([4, 5, 0, 5, 4], works={0: 4})
    task = generate(script, 4)
    assert task.robustness == (4, 6)
    assert script.calls[5:] == [(1, 4), (3, 4), (0, 4)]  # most robust first, then in order of placement


def test_at_most_so_many_second_tries():
    script = Scripted([4] * (FALLBACKS + 2), works={FALLBACKS: 4})
    with pytest.raises(Infeasible):
        generate(script, 4, layouts=FALLBACKS + 2)
    assert [index for index, accept in script.calls if accept] == list(range(FALLBACKS))


def test_nothing_below_the_floor_and_nothing_when_all_replays_are_asked_for():
    with pytest.raises(Infeasible):
        generate(Scripted([3, 2, 3, 0, 1], works={0: 6}), 4)
    strict = Scripted([5, 5, 5, 5, 5], works={0: 6})
    with pytest.raises(Infeasible):
        generate(strict, DOMAIN.robustness_replays)
    assert all(accept is None for _, accept in strict.calls)


def test_by_default_there_are_no_fallbacks():
    assert MIN_ROBUSTNESS is None
    assert RunSettings().robustness(DOMAIN) == DOMAIN.robustness_replays == 6


def test_cli_refuses_a_floor_below_one(tmp_path):
    run = run_physc("compile", EXAMPLES / "paper" / "01_SF.phys", "--min-robustness", "0", "-q")
    assert run.status == 2 and "--min-robustness" in run.stderr


def test_a_fragile_chain_compiles_as_a_fallback_only_on_request(tmp_path):
    # R seed 1 (a roll into the pig, in Phy-Q's game): none of its first 4 layouts gives a
    # solution that survives all 6 noisy replays, its margins raised or not; the message names
    # how many the most robust passed and the flag that would accept it.
    import re

    paper = EXAMPLES / "paper" / "all.paper.phys"
    args = ("compile", paper, "-s", "R", "--seed", "1", "--layouts", "4", "--color", "never")
    strict = run_physc(*args, "-q", "-o", tmp_path / "strict.xml")  # the default: no fallbacks
    found = re.search(r"passed (\d) of 6 noisy replays \(--min-robustness (\d) accepts such a one\)", strict.stderr)
    assert strict.status == 3 and found and found.group(1) == found.group(2), strict.stderr
    assert not (tmp_path / "strict.xml").exists()
    # Asked for, the fallback is tried again accepting K of the generator's replays, and must then
    # pass K of physc verify's noisy replays under every reading of the game that can change
    # them: a task marked as a fallback, or the failure says that the second try failed.
    task = tmp_path / "task.json"
    k = int(found.group(1))
    run = run_physc(*args, "--min-robustness", str(k), "-o", tmp_path / "level.xml", "--task", task)
    if run.status == 0:
        assert "noisy replays (a fallback: --min-robustness)" in run.stderr
        data = json.loads(task.read_text())
        assert k <= data["robustness"][0] < data["robustness"][1] == 6 and data["fallback"] is True and data["validated"] is True
    else:
        assert run.status == 3 and "tried again as a fallback, it failed" in run.stderr and not task.exists()


def test_the_task_counts_why_layouts_were_given_up():
    class Reasons(Scripted):
        def satisfy(self, domain, scenario, layout, rng, validate=True, accept=None, acceptance=True):
            index = len(self.calls)
            self.calls.append(accept)
            if index == 3:
                parts = Parts(None, None, "", None, (6, 6), (), (), ())
                return Outcome(True, 5, parts)
            return Outcome(False, 10 + index, given_up="too fragile" if index == 1 else "not realised")

    task = generate(Reasons([]), 4)
    assert task.layouts_tried == 4 and task.simulations == 10 + 11 + 12 + 5
    assert task.given_up == {"not realised": {"layouts": 2, "simulations": 22}, "too fragile": {"layouts": 1, "simulations": 11}}


def test_a_failure_names_the_reasons_most_frequent_first():
    class Reasons(Scripted):
        def satisfy(self, domain, scenario, layout, rng, validate=True, accept=None, acceptance=True):
            self.calls.append(accept)
            return Outcome(False, 1, given_up="not realised" if len(self.calls) % 2 == 0 else "broken")

    with pytest.raises(Infeasible) as failure:
        generate(Reasons([]), 4, layouts=5)
    assert "; given up: 3 × broken, 2 × not realised" in failure.value.message
