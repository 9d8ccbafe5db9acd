"""The Layout Graph IR: objects and the layout constraints between them.

Nodes are the scenario's objects plus the support objects that inference adds
so that every dynamic object stands under gravity (the paper's grey nodes).
Edges are layout terms (the paper's "layout grammar") with their provenance:
which interaction or restriction, or which rule of the domain, produced them,
and where in the source. `physc compile --emit layout-graph` prints it as JSON,
or as Graphviz DOT with `--format dot`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import attrs

from physc.diagnostics import Span

if TYPE_CHECKING:
    import networkx as nx

# Layout terms (the paper's table "Layout grammar").
IN_DIRECTION = "inDirection"
ON_LOCATION = "onLocation"
LOCATED_FAR = "locatedFar"
TOUCHING = "touching"
PATH_OBSTRUCTED = "pathObstructed"
LIES_ON_PATH = "liesOnPath"
# Terms that only simulation can satisfy; they have no QSR translation.
SIMULATED = (LIES_ON_PATH, PATH_OBSTRUCTED)

# Node roles.
PLAYER, OBJECT, SUPPORT = "player", "object", "support"


@attrs.frozen
class Provenance:
    """Why an edge exists: a term of the scenario, or a rule of the domain."""

    rule: str  # "interaction" | "restriction" | "support" | "path"
    text: str  # the term as written, or the rule in words
    span: Span | None = None


@attrs.frozen
class LayoutNode:
    name: str
    term: str  # the object term, or "support" for an added support
    concrete: tuple[str, ...]
    static: bool
    role: str  # PLAYER | OBJECT | SUPPORT


@attrs.frozen
class LayoutEdge:
    """`term(a, b, values)`: values are the alternatives of the last argument."""

    term: str
    a: str
    b: str
    values: tuple[str, ...] = ()
    provenance: tuple[Provenance, ...] = ()

    @property
    def simulated(self) -> bool:
        return self.term in SIMULATED

    def text(self) -> str:
        args = [self.a, self.b] + ([" | ".join(self.values)] if self.values else [])
        return f"{self.term}({', '.join(args)})"


@attrs.frozen
class LayoutGraph:
    scenario: str
    domain: str
    nodes: tuple[LayoutNode, ...]
    edges: tuple[LayoutEdge, ...]
    ramps: tuple[
        str, ...
    ] = ()  # the surfaces the ramp structure made inclined (physc.compiler.layout_rules, "Structures")

    def node(self, name: str) -> LayoutNode:
        return next(n for n in self.nodes if n.name == name)

    def to_networkx(self) -> nx.MultiDiGraph:
        import networkx as nx  # only where a graph is drawn or searched: the command line starts without it

        graph = nx.MultiDiGraph(scenario=self.scenario)
        for node in self.nodes:
            graph.add_node(node.name, node=node)
        for edge in self.edges:
            graph.add_edge(edge.a, edge.b, edge=edge)
        return graph

    def to_dot(self) -> str:
        """Graphviz DOT, coloured like the paper's figure: blue objects, grey supports,
        green edges from interactions, orange from restrictions, grey from domain rules."""
        lines = [f'digraph "{self.scenario}" {{', "  rankdir=LR;", '  node [style=filled, fontname="Helvetica"];']
        fills = {PLAYER: "#9ecae1", OBJECT: "#9ecae1", SUPPORT: "#d9d9d9"}
        for node in self.nodes:
            label = f"{node.name}\\n{' | '.join(node.concrete)}"
            lines.append(f'  "{node.name}" [label="{label}", fillcolor="{fills[node.role]}"];')
        colours = {"interaction": "#31a354", "restriction": "#e6550d", "support": "#636363", "path": "#636363"}
        for edge in self.edges:
            colour = colours[edge.provenance[0].rule] if edge.provenance else "black"
            label = edge.term + (f"\\n{' | '.join(edge.values)}" if edge.values else "")
            style = ", style=dashed" if edge.simulated else ""
            lines.append(f'  "{edge.a}" -> "{edge.b}" [label="{label}", color="{colour}"{style}];')
        lines.append("}")
        return "\n".join(lines) + "\n"
