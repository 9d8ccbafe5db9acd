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
"""

from __future__ import annotations

import math

import attrs

from physc.simulation.fidelity import Declared, matches
from physc.simulation.recognise import Recogniser, approach
from physc.simulation.trace import Interaction, Trace
from physc.simulation.where import Where

SIDES = {"right": 0.0, "above": 90.0, "left": 180.0, "below": 270.0}  # the direction each side of a body faces
ALL_SIDES = frozenset(SIDES)


GERUND = {"roll": "rolling", "slide": "sliding"}  # a motion's name in a margin's words


@attrs.frozen
class Margin:
    """How far one link was from failing: `value` in `unit`s (positive: held with that much to
    spare), `scale` the value that counts as one whole margin, `what` the quantity in words."""

    term: str  # the declared term or restriction, in .phys syntax
    index: int | None  # its place in the declared sequence; None for a restriction
    value: float
    unit: str
    scale: float
    what: str
    held: bool = True  # whether the link held in this trace

    @property
    def share(self) -> float:
        return self.value / self.scale if self.scale else self.value

    def text(self) -> str:
        """ "`fall(fBlock2, pig)`: −0.12 units of overhang (…)"."""
        return f"`{self.term}`: {self.value:+.3g} {self.unit} ({self.what})"

    def record(self) -> dict:
        return {
            "term": self.term,
            "value": round(self.value, 4),
            "unit": self.unit,
            "share": round(self.share, 4),
            "what": self.what,
            "held": self.held,
        }


@attrs.frozen
class Margins:
    """The margins of one trace: one per declared link it reached, one per restriction."""

    links: tuple[Margin, ...] = ()

    @property
    def weakest(self) -> Margin | None:
        """The link with the least to spare: a failed one first, then the smallest share."""
        return min(self.links, key=lambda m: (m.held, m.share), default=None)

    @property
    def lowest(self) -> float:
        """The weakest link's share (−inf when a link failed to be reached at all)."""
        weakest = self.weakest
        return -math.inf if weakest is None else weakest.share

    def record(self) -> list[dict]:
        return [m.record() for m in self.links]


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


def _angle(dx: float, dy: float) -> float:
    return math.degrees(math.atan2(dy, dx)) % 360.0


def _apart(a: float, b: float) -> float:
    d = abs(a - b) % 360.0
    return min(d, 360.0 - d)


def side_margin(dx: float, dy: float, sides) -> float:
    """Degrees the direction (dx, dy) lies inside the nearest of `sides`' 90° sectors (negative:
    outside all of them)."""
    angle = _angle(dx, dy)
    return max(45.0 - _apart(angle, SIDES[s]) for s in sides)


class MarginReader:
    """The margins of a domain's traces (module docstring): generic, from the trace and the
    world's recognition thresholds; a domain may extend a term's method."""

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
                out.append(Margin(declared.text, k, -1.0, "of a link", 1.0, "not realised", False))
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
        return Margin(
            text,
            k,
            left,
            "life",
            max(whole / 2, 1e-6),
            f"the life {name} has left under the worst reading (scale: half its life)",
        )

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

    # ---- the terms -------------------------------------------------------------------------
    def hit(self, declared, trace: Trace, found, since: float, matched, k: int) -> Margin | None:
        actor, target = declared.objects[0], declared.objects[1]
        text = declared.text
        sides = set(declared.directions or ()) & ALL_SIDES
        contacts = self.where.contacts(actor, target, since)
        if found is not None:
            contacts = [c for c in contacts if abs(c.time - found.time) < trace.dt / 2] or contacts
        if not contacts:
            gap = self.where.gap(actor, target, self.where.row(since), trace.steps)
            if gap is None:
                return Margin(text, k, -1.0, "of a link", 1.0, f"{actor} never came near {target}", False)
            return Margin(
                text, k, -max(gap, 0.0), "units", self.where.size(actor), f"the nearest {actor} came to {target}", False
            )
        contact = contacts[0]
        parts = []
        speed = abs(contact.relative_velocity[0] * contact.normal[0] + contact.relative_velocity[1] * contact.normal[1])
        parts.append(
            Margin(
                text,
                k,
                speed - self.recogniser.hit_speed,
                "units/s",
                self.recogniser.hit_speed,
                "approach speed beyond a hit's least",
            )
        )
        if sides and sides != ALL_SIDES:
            vx, vy = approach(trace, contact, self.where.party(contact, actor), self.where.party(contact, target))
            parts.append(Margin(text, k, side_margin(-vx, -vy, sides), "degrees", 45.0, "from striking another side"))
        return min(parts, key=lambda m: m.share)

    def _motion(self, declared, trace: Trace, found, since: float, matched, k: int, name: str) -> Margin | None:
        mover, surface = declared.objects[0], declared.objects[1]
        text, dt = declared.text, trace.dt
        if mover not in trace.names:
            return None
        index = trace.index(mover)
        spans = [
            span
            for span in self.recogniser.travels_on(trace, self.where.intervals, mover, surface)
            if span[1] >= since - 1e-9
        ]
        if found is not None:
            spans = [span for span in spans if span[0] - dt <= found.time <= span[1] + dt] or spans
        best = None  # (seconds, distance) of the travel that did most of the motion
        for span in spans:
            rows, rolling, sliding = self.recogniser.motion(trace, index, span, trace.radii.get(mover))
            frames = rolling if name == "roll" else sliding
            measured = (float(frames.sum()) * dt, self.recogniser.covered(rows, frames))
            best = measured if best is None else max(best, measured)
        need, far = self.recogniser.motion_time, self.recogniser.travel
        if best is None:
            return Margin(text, k, -need, "s", need, f"{mover} never touched {surface}", False)
        parts = [
            Margin(
                text, k, best[0] - need, "s", need, f"seconds of {GERUND.get(name, name)} beyond the least recognised"
            )
        ]
        if far > 0:
            parts.append(
                Margin(
                    text,
                    k,
                    best[1] - far,
                    "units",
                    far,
                    f"distance of {GERUND.get(name, name)} beyond the least recognised",
                )
            )
        after = next(
            (i for i in range(k + 1, len(matched)) if matched[i].objects and matched[i].objects[0] == mover), None
        )
        if after is not None and matched[after].name != "hit":
            after = None  # only a meeting has a speed to arrive at
        if found is not None and after is not None:
            start = trace.states[self.where.row(found.time), index]
            arrive = trace.states[self.where.row(matched[after].time) - 1, index]
            v0, v1 = math.hypot(start[3], start[4]), math.hypot(arrive[3], arrive[4])
            if v0 > 0 and not math.isnan(v1):
                parts.append(
                    Margin(
                        text,
                        k,
                        v1,
                        "units/s",
                        max(v0, self.recogniser.moving),
                        f"speed left when it reached {matched[after].objects[1] if len(matched[after].objects) > 1 else 'the next body'}",
                    )
                )
        return min(parts, key=lambda m: m.share)

    def roll(self, declared, trace, found, since, matched, k):
        return self._motion(declared, trace, found, since, matched, k, "roll")

    def slide(self, declared, trace, found, since, matched, k):
        return self._motion(declared, trace, found, since, matched, k, "slide")

    def fall(self, declared, trace: Trace, found, since: float, matched, k: int) -> Margin | None:
        faller, target = declared.objects[0], declared.objects[1]
        text = declared.text
        if faller not in trace.names:
            return None
        index = trace.index(faller)
        half = self.where.size(faller)
        rec = self.recogniser
        spells = self.where.spells(faller, since, trace.duration)
        if found is not None:
            spells = [s for s in spells if abs((s[0] + 1) * trace.dt - found.time) < trace.dt] or spells
        parts = []
        if not spells:  # it never left its support: how far its centre came to the edge
            support = self.where.support_before(faller, self.where.row(since))
            over = None if support is None else self.where.overhang(faller, support, self.where.row(since))
            if over is None:
                return Margin(
                    text, k, -rec.fall_height, "units", rec.fall_height, f"{faller} never left what it rested on", False
                )
            return Margin(
                text,
                k,
                min(over, 0.0),
                "units of overhang",
                half,
                f"{faller}'s centre past the edge of {support}",
                False,
            )
        if spells:
            seconds, drop = max(
                (self.where.drop(index, s) for s in spells),
                key=lambda d: min(d[0] / rec.fall_time, d[1] / rec.fall_height),
            )
            parts.append(
                Margin(text, k, seconds - rec.fall_time, "s", rec.fall_time, "seconds in the air beyond a fall's least")
            )
            parts.append(
                Margin(
                    text, k, drop - rec.fall_height, "units", rec.fall_height, "height dropped beyond a fall's least"
                )
            )
            landing = (
                spells[0][1]
                if found is None
                else next((s[1] for s in spells if abs((s[0] + 1) * trace.dt - found.time) < trace.dt), spells[0][1])
            )
            pa, pb = self.where.pose(faller, landing), self.where.pose(target, landing)
            if pa is not None and pb is not None:
                overlap = self.where.extents(pa)[0] + self.where.extents(pb)[0] - abs(pa[0] - pb[0])
                parts.append(Margin(text, k, overlap, "units of overlap", half, f"its landing from missing {target}"))
        if not parts:
            return None
        worst = min(parts, key=lambda m: m.share)
        return attrs.evolve(worst, held=found is not None)

    def bounce(self, declared, trace: Trace, found, since: float, matched, k: int) -> Margin | None:
        mover, surface = declared.objects[0], declared.objects[1]
        text, rec = declared.text, self.recogniser
        if mover not in trace.names:
            return None
        index = trace.index(mover)
        spans = [s for s in self.where.intervals.get(frozenset((mover, surface)), ()) if s[1] >= since - 1e-9]
        if found is not None:
            spans = [s for s in spans if abs(s[1] - found.time) < trace.dt / 2] or spans
        if not spans:
            gap = self.where.gap(mover, surface, self.where.row(since), trace.steps)
            return Margin(
                text,
                k,
                -max(gap or 0.0, 0.0),
                "units",
                self.where.size(mover),
                f"the nearest {mover} came to {surface}",
                False,
            )
        begin, end = spans[0]
        parts = [
            Margin(
                text,
                k,
                rec.bounce_time - (end - begin),
                "s",
                rec.bounce_time,
                "seconds its touch was short of a bounce's most",
            )
        ]
        sides = set(declared.directions or ()) & ALL_SIDES
        after = int(round(end / trace.dt))
        if sides and sides != ALL_SIDES and after < trace.steps and not math.isnan(trace.states[after, index, 3]):
            vx, vy = trace.states[after, index, 3:5]
            parts.append(
                Margin(text, k, side_margin(float(vx), float(vy), sides), "degrees", 45.0, "from leaving another way")
            )
        return min(parts, key=lambda m: m.share)

    def destroy(self, declared, trace: Trace, found, since: float, matched, k: int) -> Margin | None:
        attacker, target = declared.objects[0], declared.objects[1]
        text = declared.text
        if found is not None:
            blow = [d for d in trace.damage if d.target == target and abs(d.time - found.time) <= trace.dt * 1.5]
            if not blow:
                return None
            before = blow[0].life + blow[0].amount
            worst = sum(d.least if d.least is not None else d.amount for d in blow)
            return Margin(
                text,
                k,
                worst - before,
                "damage",
                max(before, 1e-6),
                f"the blow under the worst reading beyond the {before:.3g} life {target} had left",
            )
        dealt = [
            d
            for d in trace.damage
            if d.target == target and d.by in self.where.bodies(attacker) and d.time >= since - 1e-9
        ]
        if not dealt:
            return Margin(text, k, -1.0, "of its life", 1.0, f"{attacker} dealt {target} no damage", False)
        left = min(d.life for d in dealt)
        before = dealt[0].life + dealt[0].amount
        return Margin(text, k, -left, "damage", max(before, 1e-6), f"the life {target} had left", False)

    def touch(self, declared, trace: Trace, found, since: float, matched, k: int) -> Margin | None:
        need = self.recogniser.touch_time
        if need is None or trace.goal_met is not None:
            return None
        a, b = declared.objects[0], declared.objects[1]
        spans = self.where.intervals.get(frozenset((a, b)), ())
        longest = max((min(end, trace.duration) - begin for begin, end in spans), default=0.0)
        return Margin(
            declared.text, k, longest - need, "s", need, "seconds touching beyond the goal's", found is not None
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
            worst = min(
                side_margin(*(-v for v in approach(trace, c, self.where.party(c, a), self.where.party(c, b))), allowed)
                for c in hits
            )
            return Margin(
                text, None, worst, "degrees", 45.0, "its hits from a forbidden side", not broken and worst > 0
            )
        gap = self.where.gap(a, b, 0, self.where.row(end) + 1)
        if gap is None:
            return None
        value = min(gap, 0.0) if broken else gap
        return Margin(
            text, None, value, "units of clearance", self.where.size(a), f"the clearance {a} kept from {b}", not broken
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
        return Margin(
            text, None, 1.0 - worst, "of a fall", 1.0, "how far its longest drop was from a recognised fall", not broken
        )
