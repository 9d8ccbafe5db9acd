"""The checks a level file passes on reading: its limits, numbers, types and materials.

A level file is input nobody here wrote, so every value that reaches the physics is
checked first, and every problem is a `LevelError` naming the element and where it
is (line and column), never a Python exception later. The limits (docs/angrybirds.md,
"Level files") are generous for real levels and keep a hostile one bounded:

* the file: at most MAX_LEVEL_BYTES (real levels are about 4 KB);
* bodies: at most MAX_BODIES game objects (the largest real level has 36). A level
  of that many bodies all stacked at one spot, played for the longest simulated time
  the command line allows, ends within a minute and well under 2 GB (measured: the
  contacts of bodies overlapping at one spot grow with the square of their number);
* positions (objects, slingshot, camera): finite, |x| and |y| at most MAX_COORDINATE;
* rotations: finite, within ±MAX_ROTATION degrees;
* scales: finite, |scale| from MIN_SCALE to MAX_SCALE. Negative scales are allowed:
  Unity mirrors the platform, and two Phy-Q templates have them;
* the level's width: finite, more than 0 and at most MAX_WIDTH;
* bodies stacked into one another: at most MAX_DEEP_OVERLAPS pairs of moving objects whose
  centres are nearer than half the smaller one's smaller side. Real levels have none (their
  objects touch); in Box2D at the game's 100 + 100 iterations a pile of n bodies at one spot
  costs about n^2.6 per step (40 SquareHoles: 1.1 s a step, 150: 48 s), so such a level is
  refused rather than played for hours.

What the game itself ignores is read as the game reads it: a <TNT> or <Platform> is
its prefab whatever (or whether) its `type` says, and the `material` of anything but
a <Block> is kept as written and not used. A <Block> needs wood, stone or ice: the
game parses the name as an enumeration (case-sensitive) and fails on anything else.
"""

from __future__ import annotations

import math
import re
from typing import Literal, overload

from physc.diagnostics import SourceText
from physc.domains.angrybirds.catalogue import BIRD_PREFABS, BY_PREFAB, MATERIALS
from physc.domains.base import LevelError
from physc.suggest import did_you_mean

MAX_LEVEL_BYTES = 4 * 1024 * 1024
MAX_BODIES = 300
MAX_COORDINATE = 500.0
MAX_ROTATION = 720.0
MIN_SCALE, MAX_SCALE = 0.01, 100.0
MAX_WIDTH = 100.0
MAX_DEEP_OVERLAPS = 10
MAX_CAMERA_WIDTH = 1000.0

BLOCK_TYPES = tuple(p for p, s in BY_PREFAB.items() if s.kind == "block")
PIG_TYPES = tuple(p for p, s in BY_PREFAB.items() if s.kind == "pig")
# The prefab each element may name; TNT and Platform are their prefab whatever `type` says.
ELEMENT_TYPES = {"Block": BLOCK_TYPES, "Pig": PIG_TYPES, "TNT": ("TNT",), "Platform": ("Platform",)}
FIXED_PREFAB = {"TNT": "TNT", "Platform": "Platform"}

_NUMBER = re.compile(r"\s*[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\s*")


def check_size(data: bytes | str) -> None:
    """E0906 for a file (bytes) or text (characters) beyond MAX_LEVEL_BYTES, before any parsing."""
    if len(data) > MAX_LEVEL_BYTES:
        unit = "characters" if isinstance(data, str) else "bytes"
        raise LevelError(
            "E0906",
            f"the level file has {len(data):,} {unit}, more than physc reads ({MAX_LEVEL_BYTES:,})",
            help="real level files are a few KB; a level this large is not a Science Birds level",
        )


class Source:
    """The text of a level file, to say where an element or an attribute of it is.

    lxml gives the line on which an element's start tag ends; the column is found by
    looking back from there for the tag, and forward from the tag for the attribute."""

    def __init__(self, text: str):
        self.text = text
        self.source = SourceText("", text)  # its line index

    def position(self, element, attribute: str | None = None) -> tuple[int | None, int | None]:
        line = getattr(element, "sourceline", None)
        if line is None or not 1 <= line <= self.source.line_count:
            return None, None
        end = self.source.line_bounds(line)[1] + 1
        start = self.text.rfind(f"<{element.tag}", 0, end)
        if start < 0:
            return line, None
        if attribute is not None:
            tag_end = self.text.find(">", start)
            found = re.compile(rf"\s{re.escape(attribute)}\s*=").search(
                self.text, start, tag_end if tag_end >= 0 else end
            )
            if found:
                start = found.start() + 1
        where = self.source.span(start, start)
        return where.line, where.column

    def error(
        self, code: str, message: str, element, attribute: str | None = None, help: str | None = None
    ) -> LevelError:
        return LevelError(code, message, *self.position(element, attribute), help=help)

    # ---- values ----------------------------------------------------------------------
    @overload
    def number(self, element, attribute: str, required: Literal[True] = True) -> float: ...

    @overload
    def number(self, element, attribute: str, required: bool) -> float | None: ...

    def number(self, element, attribute: str, required: bool = True) -> float | None:
        """The finite number of an attribute (None when it is absent and not required)."""
        text = element.get(attribute)
        if text is None:
            if required:
                raise self.error("E0902", f"<{element.tag}> has no '{attribute}' attribute", element)
            return None
        if _NUMBER.fullmatch(text):
            value = float(text)  # 1e999 reads as infinity
        elif text.strip().lstrip("+-").lower() in ("nan", "inf", "infinity"):
            value = math.nan
        else:
            raise self.error(
                "E0902", f'<{element.tag}> {attribute}="{_short(text)}" is not a number', element, attribute
            )
        if not math.isfinite(value):
            raise self.error(
                "E0902", f'<{element.tag}> {attribute}="{_short(text)}" is not a finite number', element, attribute
            )
        return value

    @overload
    def bounded(
        self, element, attribute: str, low: float, high: float, what: str, required: Literal[True] = True
    ) -> float: ...

    @overload
    def bounded(self, element, attribute: str, low: float, high: float, what: str, required: bool) -> float | None: ...

    def bounded(
        self, element, attribute: str, low: float, high: float, what: str, required: bool = True
    ) -> float | None:
        """A number within [low, high]; `what` says what the range is, for the message."""
        value = self.number(element, attribute, required)
        if value is not None and not low <= value <= high:
            raise self.error(
                "E0904",
                f'<{element.tag}> {attribute}="{_short(element.get(attribute))}" is out of range: {what}',
                element,
                attribute,
            )
        return value

    def coordinate(self, element, attribute: str) -> float:
        limit = f"{MAX_COORDINATE:g}"
        return self.bounded(
            element, attribute, -MAX_COORDINATE, MAX_COORDINATE, f"positions are from -{limit} to {limit}"
        )

    def rotation(self, element) -> float | None:
        limit = f"{MAX_ROTATION:g}"
        return self.bounded(
            element,
            "rotation",
            -MAX_ROTATION,
            MAX_ROTATION,
            f"rotations are from -{limit} to {limit} degrees",
            required=False,
        )

    def scale(self, element, attribute: str) -> float | None:
        value = self.number(element, attribute, required=False)
        if value is not None and not MIN_SCALE <= abs(value) <= MAX_SCALE:
            raise self.error(
                "E0904",
                f'<{element.tag}> {attribute}="{_short(element.get(attribute))}" is out of range: '
                f"a scale's size is from {MIN_SCALE:g} to {MAX_SCALE:g} (negative mirrors)",
                element,
                attribute,
            )
        return value

    # ---- names -----------------------------------------------------------------------
    def object_type(self, element) -> str:
        """The prefab of a game object: what its `type` names, or TNT and Platform's own."""
        given = element.get("type")
        known = ELEMENT_TYPES[element.tag]
        if given in known:
            return given
        if element.tag in FIXED_PREFAB and not given:
            return FIXED_PREFAB[element.tag]  # the game ignores their type: '' or none is theirs
        what = "no 'type' attribute" if given is None else f"unknown object type '{_short(given)}'"
        message = f"<{element.tag}> has {what}" if given is None else f"{what} for <{element.tag}>"
        return self._unknown(message, given or "", known, element, "type", f"<{element.tag}> types")

    def bird_type(self, element) -> str:
        given = element.get("type")
        if given in BIRD_PREFABS:
            return given
        message = "<Bird> has no 'type' attribute" if given is None else f"unknown bird type '{_short(given)}'"
        return self._unknown(message, given or "", BIRD_PREFABS, element, "type", "bird types")

    def material(self, element) -> str | None:
        """A block's material (wood, stone or ice); for other objects whatever it says."""
        given = element.get("material")
        if element.tag != "Block" or given in MATERIALS:
            return given
        message = (
            "<Block> has no 'material' attribute"
            if given is None
            else f"unknown material '{_short(given)}' for <Block>"
        )
        return self._unknown(message, given or "", MATERIALS, element, "material", "materials", code="E0905")

    def _unknown(self, message, given, known, element, attribute, kinds, code="E0903"):
        listed = f"{kinds}: {', '.join(known)}"
        suggestion = did_you_mean(given, known) if given else None
        raise self.error(
            code,
            message,
            element,
            attribute if element.get(attribute) is not None else None,
            help=f"{suggestion} ({listed})" if suggestion else listed,
        )


def _short(text: str, limit: int = 40) -> str:
    """An attribute's text for a message: control characters escaped, long text cut."""
    text = text.encode("unicode_escape").decode("ascii") if not text.isprintable() else text
    return text if len(text) <= limit else text[: limit - 1] + "…"


def deep_overlaps(objects) -> list[tuple[int, int]]:
    """The pairs (indices) of moving objects stacked into one another: centres nearer than
    half the smaller one's smaller side (touching neighbours are a side apart)."""
    from physc.domains.angrybirds.catalogue import extent

    moving = [(i, o.x, o.y, min(extent(o))) for i, o in enumerate(objects) if BY_PREFAB[o.type].kind != "platform"]
    moving.sort(key=lambda m: m[1])
    out = []
    for k, (i, x, y, size) in enumerate(moving):
        for j, x2, y2, size2 in moving[k + 1 :]:
            near = min(size, size2) / 2
            if x2 - x >= near:
                if x2 - x >= 0.5:  # no object is more than 1 unit across its smaller side
                    break
                continue
            if math.hypot(x2 - x, y2 - y) < near:
                out.append((min(i, j), max(i, j)))
    return sorted(out)
