"""A deadline is scoped to the context that entered it (issue 72): the budget's stack is a
ContextVar, so another thread (a context of its own) neither sees nor pops it."""

from __future__ import annotations

import threading

import pytest

from physc import budget


def test_a_deadline_is_the_entering_contexts_alone():
    seen: list[float | None] = []
    with budget.deadline(0.0):
        thread = threading.Thread(target=lambda: seen.append(budget.remaining()))
        thread.start()
        thread.join()
        with pytest.raises(budget.OutOfTime):
            budget.check()
    assert seen == [None]
    assert budget.remaining() is None
    budget.check()  # the block's end took its deadline with it


def test_nested_deadlines_keep_the_nearest_end_and_restore_the_outer_one():
    with budget.deadline(100.0):
        outer = budget.remaining()
        with budget.deadline(1000.0):  # later than the enclosing block's: the enclosing one holds
            inner = budget.remaining()
            assert inner is not None and outer is not None and inner <= outer
        with budget.deadline(1.0):
            nearer = budget.remaining()
            assert nearer is not None and nearer <= 1.0
        after = budget.remaining()
        assert after is not None and 1.0 < after <= 100.0
