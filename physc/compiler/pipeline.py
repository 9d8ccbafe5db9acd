"""The compiler pipeline: the passes in order, for one scenario and one seed.

Every stage's result is computed once and cached, so `--emit qsr` and `--emit
layout` of the same scenario and seed run the same passes on the same random
stream. The one random generator (`random.Random(seed)`) is handed to the passes
explicitly, in pipeline order; nothing else draws random numbers.
"""

from __future__ import annotations

import functools
import random

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.compiler.dimension_graphs import DimensionGraphs
from physc.compiler.infeasible import Infeasible
from physc.compiler.infer_layout import InferLayout
from physc.compiler.layout_graph import LayoutGraph
from physc.compiler.place import Place
from physc.compiler.qsr_dnf import QsrDnf
from physc.compiler.to_dimension_graphs import DEFAULT_NODE_BUDGET, ToDimensionGraphs
from physc.compiler.to_qsr import ToQsr
from physc.dsl.scenario import ScenarioIR

PLACEMENT_BUDGET = 200  # consistent conjunctions that placement may try


@attrs.frozen
class Placed:
    graphs: DimensionGraphs
    layout: ConcreteLayout


class Pipeline:
    def __init__(self, domain, scenario: ScenarioIR, seed: int = 0, budget: int = DEFAULT_NODE_BUDGET):
        self.domain = domain
        self.scenario = scenario
        self.seed = seed
        self.budget = budget  # clause choices the search may try per shape draw
        self.rng = random.Random(seed)

    @functools.cached_property
    def layout_graph(self) -> LayoutGraph:
        return InferLayout(self.domain).run(self.scenario)

    @functools.cached_property
    def qsr(self) -> QsrDnf:
        return ToQsr().run(self.layout_graph, self.rng, self.seed)

    @functools.cached_property
    def placed(self) -> Placed:
        dnf = self.qsr
        search = ToDimensionGraphs(self.domain, self.budget).run(dnf, self.layout_graph, self.scenario, self.rng)
        place = Place(self.domain)
        consistent = 0
        try:
            for graphs in search:
                consistent += 1
                layout = place.run(graphs, self.scenario, dnf.deferred, self.rng)
                if layout is not None:
                    return Placed(graphs, layout)
                if consistent >= PLACEMENT_BUDGET:
                    raise Infeasible(
                        Place.name,
                        f"{consistent} consistent conjunctions were found, but no placement kept the objects "
                        "apart and the bird's targets in reach",
                        tried=graphs.conjunctions_tried,
                        budget=True,
                    )
        except Infeasible as error:
            if consistent and not error.budget:
                raise Infeasible(
                    Place.name,
                    f"{consistent} conjunctions were consistent, but none could be placed "
                    "(objects overlap, or the bird cannot reach its target)",
                    tried=error.tried,
                ) from None
            raise
        raise AssertionError("the search ends by raising Infeasible")
