"""Physics-aware preferences for the concrete objects of a scenario.

The object grammar lets `rBlock` be any rollable object and `pig` any pig, but not
every choice can carry a chain of interactions through. Drawing such choices and
repairing them later by simulation wastes layouts, and for chains of six or eight
interactions the odds of a working draw at every link multiply to almost nothing.
So, where the scenario leaves room, the draw is narrowed to what Science Birds'
physics favours:

* a pig that a block must destroy is a small pig: life 1 against the medium pig's
  15, and a block arriving at the end of a chain has little momentum left;
* a round block that hits another round block gives it its own size: between equal
  circles on one surface the impulse passes through both centres, level with the
  surface, while a small circle hitting a large one pushes it upwards and it hops
  (and then lands on its own target from above).

A declared concrete object (`rBlock: rollableBlock = circle`) is always kept: the
preferences only choose among what the scenario allows. Materials and slider
shapes stay a free draw: fixing them (stone rollers, ice sliders, masses falling
along the chain, square sliders) did not help, and square sliders alone cost the
S scenario 4 of 30 tasks (docs/generation.md).
"""

from __future__ import annotations

from physc.compiler.layout_graph import LayoutGraph
from physc.dsl.scenario import ScenarioIR

BIRD = "bird"
ROUND = ("circle", "circleSmall")


def preferred_concrete(scenario: ScenarioIR) -> dict[str, tuple[str, ...]]:
    """The concrete objects preferred for some of the scenario's objects."""
    out: dict[str, tuple[str, ...]] = {}
    for term in scenario.interactions:
        if term.name == "destroy" and term.objects[0] != BIRD:
            out[term.objects[1]] = ("pigSmall",)
    return out


def narrowed(allowed: tuple[str, ...], preferred: tuple[str, ...]) -> tuple[str, ...]:
    """The preferred among the allowed, or all allowed when none of them is preferred."""
    both = tuple(x for x in allowed if x in preferred)
    return both or allowed


def match_round_sizes(scenario: ScenarioIR, graph: LayoutGraph, concrete: dict[str, str]) -> None:
    """In sequence order, a round block hit by a round block takes its hitter's size
    (when the scenario allows it)."""
    allowed = {node.name: node.concrete for node in graph.nodes}
    for term in scenario.interactions:
        if term.name != "hit":
            continue
        a, b = term.objects
        if concrete.get(a) in ROUND and concrete.get(b) in ROUND and concrete[a] in allowed.get(b, ()):
            concrete[b] = concrete[a]


def choose_concrete(scenario: ScenarioIR, graph: LayoutGraph, rng) -> dict[str, str]:
    """A concrete object for every node of the layout graph, drawn with the preferences."""
    preferred = preferred_concrete(scenario)
    concrete = {node.name: rng.choice(narrowed(node.concrete, preferred.get(node.name, ()))) for node in graph.nodes}
    match_round_sizes(scenario, graph, concrete)
    return concrete
