"""The to-dimension-graphs pass: QSR DNF → consistent X and Y dimension graphs.

Shapes come first: the domain picks concrete objects, materials, platform lengths
and inclinations (seeded), so every QSR becomes difference constraints. The
conjunctions are then visited in the DNF's seeded order by a depth-first search
that adds one clause's constraints at a time and abandons a prefix as soon as it
closes a negative cycle; all conjunctions below an abandoned prefix count as
rejected, exactly. The pass yields consistent dimension graphs lazily: when a
later stage cannot use one, the search goes on to the next.

When no conjunction is consistent, a deletion-based search finds a minimal set of
layout edges that cannot hold together, which is reported with its source terms.
"""

from __future__ import annotations

from collections.abc import Iterator

import attrs

from physc import budget
from physc.compiler.concrete_layout import Body, ChosenRelation
from physc.compiler.difference import DifferenceSystem, Inconsistent
from physc.compiler.dimension_graphs import (
    Constraint,
    DimensionGraphs,
    LayoutParameters,
    base_constraints,
    new_systems,
    relation_constraints,
)
from physc.compiler.infeasible import Exhausted, Infeasible, readable
from physc.compiler.layout_graph import LayoutEdge
from physc.compiler.passes import LayoutDomain, PassContext, parameters_of
from physc.compiler.qsr_dnf import QsrClause, QsrDnf
from physc.dsl.scenario import ScenarioIR

# The most interactions the search takes. Its memory grows with the square of the bodies
# times the depth (a copy of both axes' distance matrices per clause on the path) and each
# clause choice costs the square of the bodies: a 64-interaction chain ends its search in
# about 35 s and 140 MB, a 200-interaction one ran for minutes at 2 GB (docs/generation.md).
CLAUSE_BUDGET = 50_000  # clause choices the layout search may try per shape draw (--clause-budget)
MAX_INTERACTIONS = 64
SHAPE_DRAWS = 12  # how many times shapes are drawn anew before giving up, if no conjunction is consistent
MAX_SHAPE_DRAWS = 120  # draws in all while consistent conjunctions are found and still asked for


class _BudgetSpent(Exception):
    pass


@attrs.define
class _Counts:
    """What the search has counted so far, over all its shape draws (the yielded graphs and
    the failure report these)."""

    tried: int = 0  # conjunctions decided, consistent or not
    rejected: int = 0  # conjunctions inconsistent, or consistent but not used by the caller
    found: int = 0  # consistent conjunctions yielded
    misfits: int = 0  # shape draws that did not fit the placement area
    nodes: int = 0  # clause choices in the current shape draw (its budget: clause_budget)


Chosen = tuple[tuple[QsrClause, str, tuple[Constraint, ...]], ...]  # (clause, its relation, the constraints)


def _apply(systems: dict[str, DifferenceSystem], constraints: list[Constraint]) -> dict[str, DifferenceSystem]:
    copies = {axis: system.copy() for axis, system in systems.items()}
    for c in constraints:
        copies[c.axis].add(c.u, c.v, c.weight)
    return copies


def clause_constraints(
    clause: QsrClause, relation: str, bodies: dict[str, Body], parameters: LayoutParameters
) -> list[Constraint]:
    return relation_constraints(relation, bodies[clause.a], bodies[clause.b], parameters, clause.edge.text())


class ToDimensionGraphs:
    name = "to-dimension-graphs"

    def __init__(self, domain: LayoutDomain, clause_budget: int = CLAUSE_BUDGET):
        self.domain = domain
        self.clause_budget = clause_budget

    def base(self, bodies: dict[str, Body]) -> tuple[dict[str, DifferenceSystem], list[Constraint]]:
        parameters = parameters_of(self.domain)
        constraints = base_constraints(bodies, parameters)
        systems = new_systems(bodies)
        for c in constraints:
            systems[c.axis].add(c.u, c.v, c.weight)
        return systems, constraints

    def run(self, ir: QsrDnf, context: PassContext) -> Iterator[DimensionGraphs]:
        """The consistent dimension graphs of the DNF `ir`, lazily, shapes drawn from the context's
        layout graph with its generator; Infeasible when they run out."""
        dnf = ir
        self._check_size(context.scenario)
        counts = _Counts()
        bodies: dict[str, Body] = {}
        for draw in range(MAX_SHAPE_DRAWS):
            # Each draw yields the consistent conjunctions for its shapes; once some were
            # found, the caller decides how many it wants (its budget of layouts) and shapes
            # are drawn on for it; if none are, the search gives up after SHAPE_DRAWS.
            if draw >= SHAPE_DRAWS and not counts.found:
                break
            bodies = self.domain.concretize(context.graph, context.scenario, context.rng)
            try:
                systems, base = self.base(bodies)
            except Inconsistent:  # these shapes do not fit the placement area at all: draw others
                counts.misfits += 1
                continue
            counts.nodes = 0
            try:
                for consistent, chosen in self._walk(dnf, bodies, counts, 0, systems, ()):
                    counts.found += 1
                    yield DimensionGraphs(
                        scenario=dnf.scenario,
                        seed=dnf.seed,
                        bodies=tuple(bodies.values()),
                        conjunction=tuple(
                            ChosenRelation(r, c.a, c.b, c.edge.text(), tuple(c.relations)) for c, r, _ in chosen
                        ),
                        constraints=tuple(base) + tuple(k for _, _, cs in chosen for k in cs),
                        conjunctions_tried=counts.tried,
                        conjunctions_rejected=counts.rejected,
                        dnf_size=dnf.size,
                        shape_draws=draw + 1,
                        systems=consistent,
                    )
                    counts.rejected += 1  # the caller came back: it could not use this one
            except _BudgetSpent:
                raise Infeasible(
                    self.name,
                    f"the search budget ran out after {readable(counts.tried)} of {readable(dnf.size)} conjunctions",
                    tried=counts.tried,
                    budget=Exhausted.CLAUSES,
                ) from None
        raise self._exhausted(dnf, bodies, counts)

    def _check_size(self, scenario: ScenarioIR) -> None:
        """Infeasible for a scenario larger than the search takes (MAX_INTERACTIONS)."""
        if len(scenario.interactions) > MAX_INTERACTIONS:
            raise Infeasible(
                self.name,
                f"the scenario has {len(scenario.interactions)} interactions; the layout search takes at most "
                f"{MAX_INTERACTIONS} (its time and memory grow with the cube of the interactions)",
                budget=Exhausted.SIZE,
            )

    def _walk(
        self,
        dnf: QsrDnf,
        bodies: dict[str, Body],
        counts: _Counts,
        depth: int,
        current: dict[str, DifferenceSystem],
        chosen: Chosen,
    ) -> Iterator[tuple[dict[str, DifferenceSystem], Chosen]]:
        """The consistent conjunctions below a prefix, depth-first in the DNF's order; a prefix
        that closes a negative cycle counts every conjunction below it as rejected."""
        if depth == len(dnf.clauses):
            counts.tried += 1
            yield current, chosen
            return
        clause = dnf.clauses[depth]
        parameters = parameters_of(self.domain)
        for relation in clause.relations:
            counts.nodes += 1
            if counts.nodes > self.clause_budget:
                raise _BudgetSpent()
            budget.check()
            constraints = clause_constraints(clause, relation, bodies, parameters)
            try:
                following = _apply(current, constraints)
            except Inconsistent:
                counts.rejected += dnf.remaining(depth + 1)
                counts.tried += dnf.remaining(depth + 1)
                continue
            yield from self._walk(
                dnf, bodies, counts, depth + 1, following, chosen + ((clause, relation, tuple(constraints)),)
            )

    def _exhausted(self, dnf: QsrDnf, bodies: dict[str, Body], counts: _Counts) -> Infeasible:
        """Why the shape draws ended without a usable conjunction: all used, no shapes fit, or
        none consistent (with a minimal conflicting set of edges, from the last shapes drawn)."""
        if counts.found:
            return Infeasible(
                self.name,
                f"the {counts.found} consistent conjunctions of {MAX_SHAPE_DRAWS} shape draws were all used",
                tried=counts.tried,
            )
        if counts.misfits == SHAPE_DRAWS:
            return Infeasible(
                self.name,
                f"the objects' shapes, drawn {SHAPE_DRAWS} times, never fit the placement area",
                tried=counts.tried,
            )
        conflicts = self.explain(dnf, bodies)
        return Infeasible(
            self.name,
            f"no conjunction of the {readable(dnf.size)} is consistent (shapes drawn {SHAPE_DRAWS} times)",
            conflicts=conflicts,
            tried=counts.tried,
        )

    def explain(self, dnf: QsrDnf, bodies: dict[str, Body]) -> tuple[LayoutEdge, ...]:
        """A minimal set of layout edges whose QSRs cannot all hold (deletion-based)."""
        parameters = parameters_of(self.domain)
        try:
            systems, _ = self.base(bodies)
        except Inconsistent:  # the last shapes drawn did not fit: nothing to explain by the clauses
            return ()
        left = [self.clause_budget]

        def feasible(clauses: list[QsrClause]) -> bool:
            def walk(depth: int, current: dict[str, DifferenceSystem]) -> bool:
                if depth == len(clauses):
                    return True
                for relation in clauses[depth].relations:
                    left[0] -= 1
                    if left[0] < 0:
                        raise _BudgetSpent()
                    budget.check()
                    try:
                        following = _apply(current, clause_constraints(clauses[depth], relation, bodies, parameters))
                    except Inconsistent:
                        continue
                    if walk(depth + 1, following):
                        return True
                return False

            return walk(0, systems)

        active = list(dnf.clauses)
        try:
            for clause in list(active):
                trial = [c for c in active if c is not clause]
                if not feasible(trial):
                    active = trial
        except _BudgetSpent:
            pass  # not minimal, but still a conflicting set
        return tuple(c.edge for c in active)
