"""Local changes for a stage that no variant realised: what kept an interaction from happening.

When a stage's best attempt stops at an interaction of its own (not at the meeting with a
new object, which placing.py and choosing.py answer), the search offers changes aimed at
what the simulation shows was wrong, each a new layout that the stage then simulates:

* `bounce(a, s, d)` did not happen: the surface turned a little either way (8°, 15°), or
  mirrored when `a` bounced away from what it must hit next;
* `fall(a, b)` did not happen: `a` at the edge of its support on the side it is pushed
  to, or its support ending there; a body for `a` that falls more readily (lighter);
* `roll`/`slide` did not happen: the surface it must move onto (and the world beyond) brought
  to the end of the one it rests on, level with it or a step down (a body set moving on one
  platform must cross onto the next); a body for the mover that the physics of its push
  favours (lighter; for a slide, slipperier); the mover next to the surface;
* `destroy(a, b)` did not happen: a body for the attacker that brings more momentum;
* the first hit did not happen: the target's own support no longer reaching out beyond it.

Everything works on the placed layout; a change is offered only where every QSR of the
chosen conjunction about what moved still holds.
"""

from __future__ import annotations

from collections.abc import Set

import attrs

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.compiler.sequence import last_hit_at, last_hit_on
from physc.search import choosing, placing
from physc.search.chain_stages import prefix
from physc.search.problem import Problem

TURNS = (-8.0, 8.0, -15.0, 15.0)  # degrees a bounce surface is turned, tried in turn
TILT = (5.0, 60.0)  # a turned bounce surface stays this inclined, in degrees
EDGE_GAP = 0.02  # layout units a faller put at the edge of its support keeps from it
SHORTEST = 0.64  # layout units a support cut to end at its faller keeps at least


def offered(problem: Problem, layout, failed, start: int):
    """(description, layout) for the first interaction `failed` (the best failed attempt of a
    stage beginning at `start`) did not realise."""
    index = failed.fidelity.matched
    interactions = problem.interactions
    if index >= len(interactions):
        return
    declared = interactions[index]
    objects = {o.name: o for o in layout.objects}
    if declared.name == "bounce":
        yield from turned(problem, layout, objects, declared.objects[1], start, mirror=False)
    elif declared.name == "fall":
        yield from to_the_edge(problem, layout, objects, declared.objects[0], index, start)
        yield from bodies_for(problem, layout, objects, declared.objects[0], "fall", start)
    elif declared.name in ("roll", "slide"):
        yield from closer(
            problem, layout, objects, declared.objects[0], declared.objects[1], declared.directions[0], start
        )
        yield from bodies_for(problem, layout, objects, declared.objects[0], declared.name, start)
        yield from next_to(
            problem, layout, objects, declared.objects[0], declared.objects[1], declared.directions[0], start
        )
    elif declared.name == "destroy":
        yield from bodies_for(problem, layout, objects, declared.objects[0], "destroy", start)
    elif declared.name == "hit" and index == 0:
        yield from exposed(problem, layout, objects, declared, start)
    elif declared.name == "hit" and index > 0 and interactions[index - 1].name == "bounce":
        bounce = interactions[index - 1]  # it bounced, but away from what it must hit
        if bounce.objects[0] == declared.objects[0]:
            yield from turned(problem, layout, objects, bounce.objects[1], start, mirror=True)


def _kept(
    problem: Problem, layout: ConcreteLayout, start: int, moved: Set[str], resting: Set[str] = frozenset()
) -> bool:
    """Whether `layout`, as the scene of stage `start`, keeps every relation of the moved objects."""
    return placing.consistent(prefix(layout, problem.entry, start), problem.parameters, moved, resting)


def _with(layout: ConcreteLayout, changed: dict[str, PlacedObject]) -> ConcreteLayout:
    return attrs.evolve(layout, objects=tuple(changed.get(o.name, o) for o in layout.objects))


def turned(problem: Problem, layout, objects, name: str, start: int, mirror: bool):
    """The bounce surface `name` turned a little either way (and, with `mirror`, tilted the
    other way: a bounce off its underside then goes the other way)."""
    surface = objects.get(name)
    if surface is None:
        return
    angles = [surface.rotation + step for step in TURNS] + ([-surface.rotation] if mirror else [])
    for angle in angles:
        if not TILT[0] <= abs(angle) <= TILT[1]:
            continue
        candidate = _with(layout, {name: attrs.evolve(surface, rotation=round(angle, 3))})
        if _kept(problem, candidate, start, {name}):
            yield f"bounce: {name} turned to {angle:.1f}°", candidate


def to_the_edge(problem: Problem, layout, objects, faller: str, index: int, start: int):
    """`faller` at the edge of its support on the side its last hit pushes it to, then the
    support cut to end just beyond it there."""
    hit_at = last_hit_at(problem.interactions[:index], faller)
    support = problem.supports.support_of.get(faller)
    if (
        hit_at is None
        or faller not in objects
        or support is None
        or support not in objects
        or objects[support].concrete in placing.GROUND
    ):
        return
    pushed = problem.pushed_by(hit_at)
    if pushed is None:
        return
    block, ledge = objects[faller], objects[support]
    sign = 1.0 if pushed == "right" else -1.0
    left, _, right, _ = placing.box(ledge)
    x = right - block.width / 2 - EDGE_GAP if sign > 0 else left + block.width / 2 + EDGE_GAP
    if abs(x - block.x) >= 0.05:
        candidate = _with(layout, {faller: attrs.evolve(block, x=round(x, 5))})
        if _kept(problem, candidate, start, {faller}, {faller}):
            yield f"fall({faller}): at the {pushed} edge of {support}", candidate
    cut = ledge_ends_at(problem, layout, objects, faller, support, pushed, start)
    if cut is not None:
        yield f"fall({faller}): {support} ends at {faller}", cut


def ledge_ends_at(problem: Problem, layout, objects, faller: str, support: str, pushed: str, start: int):
    """`layout` with `faller`'s `support` ending just beyond it on the side it is `pushed` to
    (the platform shorter at that end only; what else rests on it must still), or None: a
    smaller push then takes it over the edge."""
    block, ledge = objects.get(faller), objects.get(support)
    if block is None or ledge is None or ledge.rotation or ledge.concrete in placing.GROUND:
        return None
    left, _, right, _ = placing.box(ledge)
    b_left, _, b_right, _ = placing.box(block)
    new_left, new_right = (left, b_right + EDGE_GAP) if pushed == "right" else (b_left - EDGE_GAP, right)
    if not SHORTEST <= new_right - new_left < ledge.width - 0.05:
        return None
    cut = attrs.evolve(ledge, x=round((new_left + new_right) / 2, 5), width=round(new_right - new_left, 5))
    candidate = _with(layout, {support: cut})
    return candidate if _kept(problem, candidate, start, {support, faller}, {faller}) else None


def bodies_for(problem: Problem, layout, objects, name: str, act: str, start: int):
    """`name` as each other body it may take that does `act` better, by the estimate of
    physc.search.choosing, best first."""
    current = objects.get(name)
    if current is None:
        return
    hit = last_hit_on(problem.interactions, name)
    actor = objects.get(hit.objects[0]) if hit is not None else None
    domain = problem.domain
    actor_mass = domain.search.mass(actor) if actor is not None else None

    def estimate(body) -> float:
        return choosing.worth(act, domain.search.mass(body), domain.search.friction(body), actor_mass)

    here = estimate(current)
    for body in sorted(domain.search.bodies(current, problem.scenario), key=estimate, reverse=True):
        if estimate(body) <= here * (1 + 1e-6):
            break
        fitted = choosing.refitted(current, body, ())
        candidate = _with(layout, {name: fitted})
        if _kept(problem, candidate, start, {name}, {name}):
            material = f" {body.material}" if body.material else ""
            yield f"{act}({name}): a{material} {body.concrete}", candidate


STEPS_DOWN = (0.0, 0.15)  # layout units the next surface's top is tried below the end of the one before
SEAM = 0.02  # layout units left between a surface brought closer and the end of the one before


def closer(problem: Problem, layout, objects, mover: str, surface: str, heading: str, start: int):
    """`surface`, which `mover` must roll or slide onto from the support it rests on, and the
    world beyond it, brought back to the end of that support: level with it, or a step down."""
    support = problem.supports.support_of.get(mover)
    if (
        heading not in ("left", "right")
        or support in (None, surface)
        or surface not in objects
        or support not in objects
    ):
        return
    sign = 1.0 if heading == "right" else -1.0
    s_left, _, s_right, s_top = placing.box(objects[support])
    t_left, _, t_right, t_top = placing.box(objects[surface])
    end, near = (s_right, t_left) if sign > 0 else (s_left, t_right)
    gap = sign * (near - end)
    if gap < SEAM + 0.05 and t_top <= s_top + 1e-6:
        return
    names = placing.beyond(layout, end + sign * 1e-6, sign)
    if not names or surface not in names:
        return
    dx = -sign * (gap - SEAM)
    for drop in STEPS_DOWN:
        dy = (s_top - drop) - t_top
        moved = {
            n: attrs.evolve(objects[n], x=round(objects[n].x + dx, 5), y=round(objects[n].y + dy, 5)) for n in names
        }
        candidate = _with(layout, moved)
        if _kept(problem, candidate, start, set(names)):
            step = f", {drop:g} lower" if drop else ", level"
            yield (
                f"{mover} onto {surface}: {surface} and the world beyond brought to the end of {support}{step}",
                candidate,
            )


def next_to(problem: Problem, layout, objects, mover: str, surface: str, heading: str, start: int):
    """`mover` along its support to just before the start of `surface`."""
    if mover not in objects or surface not in objects or heading not in ("left", "right"):
        return
    block = objects[mover]
    left, _, right, _ = placing.box(objects[surface])
    gap = problem.parameters.clearance + 0.02
    x = left - block.width / 2 - gap if heading == "right" else right + block.width / 2 + gap
    if abs(x - block.x) < 0.05:
        return
    candidate = _with(layout, {mover: attrs.evolve(block, x=round(x, 5))})
    if _kept(problem, candidate, start, {mover}, {mover}):
        yield f"{mover} next to {surface}", candidate


def exposed(problem: Problem, layout, objects, declared, start: int):
    """The first hit did not happen from an allowed side: the target's own support reaches
    out beyond it on that side and shields it, so it gets shorter."""
    target = declared.objects[1]
    support = problem.supports.own_support.get(target)
    if target not in objects or support is None or support not in objects or objects[support].rotation:
        return
    left, _, right, _ = placing.box(objects[target])
    s_left, _, s_right, _ = placing.box(objects[support])
    for side in declared.directions:
        if side == "left" and s_left < left - 0.1:
            new_left, new_right = left - 0.05, s_right
        elif side == "right" and s_right > right + 0.1:
            new_left, new_right = s_left, right + 0.05
        else:
            continue
        if new_right - new_left < SHORTEST:
            continue
        cut = attrs.evolve(
            objects[support], x=round((new_left + new_right) / 2, 5), width=round(new_right - new_left, 5)
        )
        candidate = _with(layout, {support: cut})
        if _kept(problem, candidate, start, {target, support}, {target}):
            yield f"{declared.text}: {support} no longer shields {target}", candidate
