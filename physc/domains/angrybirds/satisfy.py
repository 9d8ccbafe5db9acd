"""Satisfying constraints through simulation (the paper's step 4), for angrybirds.

Given a placed layout, the satisfier builds the chain stage by stage along its
simulation (the generic sequential search, physc/generation/sequential.py, with this
domain's hooks in build.py), measuring how much of the declared sequence each candidate
shot realises (`fidelity`). Once a shot realises the whole sequence, the satisfier keeps
the first one that noise does not break, obstructs what the restrictions forbid and
guards against shortcuts. (Until issue 31 the chain was made by repairing the whole
placed layout after simulating it, a search of its own; the repair proposals are now
the local changes a stage of the sequential search tries: docs/generation.md.)
`Satisfier` is the state all this works on; each of its jobs is a mixin in a module of
its own (one job each, read and changed apart), whose methods are `Satisfier`'s:

* attempt.py: `Attempt`, one simulated play, and the outline arithmetic all parts share;
* placing.py: moving, shifting and shortening objects while the layout holds;
* repairs.py: the repair proposals that move objects (liesOnPath, closing a gap, a fall
  aimed, a bounce surface turned, …), and `proposals`, which picks them;
* impetus.py: the repair proposals that give a destroy, roll, slide or fall more force;
* obstruct.py: pathObstructed (platforms against forbidden hits) and the shortcut guard;
* robustness.py: the noisy replays, centring and firming a fragile solution.
"""

from __future__ import annotations

from collections import Counter

import attrs
import networkx as nx

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.compiler.geometry import overlapping_pair
from physc.compiler.qsr import FAR, ON_LOCATION, joined
from physc.compiler.qsr_evaluate import five_points, holds
from physc.domains.angrybirds.actions import candidate_shots
from physc.domains.angrybirds.attempt import SECONDS, Attempt
from physc.domains.angrybirds.build import AngryBirdsChain
from physc.domains.angrybirds.catalogue import by_prefab, extent
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.impetus import Impetus
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.noise import ROBUSTNESS_REPLAYS
from physc.domains.angrybirds.obstruct import Obstruction
from physc.domains.angrybirds.placing import Placing
from physc.domains.angrybirds.repairs import Repairs
from physc.domains.angrybirds.robustness import NOISE_STREAMS, Robustness
from physc.domains.angrybirds.to_level import level_from_layout
from physc.domains.angrybirds.world import PLACEMENT_AREA
from physc.dsl.scenario import ScenarioIR
from physc.generation.evaluator import Evaluator
from physc.generation.sequential import Sequential
from physc.simulation.fidelity import fidelity
from physc.simulation.stopped import why_stopped
from physc.simulation.trace import Trace

KEPT_SIMULATIONS = 256  # the satisfier's last simulations, kept (see Satisfier.kept), ~300 KB each
RESTING = tuple(q for on in ON_LOCATION.values() for q in on)  # resting on the left, the centre or the right of a support
# Why the satisfier gives a layout up (`Satisfier.given_up`), in the order of its steps.
NOT_REACHED = "no shot reaches the first target"
NOT_REALISED = "the sequence was not realised"
FRAGILE = "the solution was too fragile"
NOT_OBSTRUCTED = "a forbidden hit could not be blocked"
OBSTRUCTED_FRAGILE = "the obstacles made the solution fragile"
BROKEN = "the finished level broke the solution"


@attrs.frozen
class Satisfied:
    level: Level
    attempt: Attempt
    robustness: tuple[int, int]  # replays passed, replays run
    repairs: tuple[str, ...]
    obstacles: tuple[str, ...]
    simulations: int


def _geometry(obj: LevelObject) -> tuple:
    """Where an object is and how long and turned: what a repair that moves or reshapes it changes."""
    return (obj.x, obj.y, obj.scale_x, obj.scale_y, obj.rotation)


def _placed(obj: LevelObject, role: str) -> PlacedObject:
    width, height = extent(obj)
    return PlacedObject(obj.name, role, by_prefab(obj.type).name, obj.material, obj.x, obj.y, obj.rotation or 0.0, width, height)


class Satisfier(Repairs, Impetus, Placing, Obstruction, Robustness):
    """The search that makes a placed layout a task (see the module's docstring): the
    level it works on, simulation, the layout's constraints, the repair search and `run`,
    the whole step."""

    def __init__(self, domain, scenario: ScenarioIR, layout: ConcreteLayout, accept: int = ROBUSTNESS_REPLAYS):
        self.domain = domain
        # Noisy replays (of ROBUSTNESS_REPLAYS) a solution must pass. Fewer than all of them
        # only for a fallback. The fresh replays of the confirmation must pass as many.
        self.accept = accept
        self.nearest = 0  # most replays passed by a working solution given up as too fragile
        self.scenario = scenario
        self.level = level_from_layout(layout)
        self.placed_at = {o.name: _geometry(o) for o in self.level.objects}  # where and how placement put each object
        self.roles = {o.name: o.role for o in layout.objects}
        self.allowed = {o.name: o.concrete for o in scenario.objects}
        self.relations = tuple(layout.conjunction) + tuple(layout.separations)
        self.support_of = {r.a: r.b for r in layout.conjunction if r.relation in ("MeetN", "MeetDuringW", "MeetDuringE")}
        carried = Counter(self.support_of.values())
        self.own_support = {a: s for a, s in self.support_of.items() if self.roles.get(s) == "support" and carried[s] == 1}
        self.on_ground = {a for a, s in self.support_of.items() if s not in self.objects}
        # What rests on what and which platforms are joined: the structures that move as one.
        self.joints = nx.Graph()
        self.joints.add_edges_from(
            pair for pair in [*self.support_of.items(), *map(tuple, joined(self.relations))] if all(n in self.objects for n in pair)
        )
        self.parameters = domain.layout_parameters
        self.redirects = {tuple(t.objects) for t in scenario.interactions if t.name == "bounce"}
        self.repairs: list[str] = []
        self.obstacles: list[str] = []
        self.evaluator = Evaluator(KEPT_SIMULATIONS)
        self.best = 0  # most interactions of the sequence realised, in order, in one play
        self.furthest: Attempt | None = None  # the play that came furthest (by its fidelity's score)
        self.given_up = ""  # why `run` gave the layout up (NOT_REACHED … BROKEN), when it did

    @property
    def simulations(self) -> int:
        return self.evaluator.simulations

    # ---- the level ---------------------------------------------------------------------------
    @property
    def objects(self) -> dict[str, LevelObject]:
        return {o.name: o for o in self.level.objects}

    # ---- simulation --------------------------------------------------------------------------
    def simulate(self, shot: Shot, level: Level | None = None, seconds: float = SECONDS) -> Attempt:
        """The level (the current one unless given) played with `shot` for `seconds` at most,
        judged against the scenario (a search meets the same change again after backtracking,
        a few dozen simulations later: see `kept`)."""
        level = level or self.level

        def play() -> Attempt:
            trace = Game(level).play(
                shot, seconds, restrictions=self.scenario.restrictions, redirects=self.redirects, settle_after_solved=0.3
            )
            return Attempt("", shot, trace, fidelity(self.scenario, trace))

        attempt = self.kept(f"play {seconds:g}", level, shot, play)
        if self.furthest is None or attempt.fidelity.score > self.furthest.fidelity.score:
            self.furthest = attempt
        self.best = max(self.best, attempt.fidelity.matched)
        return attempt

    @property
    def stopped(self) -> str:
        """What the simulation that came furthest shows about where it stopped."""
        return "" if self.furthest is None else why_stopped(self.scenario, self.furthest.trace, self.furthest.fidelity)

    def flight(self, level: Level, shot: Shot) -> Trace:
        """The level played with `shot` for SECONDS, ending once it is solved: an agent's
        shot, as the obstruction's check and the shortcut guard both try them (the guard
        tries, on the same level, the shots the obstruction has just tried: see `kept`)."""
        return self.kept("flight", level, shot, lambda: Game(level).simulate(shot, SECONDS, settle_after_solved=0.0))

    def kept(self, kind: str, level: Level, shot: Shot, simulated):
        """`simulated()`, the `kind` of simulation of `level` with `shot`, run once while it
        is among the last KEPT_SIMULATIONS asked for."""
        key = (kind, level, tuple(o.name for o in level.objects), shot)  # a level's equality ignores names
        return self.evaluator.kept(key, simulated)

    def first_target(self, level: Level | None = None) -> LevelObject | None:
        """The target of the first interaction, a hit, in `level` (default: the current one)."""
        first = self.scenario.interactions[0]
        objects = self.objects if level is None else {o.name: o for o in level.objects}
        return objects.get(first.objects[1]) if first.name == "hit" else None

    def attempts(self) -> list[Attempt]:
        """Every candidate shot simulated in the current level, in the candidates' order."""
        target = self.first_target()
        if target is None:
            return []
        return [attrs.evolve(self.simulate(shot), label=label) for label, shot in candidate_shots(target)]

    # ---- constraint checks -------------------------------------------------------------------
    def consistent(self, level: Level, moved: frozenset = frozenset()) -> bool:
        """Every layout edge of the chosen conjunction holds, nothing overlaps, all inside the area.

        An edge holds when any QSR of its clause does (a repair may carry an object from
        one of the clause's regions to another: the edge is what the scenario asks for).
        An object that a repair moved (liesOnPath, closing a gap) may rest anywhere on its
        support: for it, resting on the left, middle or right part of its support all count.
        And a locatedFar edge of a moved object (one end moved to where a fall comes down)
        holds in the near tiles of its directions too: far on both axes is the layout's
        proxy for a fall, and simulation judges the fall itself (a block pushed off slowly
        comes down beside its support, nearer than the far gap)."""
        placed = {o.name: _placed(o, self.roles.get(o.name, "object")) for o in level.objects}
        # What an adopted repair moved keeps that freedom in every later check (an obstacle,
        # a distractor): it is judged as when it was moved.
        moved = moved | {o.name for o in level.objects if self.placed_at.get(o.name, _geometry(o)) != _geometry(o)}
        # So does what rests on a support that a repair moved or shortened (`expose`,
        # closing a gap): it rests on another part of it now.
        moved = moved | {a for a, support in self.support_of.items() if support in moved}
        for relation in self.relations:
            if relation.a in placed and relation.b in placed:
                names = relation.alternatives or (relation.relation,)
                if relation.a in moved and relation.relation in RESTING:
                    names = RESTING
                elif (relation.a in moved or relation.b in moved) and all(name.startswith(FAR) for name in names):
                    names = names + tuple(name[len(FAR) :] for name in names)  # the near tiles too
                a, b = placed[relation.a], placed[relation.b]
                if not any(holds(name, a, b, self.parameters.clearance, self.parameters.far) for name in names):
                    return False
        area = PLACEMENT_AREA
        corners = {}
        for name, p in placed.items():
            points = five_points(p.x, p.y, p.width, p.height, p.rotation)
            corners[name] = [(points[k].real, points[k].imag) for k in ("ll", "lr", "ur", "ul")]
            xs = [c[0] for c in corners[name]]
            ys = [c[1] for c in corners[name]]
            if min(xs) < area.left - 1e-6 or max(xs) > area.right + 1e-6 or min(ys) < area.bottom - 1e-6 or max(ys) > area.top + 1e-6:
                return False
        return overlapping_pair(corners, 1e-4, joined(self.relations)) is None

    # ---- the whole step ----------------------------------------------------------------------
    @staticmethod
    def distinct(proposals, level: Level):
        """The proposals for `level`, each changed level once: two repairs may propose the
        same change (liesOnPath from above and from below puts a pig on its surface at the
        same place), and a proposal that changes nothing is no repair. Each would be
        simulated, and count against the search's budget, for nothing."""
        seen = {level}
        for description, proposed in proposals:
            if proposed not in seen:
                seen.add(proposed)
                yield description, proposed

    def run(self) -> Satisfied | None:
        """Build the chain until a candidate realises the sequence, then keep the first
        working candidate that noise does not break, obstruct what the restrictions forbid
        and guard against shortcuts."""
        attempts = self.built()
        if attempts is None:
            return self.give_up(NOT_REALISED if self.simulations else NOT_REACHED)
        working = self.working(attempts)
        # The first working candidate that noise does not break, or else its shot moved
        # to the middle of its window of working angles, or the world around it firmed up,
        # confirmed by fresh replays (at most three are tried); if none holds up, the next
        # layout is tried.
        for candidate in working[:3]:
            chosen = candidate
            passed, total = self.robustness(chosen)
            # A fallback too is centred and firmed until it passes every replay, as when it
            # was first found: what it passed then (`nearest`) is what it is tried again for.
            if passed < ROBUSTNESS_REPLAYS:
                chosen = self.centred(candidate)
                if chosen is not None:
                    passed, total = self.robustness(chosen)
                if chosen is None or passed < ROBUSTNESS_REPLAYS:
                    chosen, passed = self.firmed(chosen or candidate, passed)
            # Every solution was chosen for passing the replays (among the candidates, the
            # centred and firmed variants, the layouts): it must pass as many fresh ones
            # too. Six replays passed say little of a solution that noise breaks one time
            # in ten (it passes them half the time); twelve in a row, a quarter.
            if passed >= self.accept:
                passed = min(passed, self.robustness(chosen, stream=NOISE_STREAMS[1])[0])
            if passed >= self.accept:
                break
            self.nearest = max(self.nearest, passed)
        else:
            return self.give_up(FRAGILE)
        checked = len(self.obstacles)
        if not self.obstruct(chosen):
            return self.give_up(NOT_OBSTRUCTED)
        if len(self.obstacles) > checked:
            again = min(self.robustness(chosen, stream=stream)[0] for stream in NOISE_STREAMS)
            if again < self.accept:
                self.nearest = max(self.nearest, again)
                return self.give_up(OBSTRUCTED_FRAGILE)
        self.guard_accidents(chosen)
        final = self.simulate(chosen.shot)
        if not final.fidelity.valid:
            return self.give_up(BROKEN)
        return Satisfied(self.level, attrs.evolve(final, label=chosen.label), (passed, total), tuple(self.repairs), tuple(self.obstacles), self.simulations)

    def built(self) -> list[Attempt] | None:
        """The sequential search (physc/generation/sequential.py): the chain built stage by
        stage along its simulation; the attempts that realise it on the level built, or None."""
        self.search = Sequential(AngryBirdsChain(self))
        found = self.search.run()
        if found is None:
            return None
        self.adopt(found.scene)
        self.repairs.extend(found.steps)
        return list(found.attempts)

    def give_up(self, why: str) -> None:
        """`run`'s answer for a layout given up: None, with the reason kept in `given_up`."""
        self.given_up = why

    @staticmethod
    def working(attempts: list[Attempt]) -> list[Attempt]:
        return [a for a in attempts if a.fidelity.valid]
