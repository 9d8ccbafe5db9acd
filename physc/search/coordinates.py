"""What the raising of margins may move: the continuous coordinates of a placed layout and its action.

A layout is not a set of free bodies: a ledge's block rests on it, platforms are joined edge to
edge into shelves, and the chosen conjunction's QSRs say where each lies. So the coordinates
move whole pieces, the ways that keep those relations (each checked against every QSR of the
conjunction and the placement area, placing.consistent):

* **the action** along the domain's `actions.nudged` line (Science Birds: the release angle), ±`raise_steps`;
* **an object along what it rests on** (sideways), where that is not the ground;
* **its structure**, everything joined to it or resting on it, transitively (a shelf with its
  blocks), sideways, and up and down where it does not stand on the ground;
* **the gap** between two objects a weak link meets: everything wholly beyond a cut between
  them moves towards or away from the first (no object may straddle the cut);
* **a surface's length**, at its far end, with the world beyond that end moved along;
* **a slope**: an inclined surface nothing rests on, turned within the world's incline rule;
* **a body**: another of the bodies the scenario allows the object (the domain's `bodies`), on
  one axis from the lightest to the heaviest (a collision's outcome is monotone in the masses,
  so neighbouring values are neighbouring physics), fitted where it stood.

Each moves within `raise_reach` clearances (the slope `raise_turn` degrees) either way; a point
of [−1, 1]ⁿ is a layout and an action (`Coordinates.apply`), or None where it leaves the
region the QSRs allow or the action is not valid. A coordinate that no small move keeps inside
the region is not offered.
"""

from __future__ import annotations

from collections.abc import Sequence

import attrs

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.compiler.qsr import joined
from physc.search import placing
from physc.search.chain_stages import supports
from physc.search.problem import Problem
from physc.simulation.margin import Margin

PROBE = 0.25  # the share of its reach a coordinate is tried at, either way, to be offered


@attrs.frozen
class Coordinate:
    kind: str  # "action", "along", "x", "y", "gap", "length", "slope", "body"
    name: str  # the object, or the pair "a→b" of a gap ("" for the action)
    moves: frozenset[str]  # what it moves (an object's, a structure's, the world beyond a cut)
    reach: float  # the most it moves either way: layout units, degrees, or the action's steps
    sign: float = 1.0  # +1: a positive value moves rightwards or lengthens (−1: the other way)
    stretch: str = ""  # a length's surface
    bodies: tuple[PlacedObject, ...] = ()  # a body's options, lightest first, and the current one's place among them
    current: int = 0
    line: int | None = None  # the action's line (Actions.lines) where it has several

    def body(self, value: float) -> PlacedObject:
        """The body `value` (in [−1, 1]) picks: the current one at 0, heavier ones above."""
        index = min(max(self.current + int(round(value * (len(self.bodies) - 1))), 0), len(self.bodies) - 1)
        return self.bodies[index]

    def text(self, value: float) -> str:
        if self.kind == "action":
            return f"{'the action' if self.line is None else self.name} {int(round(value)):+d} steps"
        if self.kind == "body":
            chosen = self.body(value / self.reach)
            return f"{self.name} a {chosen.material + ' ' if chosen.material else ''}{chosen.concrete}"
        unit = "°" if self.kind == "slope" else ""
        return f"{self.name} {self.kind} {value:+.3f}{unit}"


def weak_parts(problem: Problem, margin: Margin) -> tuple[set[str], list[tuple[str, str]]]:
    """What a weak link depends on: the objects of the link, of the one after it and of the hit
    that set its actor moving (what strikes it sets its speed), and the pairs a hit, a fall, a touch
    or a destroy among them meets (the gap between them); for a restriction, its objects and the
    surfaces the first of them rolls or slides on (a body that must not fall stays on what it
    moves along)."""
    interactions = problem.interactions
    names: set[str] = set()
    pairs: list[tuple[str, str]] = []
    if margin.index is not None:
        actor = interactions[margin.index].objects[0] if interactions[margin.index].objects else None
        pushed = [
            j for j in range(margin.index) if interactions[j].name == "hit" and interactions[j].objects[1:2] == (actor,)
        ]
        for term in [interactions[j] for j in pushed[-1:]] + list(interactions[margin.index : margin.index + 2]):
            names |= set(term.objects)
            if (
                term.name in ("hit", "fall", "touch", "destroy")
                and len(term.objects) > 1
                and (term.objects[0], term.objects[1]) not in pairs
            ):
                pairs.append((term.objects[0], term.objects[1]))
        return names, pairs
    restriction = next((r for r in problem.scenario.restrictions if r.text == margin.term), None)
    if restriction is not None:
        names |= set(restriction.objects)
        names |= {
            t.objects[1] for t in interactions if t.name in ("roll", "slide") and t.objects[0] == restriction.objects[0]
        }
    return names, pairs


def structures(layout: ConcreteLayout) -> dict[str, frozenset[str]]:
    """Each object's structure: what is joined to it or rests on it, transitively."""
    links: dict[str, set[str]] = {o.name: {o.name} for o in layout.objects}
    pairs = [tuple(pair) for pair in joined(layout.conjunction)] + [(a, b) for a, b in supports(layout).items()]
    for a, b in pairs:
        if a in links and b in links and links[a] is not links[b]:
            merged = links[a] | links[b]
            for name in merged:
                links[name] = merged
    return {name: frozenset(group) for name, group in links.items()}


@attrs.frozen
class Coordinates:
    """The coordinates of one layout and action (module docstring)."""

    problem: Problem
    layout: ConcreteLayout
    action: object  # the domain's action (its `actions` part's), opaque to the search
    axes: tuple[Coordinate, ...]

    @classmethod
    def of(
        cls,
        problem: Problem,
        layout: ConcreteLayout,
        action: object,
        names: set[str],
        pairs: Sequence[tuple[str, str]] = (),
    ) -> Coordinates:
        """The coordinates of the objects `names` (the weak links' objects), of the gaps between
        the object pairs `pairs` (what a weak link meets), and of the action."""
        settings = problem.settings
        reach = settings.raise_reach * problem.parameters.clearance
        rules = problem.domain.layout_rules
        objects = {o.name: o for o in layout.objects}
        supports = problem.supports
        # What never moves: the player's object, the ground and obstacles; a support moves only
        # with what it holds.
        fixed = set(problem.players) | {
            o.name for o in layout.objects if o.concrete in placing.GROUND or o.role == "obstacle"
        }
        groups = structures(layout)
        axes = []
        lines = problem.domain.actions.lines(action)
        for line, text in enumerate(lines):  # one a line (several: each of them, an earlier shot's too)
            axes.append(
                Coordinate(
                    "action", text, frozenset(), float(settings.raise_steps), line=line if len(lines) > 1 else None
                )
            )
        for name in sorted(n for n in names if n in objects and n not in fixed and n not in supports.fixed):
            support = supports.support_of.get(name)
            if support in objects and objects[support].concrete not in placing.GROUND:
                axes.append(Coordinate("along", name, frozenset((name,)), reach))
            group = groups[name]
            if not group & fixed:
                axes.append(Coordinate("x", name, group, reach))
                if not group & supports.on_ground:
                    axes.append(Coordinate("y", name, group, reach))
            placed = objects[name]
            if placed.concrete in (getattr(rules, "flat", None), getattr(rules, "inclined", None)):
                for sign in (1.0, -1.0):
                    far = placing.box(placed)[2] if sign > 0 else placing.box(placed)[0]
                    beyond = placing.beyond(layout, far, sign, fixed)
                    if beyond is not None:
                        axes.append(Coordinate("length", name, frozenset(beyond), reach, sign, name))
                        break
                if placed.concrete == getattr(rules, "inclined", None) and not any(
                    b == name for b in supports.support_of.values()
                ):
                    axes.append(Coordinate("slope", name, frozenset((name,)), settings.raise_turn))
            options = problem.domain.search.bodies(placed, problem.scenario)
            kinds = {(o.concrete, o.material): o for o in options}
            if len(kinds) > 1 and (placed.concrete, placed.material) in kinds:
                ranked = sorted(kinds.values(), key=problem.domain.search.mass)
                current = next(
                    i for i, o in enumerate(ranked) if (o.concrete, o.material) == (placed.concrete, placed.material)
                )
                axes.append(Coordinate("body", name, frozenset((name,)), 1.0, bodies=tuple(ranked), current=current))
        for a, b in pairs:
            if a not in objects or b not in objects or b in fixed:
                continue
            sign = 1.0 if objects[b].x >= objects[a].x else -1.0
            near = placing.box(objects[a])[2] if sign > 0 else placing.box(objects[a])[0]
            start = placing.box(objects[b])[0] if sign > 0 else placing.box(objects[b])[2]
            beyond = placing.beyond(layout, (near + start) / 2, sign, fixed)
            if beyond and b in beyond and a not in beyond:
                axes.append(Coordinate("gap", f"{a}→{b}", frozenset(beyond), reach, sign))
        unique = {}
        for axis in axes:  # one structure moved once, whichever of its objects named it
            unique.setdefault((axis.kind, axis.moves, axis.sign, axis.stretch), axis)
        axes = list(unique.values())
        space = cls(problem, layout, action, tuple(axes))
        return attrs.evolve(space, axes=tuple(axis for axis in axes if space.movable(axis)))

    def movable(self, axis: Coordinate) -> bool:
        """Whether a small move of `axis` either way stays inside the region."""
        index = self.axes.index(axis)
        for value in (PROBE, -PROBE):
            point = [0.0] * len(self.axes)
            point[index] = value
            if self.apply(point) is not None:
                return True
        return False

    def slopes(self) -> tuple[float, float]:
        """The least and most steepness (degrees) the world's incline rule draws a surface at."""
        incline = self.problem.domain.world.incline
        ranges = [incline.descending, incline.other] + ([incline.ramp] if incline.ramp else [])
        return min(r[0] for r in ranges), max(r[1] for r in ranges)

    def nearest(self, point: Sequence[float]) -> tuple[ConcreteLayout, object, str] | None:
        """(layout, action, what moved) at `point`, or, where that leaves the region, at the
        point brought back towards the origin: scaled by a half, then a quarter, then with its
        largest coordinates dropped one by one (a point's moves are each allowed alone more
        often than together). None when none of those is inside."""
        point = [float(v) for v in point]
        for scale in (1.0, 0.5, 0.25):
            found = self.apply([v * scale for v in point])
            if found is not None:
                return found
        reduced = list(point)
        for index in sorted(range(len(point)), key=lambda i: -abs(point[i]))[:-1]:
            reduced[index] = 0.0
            found = self.apply(reduced)
            if found is not None:
                return found
        return None

    def apply(self, point: Sequence[float]) -> tuple[ConcreteLayout, object, str] | None:
        """(layout, action, what moved) at `point` (in [−1, 1]ⁿ), or None outside the region."""
        problem = self.problem
        shift: dict[str, list[float]] = {}
        stretch: dict[str, tuple[float, float]] = {}
        turn: dict[str, float] = {}
        bodies: dict[str, PlacedObject] = {}
        steps: dict[int | None, int] = {}
        notes = []
        for axis, value in zip(self.axes, point, strict=True):  # one value per axis
            amount = float(value) * axis.reach
            if axis.kind == "action":
                if int(round(amount)):
                    steps[axis.line] = int(round(amount))
                    notes.append(axis.text(amount))
                continue
            if axis.kind == "body":
                chosen = axis.body(amount)
                if (chosen.concrete, chosen.material) != (
                    axis.bodies[axis.current].concrete,
                    axis.bodies[axis.current].material,
                ):
                    bodies[axis.name] = chosen
                    notes.append(axis.text(amount))
                continue
            if abs(amount) < 1e-4:
                continue
            notes.append(axis.text(amount))
            dx, dy = (0.0, amount) if axis.kind == "y" else (amount * axis.sign, 0.0)
            if axis.kind == "slope":
                turn[axis.name] = turn.get(axis.name, 0.0) + amount
                continue
            if axis.kind == "length":
                grown = stretch.get(axis.stretch, (0.0, axis.sign))
                stretch[axis.stretch] = (grown[0] + amount, axis.sign)
            for member in axis.moves:
                moved = shift.setdefault(member, [0.0, 0.0])
                moved[0] += dx
                moved[1] += dy
        objects = []
        moved = set()
        for o in self.layout.objects:
            dx, dy = shift.get(o.name, (0.0, 0.0))
            changes = {}
            if o.name in bodies:  # on the same bottom, centred where it stood
                body = bodies[o.name]
                changes.update(
                    concrete=body.concrete,
                    material=body.material,
                    width=body.width,
                    height=body.height,
                    y=round(o.y - o.height / 2 + body.height / 2 + dy, 5),
                )
                dy = 0.0
            if o.name in stretch:
                grow, sign = stretch[o.name]
                if o.width + grow < 0.3:
                    return None
                changes.update(width=round(o.width + grow, 5), x=round(o.x + dx + sign * grow / 2, 5))
            elif dx or dy or "y" in changes:
                changes.update(x=round(o.x + dx, 5), y=changes.get("y", round(o.y + dy, 5)))
            if o.name in turn:
                turned = o.rotation + turn[o.name]
                low, high = self.slopes()
                if not low <= abs(turned) <= high or turned * o.rotation <= 0:
                    return None
                changes["rotation"] = round(turned, 3)
            if changes:
                moved.add(o.name)
                o = attrs.evolve(o, **changes)
            objects.append(o)
        layout = attrs.evolve(self.layout, objects=tuple(objects)) if moved else self.layout
        if moved and not placing.consistent(layout, problem.parameters, moved, moved):
            return None
        action = self.action
        for line, step in steps.items():
            action = action if action is None else nudge(problem.domain.actions, action, step, line)
        if action is None or not problem.domain.actions.valid(problem.level_of(layout), action):
            return None
        return layout, action, ", ".join(notes)


def nudge(actions, action: object, step: int, line: int | None) -> object | None:
    """`action` moved `step` steps along its `line` (a domain with one line is not told which)."""
    return actions.nudged(action, step) if line is None else actions.nudged(action, step, line)
