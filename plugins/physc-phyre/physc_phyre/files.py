"""PHYRE's files (`Phyre.files`): tasks in PHYRE's task structure as JSON, PHYRE's own benchmark
beside a dataset, the pictures in PHYRE's look, and the task file's ball actions."""

from __future__ import annotations

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.base import MissingCapability
from physc.domains.level_files import LevelFiles
from physc.picture import FORMATS
from physc.simulation.ending import Ending
from physc_phyre.level import BallAction, PhyreLevel, SceneBody, TwoBallAction, level_from_layout
from physc_phyre.task_file import task_json


class PhyreFiles(LevelFiles):
    """PHYRE's files, for the bound domain."""

    level_classes = (PhyreLevel, SceneBody, BallAction, TwoBallAction)
    level_suffix = "json"  # task files in PHYRE's task structure
    level_format = (
        "PHYRE's Task (src/if/task.thrift of facebookresearch/phyre) as JSON with thrift's field names; the benchmark "
        "in PHYRE's own binary TaskCollection is phyre/tasks50.bin.lzma"
    )

    @property
    def solution_class(self) -> tuple[type, ...]:
        """A task's solution: one ball, or two (PHYRE's two-ball tier)."""
        return (BallAction, TwoBallAction)

    def with_solution(self, level: PhyreLevel, solution) -> PhyreLevel:
        return attrs.evolve(level, solutions=(solution,))

    def emit_level(self, level: PhyreLevel) -> str:
        """The task in PHYRE's task structure, as JSON (task_file.py)."""
        return task_json(level)

    def benchmark_files(self, tasks) -> dict[str, bytes]:
        """PHYRE's own benchmark files beside the dataset (benchmark.py)."""
        from physc_phyre.benchmark import benchmark_files

        return benchmark_files(tasks)

    def picture(self, task, fmt: str = "png") -> bytes:
        """The scene in PHYRE's look with the red ball of the solution and the paths it makes;
        a placed layout as the level it becomes."""
        from physc_phyre.picture import picture

        if fmt not in FORMATS:
            raise MissingCapability(self.domain.name, (f"picture in {fmt}",), f"--png as {fmt}")
        if isinstance(task, ConcreteLayout):
            return picture(level_from_layout(task, None), f"{task.scenario} (seed {task.seed})", None, None, fmt)
        level, solution = task.level, task.solution
        assert isinstance(level, PhyreLevel) and isinstance(solution, BallAction | TwoBallAction)  # PHYRE's own task
        trace = self.domain.play(level, solution, ending=Ending.OUTCOME)
        title = f"{task.scenario} (seed {task.seed}): {solution.aimed_at}"
        return picture(level, title, solution, trace.paths(threshold=0.5), fmt)
