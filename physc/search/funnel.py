"""Where a compile's simulations go: each placed layout's way down its chain, and their sum.

A placed layout goes down the chain stage by stage (physc.search.chain_stages): a stage is
*reached* when the search tries a variant of it (its parent realised the stages before), and
*realised* when a variant's play realises its interactions. A layout whose every stage was
realised has its chain realised; it is then *kept* (the task), or lost: *to noise* (the
solution too fragile in the noisy replays), *to a reading* (it fails `physc verify` in a
reading of what the world's files leave open, or in the second backend), or *to a later
check* (guards, stability, contrasts, properties, precision, validation, acceptance). Each
simulation is counted where it was spent: at the stage being worked on, or after the chain
(raising margins, the guards and checks, verify).

A `Passage` is one layout's (the search's Ledger keeps it); a `Funnel` sums them over a
compile (the layout loop's tally), and its `record` is what the task file, exit 3 and
`physc eval`'s report show (issue 74).
"""

from __future__ import annotations

import attrs

AFTER = (-1, -1)  # the passage's key of what is spent once the chain is realised

Stage = tuple[int, int]  # a stage by its interactions, start .. end − 1 (layouts' plans may number them apart)


@attrs.define
class Passage:
    """One placed layout's way down the chain: the stages it reached and realised, the
    simulations spent at each (AFTER: once the chain was realised), and whether it was."""

    reached: set[Stage] = attrs.field(factory=set)
    realised: set[Stage] = attrs.field(factory=set)
    spent: dict[Stage, int] = attrs.field(factory=dict)
    chain: bool = False
    at: Stage | None = None  # the stage being worked on (AFTER: after the chain; None: none)
    mark: int = 0  # the simulations counted when it began

    def enter(self, stage: Stage | None, simulations: int) -> None:
        """The search turns to `stage` (None: it is done) with `simulations` run so far: what
        was run since the last turn is the last stage's."""
        if self.at is not None:
            self.spent[self.at] = self.spent.get(self.at, 0) + simulations - self.mark
        self.at, self.mark = stage, simulations
        if stage is not None and stage != AFTER:
            self.reached.add(stage)


NOISE = ("the solution was too fragile", "the obstacles made the solution fragile")
READING = ("the solution fails physc verify in the world", "the solution fails in ")


@attrs.define
class Funnel:
    """The passages of a compile's placed layouts, summed (module docstring)."""

    proposed: int = 0  # conjunctions the layout search tried for them (placed or not)
    placed: int = 0
    reached: dict[Stage, int] = attrs.field(factory=dict)
    realised: dict[Stage, int] = attrs.field(factory=dict)
    simulations: dict[Stage, int] = attrs.field(factory=dict)
    after: int = 0  # simulations once a chain was realised
    chain: int = 0  # layouts whose chain was realised
    kept: int = 0
    lost: dict[str, int] = attrs.field(factory=dict)  # "noise", "a reading", "a later check" → layouts

    def add(self, passage: Passage, simulations: int, satisfied: bool, why: str) -> None:
        """One placed layout's `passage`, which cost `simulations` in all (verify's included),
        kept (`satisfied`) or given up for `why`."""
        self.placed += 1
        for stage in passage.reached:
            self.reached[stage] = self.reached.get(stage, 0) + 1
        for stage in passage.realised:
            self.realised[stage] = self.realised.get(stage, 0) + 1
        staged = 0
        for stage, spent in passage.spent.items():
            if stage != AFTER:
                self.simulations[stage] = self.simulations.get(stage, 0) + spent
                staged += spent
        self.after += simulations - staged
        if not passage.chain:
            return
        self.chain += 1
        if satisfied:
            self.kept += 1
            return
        lost = "noise" if why in NOISE else "a reading" if why.startswith(READING) else "a later check"
        self.lost[lost] = self.lost.get(lost, 0) + 1

    def record(self, interactions) -> dict:
        """The funnel as a task file, exit 3 and `physc eval` keep it (plain data); `interactions`:
        the scenario's, whose texts name the stages."""
        texts = [t.text for t in interactions]
        return {
            "proposed": self.proposed,
            "placed": self.placed,
            "stages": [
                {
                    "interactions": " > ".join(texts[start:end]) or "(the objects no interaction names)",
                    "reached": self.reached.get((start, end), 0),
                    "realised": self.realised.get((start, end), 0),
                    "simulations": self.simulations.get((start, end), 0),
                }
                for start, end in sorted(set(self.reached) | set(self.simulations))
            ],
            "chain_realised": self.chain,
            "kept": self.kept,
            "lost": dict(sorted(self.lost.items())),
            "simulations_after_chain": self.after,
        }


def funnel_text(record: dict) -> str:
    """A funnel's record in words: "of 63 placed layouts, stage 1 (hit(bird, pig) > …) was
    realised in 60 (1,200 simulations), …; 12 realised the chain: 1 kept, 8 lost to noise"."""
    stages = "; ".join(
        f"stage {k + 1} (`{s['interactions']}`) realised in {s['realised']} of {s['reached']} reaching it"
        f" ({s['simulations']:,} simulations)"
        for k, s in enumerate(record["stages"])
    )
    lost = ", ".join(f"{n} lost to {why}" for why, n in record["lost"].items())
    chain = f"{record['chain_realised']} realised the chain" + (
        f": {record['kept']} kept" + (f", {lost}" if lost else "") if record["chain_realised"] else ""
    )
    return (
        f"of {record['placed']} placed layout{'s' if record['placed'] != 1 else ''}"
        f"{proposed(record)}, {stages}; {chain}"
        f" ({record['simulations_after_chain']:,} simulations after the chain)"
    )


def proposed(record: dict) -> str:
    """ " (from 459 conjunctions proposed)", where the record counts them."""
    count = record.get("proposed") or 0
    return f" (from {count:,} conjunctions proposed)" if count else ""
