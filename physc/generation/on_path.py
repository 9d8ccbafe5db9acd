"""liesOnPath made true in simulation: the next target moved onto its actor's path.

The paper leaves `liesOnPath(b, a)` to simulation: b must lie where a goes. When the
play that came furthest stops at a `hit(a, b, d)` or a `fall(a, b)` that did not
happen, the simulated path of `a` after the last interaction realised says where `b`
should be. This module proposes placed layouts with `b` moved there, together with
what it rests on and what rests on that (its structure), so that `a` comes to `b` from
the declared side: for a hit from above (or a fall), `b`'s top under the path; from the
left, `b`'s left side on it; from the right, its right side. When `b` rests on a surface
of the prefix (the surface `a` rolls along), `b` alone slides along that surface's top
to the path, resting anywhere on it.

It works on the placed layout (physc.compiler.concrete_layout), not on a domain's level,
so it serves every domain: a proposal keeps every object inside the placement area,
overlapping nothing it did not overlap, and every QSR of the chosen conjunction holding.
Objects of the realised prefix never move.
"""

from __future__ import annotations

import attrs
import numpy as np

from physc.compiler.geometry import overlapping_pair
from physc.compiler.qsr import joined
from physc.compiler.qsr_evaluate import five_points, holds

RESTS_ON = ("MeetN", "MeetDuringW", "MeetDuringE")
SAMPLE_EVERY = 0.1  # seconds between the points of the path tried
SAMPLE_AFTER = 0.3  # seconds after the last interaction realised before the first point (time to recognise it)
SAMPLE_FOR = 3.0  # seconds of the path after the last interaction realised
PROPOSALS = 8  # layouts proposed at most


def structure(layout, name: str) -> set[str]:
    """`name`, what it rests on (down to what rests on nothing), and everything that rests
    on any of those: what moves with it."""
    rests_on = {r.a: r.b for r in layout.conjunction if r.relation in RESTS_ON}
    names = {o.name for o in layout.objects}
    group = {name}
    below = name
    while below in rests_on and rests_on[below] in names:
        below = rests_on[below]
        group.add(below)
    grew = True
    while grew:
        grew = False
        for a, b in rests_on.items():
            if b in group and a not in group and a in names:
                group.add(a)
                grew = True
    return group


def _box(placed) -> tuple[float, float, float, float]:
    points = [p for k, p in five_points(placed.x, placed.y, placed.width, placed.height, placed.rotation).items() if k != "c"]
    xs, ys = [p.real for p in points], [p.imag for p in points]
    return min(xs), min(ys), max(xs), max(ys)


def consistent(layout, parameters, moved: set[str], resting: set[str] = frozenset()) -> bool:
    """The objects in `moved` inside the placement area, no two objects overlapping
    (joined platforms aside), and every QSR of the chosen conjunction about a moved object
    holding (any of its clause's; for an object of `resting`, resting on any part of its
    support will do)."""
    placed = {o.name: o for o in layout.objects}
    outlines = {}
    for name, o in placed.items():
        if name in moved:
            left, bottom, right, top = _box(o)
            if left < parameters.left - 1e-6 or right > parameters.right + 1e-6 or bottom < parameters.bottom - 1e-6 or top > parameters.top + 1e-6:
                return False
        points = five_points(o.x, o.y, o.width, o.height, o.rotation)
        outlines[name] = [(points[k].real, points[k].imag) for k in ("ll", "lr", "ur", "ul")]
    if overlapping_pair(outlines, 1e-4, joined(layout.conjunction)) is not None:
        return False
    for r in layout.conjunction:  # (not placement's separations: only overlaps matter there)
        if r.a in placed and r.b in placed and (r.a in moved or r.b in moved):
            names = r.alternatives or (r.relation,)
            if r.a in resting and r.relation in RESTS_ON:
                names = RESTS_ON
            if not any(holds(n, placed[r.a], placed[r.b], parameters.clearance, parameters.far) for n in names):
                return False
    return True


def proposals(layout, scenario, trace, fidelity, parameters, scale: float = 1.0):
    """(description, layout) for the next unrealised hit or fall of `scenario`, its target
    moved onto the actor's path in `trace` (lengths × `scale` are the layout's)."""
    k = fidelity.matched
    if k >= len(scenario.interactions):
        return []
    term = scenario.interactions[k]
    if term.name not in ("hit", "fall") or len(term.objects) < 2:
        return []
    actor, target = term.objects[0], term.objects[1]
    placed = {o.name: o for o in layout.objects}
    if target not in placed or actor not in trace.names:
        return []
    group = structure(layout, target)
    chain = {n for t in scenario.interactions[:k] for n in t.objects}
    along = False  # sliding along a surface of the prefix
    if group & chain:
        rests_on = {r.a: r.b for r in layout.conjunction if r.relation in RESTS_ON}
        group = {target} | {a for a, b in rests_on.items() if b == target}
        along = rests_on.get(target) in chain and not group & chain
        if not along:
            return []
    if any(placed[n].concrete in ("floor", "ground") for n in group):
        return []
    sides = ("above",) if term.name == "fall" else tuple(d for d in term.directions if d in ("above", "left", "right"))
    since = fidelity.times[-1] if fidelity.times else 0.0
    first, last = int((since + SAMPLE_AFTER) / trace.dt), int((since + SAMPLE_FOR) / trace.dt)
    stride = max(int(round(SAMPLE_EVERY / trace.dt)), 1)
    path = trace.states[first:last:stride, trace.index(actor), :2] * scale
    left, bottom, right, top = _box(placed[target])
    out = []
    for px, py in path[~np.isnan(path[:, 0])]:
        for side in sides:
            if side == "above":
                dx, dy = px - (left + right) / 2, py - top
            elif side == "left":
                dx, dy = px - left, py - (bottom + top) / 2
            else:
                dx, dy = px - right, py - (bottom + top) / 2
            if along:
                dy = 0.0
            moved = tuple(attrs.evolve(o, x=o.x + dx, y=o.y + dy) if o.name in group else o for o in layout.objects)
            candidate = attrs.evolve(layout, objects=moved)
            if consistent(candidate, parameters, group, {target} if along else frozenset()):
                out.append((f"liesOnPath: {target} moved ({dx:+.2f}, {dy:+.2f}) onto the path of {actor}, from {side}", candidate))
                if len(out) == PROPOSALS:
                    return out
    return out
