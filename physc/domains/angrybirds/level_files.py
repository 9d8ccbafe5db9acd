"""Science Birds' files (`AngryBirds.files`): its level XML read and written, the pictures of
its levels and tasks, Phy-Q's level set beside a dataset, and the task file's shot records."""

from __future__ import annotations

from physc.domains.angrybirds.level import Camera, Level, LevelObject
from physc.domains.level_files import LevelFiles


class ScienceBirdsFiles(LevelFiles):
    """Science Birds' files, drawn in the bound domain's world."""

    level_classes = (Level, Camera, LevelObject)
    level_suffix = "xml"  # Science Birds level files
    level_format = (
        "a Science Birds level: XML in UTF-8 (ASCII; the game's own files declare utf-16 over the same bytes), as "
        "the Science Birds of the Phy-Q testbed (phy-q/benchmark, "
        "LevelLoader.cs) loads it (physc's docs/angrybirds.md)"
    )

    def level_world(self, level) -> str | None:
        return level.world

    @property
    def solution_class(self) -> tuple[type, ...]:
        from physc.domains.angrybirds.shots import BirdShot, ShotsSolution, Solution

        return (Solution, ShotsSolution, BirdShot)

    def read_level(self, data: bytes) -> Level:
        from physc.domains.angrybirds.level_xml import read_level

        return read_level(data)

    def level_text(self, data: bytes) -> str:
        """The level file's text as `read_level` decodes it (UTF-16 by its byte-order mark, else UTF-8)."""
        from physc.domains.angrybirds.level_xml import decode
        from physc.domains.base import LevelError

        try:
            return decode(data)
        except LevelError:
            return data.decode("utf-8", "replace")

    def draw(self, level, title: str, paths: dict, fmt: str = "png") -> bytes:
        from physc.domains.angrybirds.picture import draw_level, save

        return save(draw_level(level, self.domain.world, title, paths), fmt)

    def benchmark_files(self, tasks) -> dict[str, bytes]:
        """The tasks as a level set Phy-Q's game loads, with the shots its agents send (phyq_levels.py)."""
        from physc.domains.angrybirds.phyq_levels import benchmark_files

        return benchmark_files(tasks)

    def emit_level(self, level) -> str:
        from physc.domains.angrybirds.level_xml import emit_level

        return emit_level(level)

    def picture(self, task, fmt: str = "png") -> bytes:
        """The task's level with the paths its solution makes, like the paper's figure; a
        placed layout (`--emit layout --png`) as the level it becomes."""
        from physc.compiler.concrete_layout import ConcreteLayout
        from physc.domains.angrybirds.picture import draw_level, render, save
        from physc.domains.angrybirds.shots import BirdShot, ShotsSolution, Solution

        if isinstance(task, ConcreteLayout):
            return render(task, fmt, self.domain.world)
        level, solution = task.level, task.solution
        assert isinstance(level, Level) and isinstance(
            solution, Solution | ShotsSolution | BirdShot
        )  # a Science Birds task
        trace = self.domain.game(level).simulate(
            self.domain.actions.action_of(solution), self.domain.seconds, settle_after_solved=0.5
        )
        supports = frozenset(o.name for o in level.objects if o.name.startswith(("support_", "obstacle")))
        title = f"{task.scenario} (seed {task.seed}): {solution.aimed_at}"
        return save(draw_level(level, self.domain.world, title, trace.paths(), supports), fmt)
