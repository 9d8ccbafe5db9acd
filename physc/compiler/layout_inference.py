"""The steps of the paper's layout inference (physc.compiler.layout_rules), one function each.

`infer` builds the layout graph of a scenario in the order of the paper's table "Inferred
layout constraints" and of our reading of its layout optimisation (the docstring of
physc.compiler.layout_rules): the table's rows, motion along surfaces, supports and paths,
horizontal rest surfaces, continuous paths. The steps share one `Inference`, what the
inference has found so far; edges are added in the same order as they always were.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

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
from physc.compiler.layout_supports import (
    blast_supports,
    contrast_supports,
    declared_supports,
    hit_supports,
    remaining_supports,
)
from physc.compiler.sequence import OPPOSITE, falls_between, last_hit_at, last_motion, pushes
from physc.dsl.scenario import ScenarioIR, TermIR

if TYPE_CHECKING:
    from physc.compiler.layout_rules import LayoutRules
    from physc.diagnostics import Span

SIDES = ("left", "right", "above", "below")
AHEAD = {"right": "aboveLeft", "left": "aboveRight"}  # pushed right, a faller starts above its target or up to its left


def opposite(directions) -> tuple[str, ...]:
    return tuple(OPPOSITE[d] for d in directions)


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


def _interaction_provenance(term: TermIR) -> Provenance:
    return Provenance("interaction", term.text, term.span)


class GraphBuilder:
    """The graph as it is built: its nodes by name and its edges in order."""

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


@attrs.define
class Inference:
    """What the inference of one scenario has found so far, which its steps read and extend."""

    scenario: ScenarioIR
    rules: LayoutRules
    structure: str
    b: GraphBuilder
    # A list, not a set: iteration order must not depend on string hashing.
    dynamic: list[str]  # the dynamic objects besides the player's
    players: set[str]
    anywhere: tuple[str, ...]  # a support that need not be a ledge
    falls: set[str]  # the objects that fall
    ramps: list[str] = attrs.field(factory=list)  # the surfaces the ramp structure makes inclined
    motions: list[int] = attrs.field(factory=list)  # the edges of rolls and slides, by position
    surfaces: dict[str, list[str]] = attrs.field(factory=dict)  # mover → the surfaces it moves on, in order
    heading: dict[str, str] = attrs.field(factory=dict)  # mover → where it first moves
    moved_on: dict[str, TermIR] = attrs.field(factory=dict)  # mover → its first roll or slide
    support: dict[str, str] = attrs.field(factory=dict)  # object → what it rests on
    paths: dict[str, list[str]] = attrs.field(factory=dict)  # mover → the surfaces of its path

    def path_of(self, mover: str) -> list[str]:
        return self.paths.get(mover, [])

    def rest_on(self, obj: str, support: str, locations: tuple[str, ...], why: str, span: Span | None) -> None:
        """`obj` rests on `support`, at one of `locations` on it: the support edge, whose
        provenance says `why`, and `support` recorded as what `obj` rests on."""
        self.b.edge(ON_LOCATION, obj, support, locations, Provenance("support", why, span))
        self.support[obj] = support


def infer(scenario: ScenarioIR, rules: LayoutRules, structure: str = "flat") -> LayoutGraph:
    """The layout graph of `scenario` under `rules`, read in `structure` (module docstring)."""
    flat = rules.flat
    state = Inference(
        scenario,
        rules,
        structure,
        GraphBuilder(scenario, rules),
        dynamic=[o.name for o in scenario.objects if not o.static and o.term != rules.player],
        players={o.name for o in scenario.objects if o.term == rules.player},
        anywhere=(flat,) if rules.ground is None else (flat, rules.ground),
        falls={t.objects[0] for t in scenario.interactions if t.name == "fall"},
    )
    _table(state)  # 1.
    _restrictions(state)
    _motion_along_surfaces(state)  # 2.
    declared_supports(state)  # 3. (physc.compiler.layout_supports)
    hit_supports(state)
    blast_supports(state)
    contrast_supports(state)
    remaining_supports(state)
    _settle(state)
    _continuous_paths(state)  # 4.
    return _graph(state)


def _table(s: Inference) -> None:
    """1. The paper's table, for the interactions."""
    b, interactions = s.b, s.scenario.interactions
    for position, term in enumerate(interactions):
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
            s.motions.append(len(b.edges))
            b.edge(IN_DIRECTION, term.objects[0], term.objects[1], opposite(term.directions), why)
        elif term.name == "fall":
            b.edge(LOCATED_FAR, term.objects[0], term.objects[1], _fall_directions(s, position, term), why)
        elif term.name == "bounce":
            if b.is_ground(term.objects[1]):
                continue  # the ground spans the scene: nothing is beside it
            b.edge(IN_DIRECTION, term.objects[0], term.objects[1], bounced_from(term.directions), why)


def _fall_directions(s: Inference, position: int, term: TermIR) -> tuple[str, ...]:
    """Where a faller starts from its target: pushed off sideways (or, with
    fall_ahead_after_motion, rolled or slid off), it comes down ahead, not beyond its target
    the other way."""
    interactions, rules = s.scenario.interactions, s.rules
    hit = last_hit_at(interactions[:position], term.objects[0])
    pushed = None if hit is None else pushes(interactions, hit, s.players, rules.player_heading)
    moved = last_motion(interactions[:position], term.objects[0])
    if rules.fall_ahead_after_motion and moved is not None and (hit is None or moved > hit):  # it rolled or slid off
        pushed = interactions[moved].directions[0]
    if pushed is not None and tuple(term.directions) == ("above",):
        return (AHEAD[pushed],)
    return tuple(term.directions)


def _restrictions(s: Inference) -> None:
    """1. The paper's table, for the restrictions: cannotHit."""
    for term in s.scenario.restrictions:
        if term.name == "cannotHit":
            values = ("all",) if set(term.directions) == set(SIDES) else term.directions
            s.b.edge(
                PATH_OBSTRUCTED,
                term.objects[0],
                term.objects[1],
                values,
                Provenance("restriction", term.text, term.span),
            )


def _motion_along_surfaces(s: Inference) -> None:
    """2. Motion along surfaces: who rolls or slides on what, towards where."""
    for term in s.scenario.interactions:
        if term.name in ("roll", "slide"):
            mover, surface = term.objects
            s.surfaces.setdefault(mover, [])
            if surface not in s.surfaces[mover]:
                s.surfaces[mover].append(surface)
            s.heading.setdefault(mover, term.directions[0])
            s.moved_on.setdefault(mover, term)


def _settle(s: Inference) -> None:
    """What resting asks of the edges and surfaces: a mover that rests on the surface it rolls or
    slides along (set moving by one that came along the same surface) starts on it, not beside
    it (its motion's inDirection is its place on that surface, which its support's onLocation
    already gives); a surface that objects rest on is horizontal; a ramp is inclined."""
    b = s.b
    starts_on = {k for k in s.motions if s.support.get(b.edges[k].a) == b.edges[k].b}
    b.edges = [e for k, e in enumerate(b.edges) if k not in starts_on]
    for rest in s.support.values():
        b.narrow_to_flat(rest)
    for ramp in s.ramps:
        if s.rules.inclined in b.nodes[ramp].concrete:
            b.nodes[ramp] = attrs.evolve(b.nodes[ramp], concrete=(s.rules.inclined,))


def _continuous_paths(s: Inference) -> None:
    """4. cannotFall (and, with continuous_paths, every path): consecutive platforms of the path touch."""
    continuous = [
        (t.objects[0], Provenance("restriction", t.text, t.span))
        for t in s.scenario.restrictions
        if t.name == "cannotFall"
    ]
    if s.rules.continuous_paths:
        covered = {mover for mover, _ in continuous}
        continuous += [
            (mover, Provenance("support", f"{mover} moves on one continuous surface", s.moved_on[mover].span))
            for mover in s.paths
            if mover not in covered and mover in s.moved_on
        ]
    for mover, why in continuous:
        path = s.path_of(mover)
        for first, second in zip(path, path[1:], strict=False):  # consecutive pairs: one fewer than the path
            if falls_between(s.scenario.interactions, mover, first, second):
                continue  # it comes down from one onto the other: they need not meet
            if s.heading.get(mover, "right") == "right":
                s.b.edge(TOUCHING, first, second, ("upperLeft",), why)
            else:
                s.b.edge(TOUCHING, second, first, ("upperLeft",), why)


def _graph(s: Inference) -> LayoutGraph:
    """The graph built; without the player's object when the action places it."""
    nodes, edges = tuple(s.b.nodes.values()), tuple(s.b.edges)
    if not s.rules.player_placed:
        nodes = tuple(n for n in nodes if n.name not in s.players)
        edges = tuple(e for e in edges if e.a not in s.players and e.b not in s.players)
    return LayoutGraph(s.scenario.name, s.scenario.domain, nodes, edges, tuple(s.ramps))
