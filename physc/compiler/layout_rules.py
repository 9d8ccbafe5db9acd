"""The paper's layout inference rules, for any domain of the paper's interactions.

A domain configures them (`LayoutRules`: its player's object term, the concrete objects
of a flat support and of the ground, and the way the player's object flies, if it flies
one way) and hands them to the pipeline as its `layout_rules`; angrybirds and the
PHYRE-like plugin both do. The paper's table "Inferred layout constraints":

    hit(a, b, d)      → liesOnPath(b, a) ∧ inDirection(b, a, -d)
    roll(a, b, d)     → inDirection(a, b, -d)
    fall(a, b, d)     → locatedFar(a, b, d)
                        (d = aboveLeft when d is above and the hit before the fall pushes
                        a right, or, with fall_ahead_after_motion, a rolled or slid right
                        just before: it comes down ahead; see `pushes`)
    destroy, touch    → nothing of their own (the hit or fall before them places them)
    slide(a, b, d)    → inDirection(a, b, -d)
    bounce(a, b, d)   → inDirection(a, b, d), and for d left or right also inDirection(a, b, -d)
    cannotHit(a,b,d)  → pathObstructed(a, b, d)
    cannotFall(a)     → a chain of touching surfaces that a moves on

and the layout optimisation that makes the task stand under gravity. Our precise
reading (docs/qsr.md, "From scenario to layout"):

* Every dynamic object except the player's object rests on a support:
  - an object hit sideways by an object that moves along surfaces rests on the
    last surface of that mover's path, on the side the mover comes towards
    (the target lies on the path);
  - otherwise an object that rolls or slides rests on a support platform of its
    own, which its path continues from (`roll(a, s, right)` puts `a` left of `s`);
  - otherwise a new support: a flat support, or the ground, at any location; for an
    object that will fall, a platform it can be pushed off (on the part of it that
    the hit pushes it towards).
* The path of an object that rolls or slides: its support, then its surfaces in
  order, then the support of an object it hits sideways if that one has a path
  of its own. `cannotFall(a)` links consecutive platforms of a's path with
  `touching(p, q, upperLeft)` (p's upper-right point is q's upper-left: one
  continuous top edge); for a path towards the left the arguments swap.
* A surface that a dynamic object rests on is horizontal (an inclined one would
  not hold it still): such surfaces are narrowed to the flat support.

Structures: the reading above is the `flat` structure, the paper's. Where the surface a mover
rolls or slides on before it hits a target sideways may be inclined, the `ramp` structure reads
it as the game's own designers build a roll (Phy-Q's templates 2_1_3, 2_1_6, 2_1_9): the
surface is a ramp descending towards the target, and the target rests at its foot on a support
of its own, which the mover's path continues onto. Gravity then carries what a strike cannot.
`LayoutRules.structures(scenario)` names the structures a scenario has; generation tries
them all (physc.driver.pipeline), and simulation decides.
"""

from __future__ import annotations

import attrs

from physc.compiler.layout_graph import (
    IN_DIRECTION,
    LIES_ON_PATH,
    LOCATED_FAR,
    OBJECT,
    ON_LOCATION,
    PATH_OBSTRUCTED,
    PLAYER,
    SUPPORT,
    TOUCHING,
    LayoutEdge,
    LayoutGraph,
    LayoutNode,
    Provenance,
)
from physc.compiler.sequence import OPPOSITE, falls_between, last_hit_at, last_motion, pushes
from physc.dsl.scenario import ScenarioIR, TermIR

SIDES = ("left", "right", "above", "below")
AHEAD = {"right": "aboveLeft", "left": "aboveRight"}  # pushed right, a faller starts above its target or up to its left


def opposite(directions) -> tuple[str, ...]:
    return tuple(OPPOSITE[d] for d in directions)


@attrs.frozen
class LayoutRules:
    """The rules (module docstring) for one domain: `player`, the object term the player
    sets in motion; `flat`, the concrete object of a horizontal support; `ground`, that of
    the ground (None: the domain has none to rest on); `player_heading`, the way the
    player's object flies until it bounces ("right": Angry Birds' bird, shot from the left;
    None: no one way, a dropped ball); `player_placed`, whether the layout places the
    player's object (the bird at its slingshot) or the action does (PHYRE's red ball: then
    the player and its edges are left out of the graph, and the action is found by
    simulation)."""

    player: str
    flat: str
    ground: str | None = None
    player_heading: str | None = None
    player_placed: bool = True
    fall_ahead_after_motion: bool = False
    """Whether a faller that rolled or slid just before its fall starts above and behind
    its target (it comes down ahead), as one pushed off sideways does. Without it
    (angrybirds) only a push says so."""
    continuous_paths: bool = False
    """Whether the consecutive surfaces of every path touch, one continuous top edge (a
    ledge running into a ramp). Without it (angrybirds) they touch only under cannotFall,
    and the satisfier's repairs close the gaps in simulation."""

    inclined: str | None = None
    """The concrete object of an inclined surface (angrybirds: inclinedPlatform), for the
    `ramp` structure; None: the domain offers no ramps."""

    def infer(self, scenario: ScenarioIR, structure: str = "flat") -> LayoutGraph:
        return infer(scenario, self, structure)

    def structures(self, scenario: ScenarioIR) -> tuple[str, ...]:
        """The structures the scenario can be laid out in: "flat" (the paper's reading), and
        "ramp" where a mover's surface before a sideways hit may be inclined."""
        return ("flat", "ramp") if _ramps(scenario, self) else ("flat",)


class _Builder:
    def __init__(self, scenario: ScenarioIR, rules: LayoutRules):
        self.scenario = scenario
        self.flat = rules.flat
        self.ground = rules.ground
        self.nodes: dict[str, LayoutNode] = {}
        self.edges: list[LayoutEdge] = []
        for obj in scenario.objects:
            role = PLAYER if obj.term == rules.player else OBJECT
            self.nodes[obj.name] = LayoutNode(obj.name, obj.term, obj.concrete, obj.static, role)

    def edge(self, term, a, b, values, provenance: Provenance):
        self.edges.append(LayoutEdge(term, a, b, tuple(values), (provenance,)))

    def support_node(self, owner: str, concrete: tuple[str, ...]) -> str:
        name = f"support_{owner}"
        while name in self.nodes:
            name += "_"
        self.nodes[name] = LayoutNode(name, "support", concrete, True, SUPPORT)
        return name

    def is_ground(self, name: str) -> bool:
        """Whether `name` can only be the ground (which spans the scene)."""
        return self.ground is not None and self.nodes[name].concrete == (self.ground,)

    def narrow_to_flat(self, name: str) -> None:
        """A scenario surface that something rests on must be horizontal."""
        node, flat = self.nodes[name], self.flat
        if node.role != SUPPORT and flat in node.concrete and node.concrete != (flat,):
            self.nodes[name] = LayoutNode(node.name, node.term, (flat,), node.static, node.role)


def _interaction_provenance(term: TermIR) -> Provenance:
    return Provenance("interaction", term.text, term.span)


def _ramps(scenario: ScenarioIR, rules: LayoutRules) -> bool:
    """Whether some target is hit sideways by a mover coming along a surface that may be inclined."""
    if rules.inclined is None:
        return False
    return infer(scenario, rules, "ramp") != infer(scenario, rules, "flat")


def bounced_from(directions) -> tuple[str, ...]:
    """Where an object that bounces off a surface towards `directions` starts, beside it.
    `bounce(a, b, d)` means that a leaves b heading d (docs/language.md; the recogniser reads
    the heading after the bounce). Thrown back up or down, a came from that side (the paper's
    inDirection(a, b, d)); heading left or right, a came from that side and was thrown back,
    or from the other side and glanced off b's top or underside, going on the way it went."""
    out = []
    for d in directions:
        out += [d] + ([OPPOSITE[d]] if d in ("left", "right") else [])
    return tuple(dict.fromkeys(out))


def infer(scenario: ScenarioIR, rules: LayoutRules, structure: str = "flat") -> LayoutGraph:
    b = _Builder(scenario, rules)
    ramps: list[str] = []  # the surfaces the ramp structure makes inclined
    FLAT = rules.flat
    anywhere = (FLAT,) if rules.ground is None else (FLAT, rules.ground)  # a support that need not be a ledge
    # A list, not a set: iteration order must not depend on string hashing.
    dynamic = [o.name for o in scenario.objects if not o.static and o.term != rules.player]
    players = {o.name for o in scenario.objects if o.term == rules.player}
    flies = rules.player_heading

    # 1. The paper's table.
    motions: list[int] = []  # the edges of rolls and slides, by position
    for position, term in enumerate(scenario.interactions):
        why = _interaction_provenance(term)
        if term.name == "hit":
            actor, target = term.objects
            if b.is_ground(target):
                continue  # the ground spans the scene: whatever comes down meets it
            b.edge(LIES_ON_PATH, target, actor, (), why)
            b.edge(IN_DIRECTION, target, actor, opposite(term.directions), why)
        elif term.name in ("roll", "slide"):
            if b.is_ground(term.objects[1]):
                continue  # the ground spans the scene: what moves along it starts anywhere on it
            motions.append(len(b.edges))
            b.edge(IN_DIRECTION, term.objects[0], term.objects[1], opposite(term.directions), why)
        elif term.name == "fall":
            hit = last_hit_at(scenario.interactions[:position], term.objects[0])
            pushed = None if hit is None else pushes(scenario.interactions, hit, players, flies)
            moved = last_motion(scenario.interactions[:position], term.objects[0])
            if (
                rules.fall_ahead_after_motion and moved is not None and (hit is None or moved > hit)
            ):  # it rolled or slid off
                pushed = scenario.interactions[moved].directions[0]
            if pushed is not None and tuple(term.directions) == ("above",):
                # Pushed off sideways, it comes down ahead: it is not beyond its target the other way.
                b.edge(LOCATED_FAR, term.objects[0], term.objects[1], (AHEAD[pushed],), why)
            else:
                b.edge(LOCATED_FAR, term.objects[0], term.objects[1], term.directions, why)
        elif term.name == "bounce":
            if b.is_ground(term.objects[1]):
                continue  # the ground spans the scene: nothing is beside it
            b.edge(IN_DIRECTION, term.objects[0], term.objects[1], bounced_from(term.directions), why)
    for term in scenario.restrictions:
        if term.name == "cannotHit":
            values = ("all",) if set(term.directions) == set(SIDES) else term.directions
            b.edge(
                PATH_OBSTRUCTED,
                term.objects[0],
                term.objects[1],
                values,
                Provenance("restriction", term.text, term.span),
            )

    # 2. Motion along surfaces: who rolls or slides on what, towards where.
    surfaces: dict[str, list[str]] = {}
    heading: dict[str, str] = {}
    moved_on: dict[str, TermIR] = {}
    for term in scenario.interactions:
        if term.name in ("roll", "slide"):
            mover, surface = term.objects
            surfaces.setdefault(mover, [])
            if surface not in surfaces[mover]:
                surfaces[mover].append(surface)
            heading.setdefault(mover, term.directions[0])
            moved_on.setdefault(mover, term)

    # 3. Supports and paths, in the order of the sequence; first the structures a scenario
    # declares (version 2: on(a, b), a rests on b).
    support: dict[str, str] = {}
    for term in scenario.restrictions:
        if term.name == "on" and term.objects[0] in dynamic and term.objects[0] not in support:
            top, below = term.objects
            b.edge(
                ON_LOCATION,
                top,
                below,
                ("over",),
                Provenance("support", f"{top} rests on {below}: {term.text}", term.span),
            )
            support[top] = below
    paths: dict[str, list[str]] = {}
    falls = {t.objects[0] for t in scenario.interactions if t.name == "fall"}

    def path_of(mover: str) -> list[str]:
        return paths.get(mover, [])

    for position, term in enumerate(scenario.interactions):
        if term.name != "hit":
            continue
        actor, target = term.objects
        if target not in dynamic or target in support:
            continue
        sideways = [d for d in term.directions if d in ("left", "right")]
        why = _interaction_provenance(term)
        last = path_of(actor)[-1] if path_of(actor) else None
        if (
            structure == "ramp"
            and sideways
            and last in surfaces.get(actor, ())
            and not b.is_ground(last)
            and rules.inclined in b.nodes[last].concrete
            and last not in support.values()
        ):
            # The ramp: the mover comes down its surface; the target rests at the foot, on a
            # support of its own facing the ramp, which the mover's path continues onto.
            own = b.support_node(target, (FLAT,))
            b.edge(
                ON_LOCATION,
                target,
                own,
                (OPPOSITE[heading[actor]],),
                Provenance("support", f"{target} rests at the foot of the ramp {last}: {term.text}", term.span),
            )
            support[target] = own
            ramps.append(last)
            paths[actor].append(own)
        elif path_of(actor) and sideways:
            rest = path_of(actor)[-1]
            towards = heading[actor]
            where = (towards,)
            if rest in surfaces.get(target, ()) and heading[target] == towards:
                # It goes on along the same surface: it rests in its middle, ahead of its
                # hitter and with room ahead of it.
                where = ("centre",)
            b.edge(
                ON_LOCATION,
                target,
                rest,
                where,
                Provenance("support", f"{target} lies on the path of {actor}: {term.text}", term.span),
            )
            support[target] = rest
        elif target in surfaces and b.is_ground(surfaces[target][0]):
            ground = surfaces[target][0]  # it moves along the ground first: it rests on it, anywhere
            b.edge(
                ON_LOCATION,
                target,
                ground,
                ("left", "centre", "right"),
                Provenance("support", f"{target} rests on the ground it moves along", term.span),
            )
            support[target] = ground
        elif target in surfaces:
            first = moved_on[target]
            own = b.support_node(target, (FLAT,))
            toward = heading[target]
            b.edge(
                ON_LOCATION,
                target,
                own,
                (toward,),
                Provenance("support", f"{target} starts beside the surface it moves on: {first.text}", first.span),
            )
            support[target] = own
        else:
            own = b.support_node(target, (FLAT,) if target in falls else anywhere)
            if target in falls:
                pushed = pushes(scenario.interactions, position, players, flies)
                locations = (
                    (pushed,) if pushed else tuple(dict.fromkeys(loc for d in term.directions for loc in _push_off(d)))
                )
                text = f"{target} rests where it can be pushed off to fall: {term.text}"
            else:
                locations = ("left", "centre", "right")
                text = f"{target} rests on a support"
            b.edge(ON_LOCATION, target, own, locations, Provenance("support", text, term.span))
            support[target] = own
        if target in surfaces:
            paths[target] = [support[target]] + [s for s in surfaces[target] if s != support[target]]
        # A mover that hits a target with a path of its own continues onto it.
        if path_of(actor) and sideways and target in paths and paths[target][0] != path_of(actor)[-1]:
            paths[actor].append(paths[target][0])

    # A blast's targets (version 2: destroy(a, b) after explode(a)) rest beside what explodes,
    # on its support: within its reach.
    exploded: set[str] = set()
    for term in scenario.interactions:
        if term.name == "explode":
            exploded.add(term.objects[0])
        elif (
            term.name == "destroy"
            and term.objects[0] in exploded
            and term.objects[1] in dynamic
            and term.objects[1] not in support
        ):
            source, target = term.objects
            if source in support:
                b.edge(
                    ON_LOCATION,
                    target,
                    support[source],
                    ("left", "centre", "right"),
                    Provenance("support", f"{target} lies within the blast of {source}: {term.text}", term.span),
                )
                support[target] = support[source]
    # A contrast (version 2: contrast(a, b)) rests on its counterpart's support, as it does.
    for term in scenario.restrictions:
        if (
            term.name == "contrast"
            and term.objects[0] in dynamic
            and term.objects[0] not in support
            and term.objects[1] in support
        ):
            contrast, counterpart = term.objects
            b.edge(
                ON_LOCATION,
                contrast,
                support[counterpart],
                ("left", "centre", "right"),
                Provenance("support", f"{contrast} rests as {counterpart} does: {term.text}", term.span),
            )
            support[contrast] = support[counterpart]
    # Dynamic objects that nothing hits (they never move) still need a support.
    for name in dynamic:
        if name not in support:
            own = b.support_node(name, anywhere)
            b.edge(
                ON_LOCATION,
                name,
                own,
                ("left", "centre", "right"),
                Provenance("support", f"{name} rests on a support", None),
            )
            support[name] = own
    # A mover that rests on the surface it rolls or slides along (set moving by one that came
    # along the same surface) starts on it, not beside it: its motion's inDirection is its
    # place on that surface, which its support's onLocation already gives.
    starts_on = {k for k in motions if support.get(b.edges[k].a) == b.edges[k].b}
    b.edges = [e for k, e in enumerate(b.edges) if k not in starts_on]
    # Objects at rest on a surface: that surface is horizontal.
    for rest in support.values():
        b.narrow_to_flat(rest)
    for ramp in ramps:
        if rules.inclined in b.nodes[ramp].concrete:
            b.nodes[ramp] = attrs.evolve(b.nodes[ramp], concrete=(rules.inclined,))

    # 4. cannotFall (and, with continuous_paths, every path): consecutive platforms of the path touch.
    continuous = [
        (t.objects[0], Provenance("restriction", t.text, t.span))
        for t in scenario.restrictions
        if t.name == "cannotFall"
    ]
    if rules.continuous_paths:
        covered = {mover for mover, _ in continuous}
        continuous += [
            (mover, Provenance("support", f"{mover} moves on one continuous surface", moved_on[mover].span))
            for mover in paths
            if mover not in covered and mover in moved_on
        ]
    for mover, why in continuous:
        path = path_of(mover)
        for first, second in zip(path, path[1:]):
            if falls_between(scenario.interactions, mover, first, second):
                continue  # it comes down from one onto the other: they need not meet
            if heading.get(mover, "right") == "right":
                b.edge(TOUCHING, first, second, ("upperLeft",), why)
            else:
                b.edge(TOUCHING, second, first, ("upperLeft",), why)

    nodes, edges = tuple(b.nodes.values()), tuple(b.edges)
    if not rules.player_placed:
        nodes = tuple(n for n in nodes if n.name not in players)
        edges = tuple(e for e in edges if e.a not in players and e.b not in players)
    return LayoutGraph(scenario.name, scenario.domain, nodes, edges, tuple(ramps))


def _push_off(direction: str) -> tuple[str, ...]:
    """Where on its support an object should rest to fall when hit from `direction`."""
    if direction == "left":
        return ("right",)
    if direction == "right":
        return ("left",)
    return ("left", "right")
