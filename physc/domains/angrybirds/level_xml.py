"""Reading and writing Science Birds level files.

The importer takes real files as they are: they declare utf-16 but are plain
ASCII (or UTF-8) without a byte-order mark, which `ElementTree.parse` rejects;
the text is decoded first (UTF-16 when it really is, by its byte-order mark) and
parsed from a string. Problems are `LevelError`s with a code and a position,
never Python exceptions from the XML library.

The emitter writes the exact format of the game's loader with a jinja2 template:
fixed element order, one element per line, no comments, numbers with a '.' and
at most the digits they need.
"""

from __future__ import annotations

import functools
import re
import xml.etree.ElementTree as ElementTree
from importlib import resources

import jinja2
import numpy as np

from physc.domains.angrybirds.catalogue import BIRD_PREFABS, BY_PREFAB
from physc.domains.angrybirds.level import ELEMENTS, Camera, Level, LevelObject
from physc.suggest import did_you_mean


class LevelError(Exception):
    """An unusable level file: `code` is a physc diagnostic code, `line` 1-based or None."""

    def __init__(self, code: str, message: str, line: int | None = None, column: int | None = None, help: str | None = None):
        super().__init__(message)
        self.code = code
        self.message = message
        self.line = line
        self.column = column
        self.help = help


def decode(data: bytes) -> str:
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return data.decode("utf-16")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise LevelError("E0901", f"the level file is neither UTF-8 nor UTF-16 (byte 0x{data[error.start]:02x})") from None


def _number(element, attribute, required=True):
    text = element.get(attribute)
    if text is None:
        if required:
            raise LevelError("E0902", f"<{element.tag}> has no '{attribute}' attribute")
        return None
    try:
        return float(text)
    except ValueError:
        raise LevelError("E0902", f"<{element.tag}> {attribute}=\"{text}\" is not a number") from None


def parse_level(text: str) -> Level:
    # The declaration (utf-16 in real files) only labels bytes we have already decoded.
    body = re.sub(r"^\s*<\?xml[^>]*\?>", "", text, count=1)
    try:
        root = ElementTree.fromstring(body)
    except ElementTree.ParseError as error:
        line, column = error.position
        offset = text.count("\n", 0, len(text) - len(body))  # the removed declaration's lines
        reason = re.sub(r": line \d+, column \d+$", "", error.msg)
        raise LevelError("E0901", f"the level file is not well-formed XML: {reason}", line + offset, column + 1) from None
    if root.tag != "Level":
        raise LevelError("E0901", f"the root element is <{root.tag}>, not <Level>")
    camera_element = root.find("Camera")
    camera = Camera()
    if camera_element is not None:
        camera = Camera(
            _number(camera_element, "x"),
            _number(camera_element, "y"),
            _number(camera_element, "minWidth"),
            _number(camera_element, "maxWidth"),
        )
    score = root.find("Score")
    birds = tuple(b.get("type", "") for b in root.iter("Bird"))
    for bird in birds:
        if bird not in BIRD_PREFABS:
            raise LevelError("E0903", f"unknown bird type '{bird}'", help=did_you_mean(bird, BIRD_PREFABS))
    sling = root.find("Slingshot")
    slingshot = (-12.0, -2.5) if sling is None else (_number(sling, "x"), _number(sling, "y"))
    objects = []
    container = root.find("GameObjects")
    counts: dict[str, int] = {}
    for element in container if container is not None else ():
        if element.tag not in ELEMENTS:
            raise LevelError("E0903", f"unknown game object <{element.tag}>", help=did_you_mean(element.tag, ELEMENTS))
        prefab = element.get("type", "TNT" if element.tag == "TNT" else "")
        found = BY_PREFAB.get(prefab)
        if found is None or found.kind in ("bird", "ground"):
            known = [p for p, s in BY_PREFAB.items() if s.kind not in ("bird", "ground") and p]
            raise LevelError("E0903", f"unknown object type '{prefab}'", help=did_you_mean(prefab, known))
        base = "platform" if found.kind == "platform" else found.name
        counts[base] = counts.get(base, 0) + 1
        objects.append(
            LevelObject(
                element=element.tag,
                type=prefab,
                x=_number(element, "x"),
                y=_number(element, "y"),
                rotation=_number(element, "rotation", required=False),
                material=element.get("material"),
                scale_x=_number(element, "scaleX", required=False),
                scale_y=_number(element, "scaleY", required=False),
                name=f"{base}{counts[base]}",
            )
        )
    return Level(
        width=_number(root, "width", required=False) or 2.0,
        camera=camera,
        high_score=None if score is None else _number(score, "highScore"),
        birds=birds,
        slingshot=slingshot,
        objects=tuple(objects),
    )


def read_level(data: bytes) -> Level:
    return parse_level(decode(data))


def number(value: float) -> str:
    """The shortest decimal text that reads back as the same float, never in exponent
    form; whole numbers without a point, as real levels write them (the loader reads
    `width` and `highScore` as integers)."""
    value = float(value)
    if value.is_integer():
        return str(int(value))
    return np.format_float_positional(value, trim="-")


@functools.cache
def _template() -> jinja2.Template:
    source = resources.files("physc.domains.angrybirds").joinpath("templates/level.xml.j2").read_text(encoding="utf-8")
    environment = jinja2.Environment(autoescape=True, keep_trailing_newline=True, undefined=jinja2.StrictUndefined)
    return environment.from_string(source)


def emit_level(level: Level) -> str:
    return _template().render(level=level, num=number)
