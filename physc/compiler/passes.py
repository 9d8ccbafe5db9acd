"""What a compiler pass is: one `run(ir, context)` signature, as in LLVM's pass manager.

Every pass of the middle end (infer-layout, to-qsr, to-dimension-graphs, place) is
constructed with its configuration (the domain, its budgets) and then `run(ir, context)`
turns the previous stage's IR into the next one. The `PassContext` carries what every pass
may read besides its input: the checked scenario, the run's one seeded generator (drawn
from in pipeline order, so a seed gives one compile), the seed, and the earlier IRs a later
pass needs (the layout graph, the DNF's deferred edges). `LayoutDomain` is what the passes
ask of a domain (physc.domains.base.Domain has it; the compiler does not import upwards).
"""

from __future__ import annotations

import random
from typing import TYPE_CHECKING, Protocol, TypeVar

import attrs

if TYPE_CHECKING:
    from physc.compiler.concrete_layout import Body
    from physc.compiler.dimension_graphs import LayoutParameters
    from physc.compiler.layout_graph import LayoutEdge, LayoutGraph
    from physc.compiler.layout_rules import LayoutRules
    from physc.dsl.scenario import ScenarioIR

In = TypeVar("In", contravariant=True)
Out = TypeVar("Out", covariant=True)


@attrs.frozen
class PassContext:
    """What every pass may read besides its input IR (module docstring)."""

    scenario: ScenarioIR
    rng: random.Random  # the run's one generator, seeded once (random.Random(seed))
    seed: int
    layout_graph: LayoutGraph | None = None  # for to-dimension-graphs (the shapes are drawn from it)
    deferred: tuple[LayoutEdge, ...] = ()  # the DNF's edges left to simulation, which place records

    @property
    def graph(self) -> LayoutGraph:
        """The layout graph, for the passes after infer-layout (the driver puts it here)."""
        if self.layout_graph is None:
            raise ValueError("this pass reads the layout graph, which its context does not carry")
        return self.layout_graph


class Pass(Protocol[In, Out]):
    """A compiler pass: anything with a name and this `run`."""

    @property
    def name(self) -> str: ...  # the pass's name in diagnostics ("to-qsr")

    def run(self, ir: In, context: PassContext) -> Out: ...


class LayoutDomain(Protocol):
    """What the compiler's passes ask of a domain (physc.domains.base.Domain, its
    generation capabilities)."""

    @property
    def name(self) -> str: ...

    @property
    def layout_rules(self) -> LayoutRules | None: ...

    @property
    def layout_parameters(self) -> LayoutParameters | None: ...

    def concretize(self, graph: LayoutGraph, scenario: ScenarioIR, rng: random.Random) -> dict[str, Body]: ...

    def reach_targets(self, scenario: ScenarioIR) -> list[str]: ...

    def reachable(self, x: float, y: float) -> bool: ...


def rules_of(domain: LayoutDomain) -> LayoutRules:
    """The domain's layout rules; the driver has required them (physc.domains.base.require)."""
    rules = domain.layout_rules
    if rules is None:
        raise ValueError(f"the domain '{domain.name}' has no layout_rules")
    return rules


def parameters_of(domain: LayoutDomain) -> LayoutParameters:
    """The domain's layout parameters; the driver has required them (physc.domains.base.require)."""
    parameters = domain.layout_parameters
    if parameters is None:
        raise ValueError(f"the domain '{domain.name}' has no layout_parameters")
    return parameters
