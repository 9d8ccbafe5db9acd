"""A domain's files: its level files read and written, its pictures, and its task files' values;
a part of the domain (physc.domains.part), `domain.files`, which the back end and the level
commands ask. A domain writes a subclass of `LevelFiles` with what it has, names it
`files = part(MyFiles)`, and declares the capabilities among them (`emit_level`, `picture`,
`read_level`, `draw`)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from physc.domains.errors import MissingCapability
from physc.domains.part import Part

if TYPE_CHECKING:
    from physc.compiler.concrete_layout import ConcreteLayout
    from physc.compiler.task import Task


class LevelFiles(Part):
    """The files of one domain (module docstring); `self.domain` is the domain bound to its world
    and engine, which a picture is drawn in."""

    def emit_level(self, level) -> str:
        """The task's level as the domain's level file (stage level; angrybirds: Science
        Birds XML)."""
        raise MissingCapability(self.domain.name, ("emit_level",), "writing a level")

    def picture(self, task: Task | ConcreteLayout, fmt: str = "png") -> bytes:
        """A picture of the generated task, or of a placed layout (`--emit layout`), `fmt`
        "png" or "svg" (`--png`). No default: how a level looks is the domain's own; a domain
        without one says so clearly instead of drawing something wrong, and one that cannot
        draw a format raises MissingCapability (E0703) for it."""
        raise MissingCapability(self.domain.name, ("picture",), "--png")

    def read_level(self, data: bytes) -> Any:
        """The level of a level file's bytes (`physc simulate`, `trace`, `render`); LevelError
        (a diagnostic's code, message, line and column) for a file that cannot be played."""
        raise MissingCapability(self.domain.name, ("read_level",), "reading a level file")

    def level_world(self, level) -> str | None:
        """The world a level file names (`physc simulate`, `trace`, `render` and `verify` play
        it there unless told otherwise); None: it names none (the default)."""
        return None

    def level_text(self, data: bytes) -> str:
        """A level file's text as `read_level` reads it, so that a LevelError's line and column
        point into it. Default: UTF-8."""
        return data.decode("utf-8", "replace")

    max_level_bytes: int = 4 * 1024 * 1024
    """The largest level file `read_level` is given (a larger one is refused unread, E0906)."""

    def draw(self, level, title: str, paths: dict, fmt: str = "png") -> bytes:
        """A picture of `level` with `paths` (body name → [(x, y), …], drawn as arrows), in the
        domain's world (`physc render`)."""
        raise MissingCapability(self.domain.name, ("draw",), "drawing a level")

    level_format: str = "the domain's level file"
    """What a level file is, in words a dataset's README gives its users: the format, and whose
    reader and version of it the files are written for."""

    level_suffix: str = "level"
    """The file suffix of the domain's level files, without the dot (angrybirds: "xml"): what
    `physc generate` names a task's level `<seed>.<suffix>` with ("json": `<seed>.level.json`,
    beside the task's own `<seed>.json`)."""

    level_classes: tuple[type, ...] = ()
    """The attrs classes a level of this domain is made of, the level's own class first
    (angrybirds: Level, Camera, LevelObject): what reads a level back from a task file
    (physc.serialize.from_data, `physc verify`). Empty: task files of this domain cannot be
    read back."""

    @property
    def solution_class(self) -> type | tuple[type, ...] | None:
        """The attrs class of a task's solution, or a tuple of them when a domain has several
        kinds of action (PHYRE: one ball or two), for reading it back from a task file (`physc
        verify`). None: a task file's solution cannot be read back."""
        return None

    def benchmark_files(self, tasks: list[tuple[dict, str]]) -> dict[str, bytes]:
        """The files of the target world's own benchmark format that a dataset of this domain
        holds beside physc's (`physc generate`; PHYRE: its TaskCollection, observations and
        folds): {path relative to the dataset: contents}, from each generated task's manifest
        row and level file (text), in the dataset's order. Default: none."""
        return {}

    def with_solution(self, level, solution):
        """The generated task's level with its solution, if the domain's level file keeps it
        (PHYRE's task keeps its solutions; the default: the level as it is)."""
        return level
