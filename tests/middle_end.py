"""Helpers for the middle-end tests: the paper's scenarios through the pipeline."""

from __future__ import annotations

import functools

from conftest import EXAMPLES
from physc.domains import load_domain
from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze
from physc.generation.pipeline import Pipeline

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


def search(name: str, seed: int = 0, **settings):
    """The one search (physc.generation.search) on the first placed layout of a paper scenario,
    with `settings` changed from the defaults."""
    import random

    import attrs

    from physc.generation.search import Search

    scenario = next(s for s in analyze(str(EXAMPLES / "paper" / "all.paper.phys"), INSTALLED).scenarios if s.name == name)
    layout = Pipeline(DOMAIN, scenario, seed).placed.layout
    found = Search(DOMAIN, scenario, layout, random.Random(seed), DOMAIN.robustness_replays)
    if settings:
        found.settings = attrs.evolve(found.settings, **settings)
    return found
