"""The to-qsr pass: Layout Graph → QSR DNF (the paper's table "Inferred QSRs").

    inDirection(a, b, left)    → W(a,b) ∨ NW(a,b) ∨ SW(a,b)   (right, above, below alike)
    onLocation(a, b, left)     → MeetDuringW(a,b)   (centre → MeetN, right → MeetDuringE)
    locatedFar(a, b, left)     → FarW(a,b) ∨ FarNW(a,b) ∨ FarSW(a,b)   (and so on)
    touching(a, b, upperLeft)  → MeetNW(a,b)   (centreLeft → MeetW, lowerLeft → MeetSW)

An edge with several values (an overloaded direction) is the disjunction of their
QSRs. liesOnPath and pathObstructed have no QSRs: they are deferred to simulation.
"""

from __future__ import annotations

from physc.compiler import qsr
from physc.compiler.layout_graph import (
    IN_DIRECTION,
    LOCATED_FAR,
    ON_LOCATION,
    TOUCHING,
    LayoutEdge,
    LayoutGraph,
)
from physc.compiler.passes import PassContext
from physc.compiler.qsr_dnf import QsrClause, QsrDnf

TABLE = {
    IN_DIRECTION: qsr.IN_DIRECTION,
    LOCATED_FAR: qsr.LOCATED_FAR,
    ON_LOCATION: qsr.ON_LOCATION,
    TOUCHING: qsr.TOUCHING,
}

# Clauses are searched in this order: contacts first (they pin objects to each
# other), then distances, then directions; this prunes the search early.
_PRIORITY = {TOUCHING: 0, ON_LOCATION: 1, LOCATED_FAR: 2, IN_DIRECTION: 3}


def relations_for(term: str, values: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(dict.fromkeys(r for value in values for r in TABLE[term][value]))


class ToQsr:
    name = "to-qsr"

    def run(self, ir: LayoutGraph, context: PassContext) -> QsrDnf:
        """The DNF of the layout graph `ir`: each clause's relations in the context's seeded order."""
        graph, rng = ir, context.rng
        clauses: list[QsrClause] = []
        deferred: list[LayoutEdge] = []
        edges = sorted(enumerate(graph.edges), key=lambda item: (_PRIORITY.get(item[1].term, 9), item[0]))
        for _, edge in edges:
            if edge.simulated:
                deferred.append(edge)
                continue
            relations = list(relations_for(edge.term, edge.values))
            rng.shuffle(relations)
            clauses.append(QsrClause(edge, tuple(relations)))
        return QsrDnf(graph.scenario, graph.domain, context.seed, tuple(clauses), tuple(deferred))
