"""The infer-layout pass: Scenario IR → Layout Graph.

The domain's layout rules translate interactions and restrictions into layout
terms and add the supports that make the task stand. This pass then removes
redundant edges, generically: duplicates, mirrored duplicates
(`inDirection(a, b, left)` is `inDirection(b, a, right)`), and a direction
edge implied by a stronger one on the same pair (`inDirection(b, a, above)`
implies `inDirection(b, a, left | right | above | below)`). The provenance of a
removed edge is kept on the edge that implies it.
"""

from __future__ import annotations

import attrs

from physc.compiler.layout_graph import IN_DIRECTION, LayoutEdge, LayoutGraph
from physc.compiler.passes import LayoutDomain, PassContext, rules_of
from physc.dsl.scenario import ScenarioIR

_MIRROR = {"left": "right", "right": "left", "above": "below", "below": "above"}
_DIRECTIONAL = (IN_DIRECTION,)


def _oriented(edge: LayoutEdge) -> LayoutEdge:
    """A direction edge written with its objects in name order, for comparison."""
    if edge.term in _DIRECTIONAL and edge.a > edge.b:
        return attrs.evolve(edge, a=edge.b, b=edge.a, values=tuple(_MIRROR[v] for v in edge.values))
    return edge


def remove_redundant(edges: tuple[LayoutEdge, ...]) -> tuple[LayoutEdge, ...]:
    """The edges without those another implies, each kept edge with their provenance."""
    kept: list[LayoutEdge] = []
    for edge in edges:
        merged = False
        for index, other in enumerate(kept):
            x, y = _oriented(edge), _oriented(other)
            if (x.term, x.a, x.b) != (y.term, y.a, y.b):
                continue
            if set(y.values) <= set(x.values) and (x.term in _DIRECTIONAL or x.values == y.values):
                # The kept edge is at least as strong: it implies the new one.
                kept[index] = attrs.evolve(other, provenance=other.provenance + edge.provenance)
                merged = True
                break
            if set(x.values) < set(y.values) and x.term in _DIRECTIONAL:
                # The new edge is stronger: it replaces the kept one.
                kept[index] = attrs.evolve(edge, provenance=edge.provenance + other.provenance)
                merged = True
                break
        if not merged:
            kept.append(edge)
    return tuple(kept)


class InferLayout:
    name = "infer-layout"

    def __init__(self, domain: LayoutDomain, structure: str = "flat"):
        self.domain = domain
        self.structure = structure  # the layout rules' reading (physc.compiler.layout_rules, "Structures")

    def run(self, ir: ScenarioIR, context: PassContext) -> LayoutGraph:
        """The layout graph of the scenario `ir` (the context's scenario) in this pass's structure."""
        scenario = ir
        rules = rules_of(self.domain)
        graph = rules.infer(scenario) if self.structure == "flat" else rules.infer(scenario, self.structure)
        return attrs.evolve(graph, edges=remove_redundant(graph.edges))
