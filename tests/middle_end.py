"""Helpers for the middle-end tests: the paper's scenarios through the pipeline."""

from __future__ import annotations

import functools

from conftest import EXAMPLES

from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.driver.pipeline import Pipeline
from physc.dsl.frontend import analyze

DOMAIN = load_domain("angrybirds")


@functools.cache
def paper_scenarios():
    analysis = analyze(str(EXAMPLES / "paper" / "all.paper.phys"), INSTALLED)
    return {s.name: s for s in analysis.scenarios}


def pipeline(name: str, seed: int = 0) -> Pipeline:
    return Pipeline(DOMAIN, paper_scenarios()[name], seed)


def scenario_from_text(text: str):
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "x.phys"
        path.write_text(text)
        analysis = analyze(str(path), INSTALLED)
    assert not [d for d in analysis.diagnostics if d.is_error], analysis.diagnostics
    return analysis.scenarios[0]


class Searching:
    """The one search (physc.search.search) on one placed layout, its steps as methods of
    one object for the tests: the problem it reads and the ledger it writes."""

    def __init__(self, problem, rng):
        from physc.search.problem import Ledger

        self.problem, self.ledger, self.rng = problem, Ledger(), rng

    def __getattr__(self, name):  # what the problem reads: plan, placed, entry, frame, domain, …
        return getattr(self.problem, name)

    def with_settings(self, **settings):
        import attrs

        self.problem = attrs.evolve(self.problem, settings=attrs.evolve(self.problem.settings, **settings))
        return self

    def simulate(self, layout, action, seconds=None, resume=None):
        from physc.search.problem import simulate

        return simulate(self.problem, self.ledger, layout, action, seconds, resume)

    def realised(self, layout, parent, stage, lead=0):
        from physc.search.chain import realised

        return realised(self.problem, self.ledger, layout, parent, stage, lead)

    def variants(self, parent, stage):
        from physc.search.variants import variants

        return variants(self.problem, self.ledger, parent, stage)

    def on_path(self, layout, declared, stage, attempt):
        from physc.search.variants import on_path

        return on_path(self.problem, layout, declared, stage, attempt)

    def run(self):
        from physc.search.search import search

        return search(self.problem, self.ledger, self.rng)


def searching(domain, scenario, layout, seed: int = 0, accept: int | None = None, **settings) -> Searching:
    """The search of `layout` (accepting `accept` noisy replays: the domain's by default)."""
    import random

    from physc.search.problem import Problem

    problem = Problem.of(domain, scenario, layout, domain.robustness_replays if accept is None else accept)
    found = Searching(problem, random.Random(seed))
    return found.with_settings(**settings) if settings else found


def search(name: str, seed: int = 0, **settings) -> Searching:
    """The one search on the first placed layout of a paper scenario, with `settings` changed
    from the defaults."""
    scenario = next(s for s in analyze(str(EXAMPLES / "paper" / "all.paper.phys"), INSTALLED).scenarios if s.name == name)
    layout = Pipeline(DOMAIN, scenario, seed).placed.layout
    return searching(DOMAIN, scenario, layout, seed, **settings)
