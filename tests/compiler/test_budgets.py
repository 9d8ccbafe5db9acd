"""Budgets are promises: generation stops at its time budget, and the message names the
budget that ran out and what would help."""

from __future__ import annotations

import time

import pytest
from conftest import EXAMPLES, run_physc
from middle_end import DOMAIN, paper_scenarios

from physc import budget
from physc.compiler.infeasible import Exhausted, Infeasible, readable
from physc.driver.pipeline import Pipeline
from physc.driver.run_settings import RunSettings

SRF = EXAMPLES / "paper" / "13_SRF.phys"


def test_deadline_raises_at_the_next_check(monkeypatch):
    now = [100.0]
    monkeypatch.setattr(budget.time, "monotonic", lambda: now[0])
    with budget.deadline(5.0):
        budget.check()
        now[0] = 104.9
        budget.check()
        now[0] = 105.1
        with pytest.raises(budget.OutOfTime, match="5 s"):
            budget.check()
    budget.check()  # no deadline outside the block


def test_an_inner_deadline_cannot_outlast_the_outer(monkeypatch):
    now = [0.0]
    monkeypatch.setattr(budget.time, "monotonic", lambda: now[0])
    with budget.deadline(2.0):
        with budget.deadline(10.0):
            now[0] = 3.0
            with pytest.raises(budget.OutOfTime, match="2 s"):
                budget.check()


def test_a_started_deadline_is_one_budget_for_every_block_that_keeps_it(monkeypatch):
    now = [0.0]
    monkeypatch.setattr(budget.time, "monotonic", lambda: now[0])
    started = budget.Deadline(5.0)
    now[0] = 4.0
    with budget.deadline(started):  # entered late, it still ends at 5 s
        budget.check()
        now[0] = 5.1
        with pytest.raises(budget.OutOfTime, match="5 s"):
            budget.check()


def test_a_run_owns_one_deadline_for_the_rest_of_it(monkeypatch):
    run = Pipeline(DOMAIN, paper_scenarios()["R"], settings=RunSettings(time_budget=5.0))
    now = [50.0]  # the budget starts with the run's work, not when the pipeline is made
    monkeypatch.setattr(budget.time, "monotonic", lambda: now[0])
    with run.within_budget("layout"):
        now[0] = 53.0
        budget.check()
    assert run.deadline.end == 55.0
    with pytest.raises(Infeasible) as ran_out:
        with run.within_budget("layout"):  # a second block (a picture, say) keeps the same deadline
            now[0] = 55.5
            budget.check()
    error = ran_out.value
    assert error.budget is Exhausted.TIME and error.stage == "layout" and error.message == "the time budget of 5 s ran out"


def test_generation_stops_at_its_time_budget():
    started = time.monotonic()
    run = run_physc("compile", SRF, "--time-budget", "1", "-q")
    elapsed = time.monotonic() - started
    assert run.status == 3, run.stderr
    assert "error[E0802]" in run.stderr and "the time budget of 1 s ran out" in run.stderr
    assert "help: the time ran out before every layout allowed was tried: more time may help (--time-budget)" in run.stderr
    # Generous: the promise is "within about a second"; this machine may be busy.
    assert elapsed < 4.0


def test_the_layout_budget_names_its_option():
    run = run_physc("compile", SRF, "--layouts", "1", "--min-robustness", "6", "-q")
    if run.status == 0:
        pytest.skip("SRF seed 0's first layout works: nothing ran out")
    assert "error[E0802]" in run.stderr
    assert "allow more with --layouts" in run.stderr and "--clause-budget" not in run.stderr


def test_the_clause_budget_names_its_option():
    run = run_physc("compile", SRF, "--emit", "layout", "--clause-budget", "1")
    assert run.status == 3, run.stderr
    assert "try a larger --clause-budget" in run.stderr


@pytest.mark.parametrize(
    "count, text",
    [(0, "0"), (12_345, "12,345"), (999_999_999, "999,999,999"), (33 * 10**92, "≈ 3.3 × 10⁹³"), (7 * 10**9999, "≈ 7.0 × 10⁹⁹⁹⁹")],
    ids=["zero", "thousands", "below-a-billion", "94-digits", "10000-digits"],
)
def test_counts_read_as_numbers(count, text):
    assert readable(count) == text
