"""A stage's variants, most promising first: what the chain search (chain.py) tries.

* **on the path** (placing.py): the stage's new object where the simulated prefix says its
  actor goes, for each of the beam's first two actions: touching it from a declared side every
  `step` of travel, for a hit (or any other meeting); under where the actor comes down, for a
  fall (behind its centre first if it is to move next);
* **with the body its meeting favours** (choosing.py), at each place;
* **behind its blocker**, for b of a `blocks(a, b)` (`behind`);
* **as placed**;
* **local changes** (proposals.py, then the domain's own) for the first interaction the
  stage's best failed attempt missed; a change that comes nearer but not all the way is
  changed again (`repair_depth` deep).
"""

from __future__ import annotations

import itertools

from physc.search import choosing, placing, proposals
from physc.search.attempt import Attempt
from physc.search.chain_stages import ChainStage, prefix
from physc.search.coordinates import structures
from physc.search.problem import Ledger, Problem

ALONG = (
    "roll",
    "slide",
    "bounce",
    "destroy",
)  # terms whose second object is not met on the path (what it moves on, or what it already met)


def variants(problem: Problem, ledger: Ledger, parent, stage: ChainStage):
    """(description, layout, lead): the new objects on the path with the bodies the meeting
    favours, the layout as placed (with those bodies), then the local changes."""
    seen = set()
    offered = []
    interactions = problem.interactions
    if parent.attempts and stage.start < len(interactions):
        declared = interactions[stage.start]
        for lead, attempt in enumerate(parent.attempts[:2]):
            offered.append(
                (
                    lead,
                    itertools.islice(
                        on_path(problem, parent.layout, declared, stage, attempt), problem.settings.places
                    ),
                )
            )
    offered.append((0, behind(problem, parent.layout, stage)))
    offered.append((0, iter([("", parent.layout)])))
    for lead, found in offered:
        for description, layout in found:
            for body_note, bodied in with_bodies(problem, layout, parent, stage, lead):
                if bodied.objects not in seen:
                    seen.add(bodied.objects)
                    yield ", ".join(x for x in (description, body_note) if x), bodied, lead
    yield from repaired(problem, ledger, parent, stage, seen)


BEHIND_GAPS = (1.25, 2.0, 3.0)  # the gap between a blocker and what it shields, in the blocker's widths


def behind(problem: Problem, layout, stage: ChainStage):
    """(description, layout) for each `blocks(a, b)` whose b enters at this stage: b's structure
    (b, what it rests on and what rests on it) moved to stand behind where a stands, as the
    player's shots come (`rules.player_heading`): b's bottom level with a's, a gap of
    BEHIND_GAPS of a's width between them, room for a to fall out of the way; so that a bars the
    direct way to b until it is cleared, as Phy-Q's clearing-path levels stand."""
    terms = [t for t in problem.scenario.restrictions if t.name == "blocks" and t.objects[1] in stage.new]
    if not terms:
        return
    objects = {o.name: o for o in layout.objects}
    heading = 1.0 if (problem.rules.player_heading or "right") == "right" else -1.0
    groups = structures(layout)
    for term in terms:
        a, b = term.objects
        if a not in objects or b not in objects or a in groups[b]:
            continue
        left_a, bottom_a, right_a, _ = placing.box(objects[a])
        left_b, bottom_b, right_b, _ = placing.box(objects[b])
        moved = groups[b] - problem.players
        if any(objects[n].concrete in placing.GROUND or objects[n].role == "obstacle" for n in moved):
            continue  # on the ground (or held by what never moves): nothing to move it with
        for gap in BEHIND_GAPS:
            width = gap * (right_a - left_a)
            dx = (right_a + width - left_b) if heading > 0 else (left_a - width - right_b)
            candidate = placing.shifted(layout, set(moved), dx, bottom_a - bottom_b, problem.supports)
            if candidate is not None and placing.consistent(candidate, problem.parameters, set(moved), set(moved)):
                yield f"{b} behind {a}, {gap:g} of its widths beyond it", candidate


def repaired(problem: Problem, ledger: Ledger, parent, stage: ChainStage, seen: set, depth: int = 0):
    """Local changes (proposals.py, then the domain's own) for the first interaction the
    stage's best failed attempt missed; a change that comes nearer, but not all the way, is
    changed in turn (up to `repair_depth` on top of one another)."""
    failed = ledger.failed.get(stage.index)
    if failed is None:
        return
    base = parent.layout if depth == 0 else ledger.failed_layout.get(stage.index, parent.layout)
    lead = next((j for j, a in enumerate(parent.attempts) if a.label == failed.label), 0)
    changes = itertools.chain(
        proposals.offered(problem, base, failed, stage.start),
        problem.domain.search.proposals(base, problem.scenario, failed, stage.start),
    )
    for description, layout in itertools.islice(changes, problem.settings.proposals):
        if layout.objects in seen:
            continue
        seen.add(layout.objects)
        yield description, layout, lead
        if (
            depth < problem.settings.repair_depth and ledger.failed_layout.get(stage.index) is layout
        ):  # nearer: change it further
            yield from repaired(problem, ledger, parent, stage, seen, depth + 1)
            return


def with_bodies(problem: Problem, layout, parent, stage: ChainStage, lead: int):
    """`layout` as it is, then with other bodies for the stage's new object that the meeting's
    physics favours (choosing.py)."""
    yield "", layout
    if not parent.attempts or stage.start >= len(problem.interactions):
        return
    declared = problem.interactions[stage.start]
    attempt = parent.attempts[min(lead, len(parent.attempts) - 1)]
    yield from itertools.islice(
        choosing.alternatives(problem, layout, declared, stage, attempt), problem.settings.bodies - 1
    )


def on_path(problem: Problem, layout, declared, stage: ChainStage, attempt: Attempt):
    """Layouts with the stage's first new object where `attempt`'s actor meets it: under where
    it comes down, for a fall; touching it from a declared side, for a hit or any other meeting
    of two objects (PHYRE's and other domains' `touch`)."""
    actor, target = (tuple(declared.objects) + (None,))[:2]
    supports = problem.supports
    if declared.name in ALONG or target not in stage.new or actor not in attempt.trace.names:
        return
    objects = {o.name: o for o in layout.objects}
    if target not in objects or target in supports.fixed:
        return  # a surface is placed by the layout, with the shelf it belongs to
    trace = attempt.trace
    interactions = problem.interactions
    settings = problem.settings
    k = stage.start
    since = attempt.fidelity.times[k - 1] if k else 0.0
    if k and interactions[k - 1].name in ("roll", "slide", "fall"):
        since += settings.settle
    first = int(since / trace.dt)
    members = supports.movers(target, problem.entry)
    sizes = {o.name: (o.width, o.height) for o in layout.objects}
    actor_size = sizes.get(actor, (0.0, 0.0))
    places = []
    # The actor's path, then its parts' (a blue bird's other birds after its split).
    for body in [actor] + sorted(n for n, whole in trace.parts.items() if whole == actor):
        rows = trace.states[first:, trace.index(body), :]
        if declared.name != "fall":
            sideways = supports.sideways_only(target)
            found = list(
                placing.hit_places(
                    actor_size, objects[target], rows, declared.directions, sideways, problem.scale, settings
                )
            )
            if sideways and "above" in declared.directions:
                found = list(placing.landings(actor_size, objects[target], rows, problem.scale)) + found
        else:
            heading = problem.heading_after(target, k + 1)
            behind = None if heading is None else (1.0 if heading == "left" else -1.0)
            found = list(placing.landings(actor_size, objects[target], rows, problem.scale, behind))
        places += [(step, x, y, body) for step, x, y in found]
    pushed = None
    if declared.name == "hit" and target in supports.support_of:
        acts_next = next((t for t in interactions[k + 1 :] if t.objects and t.objects[0] == target), None)
        if acts_next is not None and acts_next.name == "fall":
            pushed = problem.pushed_by(k)
    for step, x, y, body in places:
        moved = placing.shifted(layout, members, x - objects[target].x, y - objects[target].y, supports)
        if moved is None:
            continue
        changed = [o for o in moved.objects if o.name in members]
        if not placing.clear(trace, first + step, changed, body, sizes, problem.scale, settings.clear):
            continue
        if not placing.consistent(prefix(moved, problem.entry, stage.start), problem.parameters, members, members):
            continue
        where = next(o for o in changed if o.name == target)
        description = f"{declared.text}: {target} on its path, at ({where.x:.2f}, {where.y:.2f})"
        if pushed is not None:  # it falls next: its ledge ending at it first, so that the push takes it over
            support = supports.support_of[target]
            edged = proposals.ledge_ends_at(
                problem, moved, {o.name: o for o in moved.objects}, target, support, pushed, stage.start
            )
            if edged is not None:
                yield f"{description}, {support} ending at it", edged
        yield description, moved
