"""Reading and writing Science Birds level files.

The importer takes real files as they are: they declare utf-16 but are plain
ASCII (or UTF-8) without a byte-order mark; the text is decoded first (UTF-16
when it really is, by its byte-order mark), the declaration blanked out, and the
text parsed. The parser is lxml's, hardened: no DTD loaded, no entity resolved, no
network, libxml2's limits on depth and entity amplification; a DOCTYPE is refused
(a level file has no use for one), and the file's size is checked before parsing.
lxml also gives each element's line, so every problem is a `LevelError` with a
code and a position (level_checks.py), never a Python exception.

The emitter writes the exact format of the game's loader with a jinja2 template:
fixed element order, one element per line, no comments, numbers with a '.' and
at most the digits they need; declared utf-8, as its bytes are (the game's own files declare
utf-16 over ASCII bytes; its loader ignores the declaration: docs/angrybirds.md, "Encoding").
"""

from __future__ import annotations

import functools
import re
from importlib import resources
from typing import TYPE_CHECKING

import lxml.etree as etree
import numpy as np

from physc.domains.angrybirds.catalogue import BY_PREFAB
from physc.domains.angrybirds.level import ELEMENTS, Camera, Level, LevelObject
from physc.domains.angrybirds.level_checks import (
    MAX_BODIES,
    MAX_CAMERA_WIDTH,
    MAX_DEEP_OVERLAPS,
    MAX_WIDTH,
    LevelError,
    Source,
    check_size,
    deep_overlaps,
)
from physc.suggest import did_you_mean

if TYPE_CHECKING:
    import jinja2

__all__ = ["LevelError", "decode", "emit_level", "parse_level", "read_level"]

_DECLARATION = re.compile(r"^\s*<\?xml[^>]*\?>")
CAMERA_WIDTHS = f"camera widths are from 0 to {MAX_CAMERA_WIDTH:g}"


def decode(data: bytes) -> str:
    """The text of a level file's bytes: UTF-16 by its byte-order mark, else UTF-8 (ASCII)."""
    check_size(data)
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError:
            raise LevelError("E0901", "the level file starts as UTF-16 but is not valid UTF-16") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise LevelError(
            "E0901", f"the level file is neither UTF-8 nor UTF-16 (byte 0x{data[error.start]:02x})"
        ) from None


def _parser() -> etree.XMLParser:
    """lxml's parser, made safe for files nobody here wrote: nothing outside the text is read."""
    return etree.XMLParser(
        resolve_entities=False, no_network=True, load_dtd=False, dtd_validation=False, huge_tree=False
    )


def _tree(text: str):
    """The root element of `text`; E0901 for anything but a plain, well-formed document."""
    # The declaration (utf-16 in real files) only labels characters already decoded, and lxml
    # refuses it in a str: it becomes spaces, so that lines and columns stay those of the file.
    body = _DECLARATION.sub(lambda m: re.sub(r"[^\n]", " ", m.group()), text, count=1)
    try:
        root = etree.fromstring(body, _parser())
    except etree.XMLSyntaxError as error:
        line, column = error.position if error.position else (None, None)
        reason = re.sub(r", line \d+, column \d+$", "", error.msg or str(error)).strip()
        raise LevelError("E0901", f"the level file is not well-formed XML: {reason}", line, column or None) from None
    except ValueError as error:  # lxml's refusal of characters XML does not allow
        raise LevelError("E0901", f"the level file is not well-formed XML: {error}") from None
    if root.getroottree().docinfo.doctype:
        found = text.find("<!DOCTYPE")
        line = None if found < 0 else text.count("\n", 0, found) + 1
        raise LevelError(
            "E0901",
            "the level file has a DOCTYPE; level files have no DTD or entities, and physc reads none",
            line,
            None if found < 0 else found - (text.rfind("\n", 0, found) + 1) + 1,
            help="remove the <!DOCTYPE …> declaration",
        )
    if root.tag != "Level":
        raise LevelError("E0901", f"the root element is <{root.tag}>, not <Level>", root.sourceline)
    return root


def _children(element, tag: str):
    """The child elements named `tag` (comments and processing instructions skipped)."""
    return [child for child in element if child.tag == tag]


def parse_level(text: str) -> Level:
    """The level a file's text describes, every value checked (level_checks.py)."""
    check_size(text)
    root = _tree(text)
    source = Source(text)
    camera = _camera(root, source)
    score = root.find("Score")
    birds = tuple(source.bird_type(bird) for bird in root.iter("Bird"))
    sling = root.find("Slingshot")
    slingshot = (-12.0, -2.5) if sling is None else (source.coordinate(sling, "x"), source.coordinate(sling, "y"))
    width = _width(root, source)
    objects, elements = _game_objects(root, source)
    _check_stacking(source, objects, elements)
    return Level(
        width=width,
        camera=camera,
        high_score=None if score is None else source.number(score, "highScore"),
        birds=birds,
        slingshot=slingshot,
        objects=tuple(objects),
        world=root.get("world"),
        generator=root.get("generator"),
    )


def _camera(root, source: Source) -> Camera:
    """The level's <Camera>, its coordinates and widths checked (the default camera without one)."""
    element = root.find("Camera")
    if element is None:
        return Camera()
    return Camera(
        source.coordinate(element, "x"),
        source.coordinate(element, "y"),
        source.bounded(element, "minWidth", 0.0, MAX_CAMERA_WIDTH, CAMERA_WIDTHS),
        source.bounded(element, "maxWidth", 0.0, MAX_CAMERA_WIDTH, CAMERA_WIDTHS),
    )


def _width(root, source: Source) -> float:
    """The <Level>'s width, checked (2 when it has none)."""
    if root.get("width") is None:
        return 2.0
    width = source.number(root, "width")
    if not 0 < width <= MAX_WIDTH:
        raise source.error(
            "E0904",
            f'<Level> width="{root.get("width")}" is out of range: more than 0 and at most {MAX_WIDTH:g}',
            root,
            "width",
        )
    return width


def _game_objects(root, source: Source) -> tuple[list[LevelObject], list]:
    """The level's <GameObjects>, each checked and named as physc names them (its base name and
    a count), with the element each came from (for a diagnostic's position)."""
    objects, elements = [], []
    counts: dict[str, int] = {}
    container = root.find("GameObjects")
    for element in container if container is not None else ():
        if not isinstance(element.tag, str):
            continue  # a comment or a processing instruction
        if element.tag not in ELEMENTS:
            raise source.error(
                "E0903",
                f"unknown game object <{element.tag}>",
                element,
                help=did_you_mean(element.tag, ELEMENTS) or f"game objects are {', '.join(f'<{e}>' for e in ELEMENTS)}",
            )
        if len(objects) == MAX_BODIES:
            raise source.error(
                "E0906",
                f"the level has more than {MAX_BODIES} game objects, the most physc plays",
                element,
                help="the largest real levels have a few dozen (docs/angrybirds.md: the limit keeps a play "
                "within a minute and 2 GB)",
            )
        prefab = source.object_type(element)
        found = BY_PREFAB[prefab]
        base = "platform" if found.kind == "platform" else found.name
        counts[base] = counts.get(base, 0) + 1
        objects.append(
            LevelObject(
                element=element.tag,
                type=prefab,
                x=source.coordinate(element, "x"),
                y=source.coordinate(element, "y"),
                rotation=source.rotation(element),
                material=source.material(element),
                scale_x=source.scale(element, "scaleX"),
                scale_y=source.scale(element, "scaleY"),
                name=f"{base}{counts[base]}",
            )
        )
        elements.append(element)
    return objects, elements


def _check_stacking(source: Source, objects: list[LevelObject], elements: list) -> None:
    """E0908 for a level with more objects stacked into one another than physc plays."""
    stacked = deep_overlaps(objects)
    if len(stacked) > MAX_DEEP_OVERLAPS:
        raise source.error(
            "E0908",
            f"{len(stacked):,} pairs of objects are stacked into one another (centres nearer than half the "
            f"smaller one), more than the {MAX_DEEP_OVERLAPS} physc plays",
            elements[stacked[MAX_DEEP_OVERLAPS][1]],
            help="real levels have none: objects touch, they do not sit inside one another; a pile of bodies "
            "at one spot takes Box2D minutes a step at the game's 100 iterations "
            '(docs/angrybirds.md, "Level files")',
        )


def read_level(data: bytes) -> Level:
    """The level of a file's bytes, as `physc simulate` reads it."""
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
    import jinja2  # only to write a level: reading one (physc simulate) starts without it

    source = resources.files("physc.domains.angrybirds").joinpath("templates/level.xml.j2").read_text(encoding="utf-8")
    environment = jinja2.Environment(autoescape=True, keep_trailing_newline=True, undefined=jinja2.StrictUndefined)
    return environment.from_string(source)


def emit_level(level: Level) -> str:
    return _template().render(level=level, num=number)
