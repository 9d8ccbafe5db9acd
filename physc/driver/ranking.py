"""The placed layouts tried first are the likeliest to realise their chain: a pool drawn ahead,
ranked by the proposal model.

Placing a layout takes milliseconds; satisfying it, a second or more. So the loop draws
`POOL` placed layouts ahead of the search and, each round, tries `ROUND` of them: the one that
has waited longest (so that every layout placed is tried in time, and the model keeps learning
from layouts it did not choose), then the likeliest by the proposal model
(physc.search.link_model), which has learned from every layout tried before the round and from
the world's prior. The rest wait in the pool. The round's size is the search's, never the
number of workers': the model learns between rounds, so a round's choice is the same however
many workers satisfy it (physc.driver.workers).

The first round takes the first layouts placed, without the model: a compile that they satisfy
(most short chains) never pays for it (scikit-learn's import and fits, about a second). Where
the model knows nothing (no prior, no layout tried), every layout's chance is the same, and the
layouts are tried in the order they were placed, as before there was a model.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Generic, Protocol, TypeVar

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.infeasible import Infeasible
from physc.search.link_features import LinkFeatures
from physc.search.link_model import LinkModel

POOL = 16  # placed layouts drawn ahead of the search
ROUND = 4  # layouts tried in a round: the model learns between rounds


class Placed(Protocol):
    """What the pool reads of a placed layout (the pipeline's Placed)."""

    @property
    def layout(self) -> ConcreteLayout: ...


P = TypeVar("P", bound=Placed)


@attrs.frozen
class Candidate(Generic[P]):
    """A placed layout in the pool: its place in the order drawn, and its links' features."""

    order: int
    placed: P
    links: tuple[LinkFeatures, ...]


@attrs.define
class Ranking(Generic[P]):
    """The pool and its rounds (module docstring)."""

    placements: Iterator[P]
    model: LinkModel
    links_of: Callable[[P], list[LinkFeatures]]
    pool: list[Candidate[P]] = attrs.field(factory=list)
    drawn: int = 0
    proposed: int = 0  # conjunctions the layout search tried for the layouts drawn (the funnel's `proposed`)
    ended: Infeasible | None = None  # why the placements ran out, once they have
    rounds: int = 0

    def round(self, size: int = ROUND) -> list[Candidate[P]]:
        """The next round's layouts, at most `size`: the longest waiting, then the likeliest.
        Infeasible when the placements have run out and the pool is empty (their reason)."""
        self._fill()
        if not self.pool:
            assert self.ended is not None, "a pool runs dry only when the placements end"
            raise self.ended
        oldest, rest = self.pool[0], self.pool[1:]
        ranked = sorted(rest, key=lambda c: (-self.model.chance(c.links), c.order)) if self.rounds else rest
        chosen = [oldest] + ranked[: max(size - 1, 0)]
        self.rounds += 1
        taken = {c.order for c in chosen}
        self.pool = [c for c in self.pool if c.order not in taken]
        return chosen

    def _fill(self) -> None:
        while self.ended is None and len(self.pool) < POOL:
            try:
                placed = next(self.placements)
            except Infeasible as error:
                self.ended = error
                return
            self.pool.append(Candidate(self.drawn, placed, tuple(self.links_of(placed))))
            self.proposed = max(self.proposed, placed.layout.conjunctions_tried)
            self.drawn += 1
