"""The errors of domains: an unknown or broken plugin, a level file that cannot be played, and
a capability asked of a domain that does not declare it."""

from __future__ import annotations


class DomainError(Exception):
    """A domain is unknown (`code` E0701), its plugin fails to load (E0702), or it
    lacks a capability that was asked for (E0703)."""

    def __init__(self, code: str, message: str, help: str | None = None, suggestions: tuple[str, ...] = ()):
        super().__init__(message)
        self.code = code
        self.message = message
        self.help = help
        self.suggestions = suggestions  # installed domain names the asked-for one may be a misspelling of


class LevelError(Exception):
    """An unusable level file (`LevelFiles.read_level`): `code` is a physc diagnostic code, `line`
    and `column` 1-based or None."""

    def __init__(
        self, code: str, message: str, line: int | None = None, column: int | None = None, help: str | None = None
    ):
        super().__init__(message)
        self.code = code
        self.message = message
        self.line = line
        self.column = column
        self.help = help

    def __str__(self) -> str:
        where = (
            "" if self.line is None else f"line {self.line}" + ("" if self.column is None else f":{self.column}") + ": "
        )
        return where + self.message


class MissingCapability(DomainError):
    """The domain `domain` lacks `hooks`, which `asked` (e.g. "--emit level") needs."""

    def __init__(self, domain: str, hooks: tuple[str, ...], asked: str):
        names = ", ".join(hooks)
        super().__init__(
            "E0703",
            f"the domain '{domain}' cannot do what {asked} needs: it has no {names}",
            "its vocabulary alone serves `physc check` and `--emit ast` or `scenario`; what each hook does is in "
            'docs/plugins.md, "The domain interface"',
        )
        self.domain = domain
        self.hooks = hooks
