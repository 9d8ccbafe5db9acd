"""Raising a margin: CMA-ES over the coordinates a weak or failed link depends on.

The search raises margins in two places: a stage whose variants all lost a link, or kept it
only in some noisy replays (chain.py), and a whole chain that does not hold under noise
(strengthen.py). Both move the same coordinates (coordinates.py: the action along the domain's
`actions.nudged` line, the places of the weak links' objects, the lengths and slopes of their
surfaces, inside the region the layout's QSRs allow) and judge a candidate the same way: played
as is and in the same noisy replays (common random numbers), its value the least margin any of
them leaves (chain.score: a failed link's margin is negative, so a link that does not happen yet
gives a slope to climb, how far it fell short). Only what counts as good differs.

The optimiser is CMA-ES (pycma): derivative-free, made for rugged objectives of a few to a few
dozen continuous coordinates, with bounds, and deterministic for a generator of its own (here
seeded with the CRC of the action's label). It adapts its step and the correlation of the
coordinates from the ranks of the candidates alone, so the jumps where a link starts or stops
happening do not mislead it.
"""

from __future__ import annotations

import zlib
from collections.abc import Callable
from typing import Generic, TypeVar

import attrs
import numpy as np

from physc.compiler.concrete_layout import ConcreteLayout
from physc.search.coordinates import Coordinates
from physc.search.problem import Ledger, Problem

OUTSIDE = 3.0  # the value (to be minimised) of a point outside the region: worse than any play

F = TypeVar("F")  # what a judge found of a candidate
R = TypeVar("R")  # what the climb gives: a candidate its `accept` took, as `accept` makes it


@attrs.frozen
class Candidate(Generic[F]):
    """A judged candidate: its layout, action and what moved, its value (higher is better),
    whether it is good (holds with the margin asked), whether it will do when nothing better
    comes (`passing`), and what the judge found (`found`: set for every passing candidate)."""

    layout: ConcreteLayout
    action: object  # the domain's action
    notes: str
    value: float
    good: bool
    passing: bool
    found: F | None = None


def climb(
    problem: Problem,
    ledger: Ledger,
    space: Coordinates,
    judge: Callable[[ConcreteLayout, object, str], Candidate[F] | None],
    label: str,
    evaluations: int,
    sigma: float,
    accept: Callable[[Candidate[F]], R | None],
) -> R | None:
    """CMA-ES over `space` from its origin, its first step `sigma` (a share of each coordinate's
    reach): each point's layout and action judged (`judge`: None for one that cannot be
    played). The first good candidate that `accept` takes is the result; when none is within
    `evaluations` candidates, `accept` of the best passing one; else None."""
    import cma  # here, not at the top: importing it takes about 0.9 s, which a run that raises nothing never pays

    if not space.axes or evaluations <= 0:
        return None
    settings = problem.settings
    # Its own generator, named after the action: pycma's default draws from NumPy's global
    # one, which other work in the same process (Dask's threads) would share.
    generator = np.random.default_rng(zlib.crc32(f"raise/{label}".encode()))
    # A flat generation (every candidate as far from the link as the last) is common where a
    # link is far from happening: the search goes on, with CMA-ES's step widened, until its budget.
    options = {
        "bounds": [-1, 1],
        "popsize": settings.raise_population,
        "seed": np.nan,
        "verbose": -9,
        "maxfevals": evaluations,
        "randn": lambda *shape: generator.standard_normal(shape),
        "tolflatfitness": evaluations,
        "tolfun": 0,
        "tolfunhist": 0,
        # No cap on the step below the bounds' own (pycma 4.5's cap, a third of the bound range,
        # fails in a one-coordinate search when the step reaches it).
        "maxstd_boundrange": np.inf,
    }
    strategy = cma.CMAEvolutionStrategy(np.zeros(len(space.axes)), sigma, options)
    best: Candidate[F] | None = None
    evaluated = 0
    while not strategy.stop() and evaluated < evaluations:
        points = strategy.ask()
        values = []
        for point in points:
            evaluated += 1
            ledger.raised += 1
            moved = space.nearest(point)
            candidate = None if moved is None else judge(*moved)
            if candidate is None:
                values.append(OUTSIDE)
                continue
            values.append(-candidate.value)
            if candidate.good:
                taken = accept(candidate)
                if taken is not None:
                    return taken
            elif candidate.passing and (best is None or candidate.value > best.value):
                best = candidate
        strategy.tell(points, values)
    return None if best is None else accept(best)
