"""The chain, stage by stage: depth first over the stages of a placed layout, with a beam,
each stage's variants ranked by the margins they leave.

The first stage is simulated with every candidate action of the domain; each later stage
with the actions that realised the one before (the `beam` best). A stage's variants are its
new objects put where the simulated prefix says their actor goes, with the bodies the physics
of the meeting favours, the layout as placed, then local changes (variants.py). A variant
that realises the stage is then replayed under the domain's noise (`stage_replays` times);
its *strength* is the least margin any of those replays leaves the stage's links
(physc.simulation.margins; negative when a replay loses one). A strong variant (strength ≥ 0:
every replay keeps every link) becomes the parent of the next stage at once; weak ones are
kept: once `weak_kept` of them have come with no strong one, the strongest goes on, and the
rest are tried in order of strength when the stage's variants are spent. So a chain is built
on links that survive their noise where the layout has them, rather than on the first that
happened once.
"""

from __future__ import annotations

import random

import attrs
import numpy as np

from physc import budget
from physc.compiler.concrete_layout import ConcreteLayout
from physc.search.attempt import Attempt, reaches
from physc.search.chain_stages import ChainStage, prefix
from physc.search.coordinates import Coordinates, weak_parts
from physc.search.problem import Ledger, Problem, replayed, simulate
from physc.search.raising import Candidate, climb
from physc.search.snapshots import snapshot
from physc.search.variants import variants
from physc.simulation.margins import Margin, Margins


@attrs.frozen
class Node:
    """A layout that realises the sequence up to the end of stage `stage`, with the attempts
    that realise it (best first), the steps that built it and the least strength of its stages."""

    layout: ConcreteLayout
    attempts: tuple[Attempt, ...]
    stage: int
    steps: tuple[str, ...] = ()
    strength: float = float("inf")


def stage_margins(problem: Problem, trace, end: int) -> Margins:
    """The margins of a stage's play, through its `end`; where the player acts again there,
    with what that action's first link needs of the play (SimulatedDomain.margins' `ahead`:
    what it acts on still there, with life to spare): the first shot's outcome is chosen for
    what the later shot needs, not found wanting only once that shot is tried."""
    if end in problem.action_starts:
        return problem.domain.margins(problem.scenario, trace, end, ahead=True)
    return problem.domain.margins(problem.scenario, trace, end)


def score(margins: Margins, end: int, matched: int) -> float:
    """One play's margin over the first `end` declared links (and the restrictions), of which it
    realised the first `matched`: the weakest link's share, at most 2, when every one held; below
    0 when one failed or a restriction broke, the lower the earlier."""
    links = [m for m in margins.links if m.index is None or m.index <= end]  # (at `end`: what it needs ahead)
    failed = [m for m in links if not m.held]
    if matched >= end and not failed:
        return min([2.0] + [m.share for m in links])
    where = {id(m): (m.index if m.index is not None else end - 1) for m in failed}
    first = min([min(matched, end - 1)] + list(where.values()))
    share = min([0.0] + [m.share for m in failed if where[id(m)] == first])
    return -(end - first) / max(end, 1) + max(share, -1.0) / max(end, 1) - 1e-3


def chain(problem: Problem, ledger: Ledger, parent: Node, i: int) -> Node | None:
    """The stages from `problem.plan[i]` on, depth first (module docstring)."""
    if i == len(problem.plan):
        return parent
    stage = problem.plan[i]
    ledger.turn(stage.span)
    settings = problem.settings
    offered = 0
    weak: list[tuple[float, int, Node]] = []
    for description, layout, lead in variants(problem, ledger, parent, stage):
        if ledger.variants_tried >= settings.variants or offered >= settings.variants_per_stage:
            break
        budget.check()
        offered += 1
        ledger.variants_tried += 1
        attempts = realised(problem, ledger, layout, parent, stage, lead)
        if not attempts:
            continue
        ledger.passage.realised.add(stage.span)
        steps = parent.steps + ((description,) if description else ())
        strength = stage_strength(problem, ledger, layout, stage, attempts[0])
        node = Node(layout, attempts, stage.index, steps, min(parent.strength, strength))
        if strength >= 0:
            found = deeper(problem, ledger, node, i)
            if found is not None:
                return found
            continue
        weak.append((strength, len(weak), node))
        if len(weak) == settings.weak_kept:  # no strong one among the first few: go on with the strongest of them
            weak.sort(key=lambda item: (-item[0], item[1]))
            found = deeper(problem, ledger, weak.pop(0)[2], i)
            if found is not None:
                return found
    weak.sort(key=lambda item: (-item[0], item[1]))
    if ledger.stages_raised < settings.raise_stages and ledger.variants_tried < settings.variants:
        ledger.stages_raised += 1
        ledger.variants_tried += 1
        if weak:
            base, lost = weak[0][2].layout, weak[0][2].attempts[0]
        else:  # the best play of a variant that failed here, and its layout (noted together)
            base, lost = ledger.failed_layout.get(stage.index), ledger.failed.get(stage.index)
        node = (
            raise_stage(problem, ledger, parent, stage, base, lost) if base is not None and lost is not None else None
        )
        if node is not None:
            ledger.passage.realised.add(stage.span)
            found = deeper(problem, ledger, node, i)
            if found is not None:
                return found
    for _, _, node in weak:
        found = deeper(problem, ledger, node, i)
        if found is not None:
            return found
    return None


def deeper(problem: Problem, ledger: Ledger, node: Node, i: int) -> Node | None:
    """The stages after `problem.plan[i]` from `node`; back at stage i when they fail."""
    found = chain(problem, ledger, node, i + 1)
    if found is None:
        ledger.turn(problem.plan[i].span)
    return found


def raise_stage(
    problem: Problem, ledger: Ledger, parent: Node, stage: ChainStage, layout: ConcreteLayout, attempt: Attempt
) -> Node | None:
    """The stage's failed or weak link raised (raising.py): the coordinates of the link the
    play lost or kept least of (and of the link after it) and the action moved by CMA-ES to
    raise the stage's strength; the first strong candidate, else the strongest that realises
    the stage, as a node; None when none realises it."""
    weakest = stage_margins(problem, attempt.trace, stage.end).weakest
    interactions = problem.interactions
    k = (
        min(attempt.fidelity.matched, len(interactions) - 1)
        if weakest is None or weakest.index is None
        else weakest.index
    )
    if weakest is None:
        weakest = Margin.failed(interactions[k].text, k, what="", unit="")
    space = Coordinates.of(problem, layout, attempt.action, *weak_parts(problem, weakest))

    def judge(candidate: ConcreteLayout, action: object, notes: str) -> Candidate[Attempt]:
        scene = prefix(candidate, problem.entry, stage.start)
        played = attrs.evolve(simulate(problem, ledger, scene, action), label=attempt.label)
        if not passes(problem, played, stage, candidate):
            return Candidate(
                candidate,
                action,
                notes,
                score(stage_margins(problem, played.trace, stage.end), stage.end, played.fidelity.matched) - 1.0,
                False,
                False,
            )
        strength = stage_strength(problem, ledger, candidate, stage, played)
        return Candidate(candidate, action, notes, strength, strength >= 0, True, played)

    settings = problem.settings
    found = climb(
        problem,
        ledger,
        space,
        judge,
        f"{stage.index}/{attempt.label}",
        settings.raise_stage_evaluations,
        settings.raise_stage_sigma,
        lambda candidate: candidate,
    )
    if found is None:
        return None
    assert found.found is not None, "a candidate the climb gives passed, and carries its play"
    step = f"{weakest.term}: margins raised: {found.notes or 'as placed'}"
    return Node(found.layout, (found.found,), stage.index, parent.steps + (step,), min(parent.strength, found.value))


def stage_strength(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, stage: ChainStage, attempt: Attempt
) -> float:
    """The least margin (`score`) that `attempt`'s action leaves the links up to the stage's end
    in the stage's scene of `layout`, as played and in `stage_replays` noisy replays."""
    domain = problem.domain
    end = stage.end
    strength = score(stage_margins(problem, attempt.trace, end), end, attempt.fidelity.matched)
    replays = problem.settings.stage_replays if domain.robustness_replays else 0
    if not replays or strength < 0:
        return strength
    scene = prefix(layout, problem.entry, stage.start)
    level = problem.level_of(scene)
    for r in range(replays):
        noise = random.Random(f"stage/{stage.index}/{attempt.label}/{r}")
        noisy_level, action = domain.actions.noisy(level, attempt.action, noise)
        played = replayed(problem, ledger, noisy_level, action)
        strength = min(strength, score(stage_margins(problem, played.trace, end), end, played.fidelity.matched))
        if strength < 0:
            break
    return strength


def realised(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, parent: Node, stage: ChainStage, lead: int = 0
) -> tuple[Attempt, ...] | None:
    """The attempts, best first, that realise every interaction up to the stage's end in the
    stage's scene of `layout`: the parent's actions (the lead's first), or at the first stage
    every candidate action (those that came nearest before, first). Among those that realise
    it, the ones whose play leaves the stage's links the most margin come first."""
    domain = problem.domain
    scene = prefix(layout, problem.entry, stage.start)
    if parent.attempts and stage.start in problem.action_starts:  # the player's next action: each parent's extended
        order = [parent.attempts[lead]] + [a for j, a in enumerate(parent.attempts) if j != lead]
        level = problem.level_of(scene)
        actions = [
            (f"{a.label}; {label}", action)
            for a in order
            for label, action in domain.actions.candidates(level, problem.scenario, stage.start, a.action, a.trace)
        ]
        screen = len(actions)
    elif parent.attempts:
        order = [parent.attempts[lead]] + [a for j, a in enumerate(parent.attempts) if j != lead]
        actions, screen = [(a.label, a.action) for a in order], 1
    else:
        order = []  # no parent: no play to resume from
        actions = domain.actions.candidates(problem.level_of(scene), problem.scenario)
        actions = [c for c in actions if c[0] in ledger.screened] + [c for c in actions if c[0] not in ledger.screened]
        screen = len(ledger.screened) or len(actions)
    good, failed = [], []
    # The domain's whole run (it stops once all is at rest): a stage's path must go on long
    # enough for the next stage to read where its actor goes, which a slow roll may take
    # most of the run to show (PHYRE: a green ball reaching its ledge's end after 6 s).
    extends = parent.attempts and stage.start in problem.action_starts
    for j, (label, action) in enumerate(actions):
        resume = snapshot(problem, scene, parent, stage, order[j]) if parent.attempts and not extends else None
        attempt = attrs.evolve(simulate(problem, ledger, scene, action, None, resume), label=label)
        if resume is not None and passes(problem, attempt, stage, layout):  # confirmed from the start
            attempt = attrs.evolve(simulate(problem, ledger, scene, action), label=label)
        (good if passes(problem, attempt, stage, layout) else failed).append(attempt)
        if j + 1 == screen and not good:
            break  # those most likely to have missed it: so will the rest, mostly
    if failed:
        best = max(failed, key=lambda a: a.fidelity.score)
        if stage.index not in ledger.failed or best.fidelity.score > ledger.failed[stage.index].fidelity.score:
            ledger.failed[stage.index] = best
            ledger.failed_layout[stage.index] = layout
        if not parent.attempts and not ledger.screened:
            ledger.screened = [
                a.label for a in sorted(failed, key=lambda a: a.fidelity.score, reverse=True)[: problem.settings.screen]
            ]
    margin = {
        id(a): min(score(stage_margins(problem, a.trace, stage.end), stage.end, a.fidelity.matched), 1.0) for a in good
    }
    good.sort(key=lambda a: (a.fidelity.score[:3], margin[id(a)], promise(problem, a, stage.end)), reverse=True)
    return tuple(good[: problem.settings.beam]) or None


def passes(problem: Problem, attempt: Attempt, stage: ChainStage, layout) -> bool:
    """Whether `attempt` realises the stage and sets up the next."""
    return reaches(attempt, stage.end, len(problem.interactions)) and sets_up(problem, attempt, stage.end, layout)


def sets_up(problem: Problem, attempt: Attempt, end: int, layout) -> bool:
    """Whether `attempt` leaves the next stage something to place its new object on: the actor
    of the interaction after the first `end` comes down (by half its height) when it is to
    fall, and still moves when it is to hit; a stage whose attempts do not is a dead end,
    however its own interactions went."""
    interactions = problem.interactions
    if end >= len(interactions) or not end:
        return True
    term = interactions[end]
    actor = term.objects[0]
    objects = {o.name: o for o in layout.objects}
    if term.name not in ("fall", "hit") or actor not in objects or actor not in attempt.trace.names:
        return True
    if term.name == "fall":
        return promise(problem, attempt, end) * problem.scale >= objects[actor].height / 2
    return promise(problem, attempt, end) >= problem.settings.moving


def promise(problem: Problem, attempt: Attempt, end: int) -> float:
    """How well `attempt` sets up the interaction after the first `end`: how far its actor comes
    down, for a fall, else how fast it moves, after the last of them."""
    interactions = problem.interactions
    if end >= len(interactions) or not end:
        return 0.0
    actor = interactions[end].objects[0]
    trace = attempt.trace
    if actor not in trace.names:
        return 0.0
    rows = trace.states[int(attempt.fidelity.times[end - 1] / trace.dt) :, trace.index(actor), :]
    rows = rows[~np.isnan(rows[:, 0])]
    if not len(rows):
        return 0.0
    if interactions[end].name == "fall":
        return float(rows[0, 1] - rows[:, 1].min())
    return float(np.hypot(rows[:, 3], rows[:, 4]).max())
