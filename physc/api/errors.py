"""The errors physc's Python API raises: one base class, so that a caller can catch what
physc reports about its input apart from a bug (any other exception)."""

from __future__ import annotations

from physc.diagnostics import Diagnostic, SourceText, render


class PhyscError(Exception):
    """What the command line reports with a diagnostic and an exit status: bad input, a
    scenario that gives no task, a file that is not what it should be."""


class ScenarioError(PhyscError):
    """The scenario text has errors (`physc check`'s diagnostics): `diagnostics` holds them all
    (errors and warnings), and the message is their text as `physc check` prints it."""

    def __init__(
        self, diagnostics: tuple[Diagnostic, ...], source: SourceText | None, name: str, message: str | None = None
    ):
        self.diagnostics = tuple(diagnostics)
        self.source = source
        self.name = name
        shown = "\n".join(render(d, source, name) for d in self.diagnostics if d.is_error)
        super().__init__(message or shown or f"{name}: the scenario cannot be compiled")


class NoTask(PhyscError):
    """The scenario is valid, but no task came of it within the budgets (`physc compile`'s exit
    status 3): `diagnostic` says where the search stopped and why, and `reason` is its message."""

    def __init__(self, diagnostic: Diagnostic):
        self.diagnostic = diagnostic
        self.reason = diagnostic.message
        super().__init__(diagnostic.message + (f" ({diagnostic.help})" if diagnostic.help else ""))


class FileError(PhyscError):
    """A task file, level file or dataset that cannot be read (missing, damaged, or another
    kind of file), or an output that cannot be written."""
