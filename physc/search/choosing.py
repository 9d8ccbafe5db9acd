"""A stage's new object given the body that the meeting's physics favours.

The body of a new object (its kind, material and size, among those its scenario allows)
is chosen when the stage is built, after the prefix has been simulated, from what the
arriving actor brings, instead of drawn before any simulation. A collision gives its
target at most (1 + e)·m₁/(m₁ + m₂) of the hitter's speed, so what the target must do next
decides which body is best:

* to roll or hit on: as fast as it can start, a lighter body (speed u);
* to slide on, or be pushed off its ledge to fall: as far as it can go, u²/μ, a lighter or
  slipperier body;
* to destroy the goal straight away, with no motion of its own between: the momentum it
  brings, m₂·u, a heavier one. (What must first fall or roll is chosen for that: a fall's
  speed comes from its height, whatever its mass.)
* to be destroyed (a goal object, which does nothing itself): the least damage destroys it,
  by the world's damage rule (`SimulatedDomain.toughness`: life and defence).

The domain says what bodies an object may take and their masses and frictions
(`SimulatedDomain.bodies`, `mass`, `friction`); the search simulates the best few and keeps
what works. The body drawn by the layout stays the first variant tried.
"""

from __future__ import annotations

import math

import attrs

from physc.compiler.concrete_layout import PlacedObject
from physc.search import placing
from physc.search.chain_stages import prefix
from physc.search.problem import Problem


def next_act(interactions, name: str, start: int) -> str | None:
    """What `name` does next as an actor from interaction `start` on: the first motion it
    makes (roll, slide, fall: what its push must give it), else "destroy" if it destroys
    something, else the first term it acts in."""
    acts = [t.name for t in interactions[start:] if t.objects and t.objects[0] == name]
    if not acts:
        destroyed = any(t.name == "destroy" and t.objects[-1] == name for t in interactions[start:])
        return "destroyed" if destroyed else None
    motion = next((a for a in acts if a not in ("hit", "destroy")), None)
    return motion or ("destroy" if "destroy" in acts else acts[0])


def worth(act: str, mass: float, friction: float, actor_mass: float | None, toughness: float = 0.0) -> float:
    """The estimate of how well a body of `mass` and `friction` (and `toughness`: the damage
    that destroys it) does `act` after a hit by an actor of `actor_mass` (None: much heavier
    than anything it hits)."""
    if act == "destroyed":
        return 1.0 / max(toughness, 1e-6)
    share = 1.0 if actor_mass is None else actor_mass / (actor_mass + mass)
    if act == "destroy":
        return mass * share
    if act in ("slide", "fall"):  # it must travel (to the edge, for a fall) against its friction
        return share * share / max(friction, 1e-3)
    return share


def refitted(old: PlacedObject, new: PlacedObject, directions: tuple[str, ...]) -> PlacedObject:
    """`new` (a body for `old`'s object) where `old` was: on the same bottom, and touching
    the same side that its actor comes from."""
    x = old.x
    if directions == ("left",):
        x = old.x - old.width / 2 + new.width / 2
    elif directions == ("right",):
        x = old.x + old.width / 2 - new.width / 2
    return attrs.evolve(new, x=round(x, 5), y=round(old.y - old.height / 2 + new.height / 2, 5))


def alternatives(problem: Problem, layout, declared, stage, attempt):
    """(note, layout) with the stage's target given each other body it may take that the
    estimate ranks above the body it has, best first."""
    if declared.name in ("roll", "slide", "bounce", "destroy") or len(declared.objects) < 2:
        return
    actor, target = declared.objects[0], declared.objects[1]
    objects = {o.name: o for o in layout.objects}
    if target not in stage.new or target not in objects or target in problem.supports.fixed:
        return
    act = next_act(problem.interactions, target, stage.start + 1)
    domain = problem.domain
    if act is None:
        return
    current = objects[target]
    options = domain.search.bodies(current, problem.scenario)
    if not options:
        return
    actor_mass = domain.search.mass(objects[actor]) if actor in objects else None

    def estimate(body) -> float:
        toughness = domain.search.toughness(body) if act == "destroyed" else 0.0
        return worth(act, domain.search.mass(body), domain.search.friction(body), actor_mass, toughness)

    here = estimate(current)
    ranked = sorted(options, key=estimate, reverse=True)
    for body in ranked:
        if estimate(body) <= here * (1 + 1e-6) or (body.concrete, body.material) == (
            current.concrete,
            current.material,
        ):
            continue
        fitted = refitted(current, body, tuple(declared.directions))
        changed = attrs.evolve(layout, objects=tuple(fitted if o.name == target else o for o in layout.objects))
        if not placing.consistent(prefix(changed, problem.entry, stage.start), problem.parameters, {target}, {target}):
            continue
        material = f" {body.material}" if body.material else ""
        yield (
            f"{target}: a{material} {body.concrete} ({act}: ×{estimate(body) / here if here else math.inf:.2f})",
            changed,
        )
