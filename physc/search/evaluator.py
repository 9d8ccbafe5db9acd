"""The evaluator: the simulations a generation asks for, counted and kept.

Every strategy judges its proposals by simulating them, and a search meets the same
proposal again (after backtracking, a few dozen simulations later; an agent's shot
tried by two checks on the same level). The evaluator runs each simulation once while
it is among the last `capacity` asked for, and counts the simulations actually run:
the figure that generation's cost is measured in (Task.simulations).
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable, Hashable
from typing import TypeVar

T = TypeVar("T")


class Evaluator:
    def __init__(self, capacity: int):
        self.capacity = capacity
        self.simulations = 0  # simulations run (a kept one asked for again is not counted)
        self._kept: OrderedDict = OrderedDict()

    def kept(self, key: Hashable, simulate: Callable[[], T]) -> T:
        """`simulate()`, run once while `key` is among the last `capacity` asked for."""
        if key in self._kept:
            self._kept.move_to_end(key)
            return self._kept[key]
        result = self.run(simulate)
        self._kept[key] = result
        if len(self._kept) > self.capacity:
            self._kept.popitem(last=False)
        return result

    def forget(self) -> None:
        """Drop every kept simulation (the count stays)."""
        self._kept.clear()

    def run(self, simulate: Callable[[], T]) -> T:
        """`simulate()`, counted, not kept (a simulation that will not be asked for again)."""
        self.simulations += 1
        return simulate()
