"""Step 3 of the layout inference (physc.compiler.layout_inference): supports and paths.

Every dynamic object except the player's rests on a support, and a mover's path runs over
its surfaces (the reading in the docstring of physc.compiler.layout_rules): the supports a
scenario declares, those of the objects hit (on a mover's path, at a ramp's foot, on the
ground, beside a surface, on a support of their own), of a blast's targets and of a
contrast, then of the objects nothing moves.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from physc.compiler.sequence import OPPOSITE, pushes
from physc.dsl.scenario import TermIR

if TYPE_CHECKING:
    from physc.compiler.layout_inference import Inference

ANY_LOCATION = ("left", "centre", "right")


def _push_off(direction: str) -> tuple[str, ...]:
    """Where on its support an object should rest to fall when hit from `direction`."""
    if direction == "left":
        return ("right",)
    if direction == "right":
        return ("left",)
    return ("left", "right")


def declared_supports(s: Inference) -> None:
    """3. Supports and paths, in the order of the sequence; first the structures a scenario
    declares (version 2: on(a, b), a rests on b)."""
    for term in s.scenario.restrictions:
        if term.name == "on" and term.objects[0] in s.dynamic and term.objects[0] not in s.support:
            top, below = term.objects
            s.rest_on(top, below, ("over",), f"{top} rests on {below}: {term.text}", term.span)


def hit_supports(s: Inference) -> None:
    """3. The support of each dynamic object that is hit, and the paths of the movers."""
    for position, term in enumerate(s.scenario.interactions):
        if term.name != "hit":
            continue
        actor, target = term.objects
        if target not in s.dynamic or target in s.support:
            continue
        sideways = [d for d in term.directions if d in ("left", "right")]
        path = s.path_of(actor)
        last = path[-1] if path else None
        if last is not None and _at_ramp_foot(s, actor, last, sideways):
            _rest_at_ramp_foot(s, term, last)
        elif path and sideways:
            _rest_on_path(s, term, path[-1])
        elif target in s.surfaces and s.b.is_ground(s.surfaces[target][0]):
            _rest_on_ground(s, term, s.surfaces[target][0])
        elif target in s.surfaces:
            _rest_beside_surface(s, target)
        else:
            _rest_on_new_support(s, position, term)
        if target in s.surfaces:
            s.paths[target] = [s.support[target]] + [x for x in s.surfaces[target] if x != s.support[target]]
        # A mover that hits a target with a path of its own continues onto it.
        if s.path_of(actor) and sideways and target in s.paths and s.paths[target][0] != s.path_of(actor)[-1]:
            s.paths[actor].append(s.paths[target][0])


def _at_ramp_foot(s: Inference, actor: str, last: str, sideways: list[str]) -> bool:
    """Whether, in the ramp structure, `actor` comes down its last surface `last` (which may be
    inclined) before it hits its target sideways."""
    return bool(
        s.structure == "ramp"
        and sideways
        and last in s.surfaces.get(actor, ())
        and not s.b.is_ground(last)
        and s.rules.inclined in s.b.nodes[last].concrete
        and last not in s.support.values()
    )


def _rest_at_ramp_foot(s: Inference, term: TermIR, ramp: str) -> None:
    """The ramp: the mover comes down its surface; the target rests at the foot, on a support
    of its own facing the ramp, which the mover's path continues onto."""
    actor, target = term.objects
    own = s.b.support_node(target, (s.rules.flat,))
    s.rest_on(
        target,
        own,
        (OPPOSITE[s.heading[actor]],),
        f"{target} rests at the foot of the ramp {ramp}: {term.text}",
        term.span,
    )
    s.ramps.append(ramp)
    s.paths[actor].append(own)


def _rest_on_path(s: Inference, term: TermIR, rest: str) -> None:
    """A target hit sideways by a mover along surfaces rests on the mover's last surface, on the
    side the mover comes towards."""
    actor, target = term.objects
    towards = s.heading[actor]
    where = (towards,)
    if rest in s.surfaces.get(target, ()) and s.heading[target] == towards:
        # It goes on along the same surface: it rests in its middle, ahead of its
        # hitter and with room ahead of it.
        where = ("centre",)
    s.rest_on(target, rest, where, f"{target} lies on the path of {actor}: {term.text}", term.span)


def _rest_on_ground(s: Inference, term: TermIR, ground: str) -> None:
    """A target that moves along the ground first rests on it, anywhere."""
    target = term.objects[1]
    s.rest_on(target, ground, ANY_LOCATION, f"{target} rests on the ground it moves along", term.span)


def _rest_beside_surface(s: Inference, target: str) -> None:
    """A target that rolls or slides rests on a support platform of its own, which its path
    continues from."""
    first = s.moved_on[target]
    own = s.b.support_node(target, (s.rules.flat,))
    s.rest_on(
        target, own, (s.heading[target],), f"{target} starts beside the surface it moves on: {first.text}", first.span
    )


def _rest_on_new_support(s: Inference, position: int, term: TermIR) -> None:
    """Otherwise a new support, anywhere on it; for a target that will fall, a platform it can
    be pushed off (on the part of it that the hit pushes it towards)."""
    target = term.objects[1]
    own = s.b.support_node(target, (s.rules.flat,) if target in s.falls else s.anywhere)
    if target in s.falls:
        pushed = pushes(s.scenario.interactions, position, s.players, s.rules.player_heading)
        locations = (pushed,) if pushed else tuple(dict.fromkeys(loc for d in term.directions for loc in _push_off(d)))
        text = f"{target} rests where it can be pushed off to fall: {term.text}"
    else:
        locations = ANY_LOCATION
        text = f"{target} rests on a support"
    s.rest_on(target, own, locations, text, term.span)


def blast_supports(s: Inference) -> None:
    """A blast's targets (version 2: destroy(a, b) after explode(a)) rest beside what explodes,
    on its support: within its reach."""
    exploded: set[str] = set()
    for term in s.scenario.interactions:
        if term.name == "explode":
            exploded.add(term.objects[0])
        elif (
            term.name == "destroy"
            and term.objects[0] in exploded
            and term.objects[1] in s.dynamic
            and term.objects[1] not in s.support
        ):
            source, target = term.objects
            if source in s.support:
                s.rest_on(
                    target,
                    s.support[source],
                    ANY_LOCATION,
                    f"{target} lies within the blast of {source}: {term.text}",
                    term.span,
                )


def contrast_supports(s: Inference) -> None:
    """A contrast (version 2: contrast(a, b)) rests on its counterpart's support, as it does."""
    for term in s.scenario.restrictions:
        if (
            term.name == "contrast"
            and term.objects[0] in s.dynamic
            and term.objects[0] not in s.support
            and term.objects[1] in s.support
        ):
            contrast, counterpart = term.objects
            s.rest_on(
                contrast,
                s.support[counterpart],
                ANY_LOCATION,
                f"{contrast} rests as {counterpart} does: {term.text}",
                term.span,
            )


def remaining_supports(s: Inference) -> None:
    """Dynamic objects that nothing hits (they never move) still need a support."""
    for name in s.dynamic:
        if name not in s.support:
            own = s.b.support_node(name, s.anywhere)
            s.rest_on(name, own, ANY_LOCATION, f"{name} rests on a support", None)
