"""Where a trace's bodies were: their boxes, the gaps between them, their spells in the air.

What margins (physc.simulation.margins) measure links with: a trace records every dynamic
body's pose and the box each body starts with (`Trace.outlines`); `Where` reads from them a
body's box at a step, the least gap between two bodies over some steps, the spells in which
a body touched nothing, and what it touched last before one.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from physc.simulation.recognise import contact_intervals
from physc.simulation.trace import Trace


class Where:
    """The geometry of one trace."""

    def __init__(self, trace: Trace):
        self.trace = trace

    @functools.cached_property
    def intervals(self) -> dict:
        """Contact intervals per pair of bodies (physc.simulation.recognise.contact_intervals)."""
        return contact_intervals(self.trace)

    def pose(self, name: str, row: int) -> tuple[float, float, float, float, float] | None:
        """(x, y, angle, half-width, half-height) of `name` at state row `row` (None: unknown or gone)."""
        trace = self.trace
        outline = trace.outlines.get(name)
        if outline is None:
            return None
        if name not in trace.names:
            return outline
        state = trace.states[min(max(row, 0), trace.steps - 1), trace.index(name)]
        if math.isnan(state[0]):
            return None
        return (float(state[0]), float(state[1]), float(state[2]), outline[3], outline[4])

    @staticmethod
    def extents(pose) -> tuple[float, float]:
        """The half-extents along x and y of a pose's box turned by its angle."""
        _, _, angle, w, h = pose
        c, s = abs(math.cos(angle)), abs(math.sin(angle))
        return w * c + h * s, w * s + h * c

    @functools.cached_property
    def _parts(self) -> dict[str, tuple[str, ...]]:
        """Each whole's bodies as the trace names them: itself, then its parts (Trace.parts)."""
        out: dict[str, list[str]] = {}
        for part, whole in self.trace.parts.items():
            out.setdefault(whole, [whole]).append(part)
        return {whole: tuple(bodies) for whole, bodies in out.items()}

    def bodies(self, name: str) -> tuple[str, ...]:
        """The bodies that are `name` as the scenario names it: itself and its parts (Science
        Birds: a blue bird and the two birds its split adds)."""
        return self._parts.get(name, (name,))

    def party(self, contact, name: str) -> str:
        """Which of `contact`'s two bodies is (a part of) `name`."""
        return contact.a if contact.a in self.bodies(name) else contact.b

    def gap(self, a: str, b: str, first: int, last: int) -> float | None:
        """The least distance between the boxes of `a` and `b` (of any of their parts) over rows
        first..last (negative: they overlap; None when neither can be placed)."""
        trace = self.trace
        best = None
        pairs = [(x, y) for x in self.bodies(a) for y in self.bodies(b)]
        for row in range(max(first, 0), min(last, trace.steps)):
            for x, y in pairs:
                pa, pb = self.pose(x, row), self.pose(y, row)
                if pa is None or pb is None:
                    continue
                (ax, ay), (bx, by) = self.extents(pa), self.extents(pb)
                dx, dy = abs(pa[0] - pb[0]) - ax - bx, abs(pa[1] - pb[1]) - ay - by
                gap = math.hypot(max(dx, 0.0), max(dy, 0.0)) if dx > 0 or dy > 0 else max(dx, dy)
                best = gap if best is None else min(best, gap)
        return best

    def size(self, name: str) -> float:
        """`name`'s larger half-extent (a length scale for its clearances)."""
        trace = self.trace
        outline = trace.outlines.get(name)
        return max(outline[3], outline[4]) if outline else 0.1

    def row(self, time: float) -> int:
        """The state row of `time` (row k holds the time (k + 1) · dt)."""
        trace = self.trace
        return min(max(int(round(time / trace.dt)) - 1, 0), trace.steps - 1)

    def contacts(self, a: str, b: str, since: float):
        """The contacts from `since` on between `a` and `b`, their parts' included, in time order."""
        trace = self.trace
        ones, others = self.bodies(a), self.bodies(b)
        return [
            c
            for c in trace.contacts
            if c.time >= since - 1e-9 and ((c.a in ones and c.b in others) or (c.b in ones and c.a in others))
        ]

    def spells(self, name: str, since: float, until: float) -> list[tuple[int, int]]:
        """(first row, row after the last) of each spell in which `name` touched nothing, begun in since..until."""
        trace = self.trace
        if name not in trace.names:
            return []
        index = trace.index(name)
        touching = np.zeros(trace.steps, dtype=bool)
        for pair, spans in self.intervals.items():
            if name in pair:
                for begin, end in spans:
                    touching[
                        max(int(round(begin / trace.dt)) - 1, 0) : min(int(math.ceil(end / trace.dt)) - 1, trace.steps)
                    ] = True
        airborne = ~touching & ~np.isnan(trace.states[:, index, 0])
        edges = np.flatnonzero(np.diff(np.concatenate([[False], airborne, [False]]).astype(int)))
        return [
            (int(a), int(b))
            for a, b in zip(edges[::2], edges[1::2], strict=True)
            if since - 1e-9 <= (a + 1) * trace.dt <= until + 1e-9
        ]

    def drop(self, index: int, spell) -> tuple[float, float]:
        trace = self.trace
        start, stop = spell
        return (stop - start) * trace.dt, float(trace.states[start, index, 1] - trace.states[stop - 1, index, 1])

    def support_before(self, name: str, row: int) -> str | None:
        """The surface or body `name` touched last before state row `row` (what it falls from)."""
        trace = self.trace
        time = (row + 1) * trace.dt
        best, when = None, -1.0
        for pair, spans in self.intervals.items():
            if name not in pair:
                continue
            (other,) = pair - {name}
            for begin, end in spans:
                if (
                    begin <= time + 1e-9
                    and end <= time + trace.dt * 1.5
                    and end > when
                    and end >= time - trace.dt * 1.5
                ):
                    best, when = other, end
        return best

    def overhang(self, name: str, support: str, since: int) -> float | None:
        """The furthest `name`'s centre came past the edge of `support` from row `since` on
        (negative: short of it)."""
        trace = self.trace
        best = None
        for row in range(since, trace.steps):
            pa, ps = self.pose(name, row), self.pose(support, row)
            if pa is None or ps is None:
                continue
            past = abs(pa[0] - ps[0]) - self.extents(ps)[0]
            best = past if best is None else max(best, past)
        return best
