"""Failure is an answer: why a well-formed scenario yields no layout or task."""

from __future__ import annotations

from physc.compiler.layout_graph import LayoutEdge


class Infeasible(Exception):
    """No task can be generated: the constraints conflict (`budget=False`) or the
    search budget ran out first (`budget=True`). `conflicts` are the layout edges
    that cannot hold together, each with the source terms it comes from."""

    def __init__(self, stage: str, message: str, conflicts: tuple[LayoutEdge, ...] = (), tried: int = 0, budget: bool = False):
        super().__init__(message)
        self.stage = stage
        self.message = message
        self.conflicts = conflicts
        self.tried = tried
        self.budget = budget
