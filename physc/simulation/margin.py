"""A margin as a value: how far one link was from failing (`Margin`), and one trace's (`Margins`).

What each kind of link measures and in which unit is said once here, by `Margin`'s named
constructors (`Margin.distance`, `Margin.speed`, `Margin.angle`, ...); the reader of a trace's
margins (physc.simulation.margins) only says which one a link has and how much.
"""

from __future__ import annotations

import math

import attrs

SIDE_SCALE = 45.0  # degrees: half a side's 90° sector, one whole margin of an angle


@attrs.frozen
class Margin:
    """How far one link was from failing: `value` in `unit`s (positive: held with that much to
    spare), `scale` the value that counts as one whole margin, `what` the quantity in words.

    Made by the constructor named for what the link measures, e.g. a speed:

    >>> m = Margin.speed("hit(bird, pig)", 0, value=0.5, scale=2.0, what="approach speed beyond a hit's least")
    >>> m.share
    0.25
    >>> print(m.text())
    `hit(bird, pig)`: +0.5 units/s (approach speed beyond a hit's least)
    >>> Margin.failed("roll(ball, ramp)", 1, what="not realised").held
    False
    """

    term: str  # the declared term or restriction, in .phys syntax
    index: int | None  # its place in the declared sequence; None for a restriction
    value: float
    unit: str
    scale: float
    what: str
    held: bool = True  # whether the link held in this trace

    # ---- the kinds of margin -------------------------------------------------------------
    @classmethod
    def failed(cls, term: str, index: int | None, *, what: str, unit: str = "of a link") -> Margin:
        """A link that failed with nothing to measure it by: a flat −1 of one whole margin."""
        return cls(term, index, -1.0, unit, 1.0, what, False)

    @classmethod
    def distance(
        cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool = True
    ) -> Margin:
        """A length in the world's units: a gap short of touching, a travel or a drop beyond the least."""
        return cls(term, index, value, "units", scale, what, held)

    @classmethod
    def speed(cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool = True) -> Margin:
        """A speed in units per second: of an approach beyond a hit's least, or left on arrival."""
        return cls(term, index, value, "units/s", scale, what, held)

    @classmethod
    def angle(cls, term: str, index: int | None, *, value: float, what: str, held: bool = True) -> Margin:
        """Degrees inside the nearest allowed side's sector (scale: half a sector, SIDE_SCALE)."""
        return cls(term, index, value, "degrees", SIDE_SCALE, what, held)

    @classmethod
    def seconds(
        cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool = True
    ) -> Margin:
        """A duration: of a motion, a drop or a touch beyond (or short of) the recogniser's."""
        return cls(term, index, value, "s", scale, what, held)

    @classmethod
    def overhang(cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool) -> Margin:
        """How far a body's centre came past the edge of what it rested on (a fall that never began)."""
        return cls(term, index, value, "units of overhang", scale, what, held)

    @classmethod
    def overlap(cls, term: str, index: int | None, *, value: float, scale: float, what: str) -> Margin:
        """How far a landing was from missing what it fell on."""
        return cls(term, index, value, "units of overlap", scale, what)

    @classmethod
    def clearance(cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool) -> Margin:
        """The room a body kept from one it must not hit."""
        return cls(term, index, value, "units of clearance", scale, what, held)

    @classmethod
    def life(cls, term: str, index: int | None, *, value: float, scale: float, what: str) -> Margin:
        """The life a body has left under the worst reading of the blows it took."""
        return cls(term, index, value, "life", scale, what)

    @classmethod
    def damage(
        cls, term: str, index: int | None, *, value: float, scale: float, what: str, held: bool = True
    ) -> Margin:
        """Damage dealt beyond (or short of) the life a body had left."""
        return cls(term, index, value, "damage", scale, what, held)

    @classmethod
    def fall_share(cls, term: str, index: int | None, *, value: float, what: str, held: bool) -> Margin:
        """How far a drop was from being recognised as a fall, in shares of one (scale 1)."""
        return cls(term, index, value, "of a fall", 1.0, what, held)

    # ---- reading one -----------------------------------------------------------------------
    @property
    def share(self) -> float:
        return self.value / self.scale if self.scale else self.value

    def text(self) -> str:
        """ "`fall(fBlock2, pig)`: −0.12 units of overhang (…)"."""
        return f"`{self.term}`: {self.value:+.3g} {self.unit} ({self.what})"

    def standing(self, qualifier: str = "") -> str:
        """The margin in words that read right whatever its sign: "+25.1 life to spare (…)" for
        a link that held, "failed by 0.4 units (…)" for one that did not ("failed (…)" where
        it has no measure of how far); `qualifier` ("at best") goes before the parenthesis.

        >>> print(Margin.life("destroy(bird, pig)", 1, value=25.1, scale=10.0, what="life left").standing("at best"))
        +25.1 life to spare at best (life left)
        >>> print(Margin.distance("fall(b, ground)", 1, value=-0.4, scale=1.0, what="drop", held=False).standing())
        failed by 0.4 units (drop)
        """
        tail = (f" {qualifier}" if qualifier else "") + f" ({self.what})"
        if self.held:
            if self.value >= 0:
                return f"{self.value:+.3g} {self.unit} to spare{tail}"
            return f"held at {self.value:+.3g} {self.unit}{tail}"
        if self.value < 0 and self.unit != "of a link":  # Margin.failed's flat −1 measures nothing
            return f"failed by {-self.value:.3g} {self.unit}{tail}"
        return f"failed{tail}"

    def named_weakest(self, qualifier: str = "") -> str:
        """This link named as a chain's weakest, in words a reader takes right: a link that held
        "came closest to failing" (with what it had to spare), one that did not "failed by" its
        margin: "the link that came closest to failing was `fall(b, ground)`: +0.3 units to
        spare (…)", "the weakest link was `fall(b, ground)`: it failed by 0.4 units (…)"."""
        if self.held:
            return f"the link that came closest to failing was `{self.term}`: {self.standing(qualifier)}"
        return f"the weakest link was `{self.term}`: it {self.standing(qualifier)}"

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
