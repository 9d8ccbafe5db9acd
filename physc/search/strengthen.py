"""A realised chain made to hold under noise: its margins measured and its weakest links raised.

A working action is replayed under the domain's noise model (`actions.noisy`, the evaluation's)
`robustness_replays` times, each replay's noise drawn from its own named generator, and each
replay's links read for their margins (physc.simulation.margins, under the worst reading of
what the world's files leave open). One that keeps every link in every replay, with a margin
under every reading, must then pass as many fresh replays too (the second of NOISE_STREAMS:
it was chosen for passing the first).

One that does not is **improved rather than discarded**: the coordinates its weak links
depend on are moved by CMA-ES to raise the least margin across the same replays (raising.py).
The first candidate that keeps every link in every replay with `raise_enough` of its margin to
spare, and passes the fresh replays, is the solution; when none does within
`raise_evaluations`, the best that passes them all is, else the layout is given up as fragile.
"""

from __future__ import annotations

import random
from collections import Counter

import attrs
import numpy as np

from physc.compiler.concrete_layout import ConcreteLayout
from physc.search.attempt import Attempt
from physc.search.chain import Node, score
from physc.search.coordinates import Coordinates, weak_parts
from physc.search.problem import Ledger, Problem, replayed, simulate
from physc.search.raising import Candidate, climb
from physc.search.settings import NOISE_STREAMS
from physc.simulation.margins import Margin, Margins
from physc.simulation.stopped import why_stopped


@attrs.frozen
class Replays:
    """An action's noisy replays in one layout: how many kept the chain, each replay's score,
    and the weakest link over them (None when a replay lost a link)."""

    passed: int
    scores: tuple[float, ...]
    weakest: Margin | None
    margins: tuple[Margins, ...] = ()

    @property
    def least(self) -> float:
        return min(self.scores, default=0.0)

    @property
    def value(self) -> float:
        """What the optimiser raises: the least score, and a tenth of the mean."""
        return self.least + 0.1 * float(np.mean(self.scores)) if self.scores else 0.0


def replays(
    problem: Problem,
    ledger: Ledger,
    attempt: Attempt,
    layout: ConcreteLayout,
    stream: str = NOISE_STREAMS[0],
    action: object = None,
    count: bool = True,
) -> Replays:
    """The domain's noisy replays of `attempt` (or of `action`, with the attempt's noise) in
    `layout`; replay r's noise is drawn from a generator named after the stream, the attempt's
    label and r. With `count`, each failed replay is counted against the link it lost (`lose`)."""
    domain = problem.domain
    level = problem.level_of(layout)
    total = len(problem.interactions)
    passed, scores, read = 0, [], []
    for r in range(domain.robustness_replays or 0):
        noise = random.Random(f"{stream}/{attempt.label}/{r}")
        noisy_level, noisy_action = domain.actions.noisy(level, attempt.action if action is None else action, noise)
        played = replayed(problem, ledger, noisy_level, noisy_action)
        margins = domain.margins(problem.scenario, played.trace)
        valid = played.fidelity.valid
        passed += valid
        scores.append(
            score(margins, total, played.fidelity.matched)
            if valid
            else min(score(margins, total, played.fidelity.matched), -1e-3)
        )
        read.append(margins)
        if not valid and count:
            lose(problem, ledger, played)
    weakest = None
    if passed == len(scores):
        weakest = min((m.weakest for m in read if m.weakest is not None), key=lambda m: m.share, default=None)
    return Replays(passed, tuple(scores), weakest, tuple(read))


def lose(problem: Problem, ledger: Ledger, played: Attempt) -> None:
    """Count a failed noisy replay against the declared interaction it lost first (a restriction
    it broke, when it realised them all), with what the first such replay shows."""
    interactions = problem.interactions
    k = played.fidelity.matched
    term = interactions[k].text if k < len(interactions) else "the restrictions"
    count, why = ledger.lost.get(term, (0, None))
    if why is None:
        why = (
            why_stopped(problem.scenario, played.trace, played.fidelity)
            if k < len(interactions)
            else ", ".join(played.fidelity.violations)
        )
    ledger.lost[term] = (count + 1, why)


def lost_links(ledger: Ledger) -> tuple[tuple[str, int, str], ...]:
    """The noisy replays' losses (Outcome.lost), most often lost first."""
    return tuple(sorted(((term, n, why) for term, (n, why) in ledger.lost.items()), key=lambda item: -item[1]))


def holds_up(problem: Problem, ledger: Ledger, attempt: Attempt, layout: ConcreteLayout) -> bool:
    """Whether the solution in `layout` still passes as many noisy replays as it must, in both
    noise streams (a change made after the confirmation is itself chosen for passing the
    replays it is checked with)."""
    return all(replays(problem, ledger, attempt, layout, stream).passed >= problem.accept for stream in NOISE_STREAMS)


def least_passed(problem: Problem, ledger: Ledger, attempt: Attempt, layout: ConcreteLayout) -> int:
    """The noisy replays the solution in `layout` passes in the noise stream it passes fewer of
    (`holds_up` asks only whether both reach what it must pass)."""
    return min(replays(problem, ledger, attempt, layout, stream).passed for stream in NOISE_STREAMS)


@attrs.frozen
class Strong:
    """A solution that holds under noise: its layout, its attempt, the replays it passed (the
    fewer of the two streams), the weakest link over them, and how the margins were raised."""

    layout: ConcreteLayout
    attempt: Attempt
    passed: int
    weakest: Margin | None
    raised: str = ""


def strengthen(problem: Problem, ledger: Ledger, node: Node) -> Strong | None:
    """The first working action of the chain's last stage that holds under noise, raised if
    need be (module docstring); None when none of the first `candidates` does."""
    settings = problem.settings
    for attempt in node.attempts:
        if not attempt.fidelity.valid:
            continue
        ledger.tried += 1
        first = replays(problem, ledger, attempt, node.layout)
        if first.passed >= problem.accept and first.least >= 0:
            strong = confirmed(problem, ledger, node.layout, attempt, first)
            if strong is not None:
                return strong
        if ledger.tried <= settings.raise_candidates:
            strong = raised(problem, ledger, node.layout, attempt, first)
            if strong is not None:
                return strong
        if first.passed >= problem.accept:  # it holds without a margin under every reading: the world's check decides
            strong = confirmed(problem, ledger, node.layout, attempt, first)
            if strong is not None:
                return strong
        if first.passed < problem.accept:  # else confirmed() noted the fewer of the two streams
            ledger.nearest = max(ledger.nearest, first.passed)
        note_weakest(ledger, first)
        if ledger.tried >= settings.candidates:
            return None
    return None


def confirmed(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, attempt: Attempt, first: Replays, raised: str = ""
) -> Strong | None:
    """`attempt` in `layout` if it passes as many fresh replays as it must (the second stream)."""
    fresh = replays(problem, ledger, attempt, layout, NOISE_STREAMS[1])
    if fresh.passed < problem.accept:
        ledger.nearest = max(ledger.nearest, min(first.passed, fresh.passed))
        note_weakest(ledger, fresh)
        return None
    weakest = min((w for w in (first.weakest, fresh.weakest) if w is not None), key=lambda m: m.share, default=None)
    return Strong(layout, attempt, min(first.passed, fresh.passed), weakest, raised)


def note_weakest(ledger: Ledger, measured: Replays) -> None:
    """Keep the strongest weakest link of the chains that did not hold (exit 3 names it)."""
    links = [m.weakest for m in measured.margins if m.weakest is not None]
    if not links:
        return
    worst = min(links, key=lambda m: (m.held, m.share))
    if ledger.weakest is None or (worst.held, worst.share) > (ledger.weakest.held, ledger.weakest.share):
        ledger.weakest = worst


def weak_objects(problem: Problem, measured: Replays) -> tuple[set[str], list[tuple[str, str]]]:
    """What the links the replays found weakest (the most often weakest two) depend on
    (coordinates.weak_parts): what the raising moves."""
    weakest = [m.weakest for m in measured.margins if m.weakest is not None]
    counts = Counter(m.term for m in weakest)
    names: set[str] = set()
    pairs: list[tuple[str, str]] = []
    for term, _ in counts.most_common(2):
        more, meets = weak_parts(problem, next(m for m in weakest if m.term == term))
        names |= more
        pairs += [pair for pair in meets if pair not in pairs]
    return names, pairs


def raised(problem: Problem, ledger: Ledger, layout: ConcreteLayout, attempt: Attempt, first: Replays) -> Strong | None:
    """The chain's weakest margins raised (raising.py) over the weak links' coordinates: the
    first candidate whose every replay keeps every link with `raise_enough` to spare and that
    passes the fresh replays, else the best that passes every replay."""
    settings = problem.settings
    total = len(problem.interactions)
    space = Coordinates.of(problem, layout, attempt.action, *weak_objects(problem, first))

    def judge(candidate: ConcreteLayout, action: object, notes: str) -> Candidate[tuple[Attempt, Replays]]:
        nominal = simulate(problem, ledger, candidate, action)
        own = score(problem.domain.margins(problem.scenario, nominal.trace), total, nominal.fidelity.matched)
        if not nominal.fidelity.valid:
            return Candidate(candidate, action, notes, own - 1.0, False, False)
        measured = replays(problem, ledger, attempt, candidate, action=action, count=False)
        note_weakest(ledger, measured)
        value = min(measured.value, own)
        better = attrs.evolve(attempt, action=action, trace=nominal.trace, fidelity=nominal.fidelity)
        holds = measured.passed >= problem.accept
        return Candidate(
            candidate,
            action,
            notes,
            value,
            holds and min(measured.least, own) >= settings.raise_enough,
            holds,
            (better, measured),
        )

    def accept(candidate: Candidate[tuple[Attempt, Replays]]) -> Strong | None:
        assert candidate.found is not None, "a candidate the climb gives passed, and carries its plays"
        better, measured = candidate.found
        return confirmed(problem, ledger, candidate.layout, better, measured, candidate.notes)

    return climb(problem, ledger, space, judge, attempt.label, settings.raise_evaluations, settings.raise_sigma, accept)
