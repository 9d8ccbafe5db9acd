"""What physc's search may ask a simulated domain beyond its levels and actions: a part of the
domain (physc.domains.part), `domain.search`. Each hook has a default that leaves its step out,
so a domain writes a subclass only for what it has (docs/plugins.md, "What the search may also ask")."""

from __future__ import annotations

import random
from collections.abc import Iterable, Sequence

from physc.domains.part import Part


class SearchHooks(Part):
    """The search's hooks of one domain (module docstring); `self.domain` is the domain bound to
    its world and engine."""

    settings = None
    """The search's budgets and beams, a physc.search.settings.SearchSettings (None: physc's
    defaults)."""

    seconds: float | None = None
    """A play's simulated time at most while searching, each turn's (None: the domain's
    `seconds`, as every other play): a domain whose plays for the search may stop sooner than
    its evaluation's says so (angrybirds)."""

    trace_scale: float = 1.0
    """Layout lengths per length of the simulation (PHYRE: pixels per metre): how a simulated
    path is read in the placed layout (physc.search.placing)."""

    blocker: str | None = None
    """The concrete object of an obstacle the guards place (a static bar); None: the domain
    places none, and its restrictions are only judged."""
    blocker_length: float = 1.0
    blocker_thickness: float = 0.1
    blocker_angles: tuple[float, ...] = ()
    """The angles (degrees) the domain's own levels lay such bars at, which the guards try first,
    the one nearest across the flight first (Science Birds: level and upright, as Phy-Q's
    templates lay most platforms); then across the flight. The default: across only."""

    priors: str | None = None
    """The package that holds the domain's priors for the proposal model, one `<world>.json` a
    world (physc.driver.link_prior; benchmarks/link_prior.py makes them); None: none, and the
    model starts from nothing."""

    def actions_at(self, level, name: str) -> Sequence[tuple[str, object]]:
        """(label, action) aimed at the object `name`: what the guards try against forbidden
        direct hits and shortcuts (the default: none, so nothing is guarded)."""
        return []

    def bodies(self, placed, scenario) -> list:
        """The other bodies `placed` (a PlacedObject) may take, as PlacedObjects of the same name
        with their concrete object, material and size: what the search chooses a new object's
        body from (physc.search.choosing). The default: none."""
        return []

    def mass(self, placed) -> float:
        """The mass of a placed body, in the units of the domain's physics (the default: its
        box's area at density 1)."""
        return placed.width * placed.height

    def friction(self, placed) -> float:
        """The friction of a placed body (the default: 0.5)."""
        return 0.5

    def toughness(self, placed) -> float:
        """The damage that destroys a placed body under the world's rules (the search gives an
        object that is to be destroyed the weakest body it may take). The default: 0, every body
        alike."""
        return 0.0

    def distractor_count(self, rng: random.Random, most: int) -> int:
        """How many distractors to try to add: for a domain that declares `distractors`, 0 to
        `most` at random (the paper's), else none."""
        return rng.randint(0, most) if "distractors" in self.domain.capabilities else 0

    def distractors(self, layout, index: int, rng: random.Random) -> Iterable:
        """Candidate distractors (PlacedObjects named for `index`), tried in turn until one is
        kept (the default: none)."""
        return ()

    def proposals(self, layout, scenario, failed, start: int):
        """(description, layout): the domain's own local changes for a stage starting at
        interaction `start` that `failed` (the best failed attempt) did not realise (the
        default: none)."""
        return ()
