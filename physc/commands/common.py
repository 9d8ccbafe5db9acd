"""What every command shares: exit statuses, usage errors, diagnostic output."""

from __future__ import annotations

import argparse
import os
import re
import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol, cast

from physc import diagnostics
from physc.diagnostics import Diagnostic

# The exit statuses, re-exported (`X as X`): the commands and plugins import them from here.
from physc.exits import EXIT_INFEASIBLE as EXIT_INFEASIBLE
from physc.exits import EXIT_INPUT as EXIT_INPUT
from physc.exits import EXIT_INTERNAL as EXIT_INTERNAL
from physc.exits import EXIT_INTERRUPTED as EXIT_INTERRUPTED
from physc.exits import EXIT_OK as EXIT_OK
from physc.exits import EXIT_STATUSES as EXIT_STATUSES
from physc.exits import EXIT_USAGE as EXIT_USAGE


class UsageError(Exception):
    pass


NEGATIVE_VALUE = re.compile(r"^-\d*\.?\d+([eE][-+]?\d+)?(,.*)?$")  # -3, -.5, -1.62,4.61, -3.5,-0.8,high


class Parser(argparse.ArgumentParser):
    """physc's argument parser: every command's help ends with the exit statuses."""

    def __init__(self, *args, **kwargs):
        kwargs.setdefault("epilog", EXIT_STATUSES)
        super().__init__(*args, **kwargs)
        # A value that starts with a negative number is a value, not an option: `--shot
        # -1.62,4.61` (argparse alone takes only a bare number such as -1.62 for one).
        self._negative_number_matcher = NEGATIVE_VALUE

    def error(self, message):  # argparse's own errors: usage, exit 2
        self.print_usage(sys.stderr)
        print(f"{self.prog}: error: {diagnostics.safe(message)}", file=sys.stderr)  # the value as typed: escaped
        raise SystemExit(EXIT_USAGE)


if TYPE_CHECKING:
    from typing import TypeAlias

    Commands: TypeAlias = argparse._SubParsersAction[Parser]
    """The subcommands of physc's parser, which each command module adds its own to."""


def reporter(args):
    def use_color() -> bool:
        if args.color == "always":
            return True
        if args.color == "never" or os.environ.get("NO_COLOR"):
            return False
        return sys.stderr.isatty()

    color = use_color()

    def report(analysis_path: str, source, found: Sequence[Diagnostic]) -> None:
        for diagnostic in found:
            print(diagnostics.render(diagnostic, source, analysis_path, color=color), file=sys.stderr)

    return report


class Aimed(Protocol):
    """A task's solution as the commands describe it: every domain's solution (angrybirds' shots,
    PHYRE's balls) names the point of interest it was aimed at."""

    aimed_at: str


def aimed_at(solution: object) -> str:
    """What a task's solution was aimed at, in words (`Task.solution` is typed `object`: the
    domain's own class, which is `Aimed`)."""
    return cast(Aimed, solution).aimed_at


def plural(n: int, word: str) -> str:
    """`n` and the word, in the plural unless n is 1 ("1 pig", "2 pigs")."""
    return f"{n} {word}{'' if n == 1 else 's'}"


def summary(errors: int, warnings: int, files: int) -> str:
    return f"{plural(errors, 'error')}, {plural(warnings, 'warning')} in {plural(files, 'file')}"


def add_format(parser, what: str = "the result") -> None:
    """--format text|json, the one spelling of machine-readable output in every command: text
    for people (the default), json on stdout for programs. `--json` is kept, hidden, for
    scripts written before the spelling was one."""
    parser.add_argument(
        "--format", choices=("text", "json"), default="text", help=f"{what} as text (default) or as JSON on stdout"
    )
    parser.add_argument("--json", dest="format", action="store_const", const="json", help=argparse.SUPPRESS)


def print_json(data) -> None:
    """Machine-readable output (--format json): indented JSON on stdout, in ASCII (\\u escapes),
    so a file name that is not valid UTF-8 prints too."""
    import json

    print(json.dumps(data, indent=2))


def check_min_robustness(value: int, domain) -> None:
    """--min-robustness counts the domain's noisy replays (physc.api.compiling.check_min_robustness)."""
    from physc.api.compiling import check_min_robustness as check

    try:
        check(value, domain, "--min-robustness")
    except ValueError as error:
        raise UsageError(str(error)) from None


def chosen(asked: Sequence[str], installed: Sequence[str], kind: str) -> list[str]:
    """The installed plugins a listing command names (`physc domains`, `physc backends`): all
    of them, or those `asked`; an unknown name is a usage error with a did-you-mean."""
    from physc.suggest import did_you_mean

    names = list(installed)
    unknown = [n for n in asked if n not in names]
    if unknown:
        hint = did_you_mean(unknown[0], names) or f"installed {kind}s: " + (", ".join(names) or "none")
        raise UsageError(f"the {kind} '{unknown[0]}' is not installed; {hint}")
    return list(asked) or names


def check_backends(args) -> None:
    """--verify-backend must name another engine than the one that simulates."""
    if getattr(args, "verify_backend", None) and args.verify_backend == args.backend:
        raise UsageError(
            f"--verify-backend {args.verify_backend} is the engine that already simulates (--backend): name another one"
        )
