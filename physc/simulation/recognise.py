"""Recognising the interactions of the `.phys` language in a simulation trace.

Backend- and domain-neutral: a `Recogniser` reads a Trace (poses, velocities, contacts,
destructions) and names what happened, in the order it happened. Its thresholds are in
the domain's units and its kinds are the domain's (which bodies are surfaces, which is
the background, which are thrown). Below, in Science Birds' terms and thresholds:

* hit(a, b, d): a contact begins at a relative speed of at least hit_speed; a is
  the body whose velocity carries it into b (for a static b, the moving one); d
  is the side of b that was struck (the larger component of a's velocity relative
  to b, reversed: of the bodies' centres, see `approach`). Chatter of one pair within
  rehit seconds is one hit.
* roll(a, s, d): a round body a travels along a surface s (a static body of the `surfaces`
  kinds) while moving at least `moving` and turning the way it moves, so that −ω·r is within
  roll_slip of its speed along its heading (ω counter-clockwise: rolling right turns clockwise),
  for at least motion_time in all, over at least `travel`; d is the way it moved. A ball
  sliding with backspin, as a ball struck by a rolling ball does (the hitter's front turns
  downwards), is not rolling, however fast it spins.
* slide(a, s, d): the same, but translating while turning at most slide_spin; a body that
  can roll (round) does not slide where `round_slides` is off (Science Birds: a round body
  rolls, a block slides, as the language's object grammar types them).
  A body travels along s while it touches s's upper side (the contact normal points up from s
  into it within max_tilt (60°) of the vertical, so a block pushed along a platform's
  underside slides on nothing) and across the hops between two such touches: a break in
  which it rises no more than hop_rise times its size (a round body's radius, another's
  smaller half-extent) above where it left s, and drops less than fall_height. With hop_rise
  0, each touch is a travel of its own.
* fall(a, b): a touches nothing for at least fall_time while dropping at least
  fall_height; b is the first thing it touches after. A thrown body (the bird)
  is not falling: its flight is not a fall.
* bounce(a, s, d): a moving object touches a surface s for less than bounce_time and leaves
  it, not in a hop of a travel along s (it rises more than hop_rise times its size); d is where
  its velocity points as it leaves. The touch is of s's upper side, or, with bounce_walls, of any
  side: a wall, a ceiling (Phy-Q's bouncing levels bounce the bird off both).
* destroy(a, b): b is destroyed by damage, a being what dealt the last blow.
* explode(a): a body of an explosive kind (Science Birds' TNT) is destroyed by damage: its
  blast is the world's rules' (the blows it deals are destroy(a, …)).
* touch(a, b): the trace's goal bodies a and b (`Trace.goal`) touch without a break for
  at least touch_time (PHYRE's goal: 3 s), recognised when the time is up; only in a
  domain that sets touch_time. Where the domain's rules time their goal (`Trace.goal_met`),
  the touch is theirs: rules may judge touching by more than contacts (PHYRE's two balls).

An interaction equal to the one just before it (one roll over two contact
intervals, a double hit) is reported once.

Restrictions broken by the interactions are physc.simulation.restrictions'; the contact spans
and approaches it reads them from, physc.simulation.contacts'.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import attrs
import numpy as np

from physc.simulation.contacts import approach, contact_intervals, side, touching_steps
from physc.simulation.trace import ContactRecord, Interaction, Trace

__all__ = ["MAX_TILT", "ORDER", "Recogniser", "approach", "contact_intervals", "side"]

MAX_TILT = 60.0  # degrees from the vertical: a surface steeper than this is a wall
ORDER = {"hit": 0, "bounce": 1, "roll": 2, "slide": 2, "fall": 3, "explode": 4, "destroy": 5, "touch": 6}


@attrs.frozen
class Recogniser:
    """The recognition of one domain: its thresholds (in its units: lengths, seconds) and
    which kinds of body are surfaces, background and thrown. Each domain's world has its own
    (`World.recogniser`; Science Birds': physc.domains.angrybirds.worlds)."""

    hit_speed: float  # a contact is a hit from this approach speed along its normal
    rehit: float  # chatter of one pair within this many seconds is one hit
    moving: float  # slower (length/s) is not rolling or sliding
    roll_slip: float  # rolling: | −ω·r − sign(vx)·|v| | <= roll_slip · |v|
    slide_spin: float  # rad/s: sliding turns at most this fast
    motion_time: float  # seconds of rolling or sliding in all
    fall_time: float  # seconds touching nothing
    fall_height: float  # length dropped
    bounce_time: float  # a touch shorter than this that leaves the surface
    bounce_speed: float  # approach speed of a bounce at least
    surfaces: tuple[str, ...]  # static kinds things roll, slide, bounce on
    background: tuple[str, ...] = ()  # kinds that are never a hit's target
    thrown: tuple[str, ...] = ()  # kinds whose flight is not a fall
    max_tilt: float = MAX_TILT
    touch_time: float | None = None  # seconds two goal bodies must touch for touch(a, b); None: never recognised
    explosive: tuple[str, ...] = ()  # kinds whose destruction is explode(a)
    travel: float = 0.0  # length a roll or slide covers at least (its net displacement)
    hop_rise: float = 0.0  # a break in a travel along a surface rising at most this × the body's size is a hop
    round_slides: bool = True  # whether a round body that skids without turning slides
    bounce_walls: bool = False  # whether a bounce off a surface's side or underside counts (else its upper side only)

    @property
    def upward(self) -> float:
        """The least upward component of a surface's normal (cos max_tilt)."""
        return math.cos(math.radians(self.max_tilt))

    def recognise(self, trace: Trace, radius: dict[str, float]) -> tuple[Interaction, ...]:
        """The interactions of a trace; `radius` gives the rolling radius of each round body."""
        found: list[Interaction] = []
        found += self._hits(trace)
        intervals = contact_intervals(trace)
        found += self._motion(trace, intervals, radius)
        found += self._falls(trace, intervals)
        found += self._bounces(trace, intervals)
        found += [
            Interaction("destroy", (d.by, d.name), None, d.time)
            for d in trace.destructions
            if d.cause == "damage" and d.by is not None
        ]
        found += [
            Interaction("explode", (d.name,), None, d.time)
            for d in trace.destructions
            if d.cause == "damage" and trace.kinds.get(d.name) in self.explosive
        ]
        found += self._touches(trace, intervals)
        ordered = sorted(found, key=lambda i: (round(i.time, 6), ORDER[i.name]))
        # One roll over two contact intervals, or a double hit, is one interaction.
        out = []
        for interaction in ordered:
            if out and (out[-1].name, out[-1].objects, out[-1].direction) == (
                interaction.name,
                interaction.objects,
                interaction.direction,
            ):
                continue
            out.append(interaction)
        return tuple(out)

    def _touches(self, trace: Trace, intervals) -> list[Interaction]:
        """touch(a, b) for the goal bodies, in the order `Trace.goal` names them, each time
        they touch for touch_time without a break, counted in steps as a domain's goal rule
        counts them (a touch the run ended in counts its last step)."""
        if self.touch_time is None or len(trace.goal) < 2:
            return []
        a, b = trace.goal[:2]
        if trace.goal_met is not None:  # the rules timed their own verdict: it is the touch
            return [Interaction("touch", (a, b), None, trace.goal_met)]
        dt, out = trace.dt, []
        for begin, end in intervals.get(frozenset((a, b)), ()):
            # Steps touching: to the separation, or, for a touch the run ended in, its last step too.
            steps = (end - begin) / dt + (1 if end >= trace.duration - dt / 2 else 0)
            if steps >= self.touch_time / dt - 0.5:
                out.append(Interaction("touch", (a, b), None, begin + self.touch_time))
        return out

    def _hits(self, trace: Trace) -> list[Interaction]:
        kinds = trace.kinds
        last: dict[tuple[str, str], float] = {}
        out = []
        for c in trace.contacts:
            # An impact: the approach along the contact normal, not sliding across a
            # flush junction onto the next platform.
            if abs(c.relative_velocity[0] * c.normal[0] + c.relative_velocity[1] * c.normal[1]) < self.hit_speed:
                continue
            static_a, static_b = kinds.get(c.a) in self.surfaces, kinds.get(c.b) in self.surfaces
            if static_a and static_b:
                continue
            rv = c.relative_velocity
            if static_a:
                actor, target = c.b, c.a
            elif static_b:
                actor, target = c.a, c.b
            else:
                push_a = c.velocity_a[0] * rv[0] + c.velocity_a[1] * rv[1]
                push_b = -(c.velocity_b[0] * rv[0] + c.velocity_b[1] * rv[1])
                actor, target = (c.a, c.b) if push_a >= push_b else (c.b, c.a)
            if kinds.get(target) in self.background:
                continue
            key = (actor, target)
            if key in last and c.time - last[key] <= self.rehit:
                last[key] = c.time
                continue
            last[key] = c.time
            # The side the actor comes from: against its velocity relative to the target
            # (the contact normal of a glancing touch on a rounded pig would say less).
            vx, vy = approach(trace, c, actor, target)
            out.append(Interaction("hit", (actor, target), side(-vx, -vy), c.time))
        return out

    def on_surfaces(self, trace: Trace, intervals):
        """(mover, surface, the mover's state index, contact spans) for each dynamic body
        touching a static surface from above: the spans whose contact normal, at the contact's
        beginning, points up from the surface into the mover within MAX_TILT of the vertical.
        A block pressed against a platform's underside or its end is not on it."""
        normals = {}
        for c in trace.contacts:
            normals.setdefault((frozenset((c.a, c.b)), c.time), c)
        for mover, surface, spans in self._touching_surfaces(trace, intervals):
            pair = frozenset((mover, surface))
            above = [span for span in spans if self._from_above(normals.get((pair, span[0])), surface)]
            if above:
                yield mover, surface, trace.index(mover), above

    def _touching_surfaces(self, trace: Trace, intervals):
        """(mover, surface, contact spans) for each pair of one dynamic body and one static
        surface (of the `surfaces` kinds) that touched, on any side."""
        for pair, spans in intervals.items():
            names = sorted(pair)
            surfaces = [n for n in names if trace.kinds.get(n) in self.surfaces]
            movers = [n for n in names if n in trace.names]
            if len(surfaces) == 1 and len(movers) == 1:
                yield movers[0], surfaces[0], spans

    def _from_above(self, contact: ContactRecord | None, surface: str) -> bool:
        """Whether the contact's normal, turned to point from the surface into the other body,
        is within MAX_TILT of straight up (no record: the contact began before the trace)."""
        if contact is None:
            return True
        upward = contact.normal[1] if contact.a == surface else -contact.normal[1]
        return upward >= self.upward

    def travels(self, trace: Trace, intervals) -> Iterator[tuple[str, str, int, list[tuple[float, float]]]]:
        """(mover, surface, the mover's state index, travel spans) for each dynamic body that
        touched a surface from above (`on_surfaces`): its touches of that surface, each joined to
        the next across a hop (`hop`)."""
        for mover, surface, index, spans in self.on_surfaces(trace, intervals):
            yield mover, surface, index, self._joined(trace, index, self.size(trace, mover), spans)

    def travels_on(self, trace: Trace, intervals, mover: str, surface: str) -> list[tuple[float, float]]:
        """The travel spans of `mover` along `surface` (none if it never touched its upper
        side): `travels` of that one pair, without reading the others."""
        if mover not in trace.names or trace.kinds.get(surface) not in self.surfaces:
            return []
        pair = frozenset((mover, surface))
        firsts: dict[float, ContactRecord] = {}
        for c in trace.contacts:
            if {c.a, c.b} == pair:
                firsts.setdefault(c.time, c)
        above = [span for span in intervals.get(pair, ()) if self._from_above(firsts.get(span[0]), surface)]
        index = trace.index(mover)
        return self._joined(trace, index, self.size(trace, mover), above)

    def _joined(self, trace: Trace, index: int, size: float, spans) -> list[tuple[float, float]]:
        """Touches of one surface, each joined to the next across a hop."""
        joined: list[tuple[float, float]] = []
        for begin, end in sorted(spans):
            if joined and self.hop(trace, index, joined[-1][1], begin, size):
                joined[-1] = (joined[-1][0], end)
            else:
                joined.append((begin, end))
        return joined

    @staticmethod
    def size(trace: Trace, name: str) -> float:
        """A body's size for its hops: a round body's radius, another's smaller half-extent."""
        if trace.radii.get(name):
            return float(trace.radii[name])
        outline = trace.outlines.get(name)
        return min(outline[3], outline[4]) if outline else 0.0

    def hop(self, trace: Trace, index: int, left: float, landed: float, size: float) -> bool:
        """Whether the break from `left` to `landed` is a hop: the body rose at most hop_rise ×
        `size` above where it left and dropped less than fall_height."""
        if self.hop_rise <= 0.0:
            return False  # no hops: every touch is a travel of its own
        if landed <= left:
            return True  # no break at all
        dt = trace.dt
        first, last = max(int(round(left / dt)) - 1, 0), min(int(round(landed / dt)), trace.steps)
        heights = trace.states[first:last, index, 1]
        heights = heights[~np.isnan(heights)]
        if not len(heights):
            return False
        return heights.max() - heights[0] <= self.hop_rise * size and heights[0] - heights[-1] < self.fall_height

    def motion(self, trace: Trace, index: int, span, r: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(rows, rolling, sliding) of the body `index` over one travel along a surface: its
        state rows, and whether it rolls or slides in each (r: its rolling radius, None for a
        body that cannot roll)."""
        dt = trace.dt
        begin, end = span
        # State row k holds the time (k + 1) · dt.
        rows = trace.states[int(round(begin / dt)) - 1 : int(round(min(end, trace.duration) / dt)) - 1, index]
        rows = rows[~np.isnan(rows[:, 0])]
        speed = np.hypot(rows[:, 3], rows[:, 4])
        moving = speed >= self.moving
        if r:
            # The contact point hardly slips: the spin's sense matches the heading.
            heading = np.sign(rows[:, 3]) * speed
            rolling = moving & (np.abs(-rows[:, 5] * r - heading) <= self.roll_slip * speed)
        else:
            rolling = np.zeros(len(rows), dtype=bool)
        sliding = moving & (np.abs(rows[:, 5]) <= self.slide_spin) & ~rolling
        if r and not self.round_slides:
            sliding[:] = False
        return rows, rolling, sliding

    def covered(self, rows: np.ndarray, frames: np.ndarray) -> float:
        """The net displacement from the first to the last of `frames` (the rows rolling or sliding)."""
        if not frames.any():
            return 0.0
        picked = rows[frames]
        return float(np.hypot(picked[-1, 0] - picked[0, 0], picked[-1, 1] - picked[0, 1]))

    def _motion(self, trace: Trace, intervals, radius) -> list[Interaction]:
        out = []
        dt = trace.dt
        for mover, surface, index, spans in self.travels(trace, intervals):
            for begin, end in spans:
                rows, rolling, sliding = self.motion(trace, index, (begin, end), radius.get(mover))
                if not len(rows):
                    continue
                for name, frames in (("roll", rolling), ("slide", sliding)):
                    if frames.sum() * dt >= self.motion_time and self.covered(rows, frames) >= self.travel:
                        first = int(np.argmax(frames))
                        direction = "right" if rows[frames, 3].sum() > 0 else "left"
                        out.append(Interaction(name, (mover, surface), direction, begin + first * dt))
        return out

    def _falls(self, trace: Trace, intervals) -> list[Interaction]:
        out = []
        dt = trace.dt
        touching = touching_steps(trace, intervals)
        airborne_all = ~touching & ~np.isnan(trace.states[:, :, 0])
        for index, name in enumerate(trace.names):
            if trace.kinds.get(name) in self.thrown:
                continue
            airborne = np.concatenate([airborne_all[:, index], [False]])
            edges = np.flatnonzero(np.diff(np.concatenate([[False], airborne]).astype(int)))
            for start, stop in zip(edges[::2], edges[1::2], strict=True):  # edges padded: rises and falls pair up
                duration = (stop - start) * dt
                drop = trace.states[start, index, 1] - trace.states[stop - 1, index, 1]
                if duration < self.fall_time or drop < self.fall_height:
                    continue
                landed = (stop + 1) * dt
                landing = next(
                    (
                        c.b if c.a == name else c.a
                        for c in trace.contacts
                        if name in (c.a, c.b) and c.time >= landed - dt * 1.5
                    ),
                    None,
                )
                if landing is not None:
                    out.append(Interaction("fall", (name, landing), None, (start + 1) * dt))
        return out

    def _bounces(self, trace: Trace, intervals) -> list[Interaction]:
        out = []
        dt = trace.dt
        for mover, surface, index, spans in self._bounced_on(trace, intervals):
            pair = frozenset((mover, surface))
            size = self.size(trace, mover)
            ordered = sorted(spans)
            for k, (begin, end) in enumerate(ordered):
                if end - begin >= self.bounce_time or end >= trace.duration:
                    continue
                incoming = next((c for c in trace.contacts if c.time == begin and {c.a, c.b} == pair), None)
                if incoming is None or incoming.speed < self.bounce_speed:
                    continue
                above = self._from_above(incoming, surface)
                if above and k + 1 < len(ordered) and self.hop(trace, index, end, ordered[k + 1][0], size):
                    continue  # a hop of a travel along the surface, not a bounce off it
                after = int(round(end / dt))
                if after >= trace.steps:
                    continue
                vx, vy = trace.states[after, index, 3:5]
                if np.isnan(vx):
                    continue
                out.append(Interaction("bounce", (mover, surface), side(vx, vy), end))
        return out

    def _bounced_on(self, trace: Trace, intervals):
        """(mover, surface, index, spans) a bounce may come from: the touches of a surface's
        upper side, or with bounce_walls its every side (a wall, a ceiling, a slope's underside)."""
        if not self.bounce_walls:
            yield from self.on_surfaces(trace, intervals)
            return
        for mover, surface, spans in self._touching_surfaces(trace, intervals):
            yield mover, surface, trace.index(mover), spans
