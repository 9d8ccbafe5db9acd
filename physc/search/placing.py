"""Where a stage's new objects go: on the path the simulated prefix gives their actor.

The search places the target of `hit(a, b, d)` where the simulated prefix says `a`
passes, touching it from a declared side, a little further along the path each time
(`SearchSettings.step`); the target of `fall(a, b)` where `a` comes down to its height.
A target that rests on the ground or on a surface others use moves only along it; one
with its own support moves with it, and so does what rests on it and enters with it.
No place is offered that the prefix's bodies pass through before the moment of the
meeting, or that breaks a QSR of the chosen conjunction.

Everything here works on the placed layout (physc.compiler.concrete_layout), not on a
domain's level, so it serves every domain: lengths of a trace times the domain's
`search.trace_scale` are the layout's.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Set

import attrs
import numpy as np

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.compiler.dimension_graphs import LayoutParameters
from physc.compiler.geometry import overlapping_pair
from physc.compiler.qsr import joined
from physc.compiler.qsr_evaluate import five_points, holds
from physc.search.chain_stages import WHOLLY_ON, supports

GROUND = ("ground", "floor")  # concretes of the ground a body may rest on
FIXED_ROLES = ("support", "obstacle", "player")  # roles of what the search never places on a path


def box(placed: PlacedObject) -> tuple[float, float, float, float]:
    """(left, bottom, right, top) of a placed object's outline."""
    points = [
        p for k, p in five_points(placed.x, placed.y, placed.width, placed.height, placed.rotation).items() if k != "c"
    ]
    xs, ys = [p.real for p in points], [p.imag for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def consistent(
    layout: ConcreteLayout, parameters: LayoutParameters, moved: Set[str], resting: Set[str] = frozenset()
) -> bool:
    """The objects in `moved` inside the placement area, no two objects overlapping (joined
    platforms aside, and the player's objects, which start in turn from one place), and every
    QSR of the chosen conjunction about a moved object holding (any of its clause's; for an
    object of `resting`, resting on any part of its support will do)."""
    placed = {o.name: o for o in layout.objects}
    outlines = {}
    for name, o in placed.items():
        if name in moved:
            left, bottom, right, top = box(o)
            if (
                left < parameters.left - 1e-6
                or right > parameters.right + 1e-6
                or bottom < parameters.bottom - 1e-6
                or top > parameters.top + 1e-6
            ):
                return False
        if o.concrete in GROUND:
            continue
        points = five_points(o.x, o.y, o.width, o.height, o.rotation)
        outlines[name] = [(points[k].real, points[k].imag) for k in ("ll", "lr", "ur", "ul")]
    players = [o.name for o in layout.objects if o.role == "player"]  # shot in turn from one place
    allowed = joined(layout.conjunction) | {frozenset(pair) for pair in itertools.combinations(players, 2)}
    if overlapping_pair(outlines, 1e-4, allowed) is not None:
        return False
    for r in layout.conjunction:  # (not placement's separations: only overlaps matter there)
        if r.a in placed and r.b in placed and (r.a in moved or r.b in moved):
            names = r.alternatives or (r.relation,)
            if r.a in resting and r.relation in WHOLLY_ON:  # anywhere on its support, as it moves along it
                names = WHOLLY_ON
            if not any(holds(n, placed[r.a], placed[r.b], parameters.clearance, parameters.far) for n in names):
                return False
    return True


@attrs.frozen
class Supports:
    """What the search reads of the placed layout once: what rests on what, which objects
    have a support of their own, which rest on the ground (or on the bottom of the placement
    area, in a domain without supports), and which the search never
    moves onto a path (supports, obstacles, the player's object, the ground; a scenario's
    own surface may be moved, with what rests on it)."""

    support_of: dict[str, str]  # object → what it rests on
    own_support: dict[str, str]  # object → the support that carries it alone
    on_ground: frozenset[str]
    fixed: frozenset[str]

    @classmethod
    def of(cls, layout: ConcreteLayout, parameters: LayoutParameters) -> Supports:
        support_of = supports(layout)
        carried: dict[str, int] = {}
        for s in support_of.values():
            carried[s] = carried.get(s, 0) + 1
        roles = {o.name: o.role for o in layout.objects}
        concretes = {o.name: o.concrete for o in layout.objects}
        own = {
            a: s
            for a, s in support_of.items()
            if roles.get(s) == "support" and carried[s] == 1 and concretes[s] not in GROUND
        }
        ground = {a for a, s in support_of.items() if concretes.get(s) in GROUND or s not in roles}
        ground |= {
            o.name for o in layout.objects if o.name not in support_of and abs(box(o)[1] - parameters.bottom) < 1e-3
        }
        ground = frozenset(ground)
        fixed = frozenset(n for n, r in roles.items() if r in FIXED_ROLES or concretes[n] in GROUND)
        return cls(support_of, own, ground, fixed)

    def movers(self, name: str, entry: dict) -> set[str]:
        """`name` with its own support and what rests on it and enters with it: what moves
        when it is placed."""
        members = {name}
        if name in self.own_support:
            members.add(self.own_support[name])
        members |= {a for a, b in self.support_of.items() if b == name and entry.get(a) == entry.get(name)}
        return members

    def sideways_only(self, name: str) -> bool:
        """Whether `name` rests on the ground or on a surface others use (it moves along it)."""
        return name in self.on_ground or (name in self.support_of and name not in self.own_support)


def shifted(
    layout: ConcreteLayout, members: set[str], dx: float, dy: float, supports: Supports
) -> ConcreteLayout | None:
    """`layout` with `members` moved together by (dx, dy) (only sideways if one rests on the
    ground); None if that moves nothing."""
    if members & supports.on_ground:
        dy = 0.0
    if abs(dx) < 1e-6 and abs(dy) < 1e-6:
        return None
    objects = tuple(
        attrs.evolve(o, x=round(o.x + dx, 5), y=round(o.y + dy, 5)) if o.name in members else o for o in layout.objects
    )
    return attrs.evolve(layout, objects=objects)


def along(rows, scale: float, step: float, moving: float):
    """(row, x, y) in layout units every `step` of travel along a path, while the body still moves."""
    last = None
    for i, (x, y, _, vx, vy, _) in enumerate(rows):
        if math.isnan(x):
            return
        if last is not None and math.hypot(vx, vy) < moving:
            return
        x, y = x * scale, y * scale
        if last is None or math.hypot(x - last[0], y - last[1]) >= step:
            last = (x, y)
            yield i, x, y


def hit_places(actor_size, target, rows, directions, sideways: bool, scale: float, settings):
    """(row, x, y) of `target`'s centre touching the actor from a declared side along its path."""
    wa, ha = actor_size
    wb, hb = target.width, target.height
    gap = settings.gap
    for step, x, y in along(rows, scale, settings.step, settings.moving):
        for side in directions:
            if side == "left":
                px, py = x + (wa + wb) / 2 + gap, y
            elif side == "right":
                px, py = x - (wa + wb) / 2 - gap, y
            elif side == "above":
                px, py = x, y - (ha + hb) / 2 - gap
            elif side == "below":
                px, py = x, y + (ha + hb) / 2 + gap
            else:
                continue
            if sideways:
                if side not in ("left", "right") or abs(y - target.y) > (ha + hb) / 2 - 0.05:
                    continue
                py = target.y
            yield step, px, py


LANDINGS = (0.0, 0.15, -0.15, 0.3, -0.3)  # shares of the two half-widths off where a fall comes down, tried in turn


def landings(faller_size, target, rows, scale: float, behind: float | None = None):
    """(row, x, y) of `target` under where a body of `faller_size` first comes down to its
    top, and a little off it (behind its centre first, `behind` = ±1, if it moves next)."""
    wa, ha = faller_size
    top = target.y + target.height / 2 + ha / 2
    landing = next(
        (
            (i, x * scale)
            for i, (x, y, _, _, vy, _) in enumerate(rows)
            if not math.isnan(x) and vy < -0.1 and y * scale <= top
        ),
        None,
    )
    if landing is None:
        return
    step, x = landing
    reach = (wa + target.width) / 2
    shares = LANDINGS if behind is None else tuple(behind * s for s in (0.25, 0.45)) + LANDINGS
    for share in shares:
        if abs(share) < 1:
            yield step, x + share * reach, target.y


def approach(
    trace, objects, sizes: dict, scale: float, margin: float, until: int | None = None, centre_only: str | None = None
) -> int | None:
    """The first row of `trace` (before `until`) at which one of its bodies comes within
    `margin` of one of `objects` (their boxes), or None; a body is a disc of half its larger
    side (`sizes`: name → (width, height)), but `centre_only`'s centre only has to stay out."""
    first = None
    rows = trace.states[:until, :, :2] * scale
    for index, name in enumerate(trace.names):
        radius, gap = (0.0, 0.0) if name == centre_only else (max(sizes.get(name, (0.0, 0.0))) / 2, margin)
        x, y = rows[:, index, 0], rows[:, index, 1]
        for obj in objects:
            near = np.flatnonzero(
                (np.abs(x - obj.x) - obj.width / 2 - radius - gap < 0)
                & (np.abs(y - obj.y) - obj.height / 2 - radius - gap < 0)
            )
            if len(near) and (first is None or near[0] < first):
                first = int(near[0])
    return first


def clear(trace, row: int, changed, actor: str, sizes: dict, scale: float, margin: float) -> bool:
    """Whether the bodies of the prefix pass clear of the `changed` objects before `row` (the
    moment the actor is to meet them); the actor's own centre only has to stay out."""
    return approach(trace, changed, sizes, scale, margin, row, actor) is None


def beyond(layout: ConcreteLayout, cut: float, sign: float, fixed: Set[str] = frozenset()) -> set[str] | None:
    """The objects wholly beyond `cut` along the heading `sign` (the ground and the player's
    object aside): what moves with a surface brought closer or stretched. None if another
    object straddles the cut, or one of `fixed` lies beyond it."""
    names = set()
    for o in layout.objects:
        if o.concrete in GROUND or o.role == "player":
            continue
        left, _, right, _ = box(o)
        near, far = (left, right) if sign > 0 else (-right, -left)
        if near >= sign * cut - 1e-9:
            if o.name in fixed:
                return None
            names.add(o.name)
        elif far > sign * cut + 1e-9:
            return None
    return names
