"""What a placed layout offers each link of its chain, as numbers: the features the proposal
model (physc.search.proposal_model) learns from.

A link is one declared interaction, `kind(a, b, directions)`. Its features are read off the
layout as placed, in the layout's units and relative to the link's own objects, so that one
kind of link in one scenario speaks of the same things as in another (a roll's run to the end
of its support is a roll's run in any scenario and any world):

* `ahead`: how far `b`'s centre lies from `a`'s in the way the link goes (its direction's
  sign: a hit from the left of `b` goes right);
* `rise`: how far `b`'s centre lies above `a`'s;
* `gap`: the free room between their outlines, across and up;
* `size_a`, `size_b`: each one's larger side;
* `mass_a`, `mass_b`: their masses, as the domain weighs them (log);
* `friction_a`: `a`'s friction;
* `run`: how far `a` may go along what it rests on before that ends, in the way of the link;
* `tilt`: the slope of what `a` rests on (or of `b`, for a bounce), in degrees, signed so that
  down the way of the link is positive.

An object the layout does not hold (a scenario's `surface` resolved at run time, the ground)
gives the features that need it 0; every feature is finite.
"""

from __future__ import annotations

import math

import attrs

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.dsl.scenario import TermIR
from physc.search import placing

NAMES = ("ahead", "rise", "gap_x", "gap_y", "size_a", "size_b", "mass_a", "mass_b", "friction_a", "run", "tilt")
FORWARD = {"left": 1.0, "right": -1.0}  # a hit *from* the left of b travels right (b's side it comes from)
HEADING = {"left": -1.0, "right": 1.0}  # a roll, slide or bounce *towards* a side travels that way


@attrs.frozen
class LinkFeatures:
    """One link's features (module docstring), by its kind and its place in the chain."""

    kind: str  # the interaction's name: hit, roll, fall, ...
    index: int  # its place among the scenario's interactions
    values: tuple[float, ...]  # in NAMES' order


def sign_of(term: TermIR, a: PlacedObject | None, b: PlacedObject | None) -> float:
    """The horizontal way the link goes: +1 right, -1 left, from its directions where they say
    one, else from where `b` lies of `a`."""
    table = FORWARD if term.name == "hit" else HEADING
    signs = {table[d] for d in term.directions if d in table}
    if len(signs) == 1:
        return signs.pop()
    if a is not None and b is not None and b.x != a.x:
        return 1.0 if b.x > a.x else -1.0
    return 1.0


def features(
    layout: ConcreteLayout, interactions: tuple[TermIR, ...], support_of: dict[str, str], domain
) -> list[LinkFeatures]:
    """Every declared link's features in `layout`; `support_of`: what each object rests on
    (placing.Supports); `domain`: its search hooks weigh the bodies (`mass`, `friction`)."""
    objects = {o.name: o for o in layout.objects}
    found = []
    for index, term in enumerate(interactions):
        a = objects.get(term.objects[0]) if term.objects else None
        b = objects.get(term.objects[1]) if len(term.objects) > 1 else None
        found.append(
            LinkFeatures(
                term.name, index, one(term, a, b, objects.get(support_of.get(a.name, "")) if a else None, domain)
            )
        )
    return found


def one(
    term: TermIR, a: PlacedObject | None, b: PlacedObject | None, support: PlacedObject | None, domain
) -> tuple[float, ...]:
    """One link's values (NAMES' order)."""
    sign = sign_of(term, a, b)
    ahead = rise = gap_x = gap_y = size_b = mass_b = run = tilt = 0.0
    size_a = mass_a = friction_a = 0.0
    if a is not None:
        size_a = max(a.width, a.height)
        mass_a = math.log(max(domain.search.mass(a), 1e-9))
        friction_a = float(domain.search.friction(a))
    if a is not None and b is not None:
        ahead, rise = sign * (b.x - a.x), b.y - a.y
        a_box, b_box = placing.box(a), placing.box(b)
        gap_x = max(b_box[0] - a_box[2], a_box[0] - b_box[2], 0.0)
        gap_y = max(b_box[1] - a_box[3], a_box[1] - b_box[3], 0.0)
    if b is not None:
        size_b = max(b.width, b.height)
        mass_b = math.log(max(domain.search.mass(b), 1e-9)) if b.role != "support" else 0.0
    if a is not None and support is not None:
        left, _, right, _ = placing.box(support)
        run = max((right - a.x) if sign > 0 else (a.x - left), 0.0)
    slope = b if term.name == "bounce" and b is not None else support
    if slope is not None:
        tilt = -sign * slope.rotation  # counter-clockwise rotation: its right end up, so down to the left
    return (ahead, rise, gap_x, gap_y, size_a, size_b, mass_a, mass_b, friction_a, run, tilt)
