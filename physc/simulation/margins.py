"""Margins: how far each link of a simulated chain was from failing, in its own physics and units.

A trace that realises a sequence says only that it did; a noisy replay fails where a link had
little to spare. `MarginReader.read` gives every declared interaction the trace realises (and
the first one it does not) and every restriction a `Margin`: positive, how much the link had
to spare; negative, by how much it failed. Each is in the units of its own physics, with a
`scale` that makes links of different kinds comparable (`share` = value / scale), so the
weakest link of a chain is the one with the smallest share:

* hit(a, b, d): the degrees a's approach (as the recogniser reads it, of the bodies' centres)
  was from the next side of b, where the scenario narrows the sides (scale 45°), and its
  speed along the contact normal beyond the recogniser's `hit_speed`; missed: how near a came
  to b (units short of touching), or a contact from the wrong side or too slow;
* roll(a, s, d), slide(a, s, d): the seconds a rolled (slid) on s beyond the recogniser's
  `motion_time`, and the share of its speed it still had when it reached the next body it
  acts on;
* fall(a, b): the seconds and height of a's drop beyond the recogniser's `fall_time` and
  `fall_height`, and how far its landing was from missing b (units of overlap, scale a's
  half-width); missed without leaving its support: how far a's centre came to its edge (units
  of overhang, negative);
* bounce(a, s, d): the degrees a's departure was from the next direction, and the seconds
  its touch was short of the recogniser's `bounce_time`;
* destroy(a, b): the damage of the destroying blow under the worst reading of the world
  (DamageRecord.least) beyond the life b had left, in damage (scale: that life);
* touch(a, b): the seconds the touch lasted beyond the recogniser's `touch_time`;
* cannotHit(a, b, D): the clearance a kept from b while its direct approach lasted (units), or
  the degrees its hits on b were from a forbidden side;
* every link's actor, and what it acts on: the life each has left when the link happens, under
  the worst reading of each blow it took before (DamageRecord.most), where that is less than the
  link's own margin; a link that could not happen because what it acts on was destroyed first by
  something else: that life, negative (how much the blows exceeded it);
* cannotFall(a): how far a's longest drop was from being recognised as a fall (share of
  `fall_time` or `fall_height`, whichever it reached less of).

The margins are read from the trace alone (poses, contacts, damage records, the bodies'
outlines and radii) with the world's recognition thresholds, so every domain has them; a
domain whose physics says more extends `MarginReader` (SimulatedDomain.margin_reader).

Three modules: the values (`Margin`, `Margins`: physc.simulation.margin), each declared link's
margin (physc.simulation.link_margins) and, here, the reading of a whole trace: which link a
margin is of, the lives that must outlast the blows before a link, and the restrictions.
"""

from __future__ import annotations

import math

import attrs

from physc.simulation.fidelity import Declared, matches
from physc.simulation.link_margins import ALL_SIDES, GERUND, SIDES, LinkMargins, side_margin
from physc.simulation.margin import Margin, Margins
from physc.simulation.recognise import Recogniser, approach
from physc.simulation.trace import Interaction, Trace
from physc.simulation.where import Where

__all__ = [
    "ALL_SIDES",
    "GERUND",
    "SIDES",
    "Margin",
    "MarginReader",
    "Margins",
    "Recognised",
    "side_margin",
]


@attrs.frozen
class _Term:
    name: str
    objects: tuple[str, ...]
    directions: tuple[str, ...]
    text: str


@attrs.frozen
class Recognised:
    """A trace's own recognised interactions as a declared sequence (physc.simulation.fidelity's
    `Declared`), so that a play with no scenario still has margins: how near each thing that
    happened came to not happening, or to happening another way."""

    interactions: tuple[_Term, ...]
    restrictions: tuple = ()

    @classmethod
    def of(cls, trace: Trace) -> Recognised:
        return cls(
            tuple(_Term(i.name, i.objects, (i.direction,) if i.direction else (), i.text()) for i in trace.interactions)
        )


class MarginReader(LinkMargins):
    """The margins of a domain's traces (module docstring): generic, from the trace and the
    world's recognition thresholds; a domain may extend a term's method (physc.simulation.link_margins)."""

    def __init__(self, recogniser: Recogniser):
        self.recogniser = recogniser

    # ---- the whole trace -----------------------------------------------------------------
    def read(self, scenario: Declared, trace: Trace, through: int | None = None) -> Margins:
        """The margins of the declared links and restrictions in `trace`; with `through`, of the
        first `through` links only, and of the restrictions until the last of them (a stage of
        a chain: what its scene does after its last link is not the chain's)."""
        found: list[Interaction] = []
        terms = tuple(scenario.interactions)[:through]
        for interaction in trace.interactions:
            if len(found) < len(terms) and matches(terms[len(found)], interaction):
                found.append(interaction)
        self.where = Where(trace)
        out = []
        for k, declared in enumerate(terms):
            if k > len(found):
                break
            since = found[k - 1].time if k else 0.0
            method = getattr(self, declared.name, None)
            margin = method(declared, trace, found[k] if k < len(found) else None, since, found, k) if method else None
            # An actor must outlast the blows before it acts, unless it acts by being destroyed
            # (an explosive's blast: the recogniser's `explosive` kinds); what it acts on must
            # outlast the blows before the link (its own blow is the link's).
            if margin is not None and k < len(found):
                outlast = (
                    [(declared.objects[0], found[k].time)]
                    if trace.kinds.get(declared.objects[0]) not in self.recogniser.explosive
                    else []
                )
                outlast += [(declared.objects[1], found[k].time - trace.dt / 2)] if len(declared.objects) > 1 else []
                for name, until in outlast:
                    lasting = self.survival(trace, name, until, declared.text, k)
                    if lasting is not None and lasting.share < margin.share:
                        margin = lasting
            if k == len(found):
                margin = self.destroyed_first(trace, declared, since, k) or margin
            if margin is not None:
                out.append(attrs.evolve(margin, index=k, held=k < len(found) and margin.held))
            elif k == len(found):
                out.append(Margin.failed(declared.text, k, what="not realised"))
        until = found[-1].time if len(found) == len(terms) and found else trace.duration
        terms = tuple(scenario.interactions)
        for restriction in getattr(scenario, "restrictions", ()):
            method = {"cannotHit": self.cannot_hit, "cannotFall": self.cannot_fall}.get(restriction.name)
            margin = method(restriction, trace, until, terms) if method else None
            if margin is not None:
                out.append(margin)
        return Margins(tuple(out))

    def survival(self, trace: Trace, name: str, time: float, text: str, k: int) -> Margin | None:
        """The life `name` has left at `time` under the worst reading of each blow before it
        (DamageRecord.most): an actor that another reading would have broken first does not act."""
        blows = [d for d in trace.damage if d.target == name and d.time <= time + 1e-9]
        if not blows or all(d.most is None for d in blows):
            return None
        whole = blows[0].life + blows[0].amount
        left = whole - sum(d.most if d.most is not None else d.amount for d in blows)
        if not math.isfinite(whole):
            return None
        return Margin.life(
            text,
            k,
            value=left,
            scale=max(whole / 2, 1e-6),
            what=f"the life {name} has left under the worst reading (scale: half its life)",
        )

    def ahead(self, scenario: Declared, trace: Trace, through: int) -> Margin | None:
        """What the link after the first `through` needs of a play that ends before it: the
        stage of a chain that ends where the player acts again (Science Birds: the next bird is
        shot once the level rests). What that link acts on must still be there when the play
        ends: the life it has left under the worst reading of the blows it took (scale: half its
        life); negative, or a failure, where it was destroyed. None: nothing to measure (no
        such link, no target, no blow)."""
        terms = tuple(scenario.interactions)
        if through >= len(terms) or len(terms[through].objects) < 2:
            return None
        declared = terms[through]
        target = declared.objects[1]
        if target not in trace.names:
            return None
        death = next((d for d in trace.destructions if d.name == target), None)
        lasting = self.survival(trace, target, trace.duration, declared.text, through)
        if death is None:
            return lasting
        if lasting is not None and lasting.value <= 0:
            return attrs.evolve(lasting, held=False, what=f"the life {target} had left before {declared.text}")
        return Margin.failed(declared.text, through, what=f"{target} gone before {declared.text} ({death.cause})")

    def destroyed_first(self, trace: Trace, declared, since: float, k: int) -> Margin | None:
        """A link that could not happen because what it acts on was destroyed first, by something
        other than its actor (Science Birds: the big pig that the first bird's blow knocked off
        its support to die on the ground, before the second bird's hit): the life it had left
        under the worst reading of the blows that destroyed it, negative by how much they
        exceeded it. A failure graded by how far it was from not happening, where a link not
        realised is a flat -1 that a raising cannot climb."""
        if len(declared.objects) < 2:
            return None
        actor, target = declared.objects[0], declared.objects[1]
        death = next(
            (
                d
                for d in trace.destructions
                if d.name == target and d.time >= since - 1e-9 and d.by not in self.where.bodies(actor)
            ),
            None,
        )
        if death is None:
            return None
        lasting = self.survival(trace, target, death.time, declared.text, k)
        if lasting is None or lasting.value > 0:
            return None
        by = f"by {death.by}" if death.by else f"({death.cause})"
        return attrs.evolve(
            lasting,
            held=False,
            what=f"the life {target} had left under the worst reading when destroyed first {by} (scale: half its life)",
        )

    # ---- restrictions ------------------------------------------------------------------------
    def cannot_hit(self, restriction, trace: Trace, until: float, terms) -> Margin | None:
        a, b = restriction.objects[0], restriction.objects[1]
        text = restriction.text or f"cannotHit({a}, {b})"
        redirected = min(
            (
                i.time
                for i in trace.interactions
                if i.name == "bounce"
                and i.objects[0] == a
                and any(t.name == "bounce" and tuple(t.objects) == i.objects for t in terms)
            ),
            default=math.inf,
        )
        end = min(until, redirected)
        broken = any(v.restriction == text and v.interaction.time <= until for v in trace.violations)
        sides = set(restriction.directions or ALL_SIDES) & ALL_SIDES
        hits = [c for c in self.where.contacts(a, b, 0.0) if c.time <= end]
        if hits and sides != ALL_SIDES:
            allowed = ALL_SIDES - sides
            approaches = (approach(trace, c, self.where.party(c, a), self.where.party(c, b)) for c in hits)
            worst = min(side_margin(-vx, -vy, allowed) for vx, vy in approaches)
            return Margin.angle(
                text, None, value=worst, what="its hits from a forbidden side", held=not broken and worst > 0
            )
        gap = self.where.gap(a, b, 0, self.where.row(end) + 1)
        if gap is None:
            return None
        value = min(gap, 0.0) if broken else gap
        return Margin.clearance(
            text,
            None,
            value=value,
            scale=self.where.size(a),
            what=f"the clearance {a} kept from {b}",
            held=not broken,
        )

    def cannot_fall(self, restriction, trace: Trace, until: float, terms) -> Margin | None:
        a = restriction.objects[0]
        text = restriction.text or f"cannotFall({a})"
        if a not in trace.names:
            return None
        rec = self.recogniser
        index = trace.index(a)
        worst = 0.0
        for spell in self.where.spells(a, 0.0, until):
            seconds, drop = self.where.drop(index, spell)
            worst = max(worst, min(seconds / rec.fall_time, drop / rec.fall_height))
        broken = any(v.restriction == text and v.interaction.time <= until for v in trace.violations)
        return Margin.fall_share(
            text, None, value=1.0 - worst, what="how far its longest drop was from a recognised fall", held=not broken
        )
