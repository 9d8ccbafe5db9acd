"""The margin of each kind of declared link (hit, roll, slide, fall, bounce, destroy, touch).

One method per term, named as the term, each measuring in a trace how far that link was from
failing (physc.simulation.margins says what each measures); `MarginReader` dispatches to them
by the term's name, and a domain whose physics says more about a link extends the method.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

import attrs

from physc.simulation.fidelity import DeclaredTerm
from physc.simulation.margin import Margin
from physc.simulation.recognise import Recogniser, approach
from physc.simulation.trace import Interaction, Trace
from physc.simulation.where import Where

SIDES = {"right": 0.0, "above": 90.0, "left": 180.0, "below": 270.0}  # the direction each side of a body faces
ALL_SIDES = frozenset(SIDES)


GERUND = {"roll": "rolling", "slide": "sliding"}  # a motion's name in a margin's words


def _angle(dx: float, dy: float) -> float:
    return math.degrees(math.atan2(dy, dx)) % 360.0


def _apart(a: float, b: float) -> float:
    d = abs(a - b) % 360.0
    return min(d, 360.0 - d)


def side_margin(dx: float, dy: float, sides: Iterable[str]) -> float:
    """Degrees the direction (dx, dy) lies inside the nearest of `sides`' 90° sectors (negative:
    outside all of them)."""
    angle = _angle(dx, dy)
    return max(45.0 - _apart(angle, SIDES[s]) for s in sides)


class LinkMargins:
    """The per-term margins of `MarginReader` (physc.simulation.margins): each method reads one
    declared link of its term, given the interaction that realised it (`found`, None: not
    realised), when the link before it happened (`since`), the links realised so far (`matched`)
    and its place `k`."""

    recogniser: Recogniser
    where: Where  # the trace being read, indexed (set by `MarginReader.read`)

    def hit(
        self, declared: DeclaredTerm, trace: Trace, found: Interaction | None, since: float, matched, k: int
    ) -> Margin | None:
        actor, target = declared.objects[0], declared.objects[1]
        text = declared.text
        sides = set(declared.directions or ()) & ALL_SIDES
        contacts = self.where.contacts(actor, target, since)
        if found is not None:
            contacts = [c for c in contacts if abs(c.time - found.time) < trace.dt / 2] or contacts
        if not contacts:
            gap = self.where.gap(actor, target, self.where.row(since), trace.steps)
            if gap is None:
                return Margin.failed(text, k, what=f"{actor} never came near {target}")
            return Margin.distance(
                text,
                k,
                value=-max(gap, 0.0),
                scale=self.where.size(actor),
                what=f"the nearest {actor} came to {target}",
                held=False,
            )
        contact = contacts[0]
        speed = abs(contact.relative_velocity[0] * contact.normal[0] + contact.relative_velocity[1] * contact.normal[1])
        parts = [
            Margin.speed(
                text,
                k,
                value=speed - self.recogniser.hit_speed,
                scale=self.recogniser.hit_speed,
                what="approach speed beyond a hit's least",
            )
        ]
        if sides and sides != ALL_SIDES:
            vx, vy = approach(trace, contact, self.where.party(contact, actor), self.where.party(contact, target))
            parts.append(Margin.angle(text, k, value=side_margin(-vx, -vy, sides), what="from striking another side"))
        return min(parts, key=lambda m: m.share)

    def _motion(
        self,
        declared: DeclaredTerm,
        trace: Trace,
        found: Interaction | None,
        since: float,
        matched: Sequence[Interaction],
        k: int,
        name: str,
    ) -> Margin | None:
        """A roll's or a slide's margin: its seconds and distance beyond the least recognised, and
        the share of its speed left when it reached the next body it acts on."""
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
            return Margin.seconds(text, k, value=-need, scale=need, what=f"{mover} never touched {surface}", held=False)
        gerund = GERUND.get(name, name)
        parts = [
            Margin.seconds(
                text, k, value=best[0] - need, scale=need, what=f"seconds of {gerund} beyond the least recognised"
            )
        ]
        if far > 0:
            parts.append(
                Margin.distance(
                    text, k, value=best[1] - far, scale=far, what=f"distance of {gerund} beyond the least recognised"
                )
            )
        arrival = self._arrival(trace, found, matched, k, mover, index)
        if arrival is not None:
            parts.append(Margin.speed(text, k, value=arrival[0], scale=arrival[1], what=arrival[2]))
        return min(parts, key=lambda m: m.share)

    def _arrival(
        self, trace: Trace, found: Interaction | None, matched: Sequence[Interaction], k: int, mover: str, index: int
    ) -> tuple[float, float, str] | None:
        """(the speed `mover` had left when it reached the body of its next hit, its scale, in
        words), when its motion `found` ends in one; None when it does not."""
        after = next(
            (i for i in range(k + 1, len(matched)) if matched[i].objects and matched[i].objects[0] == mover), None
        )
        if after is None or matched[after].name != "hit" or found is None:
            return None  # only a meeting has a speed to arrive at
        start = trace.states[self.where.row(found.time), index]
        arrive = trace.states[self.where.row(matched[after].time) - 1, index]
        v0, v1 = math.hypot(start[3], start[4]), math.hypot(arrive[3], arrive[4])
        if not (v0 > 0 and not math.isnan(v1)):
            return None
        objects = matched[after].objects
        reached = objects[1] if len(objects) > 1 else "the next body"
        return v1, max(v0, self.recogniser.moving), f"speed left when it reached {reached}"

    def roll(self, declared, trace, found, since, matched, k):
        return self._motion(declared, trace, found, since, matched, k, "roll")

    def slide(self, declared, trace, found, since, matched, k):
        return self._motion(declared, trace, found, since, matched, k, "slide")

    def fall(
        self, declared: DeclaredTerm, trace: Trace, found: Interaction | None, since: float, matched, k: int
    ) -> Margin | None:
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
        if not spells:  # it never left its support: how far its centre came to the edge
            support = self.where.support_before(faller, self.where.row(since))
            over = None if support is None else self.where.overhang(faller, support, self.where.row(since))
            if over is None:
                return Margin.distance(
                    text,
                    k,
                    value=-rec.fall_height,
                    scale=rec.fall_height,
                    what=f"{faller} never left what it rested on",
                    held=False,
                )
            return Margin.overhang(
                text,
                k,
                value=min(over, 0.0),
                scale=half,
                what=f"{faller}'s centre past the edge of {support}",
                held=False,
            )
        seconds, drop = max(
            (self.where.drop(index, s) for s in spells),
            key=lambda d: min(d[0] / rec.fall_time, d[1] / rec.fall_height),
        )
        parts = [
            Margin.seconds(
                text,
                k,
                value=seconds - rec.fall_time,
                scale=rec.fall_time,
                what="seconds in the air beyond a fall's least",
            ),
            Margin.distance(
                text,
                k,
                value=drop - rec.fall_height,
                scale=rec.fall_height,
                what="height dropped beyond a fall's least",
            ),
        ]
        landing = (
            spells[0][1]
            if found is None
            else next((s[1] for s in spells if abs((s[0] + 1) * trace.dt - found.time) < trace.dt), spells[0][1])
        )
        pa, pb = self.where.pose(faller, landing), self.where.pose(target, landing)
        if pa is not None and pb is not None:
            overlap = self.where.extents(pa)[0] + self.where.extents(pb)[0] - abs(pa[0] - pb[0])
            parts.append(Margin.overlap(text, k, value=overlap, scale=half, what=f"its landing from missing {target}"))
        worst = min(parts, key=lambda m: m.share)
        return attrs.evolve(worst, held=found is not None)

    def bounce(
        self, declared: DeclaredTerm, trace: Trace, found: Interaction | None, since: float, matched, k: int
    ) -> Margin | None:
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
            return Margin.distance(
                text,
                k,
                value=-max(gap or 0.0, 0.0),
                scale=self.where.size(mover),
                what=f"the nearest {mover} came to {surface}",
                held=False,
            )
        begin, end = spans[0]
        parts = [
            Margin.seconds(
                text,
                k,
                value=rec.bounce_time - (end - begin),
                scale=rec.bounce_time,
                what="seconds its touch was short of a bounce's most",
            )
        ]
        sides = set(declared.directions or ()) & ALL_SIDES
        after = int(round(end / trace.dt))
        if sides and sides != ALL_SIDES and after < trace.steps and not math.isnan(trace.states[after, index, 3]):
            vx, vy = trace.states[after, index, 3:5]
            side = side_margin(float(vx), float(vy), sides)
            parts.append(Margin.angle(text, k, value=side, what="from leaving another way"))
        return min(parts, key=lambda m: m.share)

    def destroy(
        self, declared: DeclaredTerm, trace: Trace, found: Interaction | None, since: float, matched, k: int
    ) -> Margin | None:
        attacker, target = declared.objects[0], declared.objects[1]
        text = declared.text
        if found is not None:
            blow = [d for d in trace.damage if d.target == target and abs(d.time - found.time) <= trace.dt * 1.5]
            if not blow:
                return None
            before = blow[0].life + blow[0].amount
            worst = sum(d.least if d.least is not None else d.amount for d in blow)
            return Margin.damage(
                text,
                k,
                value=worst - before,
                scale=max(before, 1e-6),
                what=f"the blow under the worst reading beyond the {before:.3g} life {target} had left",
            )
        dealt = [
            d
            for d in trace.damage
            if d.target == target and d.by in self.where.bodies(attacker) and d.time >= since - 1e-9
        ]
        if not dealt:
            return Margin.failed(text, k, what=f"{attacker} dealt {target} no damage", unit="of its life")
        left = min(d.life for d in dealt)
        before = dealt[0].life + dealt[0].amount
        return Margin.damage(
            text, k, value=-left, scale=max(before, 1e-6), what=f"the life {target} had left", held=False
        )

    def touch(
        self, declared: DeclaredTerm, trace: Trace, found: Interaction | None, since: float, matched, k: int
    ) -> Margin | None:
        need = self.recogniser.touch_time
        if need is None or trace.goal_met is not None:
            return None
        a, b = declared.objects[0], declared.objects[1]
        spans = self.where.intervals.get(frozenset((a, b)), ())
        longest = max((min(end, trace.duration) - begin for begin, end in spans), default=0.0)
        return Margin.seconds(
            declared.text,
            k,
            value=longest - need,
            scale=need,
            what="seconds touching beyond the goal's",
            held=found is not None,
        )
