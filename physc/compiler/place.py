"""The place pass: consistent dimension graphs → Concrete Layout.

Positions are sampled inside the propagated bounds: objects in a seeded order,
each centre drawn uniformly from the interval its constraints still allow on
each axis, then fixed, so that every later object is drawn from what is left
(for difference constraints any value in the interval extends to a solution).

Then two checks the constraint graphs do not express:

* objects must not overlap: when two do, a separation (W, E, N or S between
  them, in seeded order, the first that stays consistent) is added and the
  positions are drawn again;
* the objects the bird must hit directly must be in its reach at full stretch.

When neither can be met within a few attempts, the pass reports failure and the
search moves on to the next conjunction.
"""

from __future__ import annotations

import itertools
import random

from physc.compiler.concrete_layout import (
    Body,
    ChosenRelation,
    ConcreteLayout,
    PlacedObject,
)
from physc.compiler.difference import DifferenceSystem, Inconsistent
from physc.compiler.dimension_graphs import DimensionGraphs, point, relation_constraints
from physc.compiler.geometry import overlapping_pair, polygon
from physc.compiler.layout_graph import LayoutEdge
from physc.compiler.passes import LayoutDomain, PassContext, parameters_of
from physc.compiler.qsr import joined

ATTEMPTS = 12
SEPARATIONS = ("W", "E", "N", "S")
PRECISION = 6  # decimals kept in the layout


class Place:
    name = "place"

    def __init__(self, domain: LayoutDomain, attempts: int = ATTEMPTS):
        self.domain = domain
        self.attempts = attempts

    def _sample(
        self, systems: dict[str, DifferenceSystem], bodies: list[Body], rng: random.Random
    ) -> dict[str, tuple[float, float]]:
        """Each free body's centre drawn in the bounds left by those drawn before it (seeded order)."""
        current = {axis: system.copy() for axis, system in systems.items()}
        order = [b for b in bodies if b.fixed is None]
        rng.shuffle(order)
        centres = {b.name: b.fixed for b in bodies if b.fixed is not None}
        for body in order:
            values = []
            for axis in ("x", "y"):
                low, high = current[axis].bounds(point(body.name, "c"))
                value = rng.uniform(low, high) if high > low else (low + high) / 2
                current[axis].fix(point(body.name, "c"), value)
                values.append(value)
            centres[body.name] = (values[0], values[1])
        return centres

    def run(self, ir: DimensionGraphs, context: PassContext) -> ConcreteLayout | None:
        """A placed layout of the dimension graphs `ir`, or None when no attempt keeps the objects
        apart and the player's first targets in reach. Reads the context's scenario, its DNF's
        deferred edges and its generator."""
        graphs, rng = ir, context.rng
        bodies = list(graphs.bodies)
        by_name = {b.name: b for b in bodies}
        parameters = parameters_of(self.domain)
        systems = graphs.systems
        separations: list[ChosenRelation] = []
        targets = self.domain.reach_targets(context.scenario)
        for _attempt in range(self.attempts):
            centres = self._sample(systems, bodies, rng)
            placed = {b.name: b.geometry.points(*centres[b.name]) for b in bodies}
            clash = self._overlap(bodies, placed, joined(graphs.conjunction))
            if clash is not None:
                a, b = clash
                options = list(SEPARATIONS)
                rng.shuffle(options)
                for relation in options:
                    constraints = relation_constraints(
                        relation, by_name[a], by_name[b], parameters, "placement keeps them apart"
                    )
                    try:
                        updated = {axis: system.copy() for axis, system in systems.items()}
                        for c in constraints:
                            updated[c.axis].add(c.u, c.v, c.weight)
                    except Inconsistent:
                        continue
                    systems = updated
                    separations.append(ChosenRelation(relation, a, b, "no overlap"))
                    break
                else:
                    return None
                continue
            if not all(any(self.domain.reachable(*p) for p in placed[t].values()) for t in targets):
                continue
            return self._layout(self.domain.name, graphs, bodies, centres, separations, context.deferred)
        return None

    @staticmethod
    def _overlap(bodies: list[Body], placed: dict, joints: frozenset[frozenset[str]]) -> tuple[str, str] | None:
        """The first pair of bodies that overlap; the player's objects may share their place
        (several birds are shot in turn from one slingshot)."""
        outlines = {b.name: polygon(placed[b.name]) for b in bodies if b.concrete != "ground"}
        players = [b.name for b in bodies if b.role == "player"]
        turns = {frozenset(pair) for pair in itertools.combinations(players, 2)}
        return overlapping_pair(outlines, 1e-6, joints | turns)

    @staticmethod
    def _layout(
        domain_name: str,
        graphs: DimensionGraphs,
        bodies: list[Body],
        centres: dict[str, tuple[float, float]],
        separations: list[ChosenRelation],
        deferred: tuple[LayoutEdge, ...],
    ) -> ConcreteLayout:
        """The layout as placed: the bodies at their centres, rounded to PRECISION."""
        objects = tuple(
            PlacedObject(
                name=b.name,
                role=b.role,
                concrete=b.concrete,
                material=b.material,
                x=round(float(centres[b.name][0]), PRECISION),  # a Python float, not numpy's
                y=round(float(centres[b.name][1]), PRECISION),
                rotation=b.geometry.rotation,
                width=b.geometry.width,
                height=b.geometry.height,
            )
            for b in bodies
        )
        return ConcreteLayout(
            scenario=graphs.scenario,
            domain=domain_name,
            seed=graphs.seed,
            objects=objects,
            conjunction=graphs.conjunction,
            separations=tuple(separations),
            deferred=tuple(e.text() for e in deferred),
            conjunctions_tried=graphs.conjunctions_tried,
            conjunctions_rejected=graphs.conjunctions_rejected,
            shape_draws=graphs.shape_draws,
        )
