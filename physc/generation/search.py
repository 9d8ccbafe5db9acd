"""The one generation search: a placed layout made a task, along its causal chain.

Every domain goes through it (angrybirds and the PHYRE-like plugin alike); a domain
supplies hooks (physc.domains.simulated.SimulatedDomain), never a search of its own.
For one placed layout (a value: every step returns a new layout, none is changed in place):

1. **Stages** (stages.py): the sequence is cut where it brings objects in; a stage's scene
   holds only what has entered so far.
2. **Depth first over stages, with a beam.** The first stage is simulated with every
   candidate action of the domain; each later stage with the actions that realised the
   one before (the `beam` best, by how much speed or drop they leave the next actor).
   A stage's *variants* are its new objects put where the simulated prefix says their actor
   goes (placing.py), each with the bodies the physics of the meeting favours
   (choosing.py), then the layout as placed, then the domain's own proposals. The first
   variant that realises the stage is the parent of the next; when none does, the
   search goes back a stage. `variants` bounds the variants a layout may cost.
3. **Robustness** (robustness.py): the first working action that passes the domain's
   noisy replays, centred if needed, and as many fresh ones.
4. **Guards** (guards.py): obstacles against forbidden direct hits (`cannotHit` of the
   player) and against shortcuts, kept only if the solution still holds up.
5. **Distraction**: the domain's distractors, each kept only if the level still stands and
   the solution still holds up, and it is no way to solve the task.
6. **Stability** of the finished level, and **validation** (unless told not to).

Every simulation goes through an Evaluator, which counts it: the figure generation's cost
is measured in. Noise is drawn from generators named after the action's label, so a seed
gives the same task in any process.
"""

from __future__ import annotations

import itertools
import time

import attrs
import numpy as np

from physc import budget
from physc.domains.base import require
from physc.generation import choosing, placing, proposals, settings as reasons
from physc.generation.acceptance import verdict as judged
from physc.compiler.layout_rules import pushes
from physc.generation.attempt import Attempt, reaches
from physc.generation.evaluator import Evaluator
from physc.generation.guards import Guards
from physc.generation.outcome import Outcome, Parts
from physc.generation.robustness import Robustness
from physc.generation.snapshots import Snapshots
from physc.generation.settings import SETTINGS
from physc.generation.stages import Stage, introduced, prefix, stages
from physc.simulation.fidelity import fidelity
from physc.simulation.snapshot import Snapshot
from physc.simulation.stopped import why_stopped

ALONG = ("roll", "slide", "bounce", "destroy")  # terms whose second object is not met on the path (what it moves on, or what it already met)
KEPT_SIMULATIONS = 256  # the search's last simulations, kept: backtracking meets the same scene again


def satisfy(domain, scenario, layout, rng, validate: bool = True, accept: int | None = None, acceptance: bool = True) -> Outcome:
    """One placed layout made a task by the search with `domain`'s hooks (a SimulatedDomain),
    or why not; `accept`: the noisy replays a solution must pass (default: all of them);
    `acceptance`: whether the domain's acceptance rule judges the task."""
    require(domain, domain.search_hooks(), "generating a task")
    replays = domain.robustness_replays or 0
    return Search(domain, scenario, layout, rng, replays if accept is None else accept, validate, acceptance).run()


@attrs.frozen
class Node:
    """A layout that realises the sequence up to the end of stage `stage`, with the attempts
    that realise it (best first) and the steps that built it."""

    layout: object
    attempts: tuple
    stage: int
    steps: tuple[str, ...] = ()


class Search(Robustness, Guards, Snapshots):
    """The search for one placed layout (module docstring)."""

    def __init__(self, domain, scenario, layout, rng, accept: int, validate: bool = True, acceptance: bool = True):
        self.domain = domain
        self.scenario = scenario
        self.interactions = scenario.interactions
        self.placed = layout  # the layout as placed (the search's steps make new ones)
        self.rng = rng
        self.accept = accept
        self.validate = validate
        self.acceptance = acceptance
        self.settings = domain.search_settings or SETTINGS
        self.parameters = domain.layout_parameters
        self.scale = domain.trace_scale
        self.frame = placing.Frame.of(layout, scenario, domain.layout_parameters)
        self.entry = introduced(layout, scenario.interactions)
        self.players = {o.name for o in scenario.objects if o.term == domain.vocabulary.player}  # the player's objects
        self.plan = stages(scenario.interactions, self.entry)
        self.evaluator = Evaluator(KEPT_SIMULATIONS)
        self.best = 0  # most interactions realised in order by one play
        self.furthest: Attempt | None = None
        self.nearest = 0  # most noisy replays passed by a working action given up as fragile
        self.tried = 0  # working actions put through the noisy replays
        self.lost: dict[str, tuple[int, str]] = {}  # failed noisy replays by the interaction they lost (Robustness.lose)
        self.variants_tried = 0
        self.screened: list[str] = []  # labels of the first stage's actions that came nearest
        self.failed: dict[int, Attempt] = {}  # stage → the best attempt of a variant that failed there
        self.failed_layout: dict[int, object] = {}  # stage → the layout it failed in

    # ---- simulation ----------------------------------------------------------------------
    def level_of(self, layout):
        return self.domain.level_from_layout(layout, self.scenario)

    def play(self, level, action, seconds: float | None = None) -> Attempt:
        """`action` played in `level` (uncached: a noisy replay), judged against the scenario."""
        trace = self.evaluator.run(lambda: self.domain.play(level, action, self.scenario, seconds))
        return Attempt("", action, trace, fidelity(self.scenario, trace))

    def simulate(self, layout, action, seconds: float | None = None, resume: Snapshot | None = None) -> Attempt:
        """`action` played in `layout`'s level for `seconds` (default: the domain's), from the
        snapshot `resume` if given, judged against the scenario; run once while among the
        last KEPT_SIMULATIONS asked for."""
        key = (seconds, layout.objects, action, resume is not None and resume.step)
        options = {} if resume is None else {"resume": resume}
        trace = self.evaluator.kept(key, lambda: self.domain.play(self.level_of(layout), action, self.scenario, seconds, **options))
        attempt = Attempt("", action, trace, fidelity(self.scenario, trace))
        self.best = max(self.best, attempt.fidelity.matched)
        if self.furthest is None or attempt.fidelity.score > self.furthest.fidelity.score:
            self.furthest = attempt
        return attempt

    # ---- the whole step ------------------------------------------------------------------
    def run(self) -> Outcome:
        if not self.domain.actions(self.level_of(self.placed), self.scenario):
            return self.give_up(reasons.NO_ACTION)
        found = self.chain(Node(self.placed, (), -1), 0)
        if found is None:
            return self.give_up(reasons.NOT_REALISED)
        layout = found.layout
        chosen = self.robust(found.attempts, layout)
        if chosen is None:
            return self.give_up(reasons.FRAGILE if self.tried else reasons.NOT_REALISED)
        attempt, passed = chosen
        obstructed = self.obstruct(layout, attempt)
        if obstructed is None:
            return self.give_up(reasons.NOT_OBSTRUCTED)
        layout, obstacles = obstructed
        if obstacles:
            again = min(self.robustness(attempt, layout, stream) for stream in reasons.NOISE_STREAMS)
            if again < self.accept:
                self.nearest = max(self.nearest, again)
                return self.give_up(reasons.OBSTRUCTED_FRAGILE)
            passed = min(passed, again)
        layout, shortcuts = self.guard(layout, attempt, len(obstacles))
        if not self.evaluator.run(lambda: self.domain.stability(self.level_of(layout)))[0]:
            return self.give_up(reasons.UNSTABLE)
        distracting = time.perf_counter()
        layout, distractors = self.distract(layout, attempt)
        validating = time.perf_counter()
        validated, trace = None, attempt.trace
        if self.validate:
            final = self.play(self.level_of(layout), attempt.action)
            if not final.fidelity.valid:
                return self.give_up(reasons.NOT_VALIDATED)
            validated, trace = True, final.trace
        level = self.level_of(layout)
        if not self.domain.valid(level, attempt.action):  # the finished level (obstacles, distractors) may block it
            return self.give_up(reasons.INVALID_ACTION)
        accepting = time.perf_counter()
        verdict = judged(self.domain, level, attempt.label, attempt.action, self.evaluator) if self.acceptance else None
        if verdict is not None and not verdict.accepted:
            why = {"unstable": reasons.UNSTABLE_SOLUTION, "trivial": reasons.TRIVIAL, "solvable": reasons.SOLVABLE, "undecided": reasons.UNDECIDED}
            return self.give_up(why.get(verdict.reason, reasons.NOT_GOOD))
        solution = self.domain.solution(attempt.label, attempt.action)
        parts = Parts(
            level=self.domain.with_solution(level, solution),
            solution=solution,
            trace=trace.sequence(),
            validated=validated,
            robustness=(passed, self.domain.robustness_replays or 0),
            repairs=found.steps,
            obstacles=tuple(obstacles + shortcuts),
            distractors=tuple(distractors),
            acceptance=None if verdict is None else verdict.record(),
        )
        seconds = {"distract": validating - distracting, "validate": accepting - validating} | ({} if verdict is None else {"accept": time.perf_counter() - accepting})
        return Outcome(True, self.evaluator.simulations, parts, seconds=seconds, best=self.best, stopped=self.stopped)

    @property
    def stopped(self) -> str:
        """What the play that came furthest shows about where it stopped."""
        return "" if self.furthest is None else why_stopped(self.scenario, self.furthest.trace, self.furthest.fidelity)

    def give_up(self, why: str) -> Outcome:
        return Outcome(
            False, self.evaluator.simulations, nearest=self.nearest, given_up=why, best=self.best, stopped=self.stopped, lost=self.lost_links(),
        )

    # ---- the stage search ----------------------------------------------------------------
    def chain(self, parent: Node, i: int) -> Node | None:
        """Depth first over the stages from `self.plan[i]` (module docstring)."""
        if i == len(self.plan):
            return parent
        stage = self.plan[i]
        offered = 0
        for description, layout, lead in self.variants(parent, stage):
            if self.variants_tried >= self.settings.variants or offered >= self.settings.variants_per_stage:
                break
            budget.check()
            offered += 1
            self.variants_tried += 1
            attempts = self.realised(layout, parent, stage, lead)
            if not attempts:
                continue
            steps = parent.steps + ((description,) if description else ())
            found = self.chain(Node(layout, attempts, stage.index, steps), i + 1)
            if found is not None:
                return found
        return None

    def realised(self, layout, parent: Node, stage: Stage, lead: int = 0) -> tuple | None:
        """The attempts, best first, that realise every interaction up to the stage's end in
        the stage's scene of `layout`: the parent's actions (the lead's first), or at the
        first stage every candidate action (those that came nearest before, first)."""
        scene = prefix(layout, self.entry, stage.start)
        total = len(self.interactions)
        if parent.attempts:
            order = [parent.attempts[lead]] + [a for j, a in enumerate(parent.attempts) if j != lead]
            actions, screen = [(a.label, a.action) for a in order], 1
        else:
            actions = self.domain.actions(self.level_of(scene), self.scenario)
            actions = [c for c in actions if c[0] in self.screened] + [c for c in actions if c[0] not in self.screened]
            screen = len(self.screened) or len(actions)
        good, failed = [], []
        # The domain's whole run (it stops once all is at rest): a stage's path must go on long
        # enough for the next stage to read where its actor goes, which a slow roll may take
        # most of the run to show (PHYRE: a green ball reaching its ledge's end after 6 s).
        seconds = None
        for j, (label, action) in enumerate(actions):
            resume = self.snapshot(scene, parent, stage, order[j]) if parent.attempts else None
            attempt = attrs.evolve(self.simulate(scene, action, seconds, resume), label=label)
            if resume is not None and self.passes(attempt, stage, layout):  # confirmed from the start
                attempt = attrs.evolve(self.simulate(scene, action, seconds), label=label)
            (good if self.passes(attempt, stage, layout) else failed).append(attempt)
            if j + 1 == screen and not good:
                break  # those most likely to have missed it: so will the rest, mostly
        if failed:
            best = max(failed, key=lambda a: a.fidelity.score)
            if stage.index not in self.failed or best.fidelity.score > self.failed[stage.index].fidelity.score:
                self.failed[stage.index] = best
                self.failed_layout[stage.index] = layout
            if not parent.attempts and not self.screened:
                self.screened = [a.label for a in sorted(failed, key=lambda a: a.fidelity.score, reverse=True)[: self.settings.screen]]
        good.sort(key=lambda a: (a.fidelity.score[:3], self.promise(a, stage.end)), reverse=True)
        return tuple(good[: self.settings.beam]) or None

    def passes(self, attempt: Attempt, stage: Stage, layout) -> bool:
        """Whether `attempt` realises the stage and sets up the next."""
        return reaches(attempt, stage.end, len(self.interactions)) and self.sets_up(attempt, stage.end, layout)

    def sets_up(self, attempt: Attempt, end: int, layout) -> bool:
        """Whether `attempt` leaves the next stage something to place its new object on: the
        actor of the interaction after the first `end` comes down (by half its height) when
        it is to fall, and still moves when it is to hit; a stage whose attempts do not is a
        dead end, however its own interactions went."""
        if end >= len(self.interactions) or not end:
            return True
        term = self.interactions[end]
        actor = term.objects[0]
        objects = {o.name: o for o in layout.objects}
        if term.name not in ("fall", "hit") or actor not in objects or actor not in attempt.trace.names:
            return True
        if term.name == "fall":
            return self.promise(attempt, end) * self.scale >= objects[actor].height / 2
        return self.promise(attempt, end) >= self.settings.moving

    def promise(self, attempt: Attempt, end: int) -> float:
        """How well `attempt` sets up the interaction after the first `end`: how far its actor
        comes down, for a fall, else how fast it moves, after the last of them."""
        if end >= len(self.interactions) or not end:
            return 0.0
        actor = self.interactions[end].objects[0]
        trace = attempt.trace
        if actor not in trace.names:
            return 0.0
        rows = trace.states[int(attempt.fidelity.times[end - 1] / trace.dt) :, trace.index(actor), :]
        rows = rows[~np.isnan(rows[:, 0])]
        if not len(rows):
            return 0.0
        if self.interactions[end].name == "fall":
            return float(rows[0, 1] - rows[:, 1].min())
        return float(np.hypot(rows[:, 3], rows[:, 4]).max())

    # ---- variants ------------------------------------------------------------------------
    def variants(self, parent: Node, stage: Stage):
        """(description, layout, lead): the new objects on the path with the bodies the
        meeting favours, the layout as placed (with those bodies), then the domain's own."""
        seen = set()
        offered = []
        if parent.attempts and stage.start < len(self.interactions):
            declared = self.interactions[stage.start]
            for lead, attempt in enumerate(parent.attempts[:2]):
                offered.append((lead, itertools.islice(self.on_path(parent.layout, declared, stage, attempt), self.settings.places)))
        offered.append((0, iter([("", parent.layout)])))
        for lead, proposals in offered:
            for description, layout in proposals:
                for body_note, bodied in self.with_bodies(layout, parent, stage, lead):
                    if bodied.objects not in seen:
                        seen.add(bodied.objects)
                        yield ", ".join(x for x in (description, body_note) if x), bodied, lead
        yield from self.repaired(parent, stage, seen)

    def repaired(self, parent: Node, stage: Stage, seen: set, depth: int = 0):
        """Local changes (proposals.py, then the domain's own) for the first interaction the
        stage's best failed attempt missed; a change that comes nearer, but not all the way,
        is changed in turn (up to `repair_depth` on top of one another)."""
        failed = self.failed.get(stage.index)
        if failed is None:
            return
        base = parent.layout if depth == 0 else self.failed_layout.get(stage.index, parent.layout)
        lead = next((j for j, a in enumerate(parent.attempts) if a.label == failed.label), 0)
        changes = itertools.chain(
            proposals.offered(self, base, failed, stage.start), self.domain.proposals(base, self.scenario, failed, stage.start)
        )
        for description, layout in itertools.islice(changes, self.settings.proposals):
            if layout.objects in seen:
                continue
            seen.add(layout.objects)
            yield description, layout, lead
            if depth < self.settings.repair_depth and self.failed_layout.get(stage.index) is layout:  # nearer: change it further
                yield from self.repaired(parent, stage, seen, depth + 1)
                return

    def with_bodies(self, layout, parent: Node, stage: Stage, lead: int):
        """`layout` as it is, then with other bodies for the stage's new object that the
        meeting's physics favours (choosing.py)."""
        yield "", layout
        if not parent.attempts or stage.start >= len(self.interactions):
            return
        declared = self.interactions[stage.start]
        attempt = parent.attempts[min(lead, len(parent.attempts) - 1)]
        for note, changed in itertools.islice(choosing.alternatives(self, layout, declared, stage, attempt), self.settings.bodies - 1):
            yield note, changed

    def on_path(self, layout, declared, stage: Stage, attempt: Attempt):
        """Layouts with the stage's first new object where `attempt`'s actor meets it: under
        where it comes down, for a fall; touching it from a declared side, for a hit or any
        other meeting of two objects (PHYRE's and other domains' `touch`)."""
        actor, target = (tuple(declared.objects) + (None,))[:2]
        if declared.name in ALONG or target not in stage.new or actor not in attempt.trace.names:
            return
        objects = {o.name: o for o in layout.objects}
        if target not in objects or target in self.frame.fixed:
            return  # a surface is placed by the layout, with the shelf it belongs to
        trace = attempt.trace
        k = stage.start
        since = attempt.fidelity.times[k - 1] if k else 0.0
        if k and self.interactions[k - 1].name in ("roll", "slide", "fall"):
            since += self.settings.settle
        first = int(since / trace.dt)
        rows = trace.states[first:, trace.index(actor), :]
        members = self.frame.movers(target, self.entry)
        sizes = {o.name: (o.width, o.height) for o in layout.objects}
        actor_size = sizes.get(actor, (0.0, 0.0))
        if declared.name != "fall":
            sideways = self.frame.sideways_only(target)
            places = list(placing.hit_places(actor_size, objects[target], rows, declared.directions, sideways, self.scale, self.settings))
            if sideways and "above" in declared.directions:
                places = list(placing.landings(actor_size, objects[target], rows, self.scale)) + places
        else:
            heading = self.heading_after(target, k + 1)
            behind = None if heading is None else (1.0 if heading == "left" else -1.0)
            places = list(placing.landings(actor_size, objects[target], rows, self.scale, behind))
        pushed = None
        if declared.name == "hit" and target in self.frame.support_of:
            acts_next = next((t for t in self.interactions[k + 1 :] if t.objects and t.objects[0] == target), None)
            if acts_next is not None and acts_next.name == "fall":
                pushed = self.pushed_by(k)
        for step, x, y in places:
            moved = placing.shifted(layout, members, x - objects[target].x, y - objects[target].y, self.frame)
            if moved is None:
                continue
            changed = [o for o in moved.objects if o.name in members]
            if not placing.clear(trace, first + step, changed, actor, sizes, self.scale, self.settings.clear):
                continue
            if not placing.consistent(prefix(moved, self.entry, stage.start), self.parameters, members, members):
                continue
            where = next(o for o in changed if o.name == target)
            description = f"{declared.text}: {target} on its path, at ({where.x:.2f}, {where.y:.2f})"
            if pushed is not None:  # it falls next: its ledge ending at it first, so that the push takes it over
                support = self.frame.support_of[target]
                edged = proposals.ledge_ends_at(self, moved, {o.name: o for o in moved.objects}, target, support, pushed, stage.start)
                if edged is not None:
                    yield f"{description}, {support} ending at it", edged
            yield description, moved

    def pushed_by(self, k: int) -> str | None:
        """The way ("left" or "right") the hit `interactions[k]` pushes its target, if known
        (physc.compiler.layout_rules.pushes, with the domain's heading of the player's object)."""
        pushed = pushes(self.interactions, k, self.players, getattr(self.domain.layout_rules, "player_heading", None))
        return pushed if pushed in ("left", "right") else None

    def heading_after(self, name: str, index: int) -> str | None:
        """The way `name` next rolls or slides, from interaction `index` on."""
        term = next((t for t in self.interactions[index:] if t.name in ("roll", "slide") and t.objects[0] == name), None)
        return None if term is None else term.directions[0]
