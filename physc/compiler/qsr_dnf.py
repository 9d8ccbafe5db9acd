"""The QSR DNF IR: every layout edge as a disjunction of QSRs.

The conjunctions of the DNF are the ways to pick one QSR per clause. There can
be astronomically many (3^k), so the DNF is never expanded: its size is computed
exactly as a product, and conjunctions are visited lazily in one seeded order,
lexicographic over clause alternatives that the seed has shuffled once per clause.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import attrs

from physc.compiler.layout_graph import LayoutEdge


@attrs.frozen
class QsrClause:
    """A layout edge and the QSRs (between its two objects) that may realise it,
    in the order the seeded enumeration visits them."""

    edge: LayoutEdge
    relations: tuple[str, ...]

    @property
    def a(self) -> str:
        return self.edge.a

    @property
    def b(self) -> str:
        return self.edge.b


@attrs.frozen
class QsrDnf:
    scenario: str
    domain: str
    seed: int
    clauses: tuple[QsrClause, ...]
    deferred: tuple[LayoutEdge, ...]  # liesOnPath, pathObstructed: satisfied by simulation

    @property
    def size(self) -> int:
        return math.prod(len(c.relations) for c in self.clauses)

    def __extra_dump__(self) -> dict:
        """What `--emit qsr` shows besides the clauses: the exact size, and the first
        conjunctions of the seeded order."""
        first = [list(c) for _, c in zip(range(3), self.conjunctions(), strict=False)]
        return {"size": self.size, "first_conjunctions": first}

    def remaining(self, depth: int) -> int:
        """How many conjunctions share any one choice of the first `depth` clauses."""
        return math.prod(len(c.relations) for c in self.clauses[depth:])

    def conjunction(self, index: int) -> tuple[str, ...]:
        """The conjunction at position `index` of the seeded order."""
        if not 0 <= index < self.size:
            raise IndexError(index)
        choice = []
        for depth, clause in enumerate(self.clauses):
            digit, index = divmod(index, self.remaining(depth + 1))
            choice.append(clause.relations[digit])
        return tuple(choice)

    def conjunctions(self) -> Iterator[tuple[str, ...]]:
        """All conjunctions, lazily, in the seeded order."""

        def walk(depth, prefix):
            if depth == len(self.clauses):
                yield tuple(prefix)
                return
            for relation in self.clauses[depth].relations:
                yield from walk(depth + 1, prefix + [relation])

        return walk(0, [])
