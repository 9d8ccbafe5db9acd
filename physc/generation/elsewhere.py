"""Where else a scenario may hold: the best play of a run that gave no task, replayed in the domain's other worlds.

A scenario that gives no task in one world may give one in another (Science Birds: the paper's
roll chains need circles that roll, which Phy-Q's game does not ship and `rolling` has). Exit 3
should say so only when it is measured: the play that came furthest (its layout and action) is
replayed in each other world the domain has, and a world is named when it realises more of the
declared sequence there, or the whole of it with a stronger weakest link. The replays take a
slice of the time budget kept for them (`reserve`), so that the budget stays a promise.
"""

from __future__ import annotations

import attrs

from physc import budget
from physc.simulation.fidelity import fidelity

RESERVE_SHARE = 0.1  # of the time budget, kept for the replays elsewhere
RESERVE_MOST = 3.0  # seconds at most


@attrs.frozen
class Elsewhere:
    world: str
    matched: int
    total: int
    weakest: object | None  # physc.simulation.margins.Margin of the replay there

    def text(self) -> str:
        link = f"; weakest link {self.weakest.text()}" if self.weakest is not None else ""
        return (
            f"the best layout, replayed in the world '{self.world}', realises {self.matched} of the {self.total} interactions{link}: "
            f"--world {self.world} may carry this scenario (physc worlds describes it)"
        )


def reserve(domain, time_budget: float) -> float:
    """Seconds of the budget kept for replays elsewhere: none for a domain of one world."""
    return min(RESERVE_MOST, RESERVE_SHARE * time_budget) if len(domain.worlds) > 1 else 0.0


def elsewhere(domain, scenario, furthest, best: int, weakest) -> Elsewhere | None:
    """The first other world of `domain` where the play `furthest` ((score, level, action))
    gets further than `best` interactions here, or realises the whole sequence with every
    link held where here its weakest link (`weakest`) failed; None when none does or time is out."""
    if furthest is None:
        return None
    _, level, action = furthest
    total = len(scenario.interactions)
    here = -1.0 if weakest is None else weakest.share
    for world in domain.worlds:
        if world.name == domain.world.name:
            continue
        try:
            there = domain.at(world.name)
            trace = there.play(level, action, scenario)
        except budget.OutOfTime:
            return None
        check = fidelity(scenario, trace)
        margins = there.margins(scenario, trace) if hasattr(there, "margins") else None
        link = None if margins is None else margins.weakest
        whole = check.valid and (link is None or (link.held and link.share > max(here, 0.0)))
        if check.matched > best or (best >= total and whole):
            return Elsewhere(world.name, check.matched, total, link)
    return None
